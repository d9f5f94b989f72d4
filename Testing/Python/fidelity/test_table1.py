# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The paper's Table 1: the inner (shrink) sheet of the cube, the sphere and
the cylinder at l = 0.1, h = 0.01 and 0.005, default parameters, against
the exact offset surface; each error no worse than the paper's.

    pvpython -m pytest -s test_table1.py [--spacing h ...]     (default: 0.01 0.005)

Two readings of the paper are made explicit:
- "rotated cube" is the cube turned off the grid axes. The axis-aligned cube
  with l a multiple of h puts its offset faces on grid nodes where phi0 = 0
  and g of eq. (4) vanishes, so nothing moves and the error is ~1e-8: true,
  but not a measure of the scheme. Both rows are checked against the
  paper's cube figures.
- The cylinder's inner offset surface has sharp rims, which any curvature
  flow rounds by a fraction of h; the paper's cylinder maximum (below its
  sphere's) can only be the smooth side's. The maximum is checked on the
  side (|z - 0.5| < 0.3); the whole sheet's maximum is printed too, and the
  average is checked over the whole sheet.
"""
import sys
import time

import pytest

from narrowvolume import vtkNarrowVolumeReconstruction
import nvclouds
import nvshapes
import nvtesting

pytestmark = [pytest.mark.fidelity, pytest.mark.slow]
OFFSET = 0.1
SHAPES = ("cube", "rotated cube", "sphere", "cylinder")


def spacings(config):
    return config.getoption("spacing") or [0.01, 0.005]


def pytest_generate_tests(metafunc):
    if "h" in metafunc.fixturenames:
        cases = [(shape, h) for shape in SHAPES for h in spacings(metafunc.config)]
        metafunc.parametrize("shape, h", cases, ids=["%s-%g" % case for case in cases])


@pytest.fixture(scope="module")
def table(request):
    """Every case run, its row of the table printed: {(shape, h): (points, errors)}."""
    print("\nTable 1: inner sheet errors, l = %g, default parameters (%d steps)" %
          (OFFSET, vtkNarrowVolumeReconstruction().GetMaximumNumberOfIterations()))
    print("| case | h | points | max error | paper | average error | paper | time (s) |")
    print("|---|---|---|---|---|---|---|---|")
    rows = {}
    for shape in SHAPES:
        for h in spacings(request.config):
            xyz = nvclouds.shape_points(shape, h)
            f = vtkNarrowVolumeReconstruction()
            f.SetInputData(nvclouds.cloud(xyz))
            f.SetOffsetDistance(OFFSET)
            f.SetSampleSpacing(h)
            start = time.time()
            f.Update()
            elapsed = time.time() - start
            e = nvshapes.inner_sheet_errors(shape, nvtesting.points_of(f.GetOutput(1)), OFFSET)
            paper = nvshapes.PAPER_TABLE1.get((shape, h))
            max_text = "%.3e" % e.get("side_max", e["max"])
            if "side_max" in e:
                max_text = "%.3e (side); %.3e (with rims)" % (e["side_max"], e["max"])
            print("| %s | %g | %d | %s | %s | %.3e | %s | %.1f |" % (
                shape, h, len(xyz), max_text, "%.3e" % paper[0] if paper else "-", e["mean"],
                "%.3e" % paper[1] if paper else "-", elapsed))
            sys.stdout.flush()
            rows[(shape, h)] = e
    return rows


def test_inner_sheet_error(table, shape, h):
    e = table[(shape, h)]
    paper = nvshapes.PAPER_TABLE1.get((shape, h))
    checked_max = e.get("side_max", e["max"])
    assert e["vertices"] > 1000, "%s h=%g: inner sheet found (%d vertices)" % (shape, h, e["vertices"])
    if paper:
        assert checked_max <= paper[0], "%s h=%g: max error %.3e > paper %.3e" % (shape, h, checked_max, paper[0])
        assert e["mean"] <= paper[1], "%s h=%g: average error %.3e > paper %.3e" % (shape, h, e["mean"], paper[1])
