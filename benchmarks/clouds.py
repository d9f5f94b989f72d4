# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The benchmarks' clouds and grids, shared by the child processes of
table2.py and mpi_scaling.py (which put this folder on their PYTHONPATH)."""
import math

import numpy as np


def load(task):
    """The points of task["source"] as an (n, 3) float array: "sphere" (the
    2,964 points of Fig. 5) or "sphere1024" (500,000) on a sphere of radius
    0.45 in the unit box, "trefoil:N" (N points scattered over the tube
    around a trefoil knot of Data/make_demo_cloud.py, the demo cloud's shape),
    or the PLY file task["path"]."""
    if task["source"].startswith("trefoil:"):
        import os
        import sys
        sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Data"))
        from make_demo_cloud import trefoil_tube
        return trefoil_tube(int(task["source"].split(":")[1]))
    if task["source"].startswith("sphere"):
        n = 2964 if task["source"] == "sphere" else 500000
        i = np.arange(n) + 0.5
        polar = np.arccos(1 - 2 * i / n)
        azimuth = math.pi * (1 + 5 ** 0.5) * i
        return 0.5 + 0.45 * np.c_[np.cos(azimuth) * np.sin(polar), np.sin(azimuth) * np.sin(polar), np.cos(polar)]
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOPLY import vtkPLYReader
    reader = vtkPLYReader()
    reader.SetFileName(task["path"])
    reader.Update()
    return vtk_to_numpy(reader.GetOutput().GetPoints().GetData()).astype(float)


def spacing(xyz, task):
    """h that puts task["cells"] cells along the longest side of the padded
    box: longest + 2 (l + m h + 2 h) = cells h, with l = offset_cells h and
    m = xi cells."""
    longest = float((xyz.max(axis=0) - xyz.min(axis=0)).max())
    return longest / (task["cells"] - 2 * (task["offset_cells"] + task["xi"] + 2))
