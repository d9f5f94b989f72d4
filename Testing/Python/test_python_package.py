# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The filter through the Python package narrowvolume, in a plain VTK pipeline."""
import time

import numpy as np
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.util.vtkConstants import VTK_STRING

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

# One sheet at a time: the outer sheet is the dilation, the inner the erosion;
# choosing sheets changes the surface only, never phi.
for sheets, radius in ((1, R + L), (2, R - L)):
    chosen = run(Sheets=sheets)
    one = chosen.GetOutput(1)
    r = np.linalg.norm(nvtesting.points_of(one) - center, axis=1)
    t.check(nvtesting.regions(one) == 1 and nvtesting.boundary_edges(one) == 0, "Sheets=%d: one closed sheet" % sheets)
    t.check(abs(r.mean() - radius) < 0.5 * H, "Sheets=%d: at radius %g (%g)" % (sheets, radius, r.mean()))
    kept = vtk_to_numpy(chosen.GetOutput(0).GetPointData().GetArray("phi"))
    t.check(np.array_equal(kept, phi), "Sheets=%d: phi is the same as with both sheets (%d nodes differ)"
            % (sheets, int(np.count_nonzero(kept != phi))))

# An open surface (a cap of the sphere, as a one-sided scan) has no inner
# sheet: the warning says the input's surface is open, not that the offset is small.
cap = nvtesting.cloud(nvtesting.sphere_points(5000, R, center)[nvtesting.sphere_points(5000)[:, 2] > 0.2])
warnings = []


@calldata_type(VTK_STRING)
def on_warning(caller, event, message):
    warnings.append(message)


o = vtkNarrowVolumeReconstruction()
o.SetInputData(cap)
o.SetOffsetDistance(L)
o.SetSampleSpacing(H)
o.SetSheets(2)
o.AddObserver("WarningEvent", on_warning)
o.Update()
text = " ".join(warnings)
print("open cap, Sheets=Inner: %d triangles; warning: %s" % (o.GetOutput(1).GetNumberOfCells(), text.strip()[-200:]))
t.check(o.GetOutput(1).GetNumberOfCells() == 0, "open cap: no inner sheet")
t.check("open" in text and "did not survive" not in text, "open cap: the warning says the surface is open")

# Progress: many events, never going back, ending at 1; and an abort asked
# for at 20 % ends the run soon after (the output stage polls it too).
seen = []
times = []


def progress_run(abort_at=None):
    p = vtkNarrowVolumeReconstruction()
    p.SetInputData(data)
    p.SetOffsetDistance(L)
    p.SetSampleSpacing(H / 4)
    events = []

    def on_progress(caller, event):
        events.append((caller.GetProgress(), time.perf_counter()))
        if abort_at is not None and caller.GetProgress() >= abort_at and not caller.GetAbortExecute():
            caller.SetAbortExecute(1)
            events.append(("abort", time.perf_counter()))
    p.AddObserver("ProgressEvent", on_progress)
    start = time.perf_counter()
    p.Update()
    return p, events, start, time.perf_counter()


full, seen, start, end = progress_run()
values = [v for v, _ in seen]
whole = end - start
print("progress: %d events over %.2f s: %s" % (len(values), whole, " ".join("%.2f" % v for v in values)))
t.check(len(values) >= 20 and values[-1] == 1.0, "at least 20 progress events, the last 1 (%d)" % len(values))
t.check(all(b >= a for a, b in zip(values, values[1:])), "progress never goes back")
# At 20 % (the set-up) and at 70 % (the output stage).
for at in (0.2, 0.7):
    aborted, seen, start, end = progress_run(abort_at=at)
    asked = [moment for v, moment in seen if v == "abort"]
    if t.check(len(asked) == 1, "the abort at %g was asked for" % at):
        after = end - asked[0]
        print("abort at %.0f %%: the run ended %.3f s after the request (%.0f %% of a full run's %.2f s)"
              % (100 * at, after, 100 * after / whole, whole))
        t.check(after <= 0.3 * whole, "an abort at %g ends the run within 0.3 of its full time" % at)
        t.check(aborted.GetOutput(1).GetNumberOfPoints() == 0 and aborted.GetOutput(0).GetNumberOfPoints() == 0,
                "an aborted run leaves empty outputs")
t.finish()
