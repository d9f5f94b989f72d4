# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Issue 39: a scan to a printable hollow solid in one filter (WallThickness).

- The Table 1 sphere and a torus: the outer surface within 0.25 h of the
  sampled surface on average, the inner within 0.25 h of the wall thickness
  inside it; both closed and manifold, normals out of the material
  (outward on the outer surface, into the cavity on the inner); the field
  data's volumes match the exact ones and MinimumWallThickness the wall.
- A rotated cube sampled unevenly (sharp edges, density varying eightfold):
  closed and manifold, and no inner vertex nearer than w - h to the outer
  surface (a cell locator's search, to its triangles).
- A dumbbell whose small end's cavity is under 1 % of the large one's: by
  default it is merged into the wall (RemovedCavities 1); with a small
  MinimumCavityVolume it stays.
- The closed scans of ../shared (the statues; skipped without ../shared) at
  the defaults with a wall of 2 % of the diagonal: closed and manifold, a
  cavity, no inner vertex nearer than w - h to the outer surface, the part
  within 2 h of the scan's bounding box on every side.
- Drain holes on the sphere: one or two, the cavity open, the part closed
  and manifold, no material across the hole at the bottom, the material
  less the holes' volume.
- An open scan (a hemisphere): the part is empty and a warning says why;
  its advice (WallThickness 0) gives the shell.
- WallThickness 0 (the default): no part's field data, the shell as before.
- The command line prints the part in one line.

    pvpython -m pytest -s test_print_part.py
"""
import math
import subprocess

import numpy as np
import pytest
import nvclouds
import nvshapes
import nvtesting
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import reference, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkGenericCell, vtkPolyData, vtkStaticCellLocator

rng = np.random.default_rng(39)


def points_and_normals(surface):
    return (vtk_to_numpy(surface.GetPoints().GetData()).astype(float),
            vtk_to_numpy(surface.GetPointData().GetNormals()).astype(float))


def part_of(xyz, **settings):
    f, figures, warnings = nvtesting.run_filter(nvclouds.cloud(xyz), **settings)
    return f.GetOutput(1), figures, warnings


def check_closed(surface):
    assert surface.GetNumberOfPolys() > 0
    assert nvtesting.boundary_edges(surface) == 0, "the part has boundary or non-manifold edges"


def test_sphere():
    h, l, w = 0.01, 0.1, 0.05
    surface, figures, warnings = part_of(nvshapes.sphere_points(h), OffsetDistance=l, SampleSpacing=h,
                                         WallThickness=w)
    assert warnings == []
    check_closed(surface)
    p, n = points_and_normals(surface)
    r = np.linalg.norm(p - 0.5, axis=1)
    outer = r > 0.5 - w / 2
    outer_error = np.abs(r[outer] - 0.5).mean() / h
    inner_error = np.abs(r[~outer] - (0.5 - w)).mean() / h
    print("sphere: outer %.3f h, inner %.3f h on average" % (outer_error, inner_error))
    assert outer_error <= 0.25 and inner_error <= 0.25
    radial = (n * (p - 0.5)).sum(axis=1)
    assert (radial[outer] > 0).all(), "outer normals point out of the part"
    assert (radial[~outer] < 0).all(), "inner normals point into the cavity"
    material = 4.0 / 3.0 * math.pi * (0.5 ** 3 - (0.5 - w) ** 3)
    cavity = 4.0 / 3.0 * math.pi * (0.5 - w) ** 3
    assert figures["MaterialVolume"][0] == pytest.approx(material, rel=0.01)
    assert figures["CavityVolume"][0] == pytest.approx(cavity, rel=0.01)
    assert figures["KeptCavities"] == [1] and figures["RemovedCavities"] == [0]
    assert w - h <= figures["MinimumWallThickness"][0] <= w + 0.1 * h
    assert figures["WallThickness"] == [w]
    bounds = figures["PartBounds"]
    assert bounds[1] - bounds[0] == pytest.approx(1.0, abs=h)


R, r = 0.35, 0.15


def torus_points(spacing):
    """A torus sampled about `spacing` apart, at random, uniform by area."""
    n = int(4 * math.pi ** 2 * R * r / spacing ** 2)
    u = rng.uniform(0.0, 2.0 * math.pi, 3 * n)
    v = rng.uniform(0.0, 2.0 * math.pi, 3 * n)
    keep = rng.uniform(0.0, 1.0, 3 * n) < (R + r * np.cos(v)) / (R + r)
    u, v = u[keep][:n], v[keep][:n]
    return np.c_[(R + r * np.cos(v)) * np.cos(u), (R + r * np.cos(v)) * np.sin(u), r * np.sin(v)]


def test_torus():
    h, l, w = 0.005, 0.03, 0.04
    surface, figures, warnings = part_of(torus_points(0.6 * h), OffsetDistance=l, SampleSpacing=h,
                                         WallThickness=w)
    assert warnings == []
    check_closed(surface)
    p, n = points_and_normals(surface)
    tube = np.sqrt((np.hypot(p[:, 0], p[:, 1]) - R) ** 2 + p[:, 2] ** 2)
    outer = tube > r - w / 2
    outer_error = np.abs(tube[outer] - r).mean() / h
    inner_error = np.abs(tube[~outer] - (r - w)).mean() / h
    print("torus: outer %.3f h, inner %.3f h on average" % (outer_error, inner_error))
    assert outer_error <= 0.25 and inner_error <= 0.25
    axis = np.c_[p[:, :2] / np.hypot(p[:, 0], p[:, 1])[:, None] * R, np.zeros(len(p))]
    away = (n * (p - axis)).sum(axis=1)
    assert (away[outer] > 0).all() and (away[~outer] < 0).all()
    material = 2 * math.pi ** 2 * R * (r ** 2 - (r - w) ** 2)
    assert figures["MaterialVolume"][0] == pytest.approx(material, rel=0.02)
    assert figures["KeptCavities"] == [1]


def surface_of(points, triangles):
    """A vtkPolyData of these points and triangles."""
    from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray
    polys = vtkCellArray()
    offsets = np.arange(0, 3 * len(triangles) + 1, 3, dtype=np.int64)
    polys.SetData(numpy_to_vtkIdTypeArray(offsets, deep=1),
                  numpy_to_vtkIdTypeArray(np.ascontiguousarray(triangles, dtype=np.int64).ravel(), deep=1))
    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_to_vtk(np.ascontiguousarray(points), deep=1))
    data = vtkPolyData()
    data.SetPoints(vtk_points)
    data.SetPolys(polys)
    return data


def regions_of(surface):
    """The part's connected surfaces: (each point's region, points, triangles)."""
    return nvtesting.regions_of(surface)


def test_uneven_cube_wall():
    # The unit cube, turned, sampled with a density that varies eightfold across it.
    h, l, w = 0.01, 0.04, 0.06
    dense = nvshapes.SHAPES["rotated cube"]["points"](0.004)
    weight = 0.125 + 0.875 * (dense[:, 0] - dense[:, 0].min()) / np.ptp(dense[:, 0])
    xyz = dense[rng.uniform(0.0, 1.0, len(dense)) < weight]
    surface, figures, warnings = part_of(xyz, OffsetDistance=l, SampleSpacing=h, WallThickness=w)
    check_closed(surface)
    assert figures["KeptCavities"] == [1]
    least = least_wall(surface, w, h)
    print("cube: least distance from the inner surface to the outer: %.4f (w %.4f, h %.4f), "
          "MinimumWallThickness %.4f" % (least, w, h, figures["MinimumWallThickness"][0]))
    assert least >= w - h
    assert figures["MinimumWallThickness"][0] >= w - h


def least_wall(surface, wall, h):
    """The least distance from a vertex of the inner surfaces to the outer
    surface's triangles (the region reaching farthest from the centre), over
    every inner vertex (vtkStaticCellLocator; each search within wall + h,
    and the least is at most that)."""
    ids, points, triangles = regions_of(surface)
    outer_region = ids[np.argmax(np.linalg.norm(points - points.mean(axis=0), axis=1))]
    outer = surface_of(points, triangles[ids[triangles[:, 0]] == outer_region])
    locator = vtkStaticCellLocator()
    locator.SetDataSet(outer)
    locator.BuildLocator()
    closest, generic = [0.0, 0.0, 0.0], vtkGenericCell()
    cell, sub, d2, inside = reference(0), reference(0), reference(0.0), reference(0)
    least = wall + h
    for x in points[ids != outer_region]:
        if locator.FindClosestPointWithinRadius(x, least, closest, generic, cell, sub, d2, inside):
            least = min(least, math.sqrt(d2.get()))
    return least


# The teapot's spout ends in a rim sampled as one sheet: the closing of a
# sheet is empty, so the part stops short of the rim (2.1 h along x): there
# only "never larger than the scan" holds.
@pytest.mark.parametrize("name,rim", [("armadillo", False), ("dragon", False), ("teapot", True)])
def test_closed_scans(name, rim):
    try:
        xyz = nvclouds.scan_points(name)
    except nvclouds.ScansMissing as missing:
        pytest.skip(str(missing))
    low, high = xyz.min(axis=0), xyz.max(axis=0)
    w = 0.02 * float(np.linalg.norm(high - low))
    surface, figures, warnings = part_of(xyz, WallThickness=w)
    h = figures["SampleSpacing"][0]
    check_closed(surface)
    least = least_wall(surface, w, h)
    bounds = np.array(figures["PartBounds"]).reshape(3, 2)
    print("%s: w %.4g, h %.4g, least wall %.4g (field data %.4g), cavities kept %d, merged %d, "
          "part - scan bounds %s (in h)" % (name, w, h, least, figures["MinimumWallThickness"][0],
                                            figures["KeptCavities"][0], figures["RemovedCavities"][0],
                                            np.round((bounds - np.c_[low, high]) / h, 2).ravel().tolist()))
    assert figures["KeptCavities"][0] >= 1
    assert least >= w - h
    assert np.all(bounds[:, 0] >= low - 2 * h) and np.all(bounds[:, 1] <= high + 2 * h), "no larger than the scan"
    if not rim:
        assert np.all(np.abs(bounds - np.c_[low, high]) <= 2 * h), "the scan's size"


def test_small_cavity_merged():
    # A large ball and a small one joined by a thin solid neck along x: the
    # small ball's cavity (radius 0.09 - w) is 0.66 % of the large one's.
    h, l, w = 0.01, 0.04, 0.03
    big = nvshapes.sphere_points(0.006, radius=0.35) + np.array([-0.2, 0.0, 0.0])  # centre (0.3, 0.5, 0.5)
    small = nvshapes.sphere_points(0.006, radius=0.09) + np.array([0.45, 0.0, 0.0])  # centre (0.95, 0.5, 0.5)
    off_axis = lambda x: np.hypot(x[:, 1] - 0.5, x[:, 2] - 0.5) > 0.03
    t = np.linspace(0.0, 2.0 * math.pi, 24, endpoint=False)
    s = np.arange(0.63, 0.88, 0.006)
    neck = np.c_[np.repeat(s, len(t)), 0.5 + 0.03 * np.tile(np.cos(t), len(s)),
                 0.5 + 0.03 * np.tile(np.sin(t), len(s))]
    xyz = np.vstack([big[off_axis(big)], small[off_axis(small)], neck])
    surface, figures, warnings = part_of(xyz, OffsetDistance=l, SampleSpacing=h, WallThickness=w)
    assert warnings == []
    check_closed(surface)
    print("dumbbell, default:", {k: figures[k] for k in ("KeptCavities", "RemovedCavities", "MinimumCavityVolume",
                                                          "CavityVolume")})
    assert figures["KeptCavities"] == [1] and figures["RemovedCavities"] == [1]
    small_cavity = 4.0 / 3.0 * math.pi * (0.09 - w) ** 3
    assert figures["MinimumCavityVolume"][0] > small_cavity
    _, kept, _ = part_of(xyz, OffsetDistance=l, SampleSpacing=h, WallThickness=w,
                         MinimumCavityVolume=0.1 * small_cavity)
    assert kept["KeptCavities"] == [2] and kept["RemovedCavities"] == [0]
    # The merged cavity's volume moves from the cavities to the material; it
    # is the small ball's, less the end of the neck that reaches into it.
    merged = kept["CavityVolume"][0] - figures["CavityVolume"][0]
    assert figures["MaterialVolume"][0] - kept["MaterialVolume"][0] == pytest.approx(merged, rel=1e-9)
    assert 0.85 * small_cavity < merged < small_cavity


def test_same_part_on_any_number_of_threads():
    # The distance to the outer sheet is swept in parallel (atomic least
    # keys, in rounds): the part must not depend on the threads' order.
    h, l, w = 0.01, 0.1, 0.05
    xyz = nvshapes.sphere_points(h)
    parts = [part_of(xyz, OffsetDistance=l, SampleSpacing=h, WallThickness=w, NumberOfDrainHoles=2,
                     NumberOfThreads=threads)[0] for threads in (1, 2, 3)]
    arrays = [(vtk_to_numpy(p.GetPoints().GetData()), vtk_to_numpy(p.GetPolys().GetConnectivityArray()))
              for p in parts]
    for points, triangles in arrays[1:]:
        assert np.array_equal(points, arrays[0][0]) and np.array_equal(triangles, arrays[0][1])


def test_drain_holes():
    # One hole from the sphere's cavity, at its lowest point: the cavity
    # opens (one surface), the part stays closed and manifold, the hole is
    # round about the bottom, and the material loses about the hole's volume.
    h, l, w = 0.01, 0.1, 0.05
    xyz = nvshapes.sphere_points(h)
    _, plain, _ = part_of(xyz, OffsetDistance=l, SampleSpacing=h, WallThickness=w)
    for holes in (1, 2):
        surface, figures, warnings = part_of(xyz, OffsetDistance=l, SampleSpacing=h, WallThickness=w,
                                             NumberOfDrainHoles=holes)
        assert warnings == []
        check_closed(surface)
        ids, points, _ = regions_of(surface)
        assert len(np.unique(ids)) == 1, "the cavity opens to the outside"
        assert figures["DrainHoles"] == [holes]
        assert figures["CavityVolume"] == plain["CavityVolume"]
        radius = w  # the automatic diameter: twice the wall
        lost = plain["MaterialVolume"][0] - figures["MaterialVolume"][0]
        assert lost == pytest.approx(holes * math.pi * radius ** 2 * w, rel=0.25)
        below = points[points[:, 2] < 0.5 - 0.5 * math.sqrt(3) / 2]  # within 30 degrees of the bottom
        off_axis = np.hypot(below[:, 0] - 0.5, below[:, 1] - 0.5)
        assert off_axis.min() > 0.9 * radius, "no material across the hole at the bottom"


@pytest.mark.parametrize("axis,down", [(1, (1, 0, 0)), (2, (0, -1, 0)), (5, (0, 0, 1))])
def test_drain_hole_axis(axis, down):
    # DrainHoleAxis: the hole goes where that axis points (+X, -Y, +Z),
    # and the sphere's -z pole, the default's place, keeps its material.
    h, l, w = 0.01, 0.1, 0.05
    surface, figures, warnings = part_of(nvshapes.sphere_points(h), OffsetDistance=l, SampleSpacing=h,
                                         WallThickness=w, NumberOfDrainHoles=1, DrainHoleAxis=axis)
    assert warnings == []
    check_closed(surface)
    ids, points, _ = regions_of(surface)
    assert len(np.unique(ids)) == 1, "the cavity opens to the outside"
    assert figures["DrainHoles"] == [1]
    down = np.array(down, float)
    offset = points - 0.5
    along = offset @ down
    off_axis = np.linalg.norm(offset - np.outer(along, down), axis=1)
    pole = along > 0.5 * math.sqrt(3) / 2  # within 30 degrees of the pole the axis points to
    assert off_axis[pole].min() > 0.9 * w, "no material across the hole at the chosen pole"
    bottom = offset[:, 2] < -0.5 * math.sqrt(3) / 2
    assert np.hypot(offset[bottom, 0], offset[bottom, 1]).min() < 0.5 * w, "the -z pole keeps its material"


def test_part_size_in_the_panel():
    # PartSizeUsed, the panel's read-only text beside WallThickness: the
    # part's size against the cloud's, from the part's bounds; empty for the
    # shell.
    h, l, w = 0.01, 0.1, 0.05
    xyz = nvshapes.sphere_points(h)
    f, figures, _ = nvtesting.run_filter(nvclouds.cloud(xyz), OffsetDistance=l, SampleSpacing=h, WallThickness=w)
    bounds = figures["PartBounds"]
    low, high = xyz.min(axis=0), xyz.max(axis=0)
    size = " x ".join("%.4g" % (bounds[2 * a + 1] - bounds[2 * a]) for a in range(3))
    cloud = " x ".join("%.4g" % (high[a] - low[a]) for a in range(3))
    assert f.GetPartSizeUsed() == "%s (the cloud %s)" % (size, cloud)
    shell, _, _ = nvtesting.run_filter(nvclouds.cloud(xyz), OffsetDistance=l, SampleSpacing=h)
    assert shell.GetPartSizeUsed() == ""


def test_open_scan_warns():
    h, l, w = 0.01, 0.04, 0.03
    xyz = nvshapes.sphere_points(0.006)
    xyz = xyz[xyz[:, 2] > 0.5]
    surface, figures, warnings = part_of(xyz, OffsetDistance=l, SampleSpacing=h, WallThickness=w)
    assert surface.GetNumberOfPolys() == 0
    assert len(warnings) == 1 and "The part to print is empty" in warnings[0], warnings
    # The advice: the shell itself (which says in its turn that it encloses no cavity).
    shell, _, advised = part_of(xyz, OffsetDistance=l, SampleSpacing=h, WallThickness=0.0)
    assert shell.GetNumberOfPolys() > 0
    assert not any("part to print" in text for text in advised)


def test_default_is_the_shell():
    h, l = 0.01, 0.1
    surface, figures, warnings = part_of(nvshapes.sphere_points(h), OffsetDistance=l, SampleSpacing=h)
    assert "MaterialVolume" not in figures and "PartBounds" not in figures
    p, _ = points_and_normals(surface)
    r = np.linalg.norm(p - 0.5, axis=1)
    assert r.max() == pytest.approx(0.5 + l, abs=h)  # the shell's outer sheet, not the part


def test_command_line(tmp_path):
    cloud = tmp_path / "sphere.xyz"
    np.savetxt(cloud, nvshapes.sphere_points(0.01))
    out = tmp_path / "part.stl"
    run = subprocess.run(nvtesting.python_command() + ["-m", "narrowvolume", str(cloud), "-o", str(out),
                                                       "--offset-distance", "0.1", "--sample-spacing", "0.01",
                                                       "--wall-thickness", "0.05", "--number-of-drain-holes", "1",
                                                       "--drain-hole-axis", "plus-x"],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    line = [s for s in run.stdout.splitlines() if "part to print" in s]
    assert len(line) == 1, run.stdout
    assert "wall 0.05 " in line[0] and "1 cavity kept" in line[0], line[0]
    assert line[0].endswith(", 1 drain hole"), line[0]
    assert out.stat().st_size > 0


# Issue 47: a part never loses the scan in silence.

def run_with_errors(xyz, **settings):
    """The filter's part, field data, warnings and errors."""
    return nvtesting.run_filter_said(nvclouds.cloud(xyz), **settings)


