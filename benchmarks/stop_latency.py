# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""How soon a run hears a stop: the longest time between two reports of
progress (a GUI's abort button and Python's Ctrl-C act only in a report),
and where in the run it falls, on large noisy spheres, for the shell and a
part to print. Prints a table.

    PYTHONPATH=build/lib/python3.11/dist-packages python3 benchmarks/stop_latency.py \
        [--points 1e6 5e6] [--threads 0]

A run reports at least every 0.1 s while it asks whether to stop
(nv::CallerMonitor), so the longest gap is the longest stretch of work that
does not ask: the claim of the docs is that none is longer than about half a
second on two cores at five million points. Progress: where the gap began,
as the filter's progress (the measurement of the spacing 0-0.1; then the run
and, from 0.28 in a part's run, the part).
"""
import argparse
import time

import numpy as np


def sphere(points, seed=2):
    """`points` points on a sphere of radius 0.5 about (0.5, 0.5, 0.5), with
    noise 0.4 % of the radius."""
    rng = np.random.default_rng(seed)
    v = rng.normal(size=(int(points), 3))
    xyz = 0.5 * v / np.linalg.norm(v, axis=1)[:, None] + 0.5
    return xyz + rng.normal(scale=0.002, size=xyz.shape)


def gaps(xyz, threads, **settings):
    """(seconds of the run, the longest gap between reports, the progress where it began)."""
    import narrowvolume
    reports = []
    start = time.perf_counter()
    narrowvolume.reconstruct(xyz, progress=lambda f: reports.append((time.perf_counter(), f)),
                             NumberOfThreads=threads, **settings)
    longest = max((b[0] - a[0], a[1]) for a, b in zip(reports, reports[1:]))
    return time.perf_counter() - start, longest[0], longest[1]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--points", type=float, nargs="+", default=[1e6, 5e6])
    parser.add_argument("--threads", type=int, default=0, help="NumberOfThreads (0: all cores)")
    args = parser.parse_args()
    cases = [("shell", {}), ("part, wall 0.02", {"WallThickness": 0.02})]
    print("| points | output | run (s) | longest gap between reports (s) | at progress |")
    print("|---|---|---|---|---|")
    for points in args.points:
        xyz = sphere(points)
        for name, settings in cases:
            seconds, gap, at = gaps(xyz, args.threads, MaximumDimension=400, **settings)
            print("| %.0f | %s | %.2f | %.2f | %.3f |" % (points, name, seconds, gap, at), flush=True)


if __name__ == "__main__":
    main()
