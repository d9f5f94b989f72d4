# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Issue 37: every warning is true to what happened, and the change it
advises, followed, removes it (or the next warning says why it cannot).

On synthetic clouds that stress each case (the scans in ../shared are
checked by test_scans_defaults.py):

- holes in a closed surface: a hole wider than ClosingRadius pierces the
  wall (no cavity: one sheet) and is reported as such; ClosingRadius set to
  the value the warning gives bridges it, or the warning that follows names
  the holes the bridging left and the OffsetDistance that covers them, which
  followed leaves no gap warning and a closed shell with its cavity;
- holes from l to 1.3 l with CloseGaps off: the warning comes exactly when
  the shell has no cavity; a hole the evolved wall covers (measured in
  NumberOfGaps, the shell keeps its cavity) gets none;
- with CloseGaps off, the advised OffsetDistance covers the hole;
- an offset larger than the cloud says so, and the automatic offset it
  advises removes the warning;
- an automatic grid coarsened to 320 cells says so, and the SampleSpacing it
  advises gives offset / spacing 4 and no warning;
- an open surface (a hemisphere), and a closed one thinner than twice the
  offset, say that the shell encloses no cavity; a closed sphere does not;
  the smaller offset it advises gives the cavity;
- the command line gives the same warnings in its options' words.

    pvpython -m pytest -s test_messages.py
"""
import math
import re
import subprocess

import numpy as np
import pytest
import nvclouds
import nvtesting

L = 0.04
rng = np.random.default_rng(37)


def run(xyz, **settings):
    """The filter on the points; returns (filter, field data, warnings)."""
    f, figures, warnings = nvtesting.run_filter(nvclouds.cloud(np.asarray(xyz, dtype=float)), **settings)
    print("%s: %s" % (settings, " | ".join(w.replace("\n", " / ") for w in warnings)))
    return f, figures, warnings


def about(warnings, words):
    """The warnings that contain `words`."""
    return [w for w in warnings if words in w]


def advised(warning, name):
    """The value a warning advises for the property `name`: '... set NAME to VALUE or more'."""
    match = re.search(r"set %s to ([0-9.eE+-]+) or more" % name, warning)
    assert match, "the warning advises a value for %s: %r" % (name, warning)
    return float(match.group(1))


def sheets(f):
    """The surface's connected sheets: 1 for a shell without cavity, 2 with one."""
    return nvtesting.regions(f.GetOutput(1))


def jittered_sphere(spacing, radius=0.5):
    xyz = nvclouds.sphere_points(int(4 * math.pi * radius ** 2 / spacing ** 2), radius)
    xyz += rng.normal(scale=0.1 * spacing, size=xyz.shape)
    return radius * xyz / np.linalg.norm(xyz, axis=1)[:, None]


SPHERE = jittered_sphere(0.6 * L)


def with_hole(xyz, radius, direction=(1.0, 0.0, 0.0)):
    """The points less the cap of the given radius around direction * 0.5."""
    return xyz[np.linalg.norm(xyz - 0.5 * np.asarray(direction), axis=1) > radius]


GRID = dict(OffsetDistance=L, SampleSpacing=L / 4)


def test_a_hole_wider_than_the_closing_radius():
    """4.5 l wide, over the automatic 3 l: pierced, reported, and the advice closes it."""
    holey = with_hole(SPHERE, 4.5 * L)
    f, figures, warnings = run(holey, **GRID)
    wide = about(warnings, "wider than ClosingRadius")
    assert len(wide) == 1 and figures["PiercedGaps"][0] >= 1, "one warning of a hole wider than ClosingRadius"
    assert sheets(f) == 1, "the warning is true: the shell is pierced (one sheet, no cavity)"
    assert about(warnings, "encloses no cavity"), "and the shell says it has no cavity"
    # Followed: ClosingRadius as advised; what is left (if anything) is a hole
    # the bridging left, whose advice is a larger offset.
    radius = advised(wide[0], "ClosingRadius")
    assert radius > 3.0 * L, "the advice is a larger radius than the one used"
    f, figures, warnings = run(holey, ClosingRadius=radius, **GRID)
    assert not about(warnings, "wider than ClosingRadius"), "the advised ClosingRadius bridges the hole"
    left = about(warnings, "left open by the gap closing")
    if left:
        assert "A larger ClosingRadius does not change that" in left[0]
        f, figures, warnings = run(holey, ClosingRadius=radius, OffsetDistance=advised(left[0], "OffsetDistance"),
                                   SampleSpacing=L / 4)
    assert not about(warnings, "gap") and not about(warnings, "hole"), "no hole warning left"
    assert figures["PiercedGaps"][0] == 0 and sheets(f) == 2, "a closed shell with its cavity"
    assert not about(warnings, "encloses no cavity")


