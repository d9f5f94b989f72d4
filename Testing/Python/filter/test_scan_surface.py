# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The scan surface (Sheets SCAN_SURFACE): one closed surface through the
middle of the points, on shapes whose surface is known, clean and noisy,
sharp-edged, with a thin limb, in millimetres, unevenly sampled; open
scans, whose surface is open; and the warnings where none can be made
(points along a curve)."""
import warnings

import numpy as np
import pytest
from vtkmodules.util.numpy_support import vtk_to_numpy

import narrowvolume
from narrowvolume import vtkNarrowVolumeReconstruction
import nvtesting

RNG = np.random.default_rng(52)


def on_sphere(n, radius=1.0, center=(0.0, 0.0, 0.0)):
    v = RNG.normal(size=(n, 3))
    return radius * v / np.linalg.norm(v, axis=1)[:, None] + np.asarray(center)


def on_cube(n, half):
    """Area-uniform on the cube's faces, [-half, half]^3: its edges and corners are sharp."""
    face = RNG.integers(0, 6, n)
    p = RNG.uniform(-half, half, (n, 3))
    p[np.arange(n), face // 2] = np.where(face % 2, half, -half)
    return p


def cube_distance(x, half):
    q = np.abs(x) - half
    return np.abs(np.linalg.norm(np.maximum(q, 0.0), axis=1) + np.minimum(q.max(axis=1), 0.0))


def on_torus(n, big, small, uneven=False):
    """Area-uniform on a torus about z (uneven: 10 times denser on the x > 0 side)."""
    u, v = RNG.uniform(0, 2 * np.pi, 4 * n), RNG.uniform(0, 2 * np.pi, 4 * n)
    keep = RNG.uniform(size=4 * n) < (big + small * np.cos(v)) / (big + small)
    if uneven:
        keep &= (np.cos(u) > 0) | (RNG.uniform(size=4 * n) < 0.1)
    u, v = u[keep][:n], v[keep][:n]
    return np.c_[(big + small * np.cos(v)) * np.cos(u), (big + small * np.cos(v)) * np.sin(u), small * np.sin(v)]


def torus_distance(x, big, small):
    return np.abs(np.hypot(np.linalg.norm(x[:, :2], axis=1) - big, x[:, 2]) - small)


def diagonal(points):
    return float(np.linalg.norm(points.max(axis=0) - points.min(axis=0)))


def scan_surface(points, **settings):
    """The scan surface's run: (surface, field data, warnings' texts, spacing)."""
    with warnings.catch_warnings(record=True) as said:
        warnings.simplefilter("always")
        volume, surface = narrowvolume.reconstruct(points, Sheets=3, **settings)
    field = volume.GetFieldData()
    texts = [str(w.message) for w in said if "coarsened" not in str(w.message)]
    return surface, field, texts, field.GetArray("SampleSpacing").GetValue(0)


def value(field, name):
    return field.GetArray(name).GetValue(0)


def test_noisy_sphere_in_the_middle_of_its_points():
    """Gaussian noise of 1 % of the diagonal: the surface is one closed piece
    at the sphere's radius (the points' middle), where the closing's surface
    (the part to print's outside) follows the noise's outer envelope; the
    field data's distances are those of the noise."""
    clean = on_sphere(20000, 0.5, (1.0, 2.0, -3.0))
    sigma = 0.01 * diagonal(clean)
    points = clean + RNG.normal(scale=sigma, size=clean.shape)
    surface, field, said, h = scan_surface(points, OffsetDistance=0.1, SampleSpacing=0.02)
    assert said == [], said
    assert nvtesting.regions(surface) == 1 and nvtesting.boundary_edges(surface) == 0, "one closed piece"
    r = np.linalg.norm(nvtesting.points_of(surface) - (1.0, 2.0, -3.0), axis=1)
    print("noisy sphere: sigma %.4f (%.2f h), surface radius %.4f +- %.4f" % (sigma, sigma / h, r.mean(), r.std()))
    assert abs(r.mean() - 0.5) < 0.25 * h, "in the middle of the points: radius %g" % r.mean()
    assert r.std() < 0.5 * h, "smooth: radius spread %g" % r.std()
    envelope = _closing_radius(points)
    print("noisy sphere: the part's outside at radius %.4f" % envelope)
    assert envelope - 0.5 > 1.5 * sigma, "the closing's surface is on the envelope (%g): the case tests something" % envelope
    assert value(field, "ScanSurface") == 1 and value(field, "ScanSurfacePieces") == 1
    # |N(0, sigma)|: mean sigma sqrt(2 / pi), 95th percentile 1.96 sigma.
    mean, p95 = value(field, "ScanDistanceMean") * h, value(field, "ScanDistance95") * h
    print("noisy sphere: points' distances mean %.4f (noise %.4f), 95 %% %.4f (noise %.4f)" % (
        mean, sigma * np.sqrt(2 / np.pi), p95, 1.96 * sigma))
    assert abs(mean - sigma * np.sqrt(2 / np.pi)) < 0.15 * sigma
    assert abs(p95 - 1.96 * sigma) < 0.3 * sigma
    assert abs(value(field, "ScanSurfaceVolume") - 4 / 3 * np.pi * 0.5 ** 3) < 0.03 * 4 / 3 * np.pi * 0.5 ** 3


def _closing_radius(points):
    """The mean radius of the part to print's outer surface (a wall of 0.1, solid here) on the same run."""
    _, part = narrowvolume.reconstruct(points, OffsetDistance=0.1, SampleSpacing=0.02, WallThickness=0.1)
    r = np.linalg.norm(nvtesting.points_of(part) - (1.0, 2.0, -3.0), axis=1)
    return float(np.median(r[r > 0.45]))


def test_clean_cube_keeps_its_edges():
    """Sharp edges and corners: the surface lies on the cube (within a few
    tenths of a cell nearly everywhere), closed, one piece."""
    half = 0.5
    surface, field, said, h = scan_surface(on_cube(30000, half), OffsetDistance=0.08, SampleSpacing=0.02)
    assert said == [], said
    assert nvtesting.regions(surface) == 1 and nvtesting.boundary_edges(surface) == 0
    d = cube_distance(nvtesting.points_of(surface), half) / h
    print("clean cube: vertex distance to the cube (cells) median %.3f, 99 %% %.3f, max %.3f" % (
        np.median(d), np.quantile(d, 0.99), d.max()))
    assert np.median(d) < 0.1 and np.quantile(d, 0.99) < 1.0, "on the cube"
    assert value(field, "ScanDistanceMean") < 0.2


def test_torus_in_millimetres_unevenly_sampled():
    """A torus 100 mm across, ten times denser on one side, clean and with
    noise of 0.5 % of the diagonal: on the torus both times, one closed piece
    with its hole (genus 1: Euler characteristic 0)."""
    clean = on_torus(40000, 40.0, 12.0, uneven=True)
    for sigma in (0.0, 0.005 * diagonal(clean)):
        points = clean + RNG.normal(scale=sigma, size=clean.shape) if sigma else clean
        surface, field, said, h = scan_surface(points)
        assert said == [], said
        assert nvtesting.regions(surface) == 1 and nvtesting.boundary_edges(surface) == 0
        assert nvtesting.euler_characteristic(surface) == 0, "a torus"
        d = torus_distance(nvtesting.points_of(surface), 40.0, 12.0)
        print("torus (mm), sigma %.3f mm: h %.3f mm, vertex distance median %.3f mm, 99 %% %.3f mm" % (
            sigma, h, np.median(d), np.quantile(d, 0.99)))
        assert np.median(d) < 0.2 * h + 0.3 * sigma and np.quantile(d, 0.99) < h + sigma


def test_thin_limb_stays():
    """A ball with a limb thinner than the offset: the limb is in the surface, to its tip."""
    ball = on_sphere(12000, 0.5)
    t = RNG.uniform(0.45, 1.2, 4000)
    a = RNG.uniform(0, 2 * np.pi, 4000)
    limb = np.c_[t, 0.03 * np.cos(a), 0.03 * np.sin(a)]
    surface, _, said, h = scan_surface(np.r_[ball, limb], OffsetDistance=0.06, SampleSpacing=0.01)
    assert said == [], said
    x = nvtesting.points_of(surface)
    assert nvtesting.regions(surface) == 1 and nvtesting.boundary_edges(surface) == 0
    print("thin limb: the surface reaches x = %.3f (the limb's tip 1.2)" % x[:, 0].max())
    assert x[:, 0].max() > 1.2 - 2 * h
    on_limb = x[x[:, 0] > 0.8]
    r = np.hypot(on_limb[:, 1], on_limb[:, 2])
    assert abs(np.median(r) - 0.03) < 0.5 * h, "the limb's radius %g" % np.median(r)


def test_one_piece_per_object():
    two = np.r_[on_sphere(8000, 0.4), on_sphere(8000, 0.3, (1.5, 0.0, 0.0))]
    surface, field, said, _ = scan_surface(two, OffsetDistance=0.08, SampleSpacing=0.02)
    assert said == [], said
    assert nvtesting.regions(surface) == 2 and value(field, "ScanSurfacePieces") == 2


def test_phi_is_the_shell():
    """The scan surface changes the Surface output only: phi is the shell's."""
    points = on_sphere(5000, 0.5)
    both, _ = narrowvolume.reconstruct(points, OffsetDistance=0.1, SampleSpacing=0.025)
    scan, _ = narrowvolume.reconstruct(points, OffsetDistance=0.1, SampleSpacing=0.025, Sheets=3)
    phi = [vtk_to_numpy(v.GetPointData().GetArray("phi")) for v in (both, scan)]
    assert np.array_equal(phi[0], phi[1])


@pytest.mark.parametrize("sigma", [0.0, 0.01], ids=["clean", "noisy"])
def test_open_scan_gives_an_open_surface(sigma):
    """An open scan (a hemisphere, as one view of a scanner), clean and with
    noise of 1 % of the diagonal: one open surface on it, not closed across
    the opening and no second sheet, its boundary at the scan's rim."""
    cap = on_sphere(16000)
    cap = cap[cap[:, 2] > 0.0]
    points = cap + RNG.normal(scale=sigma * diagonal(cap), size=cap.shape) if sigma else cap
    surface, field, said, h = scan_surface(points)
    assert said == [], said
    assert value(field, "ScanSurface") == 2 and value(field, "ScanSurfaceOpenPieces") == 1
    assert nvtesting.regions(surface) == 1
    r = np.linalg.norm(nvtesting.points_of(surface), axis=1)
    print("open hemisphere, sigma %.3f: h %.4f, radius median %.4f, 99 %% off %.3f h" % (
        sigma, h, np.median(r), np.quantile(np.abs(r - 1.0), 0.99) / h))
    assert abs(np.median(r) - 1.0) < 0.1 * h + 0.2 * sigma * diagonal(cap), "on the scan, in its points' middle"
    assert np.quantile(np.abs(r - 1.0), 0.99) < h + 2.0 * sigma * diagonal(cap), "no second sheet"
    rim = nvtesting.points_of(nvtesting.boundary_of(surface))
    print("open hemisphere: boundary z from %.4f to %.4f, |z| median %.2f h, 95 %% %.2f h (the rim at 0)" % (
        rim[:, 2].min(), rim[:, 2].max(), np.median(np.abs(rim[:, 2])) / h, np.quantile(np.abs(rim[:, 2]), 0.95) / h))
    # The rim of a sampled surface is known to about a point's spacing:
    # the boundary within one of it (and the noise), nearly all within two.
    spacing = np.sqrt(2 * np.pi / len(cap))
    assert len(rim) > 0 and np.median(np.abs(rim[:, 2])) < spacing + sigma * diagonal(cap), "its boundary at the rim"
    assert np.quantile(np.abs(rim[:, 2]), 0.95) < 2 * spacing + 3 * sigma * diagonal(cap), "its boundary at the rim"
    assert np.quantile(np.linalg.norm(rim[:, :2], axis=1), 0.5) > 0.95, "the rim is the boundary (no hole inside)"


def test_scan_with_a_wide_hole():
    """A closed scan with a hole wider than the closing (the underside of a
    statue): the surface follows the scan and stays open at the hole."""
    ball = on_sphere(16000)
    surface, field, said, h = scan_surface(ball[ball[:, 2] < 0.8])
    assert said == [] and value(field, "ScanSurface") == 2 and nvtesting.regions(surface) == 1
    r = np.linalg.norm(nvtesting.points_of(surface), axis=1)
    assert np.quantile(np.abs(r - 1.0), 0.99) < h
    rim = nvtesting.points_of(nvtesting.boundary_of(surface))
    print("wide hole: boundary z %.4f to %.4f (the hole's rim at 0.8), h %.4f" % (rim[:, 2].min(), rim[:, 2].max(), h))
    assert np.quantile(np.abs(rim[:, 2] - 0.8), 0.95) < 4 * h, "open at the hole only"


def test_points_along_a_curve_are_said():
    """Points along a curve (a helix) have no surface: the warning says why
    and what to change; with a ball beside them, the surface is the ball's
    and two warnings say it lost most of the scan."""
    t = RNG.uniform(0, 6 * np.pi, 6000)
    helix = np.c_[np.cos(t), np.sin(t), 0.15 * t]
    surface, field, said, _ = scan_surface(helix)
    assert surface.GetNumberOfPoints() == 0 and value(field, "ScanSurface") == 0
    assert len(said) == 1 and said[0].startswith("The scan surface is empty: the shell neither encloses a solid nor "
                                                 "has two sides"), said
    assert "Sheets Both" in said[0] and "SampleSpacing" in said[0]
    assert np.isnan(value(field, "ScanDistanceMean"))
    surface, field, said, h = scan_surface(np.r_[on_sphere(3000, 0.3, (0.0, 0.0, -1.0)), helix])
    assert nvtesting.regions(surface) == 1 and value(field, "ScanSurface") == 1
    assert len(said) == 2, said
    assert said[0].startswith("The scan surface spans ") and "lost most of the scan" in said[0], said[0]
    assert said[1].startswith("Half of the scan's points lie farther than ") and "OffsetDistance" in said[1]


def test_progress_never_goes_back():
    """An open scan's surface (the longest way: the closed surface, then the
    open one) reports its progress in steps that never go back, to 1."""
    cap = on_sphere(6000)
    seen = []
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        narrowvolume.reconstruct(cap[cap[:, 2] > 0.0], progress=seen.append, Sheets=3)
    assert len(seen) > 10 and seen[-1] == 1.0
    assert all(b >= a for a, b in zip(seen, seen[1:])), "progress went back: %s" % seen
    assert max(b - a for a, b in zip(seen, seen[1:])) < 0.4, "no step takes most of it: %s" % seen


def test_a_wall_makes_the_part_and_says_so():
    """Sheets Scan with a wall: the part to print is made (its field data),
    and the warning says that Sheets does not apply and what to change."""
    surface, field, said, _ = scan_surface(on_sphere(3000, 0.5), OffsetDistance=0.1, SampleSpacing=0.025,
                                           WallThickness=0.1)
    assert field.GetArray("ScanSurface") is None and field.GetArray("MaterialVolume") is not None
    assert said[0] == ("Sheets is Scan, but WallThickness is 0.1: the output is the part to print, whose outer "
                       "surface lies on the scan, not the scan surface.\nSet WallThickness to 0 for the scan "
                       "surface, or Sheets to Both."), said


def test_filter_methods():
    f = vtkNarrowVolumeReconstruction()
    f.SetSheetsToScan()
    assert f.GetSheets() == f.SCAN_SURFACE == 3 and f.GetSheetsMaxValue() == 3
