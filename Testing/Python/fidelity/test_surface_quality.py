# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The surface of port 1 as a user gets it (issue 13):

- smooth where the shape is: on a densely sampled sphere (radius 0.5, points
  h / 4 apart, h = 0.01, l = 0.1) the normals are within 1 degree of the
  exact ones on average (2.4 degrees, at most 5, when contoured from phi's
  saturated profile), and within 3 at most;
- printable: closed, manifold, consistently wound, and without zero-area
  triangles, with the points in double precision or rounded to float (as an
  STL file holds them), on that sphere and on every scan of
  ../shared/data/scans at 300 cells (before, 2 to 26 zero-area triangles on
  six of the seven). The scans are skipped, with a message, without the folder.

    pvpython -m pytest -s test_surface_quality.py [--scans-dir SCANS_DIR]
"""
import numpy as np
import pytest
from vtkmodules.util.numpy_support import vtk_to_numpy

from narrowvolume import vtkNarrowVolumeReconstruction
import nvclouds
import nvshapes
import nvtesting

pytestmark = pytest.mark.fidelity
SCANS = ("bunny", "armadillo", "dragon", "teacup", "teapot", "bunny_rangescan_bun000", "demosthenes")


def shell(xyz, h, offset):
    f = vtkNarrowVolumeReconstruction()
    f.SetInputData(nvclouds.cloud(xyz))
    f.SetSampleSpacing(h)
    f.SetOffsetDistance(offset)
    f.SetOutputVolume(False)
    f.Update()
    return f.GetOutput(1)


def zero_area(points, cells):
    x = points[cells]
    return int((np.linalg.norm(np.cross(x[:, 1] - x[:, 0], x[:, 2] - x[:, 0]), axis=1) == 0).sum())


def check_printable(surface, label):
    points = nvtesting.points_of(surface).astype(float)
    cells = vtk_to_numpy(surface.GetPolys().GetConnectivityArray()).reshape(-1, 3).astype(np.int64)
    # Each directed edge once and its reverse once: every edge in exactly two
    # triangles (closed, manifold), which run along it in opposite directions
    # (wound alike).
    a = np.concatenate([cells[:, 0], cells[:, 1], cells[:, 2]])
    b = np.concatenate([cells[:, 1], cells[:, 2], cells[:, 0]])
    n = np.int64(len(points))
    directed, reverse = np.sort(a * n + b), np.sort(b * n + a)
    repeated = int((directed[1:] == directed[:-1]).sum())
    unpaired = int((directed != reverse).sum())
    degenerate = zero_area(points, cells)
    degenerate_float = zero_area(points.astype(np.float32).astype(float), cells)
    print("%s: %d triangles; directed edges repeated %d, without their reverse %d; zero-area triangles %d "
          "(float: %d)" % (label, len(cells), repeated, unpaired, degenerate, degenerate_float))
    assert len(cells) > 1000, "%s: a surface" % label
    assert repeated == 0 and unpaired == 0, "%s: closed, manifold and wound alike" % label
    assert degenerate == 0 and degenerate_float == 0, "%s: no zero-area triangle" % label


@pytest.fixture(scope="module")
def sphere():
    """The densely sampled sphere's shell (h = 0.01, points h / 4 apart, l = 0.1)."""
    return shell(nvclouds.shape_points("sphere", 0.01 / 4), 0.01, 0.1)


def test_sphere_normals(sphere):
    """The sphere: normals against the exact ones, out of the shell (away from
    the centre on the outer sheet, towards it on the inner one)."""
    x = nvtesting.points_of(sphere).astype(float) - nvshapes.CENTER
    normals = vtk_to_numpy(sphere.GetPointData().GetNormals()).astype(float)
    r = np.linalg.norm(x, axis=1)
    exact = np.where((r > 0.5)[:, None], 1.0, -1.0) * x / r[:, None]
    cosine = (exact * normals).sum(axis=1) / np.linalg.norm(normals, axis=1)
    angle = np.degrees(np.arccos(np.clip(cosine, -1.0, 1.0)))
    print("sphere, h = %g, points h/4 apart: normals %.3f degrees from the exact ones on average, %.3f at most"
          % (0.01, angle.mean(), angle.max()))
    assert angle.mean() < 1.0, "sphere: mean normal error %.3f degrees, not below 1" % angle.mean()
    assert angle.max() < 3.0, "sphere: largest normal error %.3f degrees, not below 3" % angle.max()


def test_sphere_printable(sphere):
    check_printable(sphere, "sphere")


@pytest.mark.parametrize("name", SCANS)
def test_scan_printable(scan_points, name):
    xyz = scan_points(name)
    spacing = float((xyz.max(axis=0) - xyz.min(axis=0)).max()) / 300
    check_printable(shell(xyz, spacing, 4 * spacing), "%s, 300 cells" % name)
