# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Benchmark: the filter's stages on one of table2.py's cases, run again and
again in one warm process (for a profiler to sample, or to see where the time
of a run goes without a fresh process's start-up).

    PYTHONPATH=build/lib/python3.11/dist-packages \\
        pvpython benchmarks/stages.py dragon [--repeat 8] [--volume off] [--scans DIR]

    perf record -F 1000 pvpython benchmarks/stages.py dragon --repeat 8 --volume off

Prints a Markdown table: for each stage the median over the runs and the
range, in seconds ("spacing" is GetSamplingTime(), the measurement of the
points' nearest neighbours; "Update()" the whole call).
"""
import argparse
import os
import statistics
import sys
import time

import numpy as np

import clouds
import table2


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("case", choices=list(table2.CASES))
    parser.add_argument("--repeat", type=int, default=8)
    parser.add_argument("--volume", choices=["on", "off"], default="off")
    parser.add_argument("--scans", default=clouds.SCANS_DIR)
    args = parser.parse_args()

    source, cells, offset_cells, xi, steps = table2.CASES[args.case][:5]
    task = dict(source=source, cells=cells, offset_cells=offset_cells, xi=xi, steps=steps)
    if source != "sphere":
        task["path"] = os.path.join(args.scans, source)
        if not os.path.exists(task["path"]):
            print("skipped: %s not found (the scans are read from ../shared)" % task["path"])
            return 0

    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkPolyData
    from narrowvolume import vtkNarrowVolumeReconstruction

    xyz = clouds.load(task)
    points = vtkPoints()
    points.SetData(numpy_to_vtk(np.ascontiguousarray(xyz), deep=1))
    cloud = vtkPolyData()
    cloud.SetPoints(points)
    h = 0.01 if source == "sphere" else clouds.spacing(xyz, task)

    names = ["spacing", "set-up", "evolution", "output", "Update()"]
    runs = []
    for _ in range(args.repeat):
        f = vtkNarrowVolumeReconstruction()
        f.SetInputData(cloud)
        f.SetSampleSpacing(h)
        f.SetOffsetDistance(offset_cells * h)
        f.SetXiCells(xi)
        f.SetMaximumNumberOfIterations(steps)
        f.SetOutputVolume(args.volume == "on")
        f.GlobalWarningDisplayOff()  # the scans' gap warning, once a run
        start = time.perf_counter()
        f.Update()
        runs.append((f.GetSamplingTime(), f.GetSetupTime(), f.GetEvolutionTime(), f.GetOutputTime(),
                     time.perf_counter() - start))

    print("%s: %d points, %d band nodes, %d steps, %d triangles, volume %s, %d runs in one process"
          % (args.case, len(xyz), f.GetNumberOfBandNodes(), f.GetNumberOfIterations(),
             f.GetOutput(1).GetNumberOfPolys(), args.volume, args.repeat))
    print()
    print("| stage | median (s) | range (s) |")
    print("|---|---|---|")
    for i, name in enumerate(names):
        values = [run[i] for run in runs]
        print("| %s | %.3f | %.3f to %.3f |" % (name, statistics.median(values), min(values), max(values)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
