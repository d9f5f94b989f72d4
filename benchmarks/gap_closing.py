# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Benchmark: what gap closing (CloseGaps, nvGapClosing.h) costs on the scans,
with nothing else set (the first Apply), the surface only (OutputVolume off).

    PYTHONPATH=build/lib/python3.11/dist-packages \\
        pvpython benchmarks/gap_closing.py [--repeat 5] [--scans DIR] [--dense 1000000]

Runs Update() with CloseGaps off and on in turn, in one process, and prints a
Markdown table: per scan the points added, the gaps reported without and with
closing, the median Update() of each and their ratio (the medians of the
pairs' ratios). --dense N adds a row for N points scattered over the demo's
trefoil tube (clouds.py), a cloud far denser than its automatic offset.
"""
import argparse
import statistics
import sys
import time

import numpy as np

import clouds

SCANS = ("armadillo", "armadillo_decimated", "dragon", "teapot", "teacup", "bunny", "demosthenes",
         "bunny_rangescan_bun000")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--scans", default=clouds.SCANS_DIR)
    parser.add_argument("--dense", type=int, default=0)
    args = parser.parse_args()
    scans = clouds.nvclouds.have_scans(SCANS, args.scans)
    if not scans:
        print("%s: scan rows skipped" % clouds.nvclouds.ScansMissing(args.scans))

    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkPolyData
    from narrowvolume import vtkNarrowVolumeReconstruction

    def read(name):
        if name.startswith("trefoil:"):
            points = vtkPoints()
            points.SetData(numpy_to_vtk(np.ascontiguousarray(clouds.load(dict(source=name)), dtype=float), deep=1))
            cloud = vtkPolyData()
            cloud.SetPoints(points)
            return cloud
        return clouds.nvclouds.scan(name, args.scans)

    print("| scan | points | points added | gaps without / with | Update() without (s) | with (s) | ratio |")
    print("|---|---|---|---|---|---|---|")
    names = (SCANS if scans else ()) + (("trefoil:%d" % args.dense,) if args.dense else ())
    for name in names:
        cloud = read(name)
        times = {False: [], True: []}
        figures = {}
        for _ in range(args.repeat):
            for close in (False, True):
                f = vtkNarrowVolumeReconstruction()
                f.SetInputData(cloud)
                f.SetOutputVolume(False)
                f.SetCloseGaps(close)
                f.GlobalWarningDisplayOff()
                start = time.perf_counter()
                f.Update()
                times[close].append(time.perf_counter() - start)
                field = f.GetOutput(0).GetFieldData()
                figures[close] = (field.GetArray("AddedPoints").GetValue(0), field.GetArray("NumberOfGaps").GetValue(0))
        ratios = [b / a for a, b in zip(times[False], times[True])]
        print("| %s | %d | %d | %d / %d | %.3f | %.3f | %.2f |" % (
            name, cloud.GetNumberOfPoints(), figures[True][0], figures[False][1], figures[True][1],
            statistics.median(times[False]), statistics.median(times[True]), statistics.median(ratios)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
