# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Benchmark: the paper's Fig. 16 on a cloud the project generates. The paper
times the Thai statue (5 M points, and 2.5, 1.25, 0.625, 0.3125 M by halving)
on three grids (longest side 215, 416, 833 nodes): (a) the set-up against the
number of points, (b) the time per step against the grid. Here the statue is
replaced by N points scattered over the demo's trefoil tube
(Data/make_demo_cloud.py), for the same N, on the grids given by --cells.

    pvpython benchmarks/fig16.py [--cells 215 416] [--points 0.3125 0.625 1.25 2.5 5] [--repeat 3]

Narrow Band, l = 4 h, xi = 2 h, 3 steps, OutputVolume off. Every run is a
fresh child process (table2.py's); times are medians of --repeat runs.
Prints a Markdown table: the points' spacing measurement (nearest
neighbours, for the gap warning and the automatic offset: part of every run,
outside the filter's SetupTime), the set-up (distance and band), both per
point, time per step, output and its ratio to the set-up, band nodes and
peak memory.
"""
import argparse
import os
import platform
import sys

import table2  # the children


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--cells", nargs="+", type=int, default=[215, 416])
    parser.add_argument("--points", nargs="+", type=float, default=[0.3125, 0.625, 1.25, 2.5, 5.0],
                        help="millions of points")
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    print("Machine: %s, %d cores, load average at start %s; medians of %d runs (seconds), peak RSS (MB)."
          % (platform.processor() or platform.machine(), os.cpu_count(),
             " ".join(open("/proc/loadavg").read().split()[:3]), args.repeat))
    print()
    print("| grid | points | band nodes | spacing | set-up | spacing + set-up per point | per step | output "
          "| output ÷ set-up | peak MB |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    timing = ["sampling", "setup", "evolution", "surface"]
    for cells in args.cells:
        for millions in args.points:
            n = int(round(millions * 1e6))
            task = dict(source="trefoil:%d" % n, cells=cells, offset_cells=4, xi=2, steps=3, kind="ours",
                        domain=0, volume=False)
            r = table2.median_run(task, args.repeat, timing)
            print("| %s | %s | %s | %.2f | %.2f | %.2f µs | %.3f | %.2f | %.2f | %.0f |" % (
                r["grid"], "{:,}".format(n), "{:,}".format(r["band"]), r["sampling"], r["setup"],
                1e6 * (r["sampling"] + r["setup"]) / n,
                r["evolution"] / max(1, r["iterations"]), r["surface"], r["surface"] / r["setup"], r["maxrss_mb"]))
            sys.stdout.flush()


if __name__ == "__main__":
    main()