@pytest.mark.parametrize("settings,words", [
    (dict(WallThickness=-1.0), "WallThickness must be a finite value >= 0"),
    (dict(WallThickness=0.05, DrainHoleDiameter=-0.1), "DrainHoleDiameter must be a finite value >= 0"),
    (dict(WallThickness=0.05, NumberOfDrainHoles=1, DrainHoleDiameter=0.6),
     "DrainHoleDiameter (0.6) is more than half the cloud's width"),
])
def test_inputs_that_cannot_work_refused(settings, words):
    # A negative wall (the command line's --wall-thickness -1 gave the shell),
    # a negative diameter, a hole wider than half the model across its axis
    # (it cut half the model away): an error, and no output.
    xyz = nvshapes.sphere_points(0.02)
    f, _, _, errors = run_with_errors(xyz, OffsetDistance=0.1, SampleSpacing=0.02, **settings)
    assert len(errors) == 1 and words in errors[0], errors
    assert f.GetOutput(1).GetNumberOfPoints() == 0
    if "half the cloud" in words:
        # The advice: the largest diameter it names runs.
        advised = float(errors[0].split("Set DrainHoleDiameter to ")[1].split(" ")[0])
        _, figures, _, errors = run_with_errors(xyz, OffsetDistance=0.1, SampleSpacing=0.02, WallThickness=0.05,
                                                NumberOfDrainHoles=1, DrainHoleDiameter=advised)
        assert errors == [] and figures["DrainHoles"] == [1.0]


