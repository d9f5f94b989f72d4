# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The cost of PreserveOffset against the paper's step, on the Table 1 sphere
and scans (l = 4h), one thread. Prints a table.

    pvpython benchmarks/preserve_offset.py [--steps 10] [--repeat 5] [--callgrind]

Default: the evolution time with the option on and off, runs alternating in
one process, medians of --repeat runs each (one ratio from one run, so that
the machine's load cancels as far as it can). With --callgrind: the
instructions executed in the evolution (nv::AllenCahnSolver::Run), counted
by valgrind's callgrind in one child process per case and setting: exact
and repeatable, whatever the load.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys

import numpy as np

import clouds
from clouds import nvclouds
from narrowvolume import vtkNarrowVolumeReconstruction

parser = argparse.ArgumentParser()
parser.add_argument("--steps", type=int, default=10)
parser.add_argument("--repeat", type=int, default=5)
parser.add_argument("--callgrind", action="store_true")
parser.add_argument("--scans", default=clouds.SCANS_DIR)
parser.add_argument("--child", nargs=2, help=argparse.SUPPRESS)  # CASE PRESERVE: one run, for callgrind
args = parser.parse_args()

CASES = [("sphere", "Table 1 sphere, h = 0.01"), ("teacup", "teacup, 150 cells"), ("bunny", "bunny, 150 cells"),
         ("dragon", "dragon, 200 cells")]
CELLS = {"teacup": 150, "bunny": 150, "dragon": 200}


def case_input(name):
    """(points, h, l) of a case."""
    if name == "sphere":
        return nvclouds.shape_points("sphere", 0.01), 0.01, 0.1
    xyz = nvclouds.scan_points(name, args.scans)
    h = float((xyz.max(axis=0) - xyz.min(axis=0)).max()) / CELLS[name]
    return xyz, h, 4 * h


def run(cloud, h, offset, preserve):
    f = vtkNarrowVolumeReconstruction()
    f.SetInputData(cloud)
    f.SetSampleSpacing(h)
    f.SetOffsetDistance(offset)
    f.SetMaximumNumberOfIterations(args.steps)
    f.SetNumberOfThreads(1)
    f.SetOutputVolume(False)
    f.SetPreserveOffset(preserve)
    f.Update()
    return f


if args.child:
    xyz, h, offset = case_input(args.child[0])
    f = run(nvclouds.cloud(xyz), h, offset, bool(int(args.child[1])))
    print("band nodes %d" % f.GetNumberOfBandNodes())
    sys.exit(0)

cases = [(name, label) for name, label in CASES if name == "sphere" or nvclouds.have_scans((name,), args.scans)]
if args.callgrind:
    print("%d steps, 1 thread: instructions in nv::AllenCahnSolver::Run (valgrind --tool=callgrind)" % args.steps)
    print("| case | band nodes | instructions, off | instructions, on | on / off |")
    print("|---|---|---|---|---|")
else:
    print("%d steps, 1 thread, medians of %d runs each, on and off alternating" % (args.steps, args.repeat))
    print("| case | band nodes | evolution s, off | evolution s, on | on / off |")
    print("|---|---|---|---|---|")
for name, label in cases:
    if args.callgrind:
        counts, nodes = {}, 0
        for preserve in (0, 1):
            command = ["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null",
                       "--toggle-collect=nv::AllenCahnSolver::Run(nv::Monitor*)", shutil.which("pvpython"),
                       os.path.abspath(__file__), "--steps", str(args.steps), "--scans", args.scans,
                       "--child", name, str(preserve)]
            child = subprocess.run(command, capture_output=True, text=True)
            collected = re.search(r"Collected : (\d+)", child.stderr)
            band = re.search(r"band nodes (\d+)", child.stdout)
            if child.returncode != 0 or not collected or not band:
                sys.exit("callgrind run failed: %s" % child.stderr[-2000:])
            counts[preserve], nodes = int(collected.group(1)), int(band.group(1))
        print("| %s | %d | %.4g | %.4g | %.3f |" % (label, nodes, counts[0], counts[1], counts[1] / counts[0]))
    else:
        xyz, h, offset = case_input(name)
        cloud = nvclouds.cloud(xyz)
        times = {False: [], True: []}
        for _ in range(args.repeat):
            for preserve in (False, True):
                f = run(cloud, h, offset, preserve)
                times[preserve].append(f.GetEvolutionTime())
        off, on = np.median(times[False]), np.median(times[True])
        print("| %s | %d | %.3f | %.3f | %.2f |" % (label, f.GetNumberOfBandNodes(), off, on, on / off))
    sys.stdout.flush()
