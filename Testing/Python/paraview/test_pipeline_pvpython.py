# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""ParaView's filters on the Volume output (port 0) in pvpython.

The demo cloud goes through the filter with the panel's defaults (only Input
set; OffsetDistance from the cloud's bounds). After UpdatePipelineInformation
and before the run, port 0's pipeline information already holds the grid
(whole extent, origin, spacing, float scalars), the same as the data's after
the run. Then Slice, Clip, Threshold, Contour, ResampleToImage and
PlotOverLine on port 0 give the outputs that phi on that grid implies,
checked against the volume itself with numpy.

    pvpython -m pytest test_pipeline_pvpython.py --plugin PLUGIN [--trefoil CLOUD]
"""
import types

import numpy as np
import pytest
from paraview import servermanager
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import VTK_FLOAT
from vtkmodules.vtkCommonDataModel import vtkDataObject, vtkDataSetAttributes
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as sddp

import nvtesting

pytestmark = pytest.mark.slow


@pytest.fixture(scope="module")
def p(pvs, trefoil):
    """The demo cloud and the filter with the panel's defaults after the
    information pass; what the pass declared, and what the data held then."""
    cloud = pvs.OpenDataFile(trefoil)
    shell = pvs.NarrowVolumeReconstruction(Input=cloud)
    offset_default = shell.OffsetDistance
    # GetDataInformation describes data, so before the run it is empty, as
    # for any ParaView source; the grid is in the output's pipeline
    # information (the proxy's VTK object in this builtin session).
    shell.UpdatePipelineInformation()
    algorithm = shell.GetClientSideObject()
    info = algorithm.GetOutputInformation(0)
    whole = tuple(info.Get(sddp.WHOLE_EXTENT())) if info.Has(sddp.WHOLE_EXTENT()) else None
    origin = tuple(info.Get(vtkDataObject.ORIGIN())) if info.Has(vtkDataObject.ORIGIN()) else None
    spacing = tuple(info.Get(vtkDataObject.SPACING())) if info.Has(vtkDataObject.SPACING()) else None
    scalars = vtkDataObject.GetActiveFieldInformation(info, vtkDataObject.FIELD_ASSOCIATION_POINTS,
                                                       vtkDataSetAttributes.SCALARS)
    print("information pass: whole extent %s, origin %s, spacing %s; data information extent %s, %d points" % (
        whole, origin, spacing, shell.GetDataInformation(0).GetExtent(),
        shell.GetDataInformation(0).GetNumberOfPoints()))
    return types.SimpleNamespace(
        pvs=pvs, shell=shell, algorithm=algorithm, offset_default=offset_default, whole=whole, origin=origin,
        spacing=spacing, points_before_run=algorithm.GetOutputDataObject(0).GetNumberOfPoints(),
        float_scalars=scalars is not None and scalars.Get(vtkDataObject.FIELD_ARRAY_TYPE()) == VTK_FLOAT and
        scalars.Get(vtkDataObject.FIELD_NUMBER_OF_COMPONENTS()) == 1)


def test_offset_default(p):
    assert p.offset_default == 0.0, "offset default 0 (automatic): %g" % p.offset_default


def test_information_pass(p):
    assert p.points_before_run == 0, "the filter has not run yet"
    assert p.whole is not None and p.whole[0] == 0 and p.whole[2] == 0 and p.whole[4] == 0 and \
        min(p.whole[1], p.whole[3], p.whole[5]) > 10, "information pass: a non-empty whole extent: %s" % (p.whole,)
    assert p.origin is not None and p.spacing is not None and min(p.spacing) > 0, \
        "information pass: origin and spacing"
    assert p.float_scalars, "information pass: float scalars"


@pytest.fixture(scope="module")
def run(p):
    """The run: the volume, phi on the grid (z, y, x), the grid's sizes."""
    p.shell.UpdatePipeline()
    volume = p.algorithm.GetOutputDataObject(0)
    data_extent = p.shell.GetDataInformation(0).GetExtent()
    print("after the run: data information extent %s, volume extent %s, origin %s, spacing %s" % (
        data_extent, volume.GetExtent(), volume.GetOrigin(), volume.GetSpacing()))
    nx, ny, nz = p.whole[1] + 1, p.whole[3] + 1, p.whole[5] + 1
    phi_array = volume.GetPointData().GetScalars()
    surface_triangles = p.shell.GetDataInformation(1).GetNumberOfCells()
    print("grid %d x %d x %d, h = %.6g, offset %.6g; surface %d triangles" % (
        nx, ny, nz, p.spacing[0], p.shell.OffsetDistance, surface_triangles))
    # The grid's centre, moved a quarter cell along x so that the planes cut the
    # x edges between node layers i and i + 1 instead of lying on a layer.
    i = (nx - 1) // 2
    h = p.spacing[0]
    centre = [p.origin[0] + (i + 0.25) * h, p.origin[1] + 0.5 * (ny - 1) * h, p.origin[2] + 0.5 * (nz - 1) * h]
    return types.SimpleNamespace(
        volume=volume, data_extent=data_extent, phi_array=phi_array,
        phi=vtk_to_numpy(phi_array).astype(float).reshape(nz, ny, nx) if phi_array is not None else None,
        nx=nx, ny=ny, nz=nz, h=h, i=i, centre=centre, surface_triangles=surface_triangles,
        port0=p.pvs.OutputPort(p.shell, 0))