def test_drain_holes_without_a_wall_warn():
    xyz = nvshapes.sphere_points(0.02)
    _, figures, warnings, _ = run_with_errors(xyz, OffsetDistance=0.1, SampleSpacing=0.02, NumberOfDrainHoles=2)
    assert len(warnings) == 1 and "NumberOfDrainHoles is 2, but WallThickness is 0" in warnings[0], warnings
    assert "DrainHoles" not in figures
    _, _, warnings, _ = run_with_errors(xyz, OffsetDistance=0.1, SampleSpacing=0.02, NumberOfDrainHoles=0)
    assert warnings == []


def millimetre_sphere():
    """A ball 40 mm across sampled every 1.5 mm: a model in millimetres."""
    return 40.0 * (nvshapes.sphere_points(1.5 / 40.0) - 0.5)


def test_the_grid_follows_the_wall():
    # A wall of 1.2 mm where the sampling asks for l / 4 = 0.56 mm cells
    # (about two cells across the wall, which broke into a lace before): the
    # automatic spacing gives the wall three cells, and the part is whole.
    xyz = millimetre_sphere()
    w = 1.2
    surface, figures, warnings, errors = run_with_errors(xyz, WallThickness=w, OutputVolume=False)
    h, l = figures["SampleSpacing"][0], figures["OffsetDistance"][0]
    print("grid %s: h %.4g (l / 4 %.4g), wall %.4g cells" % (surface.GetGridUsed(), h, l / 4, w / h))
    assert errors == [] and warnings == []
    assert h == pytest.approx(w / 3) and h < l / 4
    check_closed(surface.GetOutput(1))
    assert figures["KeptCavities"] == [1.0] and figures["PartPieces"] == [1.0]
    assert figures["MinimumWallThickness"][0] >= w - h
    assert figures["LostPoints"] == [0.0] and figures["RestoredPoints"] == [0.0]


