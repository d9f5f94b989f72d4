# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The cost of the printing mode (WallThickness above 0) against the plain
run (the shell), on the Table 1 sphere and the closed scans of ../shared at
their defaults, with the wall 2 % of the cloud's diagonal (as the how-to
"Hollow a scan for printing" and the test PrintPart take it). Prints a table.

    PYTHONPATH=build/lib/python3.11/dist-packages pvpython benchmarks/print_part.py \
        [--repeat 5] [--threads 1 2] [--scans ../shared/data/scans]

Each run is a child process of its own (one Update, OutputVolume off, the
surface only), so that its peak resident size (VmHWM, less the size before
the filter ran) is its own; the plain and printing runs alternate, and the
table gives the medians of --repeat runs of each and their ratio, from one
run of this script (the machine's load cancels as far as it can).
"""
import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import time

import clouds
from clouds import nvclouds, nvshapes
from held_memory import peak_mb, reset_peak, resident_mb

CASES = [("sphere", "Table 1 sphere, h 0.01, l 0.1, w 0.05"), ("armadillo", "armadillo"),
         ("dragon", "dragon"), ("teapot", "teapot")]

# The children run in pvpython, whose Python finds ParaView's VTK.
PYTHON = shutil.which("pvpython") or sys.executable

parser = argparse.ArgumentParser()
parser.add_argument("--repeat", type=int, default=5)
parser.add_argument("--threads", type=int, nargs="+", default=[1, os.cpu_count()])
parser.add_argument("--scans", default=clouds.SCANS_DIR)
parser.add_argument("--child", nargs=3, help=argparse.SUPPRESS)  # CASE THREADS WALL(0|1): one run
args = parser.parse_args()


def case_settings(name):
    """(points, settings of the printing mode) of a case; the plain run drops WallThickness."""
    import numpy as np
    if name == "sphere":
        return nvshapes.sphere_points(0.01), dict(SampleSpacing=0.01, OffsetDistance=0.1, WallThickness=0.05)
    xyz = nvclouds.scan_points(name, args.scans)
    return xyz, dict(WallThickness=0.02 * float(np.linalg.norm(xyz.max(axis=0) - xyz.min(axis=0))))


def child(name, threads, wall):
    """One Update in this process: prints {"seconds", "peak_mb", "triangles"} as JSON."""
    from narrowvolume import vtkNarrowVolumeReconstruction
    xyz, settings = case_settings(name)
    if not wall:
        del settings["WallThickness"]
    cloud = nvclouds.cloud(xyz)
    f = vtkNarrowVolumeReconstruction()
    f.SetInputData(cloud)
    for key, value in settings.items():
        getattr(f, "Set" + key)(value)
    f.SetNumberOfThreads(threads)
    f.SetOutputVolume(False)
    reset_peak()
    before = resident_mb()
    start = time.perf_counter()
    f.Update()
    seconds = time.perf_counter() - start
    print(json.dumps(dict(seconds=seconds, peak_mb=peak_mb() - before,
                          triangles=f.GetOutput(1).GetNumberOfPolys())))


def measure(name, threads, wall):
    out = subprocess.run([PYTHON, os.path.abspath(__file__), "--scans", args.scans,
                          "--child", name, str(threads), str(int(wall))],
                         check=True, capture_output=True, text=True).stdout
    return json.loads(out.strip().splitlines()[-1])


def main():
    if args.child:
        child(args.child[0], int(args.child[1]), args.child[2] == "1")
        return
    print("| case | threads | shell (s) | part (s) | part / shell | shell peak (MB) | part peak (MB) |"
          " shell triangles | part triangles |")
    print("|---|---|---|---|---|---|---|---|---|")
    for name, label in CASES:
        if name != "sphere":
            try:
                nvclouds.scan_points(name, args.scans)
            except nvclouds.ScansMissing as missing:
                print("| %s | skipped: %s |" % (label, missing))
                continue
        for threads in args.threads:
            runs = {False: [], True: []}
            for _ in range(args.repeat):
                for wall in (False, True):
                    runs[wall].append(measure(name, threads, wall))
            seconds = {w: statistics.median(r["seconds"] for r in runs[w]) for w in runs}
            peak = {w: statistics.median(r["peak_mb"] for r in runs[w]) for w in runs}
            print("| %s | %d | %.2f | %.2f | %.2fx | %.0f | %.0f | %d | %d |" % (
                label, threads, seconds[False], seconds[True], seconds[True] / seconds[False], peak[False],
                peak[True], runs[False][0]["triangles"], runs[True][0]["triangles"]), flush=True)


main()
