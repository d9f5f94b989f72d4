# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""VTK's filters on the Volume output (port 0) in a plain VTK pipeline in
Python (the narrowvolume package), the input a reader's output port and only
the offset set. The information pass declares the grid the run produces;
vtkFlyingEdges3D, vtkImageShiftScale, vtkImageGaussianSmooth and
vtkImageReslice connected to port 0 give exactly what the same filters give
on a copy of the volume (SetInputData), and what phi implies.

    pvpython -m pytest test_pipeline_vtk.py [--trefoil CLOUD]
"""
import types

import numpy as np
import pytest
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import VTK_FLOAT
from vtkmodules.vtkCommonDataModel import vtkDataObject, vtkDataSetAttributes, vtkImageData
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as sddp
from vtkmodules.vtkFiltersCore import vtkFlyingEdges3D
from vtkmodules.vtkImagingCore import vtkImageReslice, vtkImageShiftScale
from vtkmodules.vtkImagingGeneral import vtkImageGaussianSmooth
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

from narrowvolume import vtkNarrowVolumeReconstruction
import nvtesting


@pytest.fixture(scope="module")
def p(trefoil):
    """The reader and the filter (only the offset set) after the information
    pass: the reader runs (the grid follows its points), the filter does not.
    What the pass declared, and whether the filter had run, as found then."""
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(trefoil)
    f = vtkNarrowVolumeReconstruction()
    f.SetInputConnection(reader.GetOutputPort())
    f.SetOffsetDistance(0.09)
    f.UpdateInformation()
    info = f.GetOutputInformation(0)
    whole = tuple(info.Get(sddp.WHOLE_EXTENT())) if info.Has(sddp.WHOLE_EXTENT()) else None
    origin = tuple(info.Get(vtkDataObject.ORIGIN())) if info.Has(vtkDataObject.ORIGIN()) else None
    spacing = tuple(info.Get(vtkDataObject.SPACING())) if info.Has(vtkDataObject.SPACING()) else None
    scalars = vtkDataObject.GetActiveFieldInformation(info, vtkDataObject.FIELD_ASSOCIATION_POINTS,
                                                       vtkDataSetAttributes.SCALARS)
    print("information pass: whole extent %s, origin %s, spacing %s" % (whole, origin, spacing))
    return types.SimpleNamespace(
        reader=reader, f=f, whole=whole, origin=origin, spacing=spacing,
        float_scalars=scalars is not None and scalars.Get(vtkDataObject.FIELD_ARRAY_TYPE()) == VTK_FLOAT and
        scalars.Get(vtkDataObject.FIELD_NUMBER_OF_COMPONENTS()) == 1,
        ran=(f.GetNumberOfGridNodes(), f.GetOutput(0).GetNumberOfPoints()))


def test_information_pass(p):
    assert p.whole is not None and p.whole[::2] == (0, 0, 0) and min(p.whole[1::2]) > 10, "a non-empty whole extent"
    assert p.origin is not None and p.spacing is not None and min(p.spacing) > 0, "origin and spacing"
    assert p.float_scalars, "float scalars"
    assert p.ran == (0, 0), "the filter has not run yet"


def connected(p, algorithm, configure=None):
    """algorithm on port 0, and the same algorithm on a copy of the volume:
    both outputs, updated."""
    outputs = []
    for source in ("port", "copy"):
        a = algorithm()
        if source == "port":
            a.SetInputConnection(p.f.GetOutputPort(0))
        else:
            copy = vtkImageData()
            copy.DeepCopy(p.f.GetOutput(0))
            a.SetInputData(copy)
        if configure:
            configure(a)
        a.Update()
        outputs.append(a.GetOutput())
    return outputs


def scalars_of(data):
    array = data.GetPointData().GetScalars()
    return vtk_to_numpy(array).astype(float) if array is not None else np.zeros(0)


@pytest.fixture(scope="module")
def flying_edges(p):
    """vtkFlyingEdges3D at phi = 0 on port 0 (which runs the filter) and on a copy."""
    return connected(p, vtkFlyingEdges3D, lambda a: a.SetValue(0, 0.0))


def test_the_run_has_the_declared_grid(p, flying_edges):
    volume = p.f.GetOutput(0)
    print("the run: extent %s, origin %s, spacing %s" % (volume.GetExtent(), volume.GetOrigin(), volume.GetSpacing()))
    assert tuple(volume.GetExtent()) == p.whole, "the run's extent is the declared whole extent"
    assert tuple(volume.GetOrigin()) == p.origin and tuple(volume.GetSpacing()) == p.spacing, \
        "the run's origin and spacing are the declared ones"
    assert volume.GetPointData().GetScalars() is not None and \
        volume.GetPointData().GetScalars().GetName() == "phi" and \
        volume.GetPointData().GetScalars().GetDataType() == VTK_FLOAT, "phi is the float scalars"


def test_flying_edges(p, flying_edges):
    """vtkFlyingEdges3D at phi = 0 drives the run: the filter's own surface is
    the same zero level (contoured from the distance phi implies), so the same
    cut edges and triangle count exactly, each vertex moved along its edge by
    at most 0.022 h (issue 13)."""
    iso, iso_copy = flying_edges
    surface = p.f.GetOutput(1)
    shift = nvtesting.cut_edge_shift(surface, iso, p.origin, p.spacing[0])
    print("vtkFlyingEdges3D: %d triangles, %d points; port 1: %d triangles, %d points; vertices moved by %.3g h at "
          "most" % (iso.GetNumberOfPolys(), iso.GetNumberOfPoints(), surface.GetNumberOfPolys(),
                    surface.GetNumberOfPoints(), shift))
    assert iso.GetNumberOfPolys() == surface.GetNumberOfPolys() > 1000, "flying edges: the surface's triangles"
    assert 0 <= shift < 0.025, "flying edges: the surface's points on the same cut edges"
    assert iso.GetNumberOfPolys() == iso_copy.GetNumberOfPolys() and \
        np.array_equal(nvtesting.points_of(iso), nvtesting.points_of(iso_copy)), "flying edges: as on a copy"


@pytest.fixture(scope="module")
def phi(p, flying_edges):
    """phi after the run, as floats."""
    return scalars_of(p.f.GetOutput(0))


def test_shift_scale(p, phi):
    """vtkImageShiftScale: (phi + 1) / 2."""
    shifted, shifted_copy = connected(p, vtkImageShiftScale, lambda a: (a.SetShift(1.0), a.SetScale(0.5)))
    values = scalars_of(shifted)
    worst = float(np.max(np.abs(values - 0.5 * (phi + 1.0)))) if len(values) == len(phi) else -1.0
    print("vtkImageShiftScale: range [%.4f, %.4f], max |value - (phi + 1) / 2| = %.2g" % (
        values.min(), values.max(), worst))
    assert tuple(shifted.GetExtent()) == p.whole and 0 <= worst < 1e-6, "shift-scale: (phi + 1) / 2 on the grid"
    assert 0.0 <= values.min() <= 0.01 and 0.99 <= values.max() <= 1.0, "shift-scale: [-1, 1] mapped to [0, 1]"
    assert np.array_equal(values, scalars_of(shifted_copy)), "shift-scale: as on a copy"


def test_gaussian_smooth(p, phi):
    """vtkImageGaussianSmooth: the same grid, averages of phi."""
    smooth, smooth_copy = connected(p, vtkImageGaussianSmooth, lambda a: a.SetStandardDeviations(2.0, 2.0, 2.0))
    values = scalars_of(smooth)
    print("vtkImageGaussianSmooth: dimensions %s, range [%.4f, %.4f]" % (smooth.GetDimensions(), values.min(),
                                                                         values.max()))
    assert tuple(smooth.GetExtent()) == p.whole and len(values) == len(phi), "gaussian: the same grid"
    assert phi.min() - 1e-6 <= values.min() and values.max() <= phi.max() + 1e-6 and values.min() < 0 < values.max(), \
        "gaussian: within phi's range, within [-1, 1]"
    assert np.array_equal(values, scalars_of(smooth_copy)), "gaussian: as on a copy"


def test_reslice_with_its_defaults(p, phi):
    """vtkImageReslice with its defaults: the grid from the input's information, values phi."""
    same, same_copy = connected(p, vtkImageReslice)
    values = scalars_of(same)
    print("vtkImageReslice, defaults: extent %s, origin %s, max |value - phi| = %.2g" % (
        same.GetExtent(), same.GetOrigin(), float(np.max(np.abs(values - phi))) if len(values) == len(phi) else -1))
    assert tuple(same.GetExtent()) == p.whole and tuple(same.GetOrigin()) == p.origin and \
        tuple(same.GetSpacing()) == p.spacing, "reslice: the volume's grid"
    assert np.array_equal(values, phi), "reslice: the volume's values"
    assert np.array_equal(values, scalars_of(same_copy)), "reslice: as on a copy"