def test_the_run_has_the_declared_grid(p, run):
    """The run: the data has the grid the information pass declared."""
    assert tuple(run.data_extent) == p.whole and tuple(run.volume.GetExtent()) == p.whole, \
        "the run's extent is the declared whole extent"
    assert tuple(run.volume.GetOrigin()) == p.origin and tuple(run.volume.GetSpacing()) == p.spacing, \
        "the run's origin and spacing are the declared ones"
    assert run.phi_array is not None and run.phi_array.GetName() == "phi" and \
        run.phi_array.GetDataType() == VTK_FLOAT, "phi is the float scalars"


def trilinear(p, run, xyz):
    """phi interpolated trilinearly at world points (n, 3), as a probe does."""
    u = (np.asarray(xyz, dtype=float) - np.asarray(p.origin)) / run.h
    i0 = np.clip(np.floor(u).astype(int), 0, [run.nx - 2, run.ny - 2, run.nz - 2])
    w = np.clip(u - i0, 0.0, 1.0)
    value = np.zeros(len(u))
    for dx in (0, 1):
        for dy in (0, 1):
            for dz in (0, 1):
                weight = ((w[:, 0] if dx else 1 - w[:, 0]) * (w[:, 1] if dy else 1 - w[:, 1]) *
                          (w[:, 2] if dz else 1 - w[:, 2]))
                value += weight * run.phi[i0[:, 2] + dz, i0[:, 1] + dy, i0[:, 0] + dx]
    return value


def fetched(proxy):
    proxy.UpdatePipeline()
    return servermanager.Fetch(proxy)


def point_phi(data):
    return vtk_to_numpy(data.GetPointData().GetArray("phi")).astype(float)


def test_slice(p, run):
    """Slice (plane x = centre): one point per x edge it cuts, phi interpolated on it."""
    slice_ = p.pvs.Slice(Input=run.port0)
    slice_.SliceType = "Plane"
    slice_.SliceType.Origin = run.centre
    slice_.SliceType.Normal = [1.0, 0.0, 0.0]
    cut = fetched(slice_)
    values = point_phi(cut)
    error = float(np.max(np.abs(values - trilinear(p, run, nvtesting.points_of(cut))))) if len(values) else -1.0
    print("Slice: %d points, %d cells, phi in [%.4f, %.4f], max |phi - interpolated phi| = %.2g" % (
        cut.GetNumberOfPoints(), cut.GetNumberOfCells(), values.min(), values.max(), error))
    assert cut.GetNumberOfPoints() == run.ny * run.nz, "Slice: one point per cut x edge (%d)" % (run.ny * run.nz)
    assert cut.GetNumberOfCells() > 0 and -1.0 <= values.min() < 0.0 < values.max() <= 1.0, \
        "Slice: cells, phi in [-1, 1] on both sides of 0"
    assert 0.0 <= error < 1e-5, "Slice: phi is the volume's, interpolated"