def test_a_wall_too_thin_for_the_memory_limit_is_refused():
    # The model at 1:1 with a thin wall: the grid the wall needs is over the
    # limit; the error says the spacing, the memory and the ways out, before
    # anything large is allocated. Each way out, as printed, then runs.
    xyz = millimetre_sphere()
    w, limit = 1.2, 48.0  # MiB: the wall's grid needs about 36 for itself, the offset's about 16
    _, _, _, errors = run_with_errors(xyz, WallThickness=w, OutputVolume=False, MemoryLimit=limit)
    assert len(errors) == 1, errors
    error = errors[0]
    assert "WallThickness 1.2 needs a grid spacing of 0.4 or less" in error and "over the limit of 48 MiB" in error
    scale = float(error.split("scaled by ")[1].split(" ")[0])
    thicker = float(error.split("set WallThickness to ")[1].split(" ")[0])
    assert 0 < scale < 1 and thicker > w
    _, figures, _, errors = run_with_errors(scale * xyz, WallThickness=w, OutputVolume=False, MemoryLimit=limit)
    assert errors == [] and figures["KeptCavities"] == [1.0], errors
    _, figures, _, errors = run_with_errors(xyz, WallThickness=thicker, OutputVolume=False, MemoryLimit=limit)
    assert errors == [] and figures["KeptCavities"] == [1.0], errors


