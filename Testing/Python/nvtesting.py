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

    def finish(self):
        print("%s: %s (%d failed checks)" % (self.name, "FAILED" if self.failures else "passed", self.failures))
        sys.exit(1 if self.failures else 0)