def test_clip(p, run):
    """Clip by the same plane (Invert: keep x below it): the whole cells of
    layers 0..i and the cut part of layer i."""
    clip = p.pvs.Clip(Input=run.port0)
    clip.ClipType = "Plane"
    clip.ClipType.Origin = run.centre
    clip.ClipType.Normal = [1.0, 0.0, 0.0]
    clipped = fetched(clip)
    values = point_phi(clipped)
    bounds = clipped.GetBounds()
    expected_cells = (run.i + 1) * (run.ny - 1) * (run.nz - 1)
    print("Clip: %d points, %d cells (%d expected), x in [%.6f, %.6f] (plane at %.6f), phi in [%.4f, %.4f]" % (
        clipped.GetNumberOfPoints(), clipped.GetNumberOfCells(), expected_cells, bounds[0], bounds[1],
        run.centre[0], values.min(), values.max()))
    assert clipped.GetNumberOfCells() == expected_cells, "Clip: layers 0..%d of cells" % run.i
    assert abs(bounds[0] - p.origin[0]) < 1e-6 * run.h and abs(bounds[1] - run.centre[0]) < 1e-4 * run.h, \
        "Clip: from the grid's start to the plane"
    assert -1.0 <= values.min() < 0.0 < values.max() <= 1.0, "Clip: phi in [-1, 1]"


def test_threshold(p, run):
    """Threshold 0 <= phi <= 1 (AllScalars: every point of a kept cell): the
    cells of the shell, which numpy counts from the volume."""
    threshold = p.pvs.Threshold(Input=run.port0)
    threshold.Scalars = ["POINTS", "phi"]
    threshold.LowerThreshold = 0.0
    threshold.UpperThreshold = 1.0
    kept = fetched(threshold)
    values = point_phi(kept)
    nx, ny, nz = run.nx, run.ny, run.nz
    inside = (run.phi >= 0.0) & (run.phi <= 1.0)
    corners = np.ones((nz - 1, ny - 1, nx - 1), dtype=bool)
    for dz in (0, 1):
        for dy in (0, 1):
            for dx in (0, 1):
                corners &= inside[dz:nz - 1 + dz, dy:ny - 1 + dy, dx:nx - 1 + dx]
    print("Threshold: %d cells (numpy: %d), phi in [%.3g, %.4f]" % (kept.GetNumberOfCells(), int(corners.sum()),
                                                                    values.min(), values.max()))
    assert kept.GetNumberOfCells() == int(corners.sum()) > 0, "Threshold: the cells with phi in [0, 1] at every node"
    assert values.min() >= 0.0 and values.max() <= 1.0, "Threshold: all phi >= 0 (exact comparisons, no tolerance)"


def test_contour(p, run):
    """Contour phi = 0. ParaView's Contour takes vtkSynchronizedTemplates3D
    for image data, the filter's surface vtkFlyingEdges3D: both classify a
    node by phi >= 0 and take the marching-cubes case table, so they make the
    same triangles, one per case entry, slivers included. They differ only
    where phi is exactly 0 at a node: there synchronized templates merges the
    points of the edges that meet at the node and drops the triangles that
    collapse, which flying edges keeps (at most 8 cells x 5 triangles a node)."""
    contour = p.pvs.Contour(Input=run.port0)
    contour.ContourBy = ["POINTS", "phi"]
    contour.Isosurfaces = [0.0]
    iso = fetched(contour)
    zero_nodes = int(np.count_nonzero(run.phi == 0.0))
    difference = run.surface_triangles - iso.GetNumberOfCells()
    print("Contour: %d triangles, %d points; the filter's surface: %d triangles, %d points; %d nodes with phi = 0" % (
        iso.GetNumberOfCells(), iso.GetNumberOfPoints(), run.surface_triangles,
        p.shell.GetDataInformation(1).GetNumberOfPoints(), zero_nodes))
    assert 0 <= difference <= 40 * zero_nodes, \
        "Contour: the surface's triangles (difference %d, %d nodes with phi = 0)" % (difference, zero_nodes)
    assert iso.GetNumberOfCells() > 1000 and nvtesting.boundary_edges(iso) == 0, "Contour: closed"