def test_a_wall_thinner_than_the_grid_the_user_set():
    # SampleSpacing set by hand, the wall 1.5 cells: the part is a lace (or
    # nothing) and the warning says why, not that the scan is open; its
    # advice (the spacing it names) gives a whole part and no warning.
    h, l, w = 0.02, 0.1, 0.03
    xyz = nvshapes.sphere_points(0.01)
    _, _, warnings, _ = run_with_errors(xyz, OffsetDistance=l, SampleSpacing=h, WallThickness=w)
    assert any("The wall spans only 1.5 cells of the grid" in text for text in warnings), warnings
    assert not any("empty" in text for text in warnings), warnings
    advised = float([t for t in warnings if "spans only" in t][0].split("Set SampleSpacing to ")[1].split(" ")[0])
    assert advised == pytest.approx(w / 3)
    surface, figures, warnings, _ = run_with_errors(xyz, OffsetDistance=l, SampleSpacing=advised, WallThickness=w)
    assert warnings == []
    check_closed(surface.GetOutput(1))
    assert figures["KeptCavities"] == [1.0] and figures["MinimumWallThickness"][0] >= w - advised


def horse(leg):
    """A body (an ellipsoid) on four legs of radius `leg` ending in hooves,
    sampled at random about 0.02 apart: thin limbs under a large cavity."""
    generator = np.random.default_rng(47)

    def sphere(center, radius, n):
        u = generator.normal(size=(n, 3))
        return center + radius * u / np.linalg.norm(u, axis=1)[:, None]

    body_center, body_axes = np.array([0.0, 0.0, 1.0]), np.array([1.0, 0.4, 0.35])
    body = body_center + body_axes * (sphere(np.zeros(3), 1.0, 60000))
    # Ellipsoid points thinned towards an even density (a point's share of area).
    weight = np.linalg.norm((body - body_center) / body_axes ** 2, axis=1) * np.prod(body_axes)
    body = body[generator.random(len(body)) < weight / weight.max()][:14000]
    parts = [body]
    for x in (-0.7, 0.7):
        for y in (-0.18, 0.18):
            n = int(2 * math.pi * leg * 0.8 / 0.02 ** 2)
            t, z = 2 * math.pi * generator.random(n), 0.1 + 0.8 * generator.random(n)
            shank = np.c_[x + leg * np.cos(t), y + leg * np.sin(t), z]
            hoof = sphere(np.array([x, y, 0.1]), 0.05, int(4 * math.pi * 0.05 ** 2 / 0.02 ** 2))
            inside_body = (((shank - body_center) / body_axes) ** 2).sum(axis=1) < 1
            shank = shank[~inside_body & (np.linalg.norm(shank - [x, y, 0.1], axis=1) > 0.05)]
            hoof = hoof[(hoof[:, 2] < 0.1) | (np.hypot(hoof[:, 0] - x, hoof[:, 1] - y) > leg)]
            parts += [shank, hoof]
    return np.vstack(parts)


def outside_the_part(surface, xyz):
    """Each point's signed distance to the part's surface (> 0 outside)."""
    from vtkmodules.vtkFiltersCore import vtkImplicitPolyDataDistance
    distance = vtkImplicitPolyDataDistance()
    distance.SetInput(surface)
    return np.array([distance.EvaluateFunction(p) for p in xyz])


