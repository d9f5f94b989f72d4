# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The benchmarks' clouds and grids, shared by the benchmarks and by the
child processes of table2.py and mpi_scaling.py (which put this folder on
their PYTHONPATH).

The clouds themselves are those of Data/ (nvclouds.py: the synthetic
shapes of nvshapes.py, Data/'s demo cloud, the scans of ../shared/data/scans
by name), which the tests and the doc pictures use too: this module is the
benchmarks' one way to them. It puts Data/ on sys.path and gives nvclouds
and nvshapes, and nvmeasures (the surface measures) when first asked for,
`from clouds import nvmeasures`: it loads VTK's filters, which the children
that measure their memory do without.
"""
import os
import sys

DATA = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Data"))
if DATA not in sys.path:
    sys.path.insert(0, DATA)

import nvclouds  # noqa: E402
import nvshapes  # noqa: E402,F401  (given to the benchmarks)

SCANS_DIR = nvclouds.SCANS_DIR


def __getattr__(name):
    if name == "nvmeasures":
        import nvmeasures
        return nvmeasures
    raise AttributeError("module %r has no attribute %r" % (__name__, name))


def load(task):
    """The points of task["source"] as an (n, 3) float array: "sphere" (the
    2,964 points of Fig. 5) or "sphere1024" (500,000) on a sphere of radius
    0.45 in the unit box, "trefoil:N" (N points scattered over the tube
    around a trefoil knot of Data/make_demo_cloud.py, the demo cloud's shape),
    or the PLY file task["path"]."""
    if task["source"].startswith("trefoil:"):
        return nvclouds.trefoil_tube(int(task["source"].split(":")[1]))
    if task["source"].startswith("sphere"):
        n = nvclouds.FIG5_POINTS if task["source"] == "sphere" else 500000
        return nvclouds.sphere_points(n, 0.45, (0.5, 0.5, 0.5))
    return nvclouds.points_of_file(task["path"])


def spacing(xyz, task):
    """h that puts task["cells"] cells along the longest side of the padded
    box: longest + 2 (l + m h + 2 h) = cells h, with l = offset_cells h and
    m = xi cells."""
    longest = float((xyz.max(axis=0) - xyz.min(axis=0)).max())
    return longest / (task["cells"] - 2 * (task["offset_cells"] + task["xi"] + 2))