def test_the_warning_exactly_where_the_wall_is_pierced():
    """With CloseGaps off, holes from l to 1.3 l: each is measured, and the
    warning comes exactly when the evolved shell has no cavity (one sheet).
    Near l the wall covers the hole (measured in NumberOfGaps, not pierced)."""
    covered = 0
    for k in (1.0, 1.1, 1.2, 1.3):
        f, figures, warnings = run(with_hole(SPHERE, k * L), CloseGaps=False, **GRID)
        pierced = figures["PiercedGaps"][0] > 0
        print("hole of %.1f l, closing off: %d measured, %d pierced, %d sheets" % (
            k, figures["NumberOfGaps"][0], figures["PiercedGaps"][0], sheets(f)))
        assert figures["NumberOfGaps"][0] >= 1, "the hole is measured"
        assert pierced == (sheets(f) == 1), "pierced exactly when the shell has no cavity"
        assert bool(about(warnings, "pierce")) == pierced, "a warning exactly when pierced"
        covered += not pierced
    assert covered >= 1, "a hole the wall covers gets no warning"


def test_closing_off_advises_a_covering_offset():
    """CloseGaps off, a hole of 2 l: pierced; the advised offset covers it."""
    holey = with_hole(SPHERE, 2.0 * L)
    f, figures, warnings = run(holey, CloseGaps=False, **GRID)
    wide = about(warnings, "wider than OffsetDistance")
    assert len(wide) == 1 and "Turn CloseGaps on" in wide[0] and sheets(f) == 1, "pierced and reported"
    offset = advised(wide[0], "OffsetDistance")
    f, figures, warnings = run(holey, CloseGaps=False, OffsetDistance=offset, SampleSpacing=L / 4)
    assert not about(warnings, "hole") and sheets(f) == 2, "the advised offset covers the hole"


def test_an_offset_larger_than_the_cloud():
    small = nvclouds.sphere_points(400, 0.1)
    f, figures, warnings = run(small, OffsetDistance=1e9)
    assert len(about(warnings, "larger than the cloud")) == 1, "an offset larger than the cloud says so"
    assert sheets(f) == 1 and not about(warnings, "encloses no cavity"), "a ball, said once"
    f, figures, warnings = run(small, OffsetDistance=0.0)
    assert not about(warnings, "larger than the cloud") and sheets(f) == 2, "the automatic offset: the shell"


def test_a_coarsened_grid():
    """A sphere sampled finer than 320 cells of l / 4 resolve."""
    dense = jittered_sphere(0.006)
    f, figures, warnings = run(dense, OutputVolume=False)
    coarsened = about(warnings, "grid was coarsened")
    assert len(coarsened) == 1, "the coarsening is said"
    h, l = figures["SampleSpacing"][0], figures["OffsetDistance"][0]
    match = re.search(r"set SampleSpacing to ([0-9.eE+-]+)", coarsened[0])
    finer = float(match.group(1))
    assert finer < h and "OffsetDistance raised from" in coarsened[0], coarsened[0]
    asked = float(re.search(r"raised from ([0-9.eE+-]+)", coarsened[0]).group(1))
    f, figures, warnings = run(dense, OutputVolume=False, SampleSpacing=finer)
    assert not about(warnings, "coarsened"), "the advised spacing: no coarsening"
    assert abs(figures["OffsetDistance"][0] / figures["SampleSpacing"][0] - 4.0) < 1e-6
    assert abs(figures["OffsetDistance"][0] / asked - 1.0) < 1e-5, "and the offset the sampling asks for"
    # The other advice, MaximumDimension, gives that offset too, on a grid as fine.
    cells = int(re.search(r"MaximumDimension to ([0-9]+)", coarsened[0]).group(1))
    f, figures, warnings = run(dense, OutputVolume=False, MaximumDimension=cells)
    assert not about(warnings, "coarsened") and not about(warnings, "grid is coarse")
    assert abs(figures["OffsetDistance"][0] / asked - 1.0) < 1e-5, "MaximumDimension: the offset asked for"
    assert figures["SampleSpacing"][0] <= 1.01 * finer, "MaximumDimension: the finer grid"


def test_an_open_surface_and_a_thin_object():
    hemisphere = SPHERE[SPHERE[:, 2] > 0.0]
    f, figures, warnings = run(hemisphere, **GRID)
    assert len(about(warnings, "encloses no cavity")) == 1 and sheets(f) == 1, "an open surface: no cavity, said"
    f, figures, warnings = run(SPHERE, **GRID)
    assert not about(warnings, "encloses no cavity") and sheets(f) == 2, "a closed sphere: its cavity, no warning"
    small = jittered_sphere(0.01, radius=0.1)
    f, figures, warnings = run(small, OffsetDistance=0.12, SampleSpacing=0.01)
    thin = about(warnings, "encloses no cavity")
    assert len(thin) == 1 and "thinner than twice OffsetDistance" in thin[0] and sheets(f) == 1
    f, figures, warnings = run(small, OffsetDistance=0.03, SampleSpacing=0.0075)
    assert not about(warnings, "encloses no cavity") and sheets(f) == 2, "a smaller offset: the cavity"


def test_the_command_line_words(tmp_path):
    """The command line: the same warning in its options' words, exit 0."""
    path = tmp_path / "small.xyz"
    np.savetxt(str(path), nvclouds.sphere_points(400, 0.1))
    result = subprocess.run(nvtesting.python_command() + ["-m", "narrowvolume", str(path), "--offset-distance", "1e9",
                            "-o", str(tmp_path / "shell.vtp")], capture_output=True, text=True, timeout=300)
    print(result.stderr)
    assert result.returncode == 0, nvtesting.explain(result)
    assert "--offset-distance (1e+09) is larger than the cloud" in result.stderr, "in the options' words"
