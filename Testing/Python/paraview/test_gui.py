# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The real ParaView client under Xvfb: loads the plugin, opens the demo
cloud, applies Narrow Volume Reconstruction with the panel's defaults and
shows both outputs; the screenshot must show the shell, and the panel's
read-only properties the offset, spacing and grid the run chose. A PLY of
points (no cells, so it draws nothing) far from the origin gets a view of
its own: after its shell is shown as Apply shows it, the camera frames it. The Volume's grid is
declared in the information pass, before the run, and ParaView's Slice,
Clip, Threshold, Contour, Resample To Image and Plot Over Line applied to the
Volume output (of a run at twice the spacing: the claim does not depend on
the grid) give points and cells.

    pvpython -m pytest test_gui.py --plugin PLUGIN [--trefoil CLOUD] [--with-xvfb WITH_XVFB]
"""
import json
import os
import subprocess

import numpy as np
import pytest
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

import nvtesting

pytestmark = [pytest.mark.gui, pytest.mark.slow]
DOWNSTREAM = ("Slice", "Clip", "Threshold", "Contour", "ResampleToImage", "PlotOverLine")
# ParaView 6.1 as Debian builds it (VTK 9.6 with Viskores and TBB,
# assertions on) aborts in the level-of-detail filter of its render views
# (vtkmLevelOfDetail, always used there when built in) on flat data: the bins
# of a zero-length side make NaN cluster ids. A view whose geometry passes the
# LOD threshold (the shell here) and that shows a Slice kills the client, with
# or without the plugin. Where a flat mesh makes that filter abort, the view
# gets a LOD threshold beyond its data, as the README advises users; where
# the filter is absent or works, ParaView's defaults stay.
PROBE_LOD = """try:
    from vtkmodules.vtkAcceleratorsVTKmFilters import vtkmLevelOfDetail
except ImportError:
    print("absent")
    raise SystemExit(0)
from vtkmodules.vtkFiltersSources import vtkPlaneSource
from vtkmodules.vtkFiltersCore import vtkTriangleFilter
plane = vtkPlaneSource()  # in the plane x = 0
plane.SetOrigin(0, 0, 0)
plane.SetPoint1(0, 1, 0)
plane.SetPoint2(0, 0, 1)
plane.SetResolution(50, 50)
triangles = vtkTriangleFilter()
triangles.SetInputConnection(plane.GetOutputPort())
lod = vtkmLevelOfDetail()
lod.SetInputConnection(triangles.GetOutputPort())
lod.SetNumberOfDivisions(64, 64, 64)
lod.Update()
print("ok")
"""


@pytest.fixture(scope="module")
def gui(plugin_path, trefoil, with_xvfb):
    """The client's run of gui_script.py: what it saw (its JSON), and the screenshot's path."""
    return run_gui(plugin_path, trefoil, with_xvfb)


@pytest.fixture(scope="module")
def gui_ply(plugin_path, trefoil, with_xvfb):
    """The client's run of gui_script.py on a PLY of points (no cells) far from the origin."""
    return run_gui(plugin_path, trefoil, with_xvfb, NV_POINTS_PLY=points_ply(trefoil))


def points_ply(cloud):
    """The cloud's points as a PLY file without cells (as scanners write
    them), scaled by 50 and moved 500 units from the origin, where a camera
    framed on nothing does not see them. Its path."""
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkPolyData
    from vtkmodules.vtkIOPLY import vtkPLYWriter
    from vtkmodules.util.numpy_support import numpy_to_vtk
    import nvclouds
    xyz = nvclouds.points_of_file(cloud) * 50.0 + np.array([500.0, 0.0, 0.0])
    points = vtkPoints()
    points.SetData(numpy_to_vtk(xyz, deep=True))
    data = vtkPolyData()
    data.SetPoints(points)
    path = os.path.join(nvtesting.scratch_folder(prefix="nv-gui-ply-"), "points.ply")
    writer = vtkPLYWriter()
    writer.SetFileName(path)
    writer.SetInputData(data)
    writer.Write()
    return path


