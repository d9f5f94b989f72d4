# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""PreserveOffset (issue 17): more steps without the sheets' drift.

- The Table 1 sphere (l = 0.1, h = 0.01 and 0.005, default parameters) after
  10 and 20 steps with the option: the inner sheet's max and average errors
  no worse than the paper's Table 1 (the paper's scheme alone exceeds them
  after 10 steps at h = 0.01 and after 4 at h = 0.005: README, stopping rule).
- The Fig. 6 noisy spheres (test_noise_fig6.py's clouds and parameters) after
  10 steps with the option, against the 3-step default: smoother, and each
  sheet's mean radius closer to where the initial profile put it than 10
  steps of the paper's scheme leave it. The issue's targets (roughness at
  most 60 % of the default's, mean error at or below the default's) are
  printed with what is reached; the README says why they are not met.
- phi is the same, bit for bit, with 1 and 2 threads.

    pvpython -m pytest -s test_preserve_offset.py
"""
import numpy as np
import pytest
from vtkmodules.util.numpy_support import vtk_to_numpy

from narrowvolume import vtkNarrowVolumeReconstruction
import nvclouds
import nvshapes
import nvtesting

pytestmark = [pytest.mark.fidelity, pytest.mark.slow]


def reconstruct(cloud, h, offset, steps, preserve, **settings):
    f = vtkNarrowVolumeReconstruction()
    f.SetInputData(cloud)
    f.SetOffsetDistance(offset)
    f.SetSampleSpacing(h)
    f.SetMaximumNumberOfIterations(steps)
    f.SetPreserveOffset(preserve)
    for key, value in settings.items():
        getattr(f, "Set" + key)(value)
    f.Update()
    return f


# Table 1 sphere.
SPHERE_CASES = [(h, steps) for h in (0.01, 0.005) for steps in (10, 20)]


@pytest.fixture(scope="module")
def sphere_table():
    """{(h, steps): the inner sheet's errors}, the table printed."""
    print("\nTable 1 sphere, l = 0.1, default parameters, PreserveOffset on: inner sheet errors")
    print("| h | steps | max error | paper | average error | paper |")
    print("|---|---|---|---|---|---|")
    rows = {}
    for h in (0.01, 0.005):
        cloud = nvclouds.cloud(nvclouds.shape_points("sphere", h))
        paper = nvshapes.PAPER_TABLE1[("sphere", h)]
        for steps in (10, 20):
            f = reconstruct(cloud, h, 0.1, steps, True)
            e = nvshapes.inner_sheet_errors("sphere", nvtesting.points_of(f.GetOutput(1)), 0.1)
            print("| %g | %d | %.3e | %.3e | %.3e | %.3e |" % (h, steps, e["max"], paper[0], e["mean"], paper[1]),
                  flush=True)
            rows[(h, steps)] = e
    return rows


@pytest.mark.parametrize("h, steps", SPHERE_CASES, ids=["h=%g-%d-steps" % case for case in SPHERE_CASES])
def test_table1_sphere(sphere_table, h, steps):
    e = sphere_table[(h, steps)]
    paper = nvshapes.PAPER_TABLE1[("sphere", h)]
    assert e["vertices"] > 1000, "h=%g, %d steps: inner sheet found" % (h, steps)
    assert e["max"] <= paper[0], "h=%g, %d steps: max error %.3e > paper %.3e" % (h, steps, e["max"], paper[0])
    assert e["mean"] <= paper[1], "h=%g, %d steps: average error %.3e > paper %.3e" % (h, steps, e["mean"], paper[1])


# Fig. 6 noisy spheres: the clouds of test_noise_fig6.py.
R, L, H = 0.5, 0.1, 0.01
SPHERES = nvclouds.fig6_spheres(H, R)


def sheets(f):
    """Signed radial errors of the inner and outer sheets' vertices, and the roughness."""
    surface = f.GetOutput(1)
    r = np.linalg.norm(nvtesting.points_of(surface) - nvshapes.CENTER, axis=1)
    return r[r < R] - (R - L), r[r >= R] - (R + L), nvtesting.face_normal_roughness(surface)


@pytest.fixture(scope="module")
def noisy_table():
    """[{run: (inner errors, outer errors, roughness)}] for each noisy sphere, the table printed."""
    print("\nFig. 6 noisy spheres, xi = eps_4, eps = eps_12, h = 0.01: the 3-step default against 10 steps with "
          "PreserveOffset (and 10 steps without)")
    print("| points | noise | mean error, 3 steps | 10, PreserveOffset | 10, paper's scheme | target met | "
          "roughness, 3 steps | 10, PreserveOffset | ratio | target 60 % met |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    rows = []
    for points, noise, xyz in SPHERES:
        cloud = nvclouds.cloud(xyz)
        runs = {}
        for key, steps, preserve in (("initial", 0, False), ("default", 3, False), ("option", 10, True),
                                     ("paper10", 10, False)):
            runs[key] = sheets(reconstruct(cloud, H, L, steps, preserve, XiCells=4, EpsilonCells=12))
        error = {key: np.abs(np.concatenate(run[:2])).mean() for key, run in runs.items()}
        rough = {key: run[2] for key, run in runs.items()}
        print("| %d | %d %% | %.3e | %.3e | %.3e | %s | %.2f | %.2f | %.0f %% | %s |" % (
            points, round(noise * 100), error["default"], error["option"], error["paper10"],
            "yes" if error["option"] <= error["default"] else "no", rough["default"], rough["option"],
            100 * rough["option"] / rough["default"], "yes" if rough["option"] <= 0.6 * rough["default"] else "no"),
            flush=True)
        rows.append(runs)
    return rows


@pytest.mark.parametrize("case", range(len(SPHERES)),
                         ids=["%d points, %d %%" % (points, round(100 * noise)) for points, noise, _ in SPHERES])
def test_fig6_noisy_sphere(noisy_table, case):
    points, noise, _ = SPHERES[case]
    runs = noisy_table[case]
    rough = {key: run[2] for key, run in runs.items()}
    assert rough["option"] < rough["default"], "noise %g, %d points: not smoother than the 3-step default " \
        "(%.2f vs %.2f deg)" % (noise, points, rough["option"], rough["default"])
    for sheet, name in ((0, "inner"), (1, "outer")):
        held = abs(runs["option"][sheet].mean() - runs["initial"][sheet].mean())
        drifted = abs(runs["paper10"][sheet].mean() - runs["initial"][sheet].mean())
        assert held < drifted, "noise %g, %d points: the %s sheet moved %.2e from the initial profile's, " \
            "the paper's scheme %.2e" % (noise, points, name, held, drifted)


def test_same_phi_for_1_and_2_threads():
    """The same phi for any number of threads."""
    cloud = nvclouds.cloud(nvclouds.shape_points("sphere", 0.01))
    phi = []
    for threads in (1, 2):
        f = reconstruct(cloud, 0.01, 0.1, 10, True, NumberOfThreads=threads)
        phi.append(vtk_to_numpy(f.GetOutput(0).GetPointData().GetArray("phi")).copy())
    assert np.array_equal(phi[0], phi[1]), "PreserveOffset: phi differs between 1 and 2 threads"
