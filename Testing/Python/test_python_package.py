# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The filter through the Python package narrowvolume, in a plain VTK pipeline."""
import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

from narrowvolume import vtkNarrowVolumeReconstruction
import nvtesting

t = nvtesting.Checker("test_python_package")
R, L, H = 0.5, 0.1, 0.025
center = np.array([1.0, 2.0, -3.0])
data = nvtesting.cloud(nvtesting.sphere_points(5000, R, center))


def run(**settings):
    f = vtkNarrowVolumeReconstruction()
    f.SetInputData(data)
    f.SetOffsetDistance(L)
    f.SetSampleSpacing(H)
    for key, value in settings.items():
        getattr(f, "Set" + key)(value)
    f.Update()
    return f


f = run()
volume, surface = f.GetOutput(0), f.GetOutput(1)
t.check(volume.IsA("vtkImageData") and surface.IsA("vtkPolyData"), "output types")
phi = vtk_to_numpy(volume.GetPointData().GetArray("phi"))
t.check(phi.dtype == np.float32, "phi is float")
t.check(phi.min() >= -1.0 and phi.max() <= 1.0, "phi in [-1, 1]: %g %g" % (phi.min(), phi.max()))
t.check(nvtesting.boundary_edges(surface) == 0, "surface closed")
t.check(nvtesting.regions(surface) == 2, "two sheets")
r = np.linalg.norm(nvtesting.points_of(surface) - center, axis=1)
inner, outer = r[r < R], r[r > R]
t.check(abs(inner.mean() - (R - L)) < 0.5 * H, "inner sheet at R - l: %g" % inner.mean())
t.check(abs(outer.mean() - (R + L)) < 0.5 * H, "outer sheet at R + l: %g" % outer.mean())

# Field data summarises the run.
fd = volume.GetFieldData()
iterations = fd.GetArray("NumberOfIterations").GetValue(0)
t.check(iterations == f.GetMaximumNumberOfIterations(), "iterations %d" % iterations)
t.check(fd.GetArray("RelativeChange").GetNumberOfTuples() == iterations, "one relative change per step")
t.check(fd.GetArray("NarrowBandNodes").GetValue(0) == f.GetNumberOfBandNodes(), "band nodes")

# Optional arrays appear only on request.
t.check(volume.GetPointData().GetArray("Distance") is None, "no Distance by default")
g = run(OutputDistance=True, OutputNarrowBand=True, OutputInitialPhi=True)
pd = g.GetOutput(0).GetPointData()
t.check(all(pd.GetArray(n) is not None for n in ("Distance", "NarrowBand", "InitialPhi")), "optional arrays")
band = vtk_to_numpy(pd.GetArray("NarrowBand"))
t.check(int(band.sum()) == g.GetNumberOfBandNodes(), "NarrowBand marks the band")

# Same phi, bit for bit, with 1 and 2 threads.
one = vtk_to_numpy(run(NumberOfThreads=1).GetOutput(0).GetPointData().GetArray("phi"))
two = vtk_to_numpy(run(NumberOfThreads=2).GetOutput(0).GetPointData().GetArray("phi"))
t.check(np.array_equal(one, two), "bit-identical phi for 1 and 2 threads")

# Whole Domain agrees with Narrow Band on the band (the paper's comparison).
w = run(Domain=1, OutputNarrowBand=True)
wphi = vtk_to_numpy(w.GetOutput(0).GetPointData().GetArray("phi"))
nb = band.astype(bool)
l2 = float(np.sqrt(np.mean((wphi[nb] - phi[nb]) ** 2)))
print("narrow band vs whole domain: l2 difference over the band %.3e" % l2)
t.check(l2 < 5e-3, "narrow band close to whole domain: %g" % l2)

# One sheet at a time: the outer sheet is the dilation, the inner the erosion.
for sheets, radius in ((1, R + L), (2, R - L)):
    one = run(Sheets=sheets).GetOutput(1)
    r = np.linalg.norm(nvtesting.points_of(one) - center, axis=1)
    t.check(nvtesting.regions(one) == 1 and nvtesting.boundary_edges(one) == 0, "Sheets=%d: one closed sheet" % sheets)
    t.check(abs(r.mean() - radius) < 0.5 * H, "Sheets=%d: at radius %g (%g)" % (sheets, radius, r.mean()))

# Progress events reach observers.
seen = []
p = vtkNarrowVolumeReconstruction()
p.SetInputData(data)
p.SetOffsetDistance(L)
p.SetSampleSpacing(H)
p.AddObserver("ProgressEvent", lambda o, e: seen.append(o.GetProgress()))
p.Update()
t.check(len(seen) >= 5 and seen[-1] == 1.0, "progress events: %s" % seen[-3:])
t.check(all(b >= a for a, b in zip(seen, seen[1:])), "progress never goes back")
t.finish()