def run_gui(plugin_path, trefoil, with_xvfb, **environment):
    """Runs gui_script.py in the real client with the plugin (the compiled
    one, or the Python plugin's file; `environment`: more variables for the
    script): (what it saw, the screenshot's path)."""
    folder = nvtesting.scratch_folder(prefix="nv-gui-")
    env = dict(os.environ, NV_PLUGIN=plugin_path, NV_CLOUD=trefoil, NV_SCREENSHOT=os.path.join(folder, "gui.png"),
               NV_GUI_RESULT=os.path.join(folder, "result.json"), NV_FORCE_XVFB="1", **environment)
    script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "gui_script.py")
    probe = os.path.join(folder, "probe_lod.py")
    with open(probe, "w") as f:
        f.write(PROBE_LOD)
    lod_run = subprocess.run(["pvpython", probe], capture_output=True, text=True, timeout=120)
    if lod_run.stdout.strip().endswith(("ok", "absent")):
        print("vtkmLevelOfDetail on flat data: %s" % lod_run.stdout.strip().split()[-1])
    elif lod_run.returncode < 0 or lod_run.returncode == 134:
        print("vtkmLevelOfDetail on flat data: aborts (ParaView's bug), the view's LOD threshold is raised")
        env["NV_NO_LOD"] = "1"
    else:
        print("vtkmLevelOfDetail probe did not run: %s" % nvtesting.explain(lod_run))
    # --dr: the default settings, not the user's. It also keeps the welcome dialog
    # away, which ParaView 6 opens (modal, waiting for a click) while the script's
    # filter reports progress.
    run = subprocess.run([with_xvfb, "paraview", "--dr", "--script=" + script], env=env, capture_output=True,
                         text=True, timeout=300)
    assert os.path.exists(env["NV_GUI_RESULT"]), "the client ran the script: %s" % nvtesting.explain(run)
    result = json.load(open(env["NV_GUI_RESULT"]))
    print(json.dumps(result, indent=1))
    return result, env["NV_SCREENSHOT"]


def test_the_script_ran_through(gui):
    result = gui[0]
    assert result.get("ok"), "script ran through: %s" % result.get("error")
    assert result.get("label") == "Narrow Volume Reconstruction", "filter label"


def test_the_automatic_offset(gui):
    result = gui[0]
    assert result.get("offset_default") == 0.0, "offset default 0: automatic (%s)" % result.get("offset_default")
    extent = result.get("cloud_extent", 0.0)
    print("GUI: offset used %s, slider %s, cloud's largest side %s, cloud pixels %s" % (
        result.get("offset_used"), result.get("offset_slider"), extent, result.get("cloud_pixels")))
    assert 0.0 < result.get("offset_used", 0.0) < 0.05 * extent, "the automatic offset follows the sampling"
    slider = result.get("offset_slider") or [1.0, 0.0]
    assert slider[0] == 0.0 and slider[1] > 5.0 * result.get("offset_used", 1e9), \
        "the offset slider reaches well beyond the automatic offset: %s" % slider


def test_outputs_and_points_shown(gui):
    result = gui[0]
    assert result.get("cloud_pixels", 0) > 500, \
        "the input points are drawn after Apply (%s pixels)" % result.get("cloud_pixels")
    assert result.get("surface_cells", 0) > 10000, "surface computed with the panel's defaults"
    assert result.get("volume_points", 0) > 100000, "volume computed"
    assert result.get("cloud_visible"), "the input points stay visible"


def test_panel_shows_what_the_run_chose(gui):
    """The read-only properties beside Offset Distance, Closing Radius and
    Sample Spacing show the values of the run, as field data has them."""
    result = gui[0]
    panel, field = result.get("panel_used") or {}, result.get("field_used") or {}
    print("panel: %s; field data: %s; volume dimensions %s" % (panel, field, result.get("volume_dimensions")))
    for name in ("OffsetDistance", "SampleSpacing", "ClosingRadius"):
        assert panel.get(name + "Used", 0.0) > 0.0 and panel.get(name + "Used") == pytest.approx(field.get(name)), \
            "the panel's %sUsed is the run's %s" % (name, name)
    assert panel.get("GridDimensionsUsed") == result.get("volume_dimensions"), "the grid of scripts is the volume's"


def test_panel_shows_the_grid_in_one_field(gui):
    """The panel shows the grid the run chose as one read-only text,
    "221 x 260 x 200", which fits its default width (three fields of their
    own did not): of the information properties it draws, one holds the
    grid, with one element; the three integers stay for scripts
    (shell.GridDimensionsUsed), off the panel."""
    result = gui[0]
    shown = result.get("panel_information") or {}
    print("read-only values the panel draws: %s; hidden from it: %s" % (shown, result.get("panel_hidden")))
    grid = {name: facts for name, facts in shown.items() if "Grid" in name}
    assert list(grid) == ["GridUsed"] and grid["GridUsed"][:2] == ["vtkSMStringVectorProperty", 1], \
        "the panel draws the grid as one read-only text field: %s" % grid
    assert (result.get("panel_used") or {}).get("GridUsed") == " x ".join(
        str(n) for n in result.get("volume_dimensions") or ()), "the panel's grid text is the volume's"
    assert set(shown) == {"OffsetDistanceUsed", "ClosingRadiusUsed", "SampleSpacingUsed", "GridUsed",
                          "PartSizeUsed"}, \
        "the panel's read-only values: %s" % sorted(shown)


