# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Generates Data/trefoil.vtp, the project's own demo point cloud.

About 30,000 points over a tube of radius 0.25 around a trefoil knot (a closed
surface with a handle-rich shape), spaced as a scanner spaces them: rings
across the tube at even steps along it, each point jittered by up to a
quarter of the spacing (fixed seed), so that neighbours are about equally far
apart everywhere and denser on the inside of the bends, where the tube's
surface is shorter. (trefoil_tube scatters points at random instead, as
the dense clouds of benchmarks/fig16.py do: uniform random points leave
gaps a few times wider than their typical spacing.) The points are stored in
random order, so that every k-th point is an even subset. Run with pvpython
(or any Python with VTK and numpy):

    pvpython Data/make_demo_cloud.py Data/trefoil.vtp
"""
import sys

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter


def knot(t):
    """The knot's centre line at parameters t and its derivative."""
    c = np.c_[np.sin(t) + 2 * np.sin(2 * t), np.cos(t) - 2 * np.cos(2 * t), -np.sin(3 * t)] / 3.0
    dc = np.c_[np.cos(t) + 4 * np.cos(2 * t), -np.sin(t) + 4 * np.sin(2 * t), -3 * np.cos(3 * t)] / 3.0
    return c, dc


def tube_points(t, s, tube_radius):
    """Points at parameter t along the knot and angle s around it."""
    c, dc = knot(t)
    tangent = dc / np.linalg.norm(dc, axis=1)[:, None]
    # A frame around the tangent.
    helper = np.where(np.abs(tangent[:, 2:3]) < 0.9, [[0.0, 0.0, 1.0]], [[1.0, 0.0, 0.0]])
    normal = np.cross(tangent, helper)
    normal /= np.linalg.norm(normal, axis=1)[:, None]
    binormal = np.cross(tangent, normal)
    ring = np.cos(s)[:, None] * normal + np.sin(s)[:, None] * binormal
    return c + tube_radius * ring


def trefoil_tube(n, tube_radius=0.25, seed=7):
    """n points scattered uniformly at random in (t, s)."""
    rng = np.random.default_rng(seed)
    t = rng.uniform(0.0, 2.0 * np.pi, n)
    s = rng.uniform(0.0, 2.0 * np.pi, n)
    return tube_points(t, s, tube_radius)


def scanned_trefoil_tube(n, tube_radius=0.25, seed=7, jitter=0.5):
    """About n points in rings across the tube, evenly spaced by arc length
    along the knot and by angle around it (alternate rings offset by half a
    step), each moved by up to jitter / 2 of a step in both directions."""
    rng = np.random.default_rng(seed)
    t_fine = np.linspace(0.0, 2.0 * np.pi, 20001)
    speed = np.linalg.norm(knot(t_fine)[1], axis=1)
    arc = np.concatenate([[0.0], np.cumsum(0.5 * (speed[1:] + speed[:-1]) * np.diff(t_fine))])
    # Rings and points a ring such that both steps are about equal.
    per_ring = int(round(np.sqrt(n * 2.0 * np.pi * tube_radius / arc[-1])))
    rings = n // per_ring
    ring, k = np.meshgrid(np.arange(rings), np.arange(per_ring), indexing="ij")
    ring, k = ring.ravel(), k.ravel()
    along = (ring + 0.5 + jitter * rng.uniform(-0.5, 0.5, ring.size)) / rings
    around = (k + 0.5 * (ring % 2) + jitter * rng.uniform(-0.5, 0.5, ring.size)) / per_ring
    xyz = tube_points(np.interp(along * arc[-1], arc, t_fine), 2.0 * np.pi * around, tube_radius)
    return xyz[rng.permutation(len(xyz))]


def main(path):
    xyz = scanned_trefoil_tube(30000).astype(np.float32)
    points = vtkPoints()
    points.SetData(numpy_to_vtk(xyz, deep=1))
    cloud = vtkPolyData()
    cloud.SetPoints(points)
    # One vertex cell per point, so that ParaView draws the cloud as it opens.
    vertices = vtkCellArray()
    vertices.SetData(numpy_to_vtk(np.arange(len(xyz) + 1, dtype=np.int64), deep=1),
                     numpy_to_vtk(np.arange(len(xyz), dtype=np.int64), deep=1))
    cloud.SetVerts(vertices)
    writer = vtkXMLPolyDataWriter()
    writer.SetFileName(path)
    writer.SetInputData(cloud)
    writer.SetDataModeToBinary()
    writer.Write()


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "trefoil.vtp")
