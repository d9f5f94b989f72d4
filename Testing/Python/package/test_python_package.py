# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The filter through the Python package narrowvolume, in a plain VTK pipeline."""
import time

import numpy as np
import pytest
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.util.vtkConstants import VTK_STRING

from narrowvolume import vtkNarrowVolumeReconstruction
import nvclouds
import nvtesting

R, L, H = 0.5, 0.1, 0.025
CENTER = np.array([1.0, 2.0, -3.0])
DATA = nvclouds.cloud(nvclouds.sphere_points(5000, R, CENTER))


def run(**settings):
    f = vtkNarrowVolumeReconstruction()
    f.SetInputData(DATA)
    f.SetOffsetDistance(L)
    f.SetSampleSpacing(H)
    for key, value in settings.items():
        getattr(f, "Set" + key)(value)
    f.Update()
    return f


def phi_of(f):
    return vtk_to_numpy(f.GetOutput(0).GetPointData().GetArray("phi"))


@pytest.fixture(scope="module")
def default():
    """A run with the offset and spacing set, nothing else."""
    return run()


@pytest.fixture(scope="module")
def optional():
    """A run with the optional arrays."""
    return run(OutputDistance=True, OutputNarrowBand=True, OutputInitialPhi=True)


def test_outputs(default):
    volume, surface = default.GetOutput(0), default.GetOutput(1)
    assert volume.IsA("vtkImageData") and surface.IsA("vtkPolyData"), "output types"
    phi = phi_of(default)
    assert phi.dtype == np.float32, "phi is float"
    assert phi.min() >= -1.0 and phi.max() <= 1.0, "phi in [-1, 1]: %g %g" % (phi.min(), phi.max())
    assert nvtesting.boundary_edges(surface) == 0, "surface closed"
    assert nvtesting.regions(surface) == 2, "two sheets"
    r = np.linalg.norm(nvtesting.points_of(surface) - CENTER, axis=1)
    inner, outer = r[r < R], r[r > R]
    assert abs(inner.mean() - (R - L)) < 0.5 * H, "inner sheet at R - l: %g" % inner.mean()
    assert abs(outer.mean() - (R + L)) < 0.5 * H, "outer sheet at R + l: %g" % outer.mean()


def test_field_data_summarises_the_run(default):
    fd = default.GetOutput(0).GetFieldData()
    iterations = fd.GetArray("NumberOfIterations").GetValue(0)
    assert iterations == default.GetMaximumNumberOfIterations(), "iterations %d" % iterations
    assert fd.GetArray("RelativeChange").GetNumberOfTuples() == iterations, "one relative change per step"
    assert fd.GetArray("NarrowBandNodes").GetValue(0) == default.GetNumberOfBandNodes(), "band nodes"


def test_optional_arrays_only_on_request(default, optional):
    assert default.GetOutput(0).GetPointData().GetArray("Distance") is None, "no Distance by default"
    pd = optional.GetOutput(0).GetPointData()
    assert all(pd.GetArray(n) is not None for n in ("Distance", "NarrowBand", "InitialPhi")), "optional arrays"
    band = vtk_to_numpy(pd.GetArray("NarrowBand"))
    assert int(band.sum()) == optional.GetNumberOfBandNodes(), "NarrowBand marks the band"


def test_same_phi_for_1_and_2_threads():
    one = phi_of(run(NumberOfThreads=1))
    two = phi_of(run(NumberOfThreads=2))
    assert np.array_equal(one, two), "bit-identical phi for 1 and 2 threads"


def test_whole_domain_agrees_on_the_band(default, optional):
    """Whole Domain agrees with Narrow Band on the band (the paper's comparison)."""
    wphi = phi_of(run(Domain=1, OutputNarrowBand=True))
    nb = vtk_to_numpy(optional.GetOutput(0).GetPointData().GetArray("NarrowBand")).astype(bool)
    phi = phi_of(default)
    l2 = float(np.sqrt(np.mean((wphi[nb] - phi[nb]) ** 2)))
    print("narrow band vs whole domain: l2 difference over the band %.3e" % l2)
    assert l2 < 5e-3, "narrow band close to whole domain: %g" % l2


@pytest.mark.parametrize("sheets, radius", [(1, R + L), (2, R - L)], ids=["outer", "inner"])
def test_one_sheet(default, sheets, radius):
    """One sheet at a time: the outer sheet is the dilation, the inner the
    erosion; choosing sheets changes the surface only, never phi."""
    chosen = run(Sheets=sheets)
    one = chosen.GetOutput(1)
    r = np.linalg.norm(nvtesting.points_of(one) - CENTER, axis=1)
    assert nvtesting.regions(one) == 1 and nvtesting.boundary_edges(one) == 0, "Sheets=%d: one closed sheet" % sheets
    assert abs(r.mean() - radius) < 0.5 * H, "Sheets=%d: at radius %g (%g)" % (sheets, radius, r.mean())
    kept, phi = phi_of(chosen), phi_of(default)
    assert np.array_equal(kept, phi), "Sheets=%d: phi is the same as with both sheets (%d nodes differ)" % (
        sheets, int(np.count_nonzero(kept != phi)))


def test_open_cap_warns_that_the_surface_is_open():
    """An open surface (a cap of the sphere, as a one-sided scan) has no inner
    sheet: the warning says the input's surface is open, not that the offset is small."""
    cap = nvclouds.cloud(nvclouds.sphere_points(5000, R, CENTER)[nvclouds.sphere_points(5000)[:, 2] > 0.2])
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
    print("open cap, Sheets=Inner: %d triangles; warning: %s" % (o.GetOutput(1).GetNumberOfCells(),
                                                                  text.strip()[-200:]))
    assert o.GetOutput(1).GetNumberOfCells() == 0, "open cap: no inner sheet"
    assert "open" in text and "did not survive" not in text, "open cap: the warning says the surface is open"


# Progress: many events, never going back, ending at 1; and an abort asked
# for at 20 % ends the run soon after (the output stage polls it too).
def progress_run(abort_at=None):
    p = vtkNarrowVolumeReconstruction()
    p.SetInputData(DATA)
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


@pytest.fixture(scope="module")
def full_run():
    """A full run's progress fractions and its time."""
    _, seen, start, end = progress_run()
    return [v for v, _ in seen], end - start


def test_progress(full_run):
    values, whole = full_run
    print("progress: %d events over %.2f s: %s" % (len(values), whole, " ".join("%.2f" % v for v in values)))
    assert len(values) >= 20 and values[-1] == 1.0, "at least 20 progress events, the last 1 (%d)" % len(values)
    assert all(b >= a for a, b in zip(values, values[1:])), "progress never goes back"


@pytest.mark.parametrize("at", [0.2, 0.7], ids=["set-up", "output stage"])
def test_abort(full_run, at):
    """An abort at 20 % (the set-up) and at 70 % (the output stage)."""
    whole = full_run[1]
    aborted, seen, start, end = progress_run(abort_at=at)
    asked = [moment for v, moment in seen if v == "abort"]
    assert len(asked) == 1, "the abort at %g was asked for" % at
    after = end - asked[0]
    print("abort at %.0f %%: the run ended %.3f s after the request (%.0f %% of a full run's %.2f s)"
          % (100 * at, after, 100 * after / whole, whole))
    assert after <= 0.3 * whole, "an abort at %g ends the run within 0.3 of its full time" % at
    assert aborted.GetOutput(1).GetNumberOfPoints() == 0 and aborted.GetOutput(0).GetNumberOfPoints() == 0, \
        "an aborted run leaves empty outputs"
