# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Generates Data/trefoil.vtp, the project's own demo point cloud.

Points scattered at random (fixed seed) over a tube of radius 0.25 around a
trefoil knot: a closed surface with a handle-rich shape and uneven density,
like a scan. Run with pvpython (or any Python with VTK and numpy):

    pvpython Data/make_demo_cloud.py Data/trefoil.vtp
"""
import sys

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter


def trefoil_tube(n, tube_radius=0.25, seed=7):
    rng = np.random.default_rng(seed)
    t = rng.uniform(0.0, 2.0 * np.pi, n)
    s = rng.uniform(0.0, 2.0 * np.pi, n)
    # The knot's centre line and its derivative.
    c = np.c_[np.sin(t) + 2 * np.sin(2 * t), np.cos(t) - 2 * np.cos(2 * t), -np.sin(3 * t)] / 3.0
    dc = np.c_[np.cos(t) + 4 * np.cos(2 * t), -np.sin(t) + 4 * np.sin(2 * t), -3 * np.cos(3 * t)] / 3.0
    tangent = dc / np.linalg.norm(dc, axis=1)[:, None]
    # A frame around the tangent.
    helper = np.where(np.abs(tangent[:, 2:3]) < 0.9, [[0.0, 0.0, 1.0]], [[1.0, 0.0, 0.0]])
    normal = np.cross(tangent, helper)
    normal /= np.linalg.norm(normal, axis=1)[:, None]
    binormal = np.cross(tangent, normal)
    ring = np.cos(s)[:, None] * normal + np.sin(s)[:, None] * binormal
    return c + tube_radius * ring


def main(path):
    xyz = trefoil_tube(30000).astype(np.float32)
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
