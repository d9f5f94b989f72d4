# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""VTK's filters on the Volume output (port 0) in a plain VTK pipeline in
Python (the narrowvolume package), the input a reader's output port and only
the offset set. The information pass declares the grid the run produces;
vtkFlyingEdges3D, vtkImageShiftScale, vtkImageGaussianSmooth and
vtkImageReslice connected to port 0 give exactly what the same filters give
on a copy of the volume (SetInputData), and what phi implies.

    pvpython test_pipeline_vtk.py CLOUD
"""
import sys
import time

import numpy as np
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

start = time.time()
t = nvtesting.Checker("test_pipeline_vtk")
reader = vtkXMLPolyDataReader()
reader.SetFileName(sys.argv[1])
f = vtkNarrowVolumeReconstruction()
f.SetInputConnection(reader.GetOutputPort())
f.SetOffsetDistance(0.09)

# --- The information pass: the reader runs (the grid follows its points),
# the filter does not.
f.UpdateInformation()
info = f.GetOutputInformation(0)
whole = tuple(info.Get(sddp.WHOLE_EXTENT())) if info.Has(sddp.WHOLE_EXTENT()) else None
origin = tuple(info.Get(vtkDataObject.ORIGIN())) if info.Has(vtkDataObject.ORIGIN()) else None
spacing = tuple(info.Get(vtkDataObject.SPACING())) if info.Has(vtkDataObject.SPACING()) else None
scalars = vtkDataObject.GetActiveFieldInformation(info, vtkDataObject.FIELD_ASSOCIATION_POINTS,
                                                   vtkDataSetAttributes.SCALARS)
print("information pass: whole extent %s, origin %s, spacing %s" % (whole, origin, spacing))
t.check(whole is not None and whole[::2] == (0, 0, 0) and min(whole[1::2]) > 10, "a non-empty whole extent")
t.check(origin is not None and spacing is not None and min(spacing) > 0, "origin and spacing")
t.check(scalars is not None and scalars.Get(vtkDataObject.FIELD_ARRAY_TYPE()) == VTK_FLOAT and
        scalars.Get(vtkDataObject.FIELD_NUMBER_OF_COMPONENTS()) == 1, "float scalars")
t.check(f.GetNumberOfGridNodes() == 0 and f.GetOutput(0).GetNumberOfPoints() == 0, "the filter has not run yet")
if whole is None or origin is None or spacing is None:
    t.finish()


def connected(algorithm, configure=None):
    """algorithm on port 0, and the same algorithm on a copy of the volume:
    both outputs, updated."""
    outputs = []
    for source in ("port", "copy"):
        a = algorithm()
        if source == "port":
            a.SetInputConnection(f.GetOutputPort(0))
        else:
            copy = vtkImageData()
            copy.DeepCopy(f.GetOutput(0))
            a.SetInputData(copy)
        if configure:
            configure(a)
        a.Update()
        outputs.append(a.GetOutput())
    return outputs


def scalars_of(data):
    array = data.GetPointData().GetScalars()
    return vtk_to_numpy(array).astype(float) if array is not None else np.zeros(0)


# --- vtkFlyingEdges3D at phi = 0 drives the run: the filter's own surface is
# the same zero level (contoured from the distance phi implies), so the same
# cut edges and triangle count exactly, each vertex moved along its edge by
# at most 0.022 h (issue 13).
(iso, iso_copy) = connected(vtkFlyingEdges3D, lambda a: a.SetValue(0, 0.0))
volume, surface = f.GetOutput(0), f.GetOutput(1)
print("the run: extent %s, origin %s, spacing %s" % (volume.GetExtent(), volume.GetOrigin(), volume.GetSpacing()))
t.check(tuple(volume.GetExtent()) == whole, "the run's extent is the declared whole extent")
t.check(tuple(volume.GetOrigin()) == origin and tuple(volume.GetSpacing()) == spacing,
        "the run's origin and spacing are the declared ones")
t.check(volume.GetPointData().GetScalars() is not None and volume.GetPointData().GetScalars().GetName() == "phi" and
        volume.GetPointData().GetScalars().GetDataType() == VTK_FLOAT, "phi is the float scalars")
phi = scalars_of(volume)
nx, ny, nz = volume.GetDimensions()
h = spacing[0]
shift = nvtesting.cut_edge_shift(surface, iso, origin, h)
print("vtkFlyingEdges3D: %d triangles, %d points; port 1: %d triangles, %d points; vertices moved by %.3g h at most"
      % (iso.GetNumberOfPolys(), iso.GetNumberOfPoints(), surface.GetNumberOfPolys(), surface.GetNumberOfPoints(),
         shift))
t.check(iso.GetNumberOfPolys() == surface.GetNumberOfPolys() > 1000, "flying edges: the surface's triangles")
t.check(0 <= shift < 0.025, "flying edges: the surface's points on the same cut edges")
t.check(iso.GetNumberOfPolys() == iso_copy.GetNumberOfPolys() and
        np.array_equal(nvtesting.points_of(iso), nvtesting.points_of(iso_copy)), "flying edges: as on a copy")

# --- vtkImageShiftScale: (phi + 1) / 2.
(shifted, shifted_copy) = connected(vtkImageShiftScale, lambda a: (a.SetShift(1.0), a.SetScale(0.5)))
values = scalars_of(shifted)
worst = float(np.max(np.abs(values - 0.5 * (phi + 1.0)))) if len(values) == len(phi) else -1.0
print("vtkImageShiftScale: range [%.4f, %.4f], max |value - (phi + 1) / 2| = %.2g" % (values.min(), values.max(), worst))
t.check(tuple(shifted.GetExtent()) == whole and 0 <= worst < 1e-6, "shift-scale: (phi + 1) / 2 on the grid")
t.check(0.0 <= values.min() <= 0.01 and 0.99 <= values.max() <= 1.0, "shift-scale: [-1, 1] mapped to [0, 1]")
t.check(np.array_equal(values, scalars_of(shifted_copy)), "shift-scale: as on a copy")

# --- vtkImageGaussianSmooth: the same grid, averages of phi.
(smooth, smooth_copy) = connected(vtkImageGaussianSmooth, lambda a: a.SetStandardDeviations(2.0, 2.0, 2.0))
values = scalars_of(smooth)
print("vtkImageGaussianSmooth: dimensions %s, range [%.4f, %.4f]" % (smooth.GetDimensions(), values.min(), values.max()))
t.check(tuple(smooth.GetExtent()) == whole and len(values) == len(phi), "gaussian: the same grid")
t.check(phi.min() - 1e-6 <= values.min() and values.max() <= phi.max() + 1e-6 and values.min() < 0 < values.max(),
        "gaussian: within phi's range, within [-1, 1]")
t.check(np.array_equal(values, scalars_of(smooth_copy)), "gaussian: as on a copy")

# --- vtkImageReslice with its defaults: the grid from the input's
# information, values phi; and onto every other node, linear.
(same, same_copy) = connected(vtkImageReslice)
values = scalars_of(same)
print("vtkImageReslice, defaults: extent %s, origin %s, max |value - phi| = %.2g" % (
    same.GetExtent(), same.GetOrigin(), float(np.max(np.abs(values - phi))) if len(values) == len(phi) else -1))
t.check(tuple(same.GetExtent()) == whole and tuple(same.GetOrigin()) == origin and
        tuple(same.GetSpacing()) == spacing, "reslice: the volume's grid")
t.check(np.array_equal(values, phi), "reslice: the volume's values")
t.check(np.array_equal(values, scalars_of(same_copy)), "reslice: as on a copy")
half = ((nx - 1) // 2, (ny - 1) // 2, (nz - 1) // 2)


def every_other_node(a):
    a.SetInterpolationModeToLinear()
    a.SetOutputOrigin(origin)
    a.SetOutputSpacing(2 * h, 2 * h, 2 * h)
    a.SetOutputExtent(0, half[0], 0, half[1], 0, half[2])


(coarse, coarse_copy) = connected(vtkImageReslice, every_other_node)
values = scalars_of(coarse)
expected = phi.reshape(nz, ny, nx)[::2, ::2, ::2][:half[2] + 1, :half[1] + 1, :half[0] + 1].ravel()
worst = float(np.max(np.abs(values - expected))) if len(values) == len(expected) else -1.0
print("vtkImageReslice, every other node: dimensions %s, origin %s, spacing %s, max |value - phi| = %.2g" % (
    coarse.GetDimensions(), coarse.GetOrigin(), coarse.GetSpacing(), worst))
t.check(tuple(coarse.GetDimensions()) == tuple(n + 1 for n in half) and
        np.allclose(coarse.GetOrigin(), origin, rtol=0, atol=1e-12) and
        abs(coarse.GetSpacing()[0] - 2 * h) < 1e-12, "reslice: the requested grid")
t.check(0 <= worst < 1e-5, "reslice: phi at every other node")
t.check(np.array_equal(values, scalars_of(coarse_copy)), "reslice: as on a copy")
print("run time %.1f s" % (time.time() - start))
t.finish()
