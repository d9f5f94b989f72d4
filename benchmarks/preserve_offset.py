# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The cost of PreserveOffset: the evolution time per step with the option
on and off, measured in one process, runs alternating, medians of --repeat
runs each (a ratio from one run, so the machine's load cancels as far as it
can). Prints a table.

    pvpython benchmarks/preserve_offset.py [--steps 10] [--repeat 5] [--threads 1] [--scans ../shared/data/scans]
"""
import argparse
import os
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "Testing", "Python"))
import nvshapes  # noqa: E402
import nvtesting  # noqa: E402
from narrowvolume import vtkNarrowVolumeReconstruction  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("--steps", type=int, default=10)
parser.add_argument("--repeat", type=int, default=5)
parser.add_argument("--threads", type=int, default=1)
parser.add_argument("--scans", default=os.path.join(HERE, "..", "..", "shared", "data", "scans"))
args = parser.parse_args()


def scan(name, cells):
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOPLY import vtkPLYReader
    reader = vtkPLYReader()
    reader.SetFileName(os.path.join(args.scans, name + ".ply"))
    reader.Update()
    xyz = vtk_to_numpy(reader.GetOutput().GetPoints().GetData()).astype(float)
    h = float((xyz.max(axis=0) - xyz.min(axis=0)).max()) / cells
    return xyz, h, 4 * h


cases = [("Table 1 sphere, h = 0.01", nvshapes.sphere_points(0.01), 0.01, 0.1)]
for name, cells in (("teacup", 250), ("bunny", 200), ("dragon", 200)):
    if os.path.isfile(os.path.join(args.scans, name + ".ply")):
        cases.append(("%s, %d cells, l = 4h" % (name, cells),) + scan(name, cells))

print("%d steps, %d thread(s), medians of %d runs each, on and off alternating" % (args.steps, args.threads, args.repeat))
print("| case | band nodes | evolution s, off | evolution s, on | on / off |")
print("|---|---|---|---|---|")
for label, xyz, h, offset in cases:
    cloud = nvtesting.cloud(xyz)
    times = {False: [], True: []}
    nodes = 0
    for _ in range(args.repeat):
        for preserve in (False, True):
            f = vtkNarrowVolumeReconstruction()
            f.SetInputData(cloud)
            f.SetSampleSpacing(h)
            f.SetOffsetDistance(offset)
            f.SetMaximumNumberOfIterations(args.steps)
            f.SetNumberOfThreads(args.threads)
            f.SetOutputVolume(False)
            f.SetPreserveOffset(preserve)
            f.Update()
            times[preserve].append(f.GetEvolutionTime())
            nodes = f.GetOutput(0).GetFieldData().GetArray("NarrowBandNodes")
    off, on = np.median(times[False]), np.median(times[True])
    count = int(nodes.GetValue(0)) if nodes else -1
    print("| %s | %d | %.3f | %.3f | %.2f |" % (label, count, off, on, on / off))
    sys.stdout.flush()
