# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Measures of a surface (the filter's shell, or any vtkPolyData of
triangles): open edges, enclosed volume, pieces, the Euler characteristic,
the roughness of its normals, its vertices against a reference's cut edges.
Shared by the tests (Testing/Python, through nvtesting), the benchmarks and
the doc pictures; needs VTK's filters (the clouds of nvclouds.py need only
numpy until they are read or made into VTK data)."""
import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkFiltersCore import (vtkCleanPolyData, vtkFeatureEdges, vtkMassProperties,
                                      vtkPolyDataConnectivityFilter)


def boundary_edges(surface):
    edges = vtkFeatureEdges()
    edges.SetInputData(surface)
    edges.BoundaryEdgesOn()
    edges.NonManifoldEdgesOn()
    edges.FeatureEdgesOff()
    edges.ManifoldEdgesOff()
    edges.Update()
    return edges.GetOutput().GetNumberOfCells()


def boundary_of(surface):
    """The surface's boundary edges (those of one triangle), as lines."""
    edges = vtkFeatureEdges()
    edges.SetInputData(surface)
    edges.BoundaryEdgesOn()
    edges.NonManifoldEdgesOff()
    edges.FeatureEdgesOff()
    edges.ManifoldEdgesOff()
    edges.Update()
    return edges.GetOutput()


def volume_of(surface):
    """The signed volume a closed surface encloses (divergence theorem; normals point out of the shell)."""
    if surface.GetNumberOfPolys() == 0:
        return 0.0
    xyz = vtk_to_numpy(surface.GetPoints().GetData()).astype(float)
    triangles = vtk_to_numpy(surface.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    a, b, c = xyz[triangles[:, 0]], xyz[triangles[:, 1]], xyz[triangles[:, 2]]
    return float(np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6.0)


def regions_of(surface):
    """The surface's connected pieces: (each point's piece, the points, the
    triangles as rows of point indices), by vtkPolyDataConnectivityFilter."""
    connectivity = vtkPolyDataConnectivityFilter()
    connectivity.SetInputData(surface)
    connectivity.SetExtractionModeToAllRegions()
    connectivity.ColorRegionsOn()
    connectivity.Update()
    pieces = connectivity.GetOutput()
    region = vtk_to_numpy(pieces.GetPointData().GetArray("RegionId"))
    xyz = vtk_to_numpy(pieces.GetPoints().GetData()).astype(float)
    triangles = vtk_to_numpy(pieces.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    return region, xyz, triangles


def sheet_volumes(surface):
    """(the volume the outer sheets enclose, the volume of the cavities the
    inner sheets enclose) of a shell's both sheets, from one surface: each
    connected piece's signed volume, an outer sheet's positive, an inner
    sheet's negative (it faces its cavity). The same as the volumes of the
    runs with Sheets 1 and 2, to the rounding of the sums."""
    if surface.GetNumberOfPolys() == 0:
        return 0.0, 0.0
    region, xyz, triangles = regions_of(surface)
    a, b, c = xyz[triangles[:, 0]], xyz[triangles[:, 1]], xyz[triangles[:, 2]]
    volumes = np.bincount(region[triangles[:, 0]], weights=np.einsum("ij,ij->i", a, np.cross(b, c)) / 6.0)
    return float(volumes[volumes > 0].sum()), float(-volumes[volumes < 0].sum())


def merged_surface(surface):
    """Merges the coincident points of surface pieces (exactly); returns
    (triangles, open edges, area)."""
    clean = vtkCleanPolyData()
    clean.SetInputData(surface)
    clean.SetTolerance(0.0)
    clean.Update()
    mass = vtkMassProperties()
    mass.SetInputData(clean.GetOutput())
    mass.Update()
    return clean.GetOutput().GetNumberOfPolys(), boundary_edges(clean.GetOutput()), mass.GetSurfaceArea()


def regions(surface):
    connectivity = vtkPolyDataConnectivityFilter()
    connectivity.SetInputData(surface)
    connectivity.SetExtractionModeToAllRegions()
    connectivity.Update()
    return connectivity.GetNumberOfExtractedRegions()


def points_of(dataset):
    return vtk_to_numpy(dataset.GetPoints().GetData())


def _vertices_by_edge(surface, origin, h):
    """{(i, j, k, axis) of the grid edge: fraction of h along it} for the
    surface's vertices, and the number within 1e-4 h of a node (which cannot
    tell their edge)."""
    u = (points_of(surface).astype(float) - np.asarray(origin)) / h
    off = np.abs(u - np.round(u))
    axis = off.argmax(axis=1)
    at_node = off.max(axis=1) <= 1e-4
    rows = np.arange(len(u))[~at_node]
    edges = {}
    for r in rows:
        a = axis[r]
        key = tuple(int(np.floor(u[r, b])) if b == a else int(round(u[r, b])) for b in range(3)) + (int(a),)
        edges[key] = u[r, a] - np.floor(u[r, a])
    return edges, int(at_node.sum())


def cut_edge_shift(surface, reference, origin, h, margin=1e-3):
    """Whether the surface's vertices lie on the reference's cut edges of the
    grid, one each; then the largest move along an edge (in h) from the
    reference's vertex, itself first moved `margin` h off the nodes (the
    filter keeps its vertices that far from them). -1 if the edges differ."""
    ours, ours_at_nodes = _vertices_by_edge(surface, origin, h)
    theirs, theirs_at_nodes = _vertices_by_edge(reference, origin, h)
    shift, unmatched = 0.0, 0
    for key, t in ours.items():
        if key in theirs:
            shift = max(shift, abs(t - min(1.0 - margin, max(margin, theirs[key]))))
        elif abs(t - margin) < 1e-6 or abs(t - 1.0 + margin) < 1e-6:
            unmatched += 1  # the reference's vertex sits on the node
        else:
            return -1.0
    same = ours_at_nodes == 0 and unmatched == theirs_at_nodes and len(ours) - unmatched == len(theirs)
    return shift if same else -1.0


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