def test_a_thin_limb_is_not_lost():
    # Legs 1.8 cells thick under the body's cavity, at the defaults with a
    # wall of 2 % of the diagonal: the closing loses them (the part was four
    # stumps, or lost its hooves, before, with no word). Material is put back
    # around the points it lost, the part is one closed piece, every scan
    # point within 2 h of it, and the warning says so and where.
    xyz = horse(0.012)
    w = 0.02 * float(np.linalg.norm(xyz.max(axis=0) - xyz.min(axis=0)))
    f, figures, warnings, errors = run_with_errors(xyz, WallThickness=w, OutputVolume=False)
    h = figures["SampleSpacing"][0]
    surface = f.GetOutput(1)
    outside = outside_the_part(surface, xyz)
    print("horse: h %.4g, restored %d, lost %d, farthest scan point %.2f h outside" %
          (h, figures["RestoredPoints"][0], figures["LostPoints"][0], outside.max() / h))
    assert errors == []
    check_closed(surface)
    assert figures["PartPieces"] == [1.0] and figures["KeptCavities"] == [1.0]
    assert figures["RestoredPoints"][0] > 100 and figures["LostPoints"] == [0.0]
    assert outside.max() <= figures["LostDistance"][0] == pytest.approx(2 * h)
    restored = [text for text in warnings if "The part had lost" in text]
    assert len(restored) == 1, warnings
    # The place it names is on a leg: below the body.
    center = [float(v) for v in restored[0].split("points around (")[1].split(")")[0].split(",")]
    assert center[2] < 0.8 and abs(abs(center[0]) - 0.7) < 0.05, center
    # Legs thick enough for the closing: nothing restored, nothing said.
    f, figures, warnings, errors = run_with_errors(horse(0.035), WallThickness=w, OutputVolume=False)
    assert figures["RestoredPoints"] == [0.0] and figures["LostPoints"] == [0.0] and figures["PartPieces"] == [1.0]
    assert not any("part" in text for text in warnings), warnings