def test_camera_framed_where_the_cloud_drew_nothing(gui_ply):
    """A PLY of points draws nothing, so its view keeps an empty framing;
    after the filter's outputs are shown as Apply shows them, the shell is
    in the picture, and the cloud shows as points (Point Gaussian)."""
    result = gui_ply[0]
    assert result.get("ok"), "script ran through: %s" % result.get("error")
    print("PLY cloud: %s cells, %s pixels drawn; its shell: %s triangles, %s pixels drawn (of 120000)" % (
        result.get("ply_cloud_cells"), result.get("ply_cloud_pixels"), result.get("ply_shell_cells"),
        result.get("ply_shell_pixels")))
    # (the orientation axes in the corner draw about 100 pixels)
    assert result.get("ply_cloud_cells") == 0 and result.get("ply_cloud_pixels", 1e6) < 0.005 * 400 * 300, \
        "the PLY cloud has no cells and draws nothing"
    assert result.get("ply_shell_cells", 0) > 10000, "the shell of the PLY cloud was computed"
    assert result.get("ply_shell_pixels", 0) > 0.05 * 400 * 300, "the camera frames the shell"
    print("the PLY cloud after: %s, %s pixels drawn" % (result.get("ply_cloud_representation"),
                                                       result.get("ply_cloud_pixels_after")))
    assert result.get("ply_cloud_representation") == "Point Gaussian" and \
        result.get("ply_cloud_pixels_after", 0) > 0.02 * 400 * 300, "the cloud shows as points"


def test_information_pass(gui):
    """The information pass declared the grid the run produced."""
    result = gui[0]
    declared = result.get("info_whole_extent")
    assert declared is not None and declared[::2] == [0, 0, 0] and min(declared[1::2]) > 10 and \
        result.get("points_before_run") == 0, "the information pass declares a grid before the run: %s" % (declared,)
    assert declared == result.get("volume_extent"), "the run's extent is the declared one: %s" % (
        result.get("volume_extent"))


@pytest.mark.parametrize("name", DOWNSTREAM)
def test_paraview_filter_on_the_volume(gui, name):
    """ParaView's filters applied to the Volume output."""
    counts = gui[0].get("downstream_" + name) or {}
    phi_range = counts.get("phi_range") or [2.0, -2.0]  # phi missing: fails the range check
    print("%s on the Volume (grid %s): %s points, %s cells, phi in %s" % (
        name, gui[0].get("downstream_grid"), counts.get("points"), counts.get("cells"), phi_range))
    assert counts.get("points", 0) > 0 and counts.get("cells", 0) > 0, "%s on the Volume: points and cells" % name
    assert -1.0 <= phi_range[0] <= phi_range[1] <= 1.0, "%s on the Volume: phi in [-1, 1]" % name


def test_threshold_keeps_phi_at_least_0(gui):
    assert ((gui[0].get("downstream_Threshold") or {}).get("phi_range") or [-1])[0] >= 0.0, \
        "Threshold on the Volume: phi >= 0"


def test_screenshot(gui):
    png = vtkPNGReader()
    png.SetFileName(gui[1])
    png.Update()
    image = vtk_to_numpy(png.GetOutput().GetPointData().GetScalars())[:, :3].astype(int)
    background = np.median(image, axis=0)
    content = np.abs(image - background).sum(axis=1) > 60
    orange = (image[:, 0] > image[:, 2] + 40)  # the shell's colour
    print("screenshot: %.1f %% content, %.1f %% shell-coloured" % (100 * content.mean(), 100 * orange.mean()))
    assert content.mean() > 0.05, "the screenshot has content"
    assert orange.mean() > 0.02, "the shell is in the picture"


START_SCRIPT = """import json, os
from paraview import servermanager
definitions = servermanager.ProxyManager().SMProxyManager.GetProxyDefinitionManager()
json.dump({"filter": bool(definitions.HasDefinition("filters", "NarrowVolumeReconstruction")),
           "laz_reader": bool(definitions.HasDefinition("sources", "LAZPointCloudReader"))},
          open(os.environ["NV_START_RESULT"], "w"))
os._exit(0)
"""


def test_start_with_pv_plugin_path(plugin_path, with_xvfb):
    """ParaView started with PV_PLUGIN_PATH naming the plugin's folder loads
    the filter and the Python readers, and prints no Python traceback (the
    readers sit in a folder ParaView does not load by itself)."""
    folder = nvtesting.scratch_folder(prefix="nv-gui-start-")
    script = os.path.join(folder, "start.py")
    with open(script, "w") as f:
        f.write(START_SCRIPT)
    env = dict(os.environ, PV_PLUGIN_PATH=os.path.dirname(plugin_path), NV_FORCE_XVFB="1",
               NV_START_RESULT=os.path.join(folder, "start.json"))
    run = subprocess.run([with_xvfb, "paraview", "--dr", "--script=" + script], env=env, capture_output=True,
                         text=True, timeout=300)
    output = run.stdout + run.stderr
    assert os.path.exists(env["NV_START_RESULT"]), "the client ran the script: %s" % nvtesting.explain(run)
    loaded = json.load(open(env["NV_START_RESULT"]))
    print("PV_PLUGIN_PATH start: %s; output: %r" % (loaded, output.strip()[-500:]))
    assert "Traceback" not in output, "no Python traceback at start: %s" % output
    assert loaded == {"filter": True, "laz_reader": True}, "the filter and the Python readers are loaded"
