# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Renders doc/images/benchmark.png: the filter's time against the number of
points, on two grids (the README's Fig. 16 benchmark, benchmarks/fig16.py:
N points scattered over the demo's trefoil tube, l = 4 h, 3 steps,
OutputVolume off, every run a fresh pvpython process, medians of --repeat).

    pvpython doc/pictures/benchmark.py                 # plot doc/pictures/benchmark.csv
    pvpython doc/pictures/benchmark.py --measure [--cells 215 416] \\
        [--points 0.3125 0.625 1.25 2.5 5] [--repeat 3]  # measure, write the CSV, plot

--measure runs the benchmark and writes doc/pictures/benchmark.csv (its
first lines, starting with #, hold the command, the commit, the machine and
its load); without it the script plots the CSV that is there (measuring a
small configuration first if there is none). The defaults of --measure are
the README's table (several minutes on 2 cores); for a quick check,
--cells 64 128 --points 0.02 0.04 0.08 --repeat 1. Timing on a shared
machine is noisy: measure when it is quiet.
"""
import argparse
import csv
import os
import platform
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.normpath(os.path.join(HERE, "..", ".."))
BUILD = os.environ.get("BUILD_DIR") or os.path.join(SOURCE, "build")
CSV = os.path.join(HERE, "benchmark.csv")
PNG = os.path.join(SOURCE, "doc", "images", "benchmark.png")
COLUMNS = ["cells", "points", "grid", "band_nodes", "sampling_s", "setup_s", "evolution_s", "iterations",
           "output_s", "update_s", "peak_mb"]
QUICK = dict(cells=[64, 128], points=[0.02, 0.04, 0.08], repeat=1)


def measure(cells, points, repeat):
    sys.path.insert(0, os.path.join(SOURCE, "benchmarks"))
    packages = os.path.join(BUILD, "lib", "python3.11", "dist-packages")
    os.environ["PYTHONPATH"] = os.pathsep.join(p for p in (packages, os.environ.get("PYTHONPATH")) if p)
    import table2  # the benchmarks' children: one fresh pvpython process a run

    commit = subprocess.run(["git", "-C", SOURCE, "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True).stdout.strip() or "unknown"
    command = "pvpython doc/pictures/benchmark.py --measure --cells %s --points %s --repeat %d" % (
        " ".join(map(str, cells)), " ".join(map(str, points)), repeat)
    rows = []
    for c in cells:
        for millions in points:
            n = int(round(millions * 1e6))
            task = dict(source="trefoil:%d" % n, cells=c, offset_cells=4, xi=2, steps=3, kind="ours", domain=0,
                        volume=False)
            r = table2.median_run(task, repeat, ["sampling", "setup", "evolution", "surface", "update"])
            row = [c, n, r["grid"], r["band"], r["sampling"], r["setup"], r["evolution"], r["iterations"],
                   r["surface"], r["update"], r["maxrss_mb"]]
            print("cells %d, %s points: Update() %.3f s" % (c, format(n, ","), r["update"]), flush=True)
            rows.append(row)
    with open(CSV, "w", newline="") as f:
        f.write("# %s\n" % command)
        f.write("# commit %s, %s, %d cores, load average at start %s, medians of %d fresh processes (s)\n" % (
            commit, platform.machine(), os.cpu_count(), " ".join(open("/proc/loadavg").read().split()[:3]),
            repeat))
        writer = csv.writer(f)
        writer.writerow(COLUMNS)
        for row in rows:
            writer.writerow([("%.4f" % v) if isinstance(v, float) else v for v in row])
    print("wrote %s" % os.path.relpath(CSV, SOURCE))


def read():
    with open(CSV) as f:
        notes = []
        lines = []
        for line in f:
            (notes if line.startswith("#") else lines).append(line)
    rows = list(csv.DictReader(lines))
    return [n.lstrip("# ").strip() for n in notes], rows


def plot():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    notes, rows = read()
    grids = sorted({int(r["cells"]) for r in rows})
    fig, axes = plt.subplots(1, 2, figsize=(10, 4.2))
    colors = ["tab:blue", "tab:orange", "tab:green", "tab:red"]
    for color, cells in zip(colors, grids):
        mine = sorted((r for r in rows if int(r["cells"]) == cells), key=lambda r: int(r["points"]))
        n = [int(r["points"]) for r in mine]
        grid = mine[0]["grid"].replace("x", "×")
        axes[0].plot(n, [float(r["update_s"]) for r in mine], "o-", color=color, label="whole Update(), %s" % grid)
        axes[0].plot(n, [float(r["sampling_s"]) + float(r["setup_s"]) for r in mine], "s--", color=color,
                     alpha=0.7, label="spacing + set-up, %s" % grid)
        per_step = [float(r["evolution_s"]) / max(1, int(r["iterations"])) for r in mine]
        axes[1].plot([int(r["band_nodes"]) for r in mine], per_step, "o", color=color, label=grid)
    axes[0].set_xscale("log")
    axes[0].set_yscale("log")
    axes[0].set_xlabel("points")
    axes[0].set_ylabel("seconds")
    axes[0].set_title("time against the number of points", fontsize=10)
    axes[0].legend(fontsize=8)
    axes[1].set_xscale("log")
    axes[1].set_yscale("log")
    axes[1].set_xlabel("band nodes")
    axes[1].set_ylabel("seconds per time step")
    axes[1].set_title("a time step follows the band, not the points", fontsize=10)
    axes[1].legend(fontsize=8, title="grid")
    for ax in axes:
        ax.grid(alpha=0.3, which="both")
    fig.suptitle("Points over the demo's trefoil tube, l = 4h, 3 steps, Output Volume off", fontsize=11)
    fig.text(0.5, 0.01, "\n".join(notes), ha="center", va="bottom", fontsize=7, color="0.35")
    fig.tight_layout(rect=(0, 0.07, 1, 1))
    os.makedirs(os.path.dirname(PNG), exist_ok=True)
    fig.savefig(PNG, dpi=120, facecolor="white")
    print("wrote %s (%d kB)" % (os.path.relpath(PNG, SOURCE), os.path.getsize(PNG) // 1024))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--measure", action="store_true", help="run the benchmark and rewrite the CSV")
    parser.add_argument("--cells", nargs="+", type=int, default=[215, 416], help="cells along the longest side")
    parser.add_argument("--points", nargs="+", type=float, default=[0.3125, 0.625, 1.25, 2.5, 5.0],
                        help="millions of points")
    parser.add_argument("--repeat", type=int, default=3, help="runs of each, their median")
    parser.add_argument("--quick", action="store_true",
                        help="with --measure: the small configuration (--cells 64 128 --points 0.02 0.04 0.08 "
                             "--repeat 1)")
    args = parser.parse_args()
    if args.quick:
        args.cells, args.points, args.repeat = QUICK["cells"], QUICK["points"], QUICK["repeat"]
    if args.measure:
        measure(args.cells, args.points, args.repeat)
    elif not os.path.exists(CSV):
        print("no %s: measuring the small configuration first" % os.path.relpath(CSV, SOURCE))
        measure(QUICK["cells"], QUICK["points"], QUICK["repeat"])
    plot()


if __name__ == "__main__":
    main()