def test_reslice_onto_every_other_node(p, phi):
    """vtkImageReslice onto every other node, linear: phi there."""
    nx, ny, nz = p.f.GetOutput(0).GetDimensions()
    h = p.spacing[0]
    half = ((nx - 1) // 2, (ny - 1) // 2, (nz - 1) // 2)

    def every_other_node(a):
        a.SetInterpolationModeToLinear()
        a.SetOutputOrigin(p.origin)
        a.SetOutputSpacing(2 * h, 2 * h, 2 * h)
        a.SetOutputExtent(0, half[0], 0, half[1], 0, half[2])

    coarse, coarse_copy = connected(p, vtkImageReslice, every_other_node)
    values = scalars_of(coarse)
    expected = phi.reshape(nz, ny, nx)[::2, ::2, ::2][:half[2] + 1, :half[1] + 1, :half[0] + 1].ravel()
    worst = float(np.max(np.abs(values - expected))) if len(values) == len(expected) else -1.0
    print("vtkImageReslice, every other node: dimensions %s, origin %s, spacing %s, max |value - phi| = %.2g" % (
        coarse.GetDimensions(), coarse.GetOrigin(), coarse.GetSpacing(), worst))
    assert tuple(coarse.GetDimensions()) == tuple(n + 1 for n in half) and \
        np.allclose(coarse.GetOrigin(), p.origin, rtol=0, atol=1e-12) and \
        abs(coarse.GetSpacing()[0] - 2 * h) < 1e-12, "reslice: the requested grid"
    assert 0 <= worst < 1e-5, "reslice: phi at every other node"
    assert np.array_equal(values, scalars_of(coarse_copy)), "reslice: as on a copy"
