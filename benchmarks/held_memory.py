# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Benchmark: the memory the filter holds between runs (its measurement of
the points' spacing, kept so that changing a property does not measure
again), on N points scattered over the demo's trefoil tube.

    PYTHONPATH=build/lib/python3.11/dist-packages pvpython benchmarks/held_memory.py [--points 5000000]

Prints a Markdown row: the process's resident size after the information
pass and after Update() (OutputVolume off, 120 cells along the longest side),
each minus the size before the filter existed, the surface's own size, the
peak resident size from then on, minus the same, and the information pass's
time. Run it with two builds'
packages to compare them.
"""
import argparse
import os
import sys
import time

import numpy as np

import clouds


def resident_mb():
    with open("/proc/self/statm") as statm:
        return int(statm.read().split()[1]) * os.sysconf("SC_PAGE_SIZE") / 2.0 ** 20


def peak_mb():
    """The peak resident size since reset_peak() (VmHWM)."""
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith("VmHWM:"):
                return int(line.split()[1]) / 1024.0
    return float("nan")


def reset_peak():
    """Forgets the peak so far (the cloud's generation): Linux 4.0 and later."""
    with open("/proc/self/clear_refs", "w") as clear:
        clear.write("5")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--points", type=int, default=5000000)
    args = parser.parse_args()

    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkPolyData
    from narrowvolume import vtkNarrowVolumeReconstruction

    xyz = clouds.load(dict(source="trefoil:%d" % args.points))
    points = vtkPoints()
    points.SetData(numpy_to_vtk(np.ascontiguousarray(xyz), deep=1))
    del xyz
    cloud = vtkPolyData()
    cloud.SetPoints(points)
    reset_peak()
    before = resident_mb()
    f = vtkNarrowVolumeReconstruction()
    f.GlobalWarningDisplayOff()  # the random cloud's gap warning
    f.SetInputData(cloud)
    f.SetMaximumDimension(120)
    f.SetOutputVolume(False)
    start = time.perf_counter()
    f.UpdateInformation()
    information = time.perf_counter() - start
    after_information = resident_mb()
    f.Update()
    after_run = resident_mb()
    print("| points | held after the information pass (MB) | held after Update() (MB) | surface (MB) | "
          "peak above the cloud (MB) | information pass (s) |")
    print("|---|---|---|---|---|---|")
    print("| %d | %.0f | %.0f | %.0f | %.0f | %.2f |" % (
        args.points, after_information - before, after_run - before, f.GetOutput(1).GetActualMemorySize() / 1024.0,
        peak_mb() - before, information))
    return 0


if __name__ == "__main__":
    sys.exit(main())