def test_resample_to_image(p, run):
    """ResampleToImage to 40 x 30 x 20 over the volume's bounds: the
    requested grid, every sample valid, phi the trilinear interpolation."""
    resample = p.pvs.ResampleToImage(Input=run.port0)
    resample.SamplingDimensions = [40, 30, 20]
    image = fetched(resample)
    values = point_phi(image)
    mask = vtk_to_numpy(image.GetPointData().GetArray("vtkValidPointMask"))
    sample_points = np.array([image.GetPoint(k) for k in range(image.GetNumberOfPoints())])
    error = float(np.max(np.abs(values - trilinear(p, run, sample_points))))
    print("ResampleToImage: dimensions %s, %d valid of %d, phi in [%.4f, %.4f], max |phi - interpolated phi| = %.2g"
          % (image.GetDimensions(), int(mask.sum()), len(mask), values.min(), values.max(), error))
    assert tuple(image.GetDimensions()) == (40, 30, 20), "ResampleToImage: the requested dimensions"
    assert int(mask.sum()) == len(mask), "ResampleToImage: every sample inside the volume"
    assert -1.0 <= values.min() < 0.0 < values.max() <= 1.0 and error < 1e-5, \
        "ResampleToImage: phi in [-1, 1], the volume's, interpolated"


def test_plot_over_line(p, run):
    """PlotOverLine along y through the centre: phi along the line, and
    where it changes sign. The knot's centre line passes through (0, -1, 0)
    and (0, -1/3, 0), so the line goes through the tube twice, and through a
    tube's thick shell is 4 sign changes (outer, inner, inner, outer sheet);
    between the two tubes, and near (+-0.29, 0.17, 0) where the line passes
    the tube within the shell, the shells merge: at least 4 in all."""
    line = p.pvs.PlotOverLine(Input=run.port0)
    line.Point1 = [run.centre[0], p.origin[1], run.centre[2]]
    line.Point2 = [run.centre[0], p.origin[1] + (run.ny - 1) * run.h, run.centre[2]]
    probe = fetched(line)
    values = point_phi(probe)
    valid = vtk_to_numpy(probe.GetPointData().GetArray("vtkValidPointMask")).astype(bool)
    along = values[valid]
    crossings = int(np.count_nonzero(np.signbit(along[1:]) != np.signbit(along[:-1])))
    error = float(np.max(np.abs(along - trilinear(p, run, nvtesting.points_of(probe)[valid]))))
    print("PlotOverLine: %d points, %d valid, phi in [%.4f, %.4f], %d sign changes, max |phi - interpolated phi| = "
          "%.2g" % (probe.GetNumberOfPoints(), int(valid.sum()), along.min(), along.max(), crossings, error))
    if crossings:
        where = nvtesting.points_of(probe)[valid][1:][np.signbit(along[1:]) != np.signbit(along[:-1])][:, 1]
        print("PlotOverLine: sign changes at y = %s" % ", ".join("%.3f" % y for y in where))
    assert valid.sum() == probe.GetNumberOfPoints() > 100, "PlotOverLine: every point inside the volume"
    assert crossings >= 4 and crossings % 2 == 0, "PlotOverLine: crosses phi = 0 at least 4 times (%d)" % crossings
    assert error < 1e-5, "PlotOverLine: phi is the volume's, interpolated"
