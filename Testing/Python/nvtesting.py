"""Helpers shared by the Python tests: point clouds and surface checks."""
import math
import sys

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkFiltersCore import vtkFeatureEdges, vtkPolyDataConnectivityFilter


def sphere_points(n, radius=0.5, center=(0.0, 0.0, 0.0)):
    """n points spread evenly on a sphere (Fibonacci lattice), as an (n, 3) array."""
    i = np.arange(n) + 0.5
    polar = np.arccos(1.0 - 2.0 * i / n)
    azimuth = math.pi * (1.0 + 5.0 ** 0.5) * i
    unit = np.c_[np.cos(azimuth) * np.sin(polar), np.sin(azimuth) * np.sin(polar), np.cos(polar)]
    return unit * radius + np.asarray(center)


def cloud(xyz):
    """A vtkPolyData holding only points."""
    points = vtkPoints()
    points.SetData(numpy_to_vtk(np.ascontiguousarray(xyz, dtype=float), deep=1))
    data = vtkPolyData()
    data.SetPoints(points)
    return data


def boundary_edges(surface):
    edges = vtkFeatureEdges()
    edges.SetInputData(surface)
    edges.BoundaryEdgesOn()
    edges.NonManifoldEdgesOn()
    edges.FeatureEdgesOff()
    edges.ManifoldEdgesOff()
    edges.Update()
    return edges.GetOutput().GetNumberOfCells()


def regions(surface):
    connectivity = vtkPolyDataConnectivityFilter()
    connectivity.SetInputData(surface)
    connectivity.SetExtractionModeToAllRegions()
    connectivity.Update()
    return connectivity.GetNumberOfExtractedRegions()


def points_of(dataset):
    return vtk_to_numpy(dataset.GetPoints().GetData())


class Checker:
    """Counts failed checks and prints each one; exit code via finish()."""

    def __init__(self, name):
        self.name = name
        self.failures = 0

    def check(self, condition, message):
        if not condition:
            self.failures += 1
            print("FAILED:", message)
        return condition

    def finish(self):
        print("%s: %s (%d failed checks)" % (self.name, "FAILED" if self.failures else "passed", self.failures))
        sys.exit(1 if self.failures else 0)


def face_normal_roughness(surface):
    """Mean angle (degrees) between the normals of triangles that share an
    edge: 0 for a plane, small for a smooth surface, larger for a wrinkled one."""
    from vtkmodules.vtkFiltersCore import vtkTriangleFilter

    triangles = vtkTriangleFilter()
    triangles.SetInputData(surface)
    triangles.Update()
    mesh = triangles.GetOutput()
    x = points_of(mesh)
    cells = vtk_to_numpy(mesh.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    n = np.cross(x[cells[:, 1]] - x[cells[:, 0]], x[cells[:, 2]] - x[cells[:, 0]])
    length = np.linalg.norm(n, axis=1)
    # Slivers of zero area (flying edges makes a few where phi = 0 at a node) have no normal.
    cells, n = cells[length > 0], n[length > 0] / length[length > 0][:, None]
    # Each edge, as a sorted vertex pair, with the triangle it belongs to.
    edges = np.vstack([cells[:, [0, 1]], cells[:, [1, 2]], cells[:, [2, 0]]])
    edges.sort(axis=1)
    owner = np.tile(np.arange(len(cells)), 3)
    order = np.lexsort((edges[:, 1], edges[:, 0]))
    edges, owner = edges[order], owner[order]
    same = np.all(edges[1:] == edges[:-1], axis=1)
    a, b = owner[:-1][same], owner[1:][same]
    cosine = np.clip((n[a] * n[b]).sum(axis=1), -1.0, 1.0)
    return float(np.degrees(np.arccos(cosine)).mean())


def euler_characteristic(surface):
    """V - E + F of a triangle mesh: 2 per closed sphere-like sheet, 2 less for
    every tunnel (a hole through the shell's wall, or a handle)."""
    cells = vtk_to_numpy(surface.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    edges = np.vstack([cells[:, [0, 1]], cells[:, [1, 2]], cells[:, [2, 0]]])
    edges.sort(axis=1)
    unique_edges = np.unique(edges, axis=0)
    used = np.unique(cells)
    return int(len(used) - len(unique_edges) + len(cells))