def test_command_line_scale_and_names(tmp_path):
    # --scale to print size (the how-to's first step on the command line),
    # the default output named for the part, and a negative wall refused.
    cloud = tmp_path / "ball.xyz"
    np.savetxt(cloud, millimetre_sphere())
    run = subprocess.run(nvtesting.python_command() + ["-m", "narrowvolume", str(cloud), "--scale", "0.5",
                                                       "--wall-thickness", "1.2"],
                         capture_output=True, text=True, cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    line = [s for s in run.stdout.splitlines() if "part to print" in s][0]
    size = [float(v) for v in line.split("part to print: ")[1].split(",")[0].split(" x ")]
    assert all(19.0 < v < 20.5 for v in size), line  # the 40 mm ball at 1:2
    assert (tmp_path / "ball_part.stl").stat().st_size > 0 and not (tmp_path / "ball_shell.stl").exists()
    refused = subprocess.run(nvtesting.python_command() + ["-m", "narrowvolume", str(cloud), "--wall-thickness", "-1"],
                             capture_output=True, text=True, cwd=tmp_path)
    assert refused.returncode == 1 and "--wall-thickness must be a finite value >= 0" in refused.stderr, refused.stderr
    bad = subprocess.run(nvtesting.python_command() + ["-m", "narrowvolume", str(cloud), "--scale", "0"],
                         capture_output=True, text=True, cwd=tmp_path)
    assert bad.returncode == 2 and "--scale must be a finite factor above 0" in bad.stderr, bad.stderr


def body_on_a_leg(leg=0.03, spacing=0.015):
    """A ball of radius 0.5 on one solid leg (radius `leg`, thinner than
    twice the wall) standing under its centre: the cavity's lowest point is
    right above the leg."""
    body = nvshapes.sphere_points(spacing) + [0.0, 0.0, 0.5]  # centre (0.5, 0.5, 1), radius 0.5
    n, m = int(2 * math.pi * leg / spacing), int(0.55 / spacing)
    a, z = np.meshgrid(2 * math.pi * np.arange(n) / n, 0.55 * np.arange(m + 1) / m)
    shank = np.c_[0.5 + leg * np.cos(a.ravel()), 0.5 + leg * np.sin(a.ravel()), z.ravel()]
    shank = shank[np.linalg.norm(shank - [0.5, 0.5, 1.0], axis=1) > 0.5]
    foot = [[0.5 + q * math.cos(b), 0.5 + q * math.sin(b), 0.0]
            for q in np.linspace(0.0, leg, 4)[1:] for b in np.linspace(0.0, 2 * math.pi, 12, endpoint=False)]
    body = body[~((np.hypot(body[:, 0] - 0.5, body[:, 1] - 0.5) < leg) & (body[:, 2] < 0.6))]
    return np.vstack([body, shank, foot, [[0.5, 0.5, 0.0]]])


def test_drain_holes_never_down_a_leg():
    # The first place a hole would start is above the leg; straight down,
    # the hole (wider than the leg) ran its whole length and cut it away.
    # A hole runs at most 2 (l + w) + 2 h through the part: that place is
    # passed over, both holes start beside it, and the leg stays whole.
    xyz = body_on_a_leg()
    f, figures, warnings, errors = run_with_errors(xyz, OffsetDistance=0.04, SampleSpacing=0.01, WallThickness=0.05,
                                                   NumberOfDrainHoles=2)
    surface = f.GetOutput(1)
    assert errors == [] and warnings == []
    check_closed(surface)
    assert figures["DrainHoles"] == [2.0] and figures["PartPieces"] == [1.0]
    p = vtk_to_numpy(surface.GetPoints().GetData())
    shank = p[(p[:, 2] > 0.1) & (p[:, 2] < 0.4) & (np.hypot(p[:, 0] - 0.5, p[:, 1] - 0.5) < 0.06)]
    radius = np.hypot(shank[:, 0] - 0.5, shank[:, 1] - 0.5)
    print("the leg: %d vertices, radius %.3f to %.3f" % (len(shank), radius.min(), radius.max()))
    assert len(shank) > 100 and radius.min() > 0.02, "the leg is whole, not slotted or cut away"


def test_cavity_closing_distance():
    # CavityClosingDistance c (PrusaSlicer's hollowing closing distance): the
    # cavity made c deeper and grown back. In a cube with a wall of 0.1 the
    # cavity is a cube of side 0.8: its corners become spheres of radius c
    # (the corner's vertex (sqrt 3 - 1) c from the sharp corner), its volume
    # the opening's exact one; a cavity narrower than 2 c vanishes; 0 keeps
    # the sharp cube. The cube's faces lie on the grid's planes, as do its
    # sheets, where phi is exactly 0: a plane of zeros inside the outer
    # sheet stopped the distance D, and the wall came out 0.035, not 0.1.
    xyz = nvshapes.cube_points(0.01)
    h, l, w = 0.01, 0.04, 0.1
    corners = np.array([[a, b, c] for a in (w, 1 - w) for b in (w, 1 - w) for c in (w, 1 - w)])
    side = 1.0 - 2.0 * w
    for c in (0.0, 0.1):
        f, figures, warnings, errors = run_with_errors(xyz, OffsetDistance=l, SampleSpacing=h, WallThickness=w,
                                                       CavityClosingDistance=c, OutputVolume=False)
        assert errors == [] and warnings == []
        check_closed(f.GetOutput(1))
        p = vtk_to_numpy(f.GetOutput(1).GetPoints().GetData())
        inner = p[np.all((p > w / 2) & (p < 1 - w / 2), axis=1)]
        gap = np.linalg.norm(inner[:, None, :] - corners[None], axis=2).min(axis=0)
        exact = side ** 3 - 12 * (side - 2 * c) * (1 - math.pi / 4) * c ** 2 - 8 * (1 - math.pi / 6) * c ** 3
        print("c %.2f: cavity %.5f (exact %.5f), corners %.4f to %.4f from the sharp ones, least wall %.4f" %
              (c, figures["CavityVolume"][0], exact, gap.min(), gap.max(), figures["MinimumWallThickness"][0]))
        assert figures["KeptCavities"] == [1.0]
        assert figures["CavityVolume"][0] == pytest.approx(exact, rel=0.015)
        assert figures["MinimumWallThickness"][0] >= w - h
        if c == 0.0:
            assert gap.max() < 2 * h, "sharp corners"
        else:
            assert gap.min() >= (math.sqrt(3) - 1) * c - h and gap.max() <= (math.sqrt(3) - 1) * c + 2 * h
    # Narrower than 2 c: no cavity, a solid part.
    _, figures, _, errors = run_with_errors(xyz, OffsetDistance=l, SampleSpacing=h, WallThickness=w,
                                            CavityClosingDistance=0.45, OutputVolume=False)
    assert errors == [] and figures["KeptCavities"] == [0.0]
    _, _, _, errors = run_with_errors(xyz, OffsetDistance=l, SampleSpacing=h, WallThickness=w,
                                      CavityClosingDistance=-1.0)
    assert len(errors) == 1 and "CavityClosingDistance must be a finite value >= 0" in errors[0]


# Drain holes where a printer user wants them (DrainHolePositions, DrainHoleAngle).

def material_near_line(points, through, direction, beyond):
    """How near the part's vertices come to the line through `through`
    along `direction`, among those more than `beyond` along it."""
    direction = np.asarray(direction, float)
    offset = points - np.asarray(through, float)
    along = offset @ direction
    off_axis = np.linalg.norm(offset - np.outer(along, direction), axis=1)
    return off_axis[along > beyond].min()


def test_drain_holes_at_positions():
    # A position on the sphere's side (a scan point): the hole runs from the
    # cavity's nearest point through it, sideways although down is -z; a
    # position inside the cavity: its hole leaves by the shortest way down.
    # No hole elsewhere: the -z pole keeps its material in the first.
    h, l, w = 0.01, 0.1, 0.05
    xyz = nvshapes.sphere_points(h)
    side, figures, warnings = part_of(xyz, OffsetDistance=l, SampleSpacing=h, WallThickness=w,
                                      DrainHolePositions=[(1.0, 0.5, 0.5)])
    assert warnings == [] and figures["DrainHoles"] == [1.0]
    check_closed(side)
    ids, points, _ = regions_of(side)
    assert len(np.unique(ids)) == 1, "the cavity opens to the outside"
    assert material_near_line(points, (0.5, 0.5, 0.5), (1, 0, 0), 0.5 * math.sqrt(3) / 2) > 0.9 * w
    assert material_near_line(points, (0.5, 0.5, 0.5), (0, 0, -1), 0.5 * math.sqrt(3) / 2) < 0.5 * w
    inside, figures, warnings = part_of(xyz, OffsetDistance=l, SampleSpacing=h, WallThickness=w,
                                        DrainHolePositions=[(0.5, 0.5, 0.5)])
    assert warnings == [] and figures["DrainHoles"] == [1.0]
    check_closed(inside)
    points = points_and_normals(inside)[0]
    assert material_near_line(points, (0.5, 0.5, 0.5), (0, 0, -1), 0.5 * math.sqrt(3) / 2) > 0.9 * w
    assert material_near_line(points, (0.5, 0.5, 0.5), (1, 0, 0), 0.5 * math.sqrt(3) / 2) < 0.5 * w


def test_a_drain_hole_position_away_from_the_cavities_warns():
    # A position far outside the part makes no hole, and the warnings say
    # where it is and that the cavity is left sealed; a position on the
    # part's surface, as the advice says, makes the hole and no warning.
    h, l, w = 0.01, 0.1, 0.05
    xyz = nvshapes.sphere_points(h)
    _, figures, warnings = part_of(xyz, OffsetDistance=l, SampleSpacing=h, WallThickness=w,
                                   DrainHolePositions=[(3.0, 0.5, 0.5)])
    assert figures["DrainHoles"] == [0.0]
    assert any("1 drain hole position was given" in t and "0 made" in t and "(3, 0.5, 0.5)" in t and
               "Place each position on the part's surface" in t for t in warnings), warnings
    assert any("1 cavity of the 1 kept has no drain hole" in t for t in warnings), warnings
    _, figures, warnings = part_of(xyz, OffsetDistance=l, SampleSpacing=h, WallThickness=w,
                                   DrainHolePositions=[(0.5, 0.5, 0.0)])
    assert figures["DrainHoles"] == [1.0] and warnings == []


def test_a_drain_hole_position_over_a_leg():
    # A position in the cavity right above the leg: straight down would run
    # the leg's length. Within DrainHoleAngle the hole leans off the leg and
    # is made beside it; at angle 0 it is not made, and the warning names
    # the angle as the way out. The leg stays whole either way.
    xyz = body_on_a_leg()
    settings = dict(OffsetDistance=0.04, SampleSpacing=0.01, WallThickness=0.05, DrainHolePositions=[(0.5, 0.5, 0.6)])
    for angle, holes in ((30.0, 1.0), (0.0, 0.0)):
        f, figures, warnings, errors = run_with_errors(xyz, DrainHoleAngle=angle, **settings)
        surface = f.GetOutput(1)
        assert errors == []
        check_closed(surface)
        assert figures["DrainHoles"] == [holes] and figures["PartPieces"] == [1.0]
        if holes:
            assert warnings == []
        else:
            assert any("passed over where the hole's way" in t and "within DrainHoleAngle (0 degrees)" in t and
                       "raise DrainHoleAngle" in t for t in warnings), warnings
        p = vtk_to_numpy(surface.GetPoints().GetData())
        shank = p[(p[:, 2] > 0.1) & (p[:, 2] < 0.4) & (np.hypot(p[:, 0] - 0.5, p[:, 1] - 0.5) < 0.06)]
        radius = np.hypot(shank[:, 0] - 0.5, shank[:, 1] - 0.5)
        assert len(shank) > 100 and radius.min() > 0.02, "the leg is whole, not slotted or cut away"


def test_drain_hole_positions_refused_or_warned():
    # Positions without a wall warn (the shell has no holes); a position
    # with a coordinate that is not finite is refused.
    xyz = nvshapes.sphere_points(0.02)
    _, _, warnings, errors = run_with_errors(xyz, OffsetDistance=0.1, SampleSpacing=0.02,
                                             DrainHolePositions=[(0.5, 0.5, 0.0)])
    assert errors == [] and any("DrainHolePositions gives 1 place, but WallThickness is 0" in t for t in warnings)
    _, _, _, errors = run_with_errors(xyz, OffsetDistance=0.1, SampleSpacing=0.02, WallThickness=0.05,
                                      DrainHolePositions=[(0.5, float("nan"), 0.0)])
    assert any("DrainHolePositions must be points, three finite coordinates each" in t for t in errors), errors


def test_drain_hole_positions_on_the_command_line_and_in_python(tmp_path):
    # --drain-hole-positions X Y Z, in the cloud file's coordinates, scaled
    # with it by --scale; reconstruct() takes an (n, 3) array.
    import narrowvolume
    cloud = tmp_path / "sphere.xyz"
    np.savetxt(cloud, nvshapes.sphere_points(0.01))
    run = subprocess.run(nvtesting.python_command() + ["-m", "narrowvolume", str(cloud), "--scale", "2",
                                                       "--offset-distance", "0.2", "--sample-spacing", "0.02",
                                                       "--wall-thickness", "0.1", "--drain-hole-positions",
                                                       "1", "0.5", "0.5", "--drain-hole-positions", "0.5", "0.5", "0"],
                         capture_output=True, text=True, cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    assert "warning" not in run.stderr, run.stderr
    line = [s for s in run.stdout.splitlines() if "part to print" in s][0]
    assert line.endswith(", 2 drain holes"), line
    volume, _ = narrowvolume.reconstruct(nvshapes.sphere_points(0.01), OffsetDistance=0.1, SampleSpacing=0.01,
                                         WallThickness=0.05, drain_hole_positions=np.array([[1.0, 0.5, 0.5]]))
    assert volume.GetFieldData().GetArray("DrainHoles").GetValue(0) == 1
    with pytest.raises(ValueError, match="takes points"):
        narrowvolume.reconstruct(nvshapes.sphere_points(0.02), WallThickness=0.05, drain_hole_positions=[1.0, 2.0])


def test_a_part_over_the_memory_limit_gets_the_parts_advice():
    # A part on a grid the user made finer than its wall needs, over
    # MemoryLimit: refused with the spacing the wall needs; not with
    # "turn OutputVolume off", which saves a part nothing (its dense phi is
    # needed). Following the advice (the wall's spacing) runs.
    xyz = nvshapes.sphere_points(0.02)
    settings = dict(OffsetDistance=0.05, WallThickness=0.03, MemoryLimit=60)
    _, _, _, errors = run_with_errors(xyz, SampleSpacing=0.002, **settings)
    assert len(errors) == 1 and "too large" in errors[0], errors
    assert "A part's wall of 0.03 needs a spacing of 0.01 (SampleSpacing 0 chooses it)" in errors[0], errors
    assert "OutputVolume" not in errors[0], errors
    _, figures, _, errors = run_with_errors(xyz, SampleSpacing=0.01, **settings)
    assert errors == [] and figures["MaterialVolume"][0] > 0
