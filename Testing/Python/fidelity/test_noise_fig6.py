# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The paper's Fig. 6: a sphere of radius 0.5 sampled with 5 % and 10 % random
noise, l = 0.1, xi = eps_4, eps = eps_12, h = 0.01. The average error of the
offset surfaces, and the evolution leaving the surface smoother than the
initial profile's surface.

Noise of a % means every point's radius is multiplied by 1 + a u, with u
uniform in [-1, 1] (fixed seed): a radial amplitude A = a R. The error of a
vertex is its distance to the exact offset sphere of its sheet (radius 0.4
inside, 0.6 outside), averaged over both sheets.

The paper gives neither its noise model nor its number of points, and the
result depends on the second: each sheet lies at distance l from the nearest
points, so it follows the outermost (or innermost) noisy points near it, and
the denser the sampling, the more extreme the points it finds. At the paper's
own sphere density (Fig. 5: 2,964 points) the errors must be no worse than
the paper's 2.242e-2 and 3.755e-2; with dense sampling (points h apart,
31,416) they must stay below the noise amplitude A, the bound that follows
from every point lying within A of the sphere.
"""
import numpy as np
import pytest

from narrowvolume import vtkNarrowVolumeReconstruction
import nvclouds
import nvshapes
import nvtesting

pytestmark = pytest.mark.fidelity
PAPER = {0.05: 2.242e-2, 0.10: 3.755e-2}
R, L, H = 0.5, 0.1, 0.01
SPHERES = nvclouds.fig6_spheres(H, R)


@pytest.fixture(scope="module")
def table():
    """Every cloud run, its row of the table printed: [(errors of both
    sheets, roughness before and after the evolution, sheets)]."""
    print("\n| points | noise | average error (both sheets) | inner | outer | paper | bound A | "
          "roughness phi0 -> final (deg) |")
    print("|---|---|---|---|---|---|---|---|")
    rows = []
    for points, noise, xyz in SPHERES:
        f = vtkNarrowVolumeReconstruction()
        f.SetInputData(nvclouds.cloud(xyz))
        f.SetOffsetDistance(L)
        f.SetSampleSpacing(H)
        f.SetXiCells(4)
        f.SetEpsilonCells(12)
        f.SetMaximumNumberOfIterations(0)  # the initial profile's surface
        f.Update()
        before = nvtesting.face_normal_roughness(f.GetOutput(1))
        f.SetMaximumNumberOfIterations(3)  # the default
        f.Update()
        surface = f.GetOutput(1)
        after = nvtesting.face_normal_roughness(surface)
        r = np.linalg.norm(nvtesting.points_of(surface) - nvshapes.CENTER, axis=1)
        inner, outer = np.abs(r[r < R] - (R - L)), np.abs(r[r >= R] - (R + L))
        both = np.concatenate([inner, outer]).mean()
        print("| %d | %d %% | %.3e | %.3e | %.3e | %.3e | %.3e | %.2f -> %.2f |" % (
            points, round(noise * 100), both, inner.mean(), outer.mean(), PAPER[noise], noise * R, before, after))
        rows.append(dict(both=both, before=before, after=after, sheets=nvtesting.regions(surface)))
    return rows


@pytest.mark.parametrize("case", range(len(SPHERES)),
                         ids=["%d points, %d %%" % (points, round(100 * noise)) for points, noise, _ in SPHERES])
def test_noisy_sphere(table, case):
    points, noise, _ = SPHERES[case]
    row = table[case]
    paper, both, before, after = PAPER[noise], row["both"], row["before"], row["after"]
    amplitude = noise * R
    assert row["sheets"] == 2, "noise %g: two sheets" % noise
    if points == nvclouds.FIG5_POINTS:  # the paper's density: compared with the paper
        assert both <= paper, "noise %g: average error %.3e above the paper's %.3e" % (noise, both, paper)
    assert both < amplitude, "noise %g: average error %.3e above the noise amplitude" % (noise, both)
    assert after < 0.8 * before, "noise %g: smoother after evolution (%.2f -> %.2f deg)" % (noise, before, after)
