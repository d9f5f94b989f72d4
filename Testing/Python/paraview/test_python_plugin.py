# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The ParaView Python plugin of the pip package (NarrowVolumePythonPlugin.py)
against the compiled plugin, in pvpython and in pvbatch under MPI.

The wheel that PipWheel built is installed as the README says for a
ParaView: `python3.X -m pip install --no-deps --target FOLDER` (the wheel's
file in place of the package's name), with the Python ParaView runs. Then
python_plugin_script.py records, in a pvpython of its own for each plugin,
what a user meets: the proxy and its properties (labels, defaults, domains,
groups, advanced flags, documentation), the outputs on a scan with the
defaults, progress, an abort and a bad input's error. Both records must be
the same, the outputs bit for bit.
"""
import glob
import json
import os
import shutil
import subprocess
import sys

import numpy as np
import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(HERE, "python_plugin_script.py")


@pytest.fixture(scope="module")
def work(tmp_path_factory):
    return tmp_path_factory.mktemp("python-plugin")


@pytest.fixture(scope="module")
def python_plugin(wheel_dir, work):
    """The Python plugin of the wheel, installed for this ParaView's Python."""
    wheels = sorted(glob.glob(os.path.join(wheel_dir, "narrowvolume-*-cp%d%d-*.whl" % sys.version_info[:2])))
    assert wheels, "no wheel for Python %d.%d in %s: PipWheel builds it" % (sys.version_info[:2] + (wheel_dir,))
    python = shutil.which("python%d.%d" % sys.version_info[:2])
    assert python, "no python%d.%d beside this ParaView" % sys.version_info[:2]
    target = os.path.join(work, "paraview-packages")
    subprocess.run([python, "-m", "pip", "install", "--no-deps", "--no-index", "--target", target, wheels[-1]],
                   check=True)
    plugin = os.path.join(target, "narrowvolume", "plugin", "NarrowVolumePythonPlugin.py")
    assert os.path.isfile(plugin)
    return plugin


@pytest.fixture(scope="module")
def cloud(scans_dir, trefoil, work):
    """A scan (the decimated armadillo) as a .vtp file; the trefoil without ../shared."""
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLPolyDataWriter
    import nvclouds
    if os.path.isfile(os.path.join(scans_dir, "armadillo_decimated.ply")):
        data = nvclouds.scan("armadillo_decimated", scans_dir)
    else:
        reader = vtkXMLPolyDataReader()
        reader.SetFileName(trefoil)
        reader.Update()
        data = reader.GetOutput()
    path = os.path.join(work, "cloud.vtp")
    writer = vtkXMLPolyDataWriter()
    writer.SetFileName(path)
    writer.SetDataModeToBinary()  # not Appended: Debian 12's VTK 9.2 reads that back empty
    writer.SetInputData(data)
    assert writer.Write()
    return path


def record(command, out, env=None):
    completed = subprocess.run(command, capture_output=True, text=True, env=env, timeout=600)
    print(completed.stdout[-2000:], completed.stderr[-4000:])
    assert completed.returncode == 0, "%s failed" % " ".join(command)
    arrays = np.load(out + ".npz")
    if not os.path.exists(out + ".json"):
        return None, arrays
    with open(out + ".json") as f:
        return json.load(f), arrays


def pvpython():
    return [sys.executable] if "pvpython" in os.path.basename(sys.executable) else [shutil.which("pvpython")]


@pytest.fixture(scope="module")
def records(python_plugin, plugin_path, cloud, work):
    """(compiled plugin's record, Python plugin's record), each (json, arrays)."""
    out = {}
    for mode, plugin in (("compiled", plugin_path), ("python", python_plugin)):
        base = os.path.join(work, mode)
        out[mode] = record(pvpython() + ["--force-offscreen-rendering", SCRIPT, mode, plugin, cloud, base], base)
    return out["compiled"], out["python"]


def test_paraview_plugin_option(python_plugin):
    """`narrowvolume --paraview-plugin` prints the plugin's absolute path and nothing else."""
    env = dict(os.environ, PYTHONPATH=os.path.dirname(os.path.dirname(os.path.dirname(python_plugin))))
    completed = subprocess.run(pvpython() + ["-m", "narrowvolume", "--paraview-plugin"], capture_output=True,
                               text=True, env=env, timeout=120)
    assert completed.returncode == 0, completed.stderr
    assert completed.stdout == os.path.abspath(python_plugin) + "\n"


def test_same_proxy(records):
    """The same proxy: name, label, group, menu, the outputs Volume and Surface, the property groups."""
    (compiled, _), (python, _) = records
    assert python["proxy"] == compiled["proxy"]
    assert python["proxy"]["outputs"] == ["Volume", "Surface"]
    assert ["ShowInMenu", "Point Interpolation", None] in python["proxy"]["hints"]


def test_same_properties(records):
    """The same properties with the same labels, defaults, domains, advanced flags and documentation."""
    (compiled, _), (python, _) = records
    assert sorted(python["properties"]) == sorted(compiled["properties"])
    for name, described in compiled["properties"].items():
        assert python["properties"][name] == described, name


def test_outputs_bit_identical(records):
    """With the defaults, phi to the bit and the same triangles (points, connectivity)."""
    (compiled, c), (python, p) = records
    assert c["phi"].size > 0 and len(c["triangles"]) > 0
    for name in ("dimensions", "phi", "points", "triangles"):
        assert np.array_equal(p[name], c[name]), name
    assert python["field_data"] == compiled["field_data"]


def test_grid_used(records):
    """The grid of the run as the panel shows it, one text ("322 x 305 x
    171"), and as pvpython's shell.GridDimensionsUsed, three integers: the
    Volume's dimensions, alike in both plugins."""
    (compiled, c), (python, _) = records
    text, dimensions = compiled.get("grid_used") or ("", [])
    assert dimensions == [int(n) for n in c["dimensions"]] and text == " x ".join(str(n) for n in dimensions)
    assert python.get("grid_used") == compiled["grid_used"]


def test_progress_abort_and_errors(records):
    """Progress from 0 to 1 in many steps, never back; an abort empties the
    outputs and the next run is whole; a NaN point gives the filter's error."""
    (compiled, _), (python, _) = records
    progress = python["progress"]
    assert len(progress) >= 10 and progress[-1] == 1.0
    assert all(b >= a for a, b in zip(progress, progress[1:]))
    assert python["abort"]["volume points"] == 0 and python["abort"]["surface points"] == 0
    assert python["abort"]["after"] > 0 and python["abort"] == compiled["abort"]
    errors = python["bad input"]["errors"]
    assert len(errors) == 1 and "non-finite coordinate" in errors[0]
    assert errors[0] in compiled["bad input"]["errors"][0]
    assert python["bad input"]["surface points"] == 0


def test_a_part_with_placed_drain_holes(records):
    """DrainHolePositions, a list property, set in pvpython on both plugins
    (ParaView sets it point by point on the algorithm, the Python one's
    too): the same part, with the hole made."""
    (compiled, _), (python, _) = records
    assert compiled["part"] == {"DrainHoles": 1.0, "KeptCavities": 1.0, "positions": [0.5, 0.0, 0.0]}
    assert python["part"] == compiled["part"]


def test_framing_alike(records):
    """The client's behaviours (NarrowVolumeClientBehaviors.cxx and
    _paraview_client.py) in pvpython: a cloud of points far from the origin,
    which draws nothing, then the filter's outputs shown as Apply shows them:
    the camera on the shell and the cloud as Point Gaussian discs, alike in
    both plugins."""
    (compiled, _), (python, _) = records
    assert compiled["framing"] == {"cloud representation": "Point Gaussian", "focal point near the shell": True}
    assert python["framing"] == compiled["framing"]


@pytest.mark.mpi
def test_readers_open_each_format(python_plugin, work):
    """The Python plugin's readers, as File > Open picks them by extension:
    .xyz text, PCD (ascii, binary, binary_compressed), LAS, and LAZ and E57
    where laspy and pye57 import (InstallScanModules installs them): the
    points, one vertex each, PCD's colours as "Colors"."""
    import nvpointfiles
    rng = np.random.default_rng(11)
    xyz = rng.random((50, 3)) * [3.0, 2.0, 1.0]
    files = {}
    text = os.path.join(work, "cloud.xyz")
    np.savetxt(text, xyz, fmt="%.17g", header="x y z")
    files[text] = xyz
    rgb = (rng.integers(0, 256, (50, 3)) * [65536, 256, 1]).sum(axis=1).astype(np.uint32).view(np.float32)
    fields = [("x", "F", 4, 1), ("y", "F", 4, 1), ("z", "F", 4, 1), ("rgb", "F", 4, 1), ("_", "U", 1, 4)]
    for data in ("ascii", "binary", "binary_compressed"):
        path = os.path.join(work, "cloud_%s.pcd" % data)
        nvpointfiles.write_pcd(path, fields, {"x": xyz[:, 0], "y": xyz[:, 1], "z": xyz[:, 2], "rgb": rgb}, data)
        files[path] = xyz.astype(np.float32).astype(np.float64)
    expected = {p: dict(v, reader="PointCloudTextReader" if p.endswith(".xyz") else "PCDPointCloudReader")
                for p, v in ((p, {"xyz": x}) for p, x in files.items())}
    # LAS with the C++ parser (narrowvolume._core.read_las): no module needed.
    las = os.path.join(work, "cloud.las")
    nvpointfiles.write_las(las, 4, 1, xyz)
    expected[las] = {"xyz": None, "reader": "LASPointCloudReader"}
    try:
        import laspy  # in pvpython's Python: InstallScanModules's HOME
        import pye57
        header = laspy.LasHeader(point_format=1, version="1.2")
        header.scales, header.offsets = [1e-4] * 3, [0.0] * 3
        compressed = laspy.LasData(header)
        compressed.x, compressed.y, compressed.z = xyz.T
        laz = os.path.join(work, "cloud.laz")
        compressed.write(laz)
        expected[laz] = {"xyz": None, "reader": "LAZPointCloudReader"}
        e57_path = os.path.join(work, "cloud.e57")
        e57 = pye57.E57(e57_path, mode="w")
        e57.write_scan_raw({"cartesianX": xyz[:, 0], "cartesianY": xyz[:, 1], "cartesianZ": xyz[:, 2]})
        e57.close()
        expected[e57_path] = {"xyz": None, "reader": "E57PointCloudReader"}
    except ImportError as error:
        print("laspy or pye57 does not import here (%s): LAZ and E57 are not tried" % error)
    listing = os.path.join(work, "files.json")
    with open(listing, "w") as f:
        json.dump(sorted(expected), f)
    base = os.path.join(work, "readers")
    completed = subprocess.run(pvpython() + ["--force-offscreen-rendering", SCRIPT, "python", python_plugin, listing,
                                             base], capture_output=True, text=True, timeout=600)
    print(completed.stdout[-3000:], completed.stderr[-3000:])
    assert completed.returncode == 0
    with open(base + ".json") as f:
        opened = json.load(f)
    for path, wanted in expected.items():
        got = opened[path]
        assert got is not None, path
        assert got["reader"] == wanted["reader"], path
        assert got["vertices"] == got["points"] == 50, path
        if wanted["xyz"] is not None:
            assert np.array_equal(np.array(got["xyz"]), wanted["xyz"]), path
        if path.endswith(".pcd"):
            assert got["arrays"] == ["Colors"], path
        if path.endswith((".las", ".laz", ".e57")):  # stored in 1e-3, 1e-4 and single precision
            assert np.abs(np.array(got["xyz"]) - xyz).max() <= 0.0005 + 1e-12, path


@pytest.mark.gui
def test_gui(python_plugin, trefoil, with_xvfb):
    """The real client under Xvfb with the Python plugin, as gui_script.py
    drives the compiled one (test_gui.py): the panel's defaults give the
    shell, both outputs show beside the points, ParaView's filters run on
    the Volume output, the panel shows what the run chose, and a view that
    drew nothing frames the shell."""
    import test_gui
    result, screenshot = test_gui.run_gui(python_plugin, trefoil, with_xvfb, NV_MEND_GETARGSPEC="1")
    assert result.get("ok"), "script ran through: %s" % result.get("error")
    assert result.get("label") == "Narrow Volume Reconstruction"
    assert result.get("offset_default") == 0.0 and result.get("offset_used", 0.0) > 0.0
    assert result.get("surface_cells", 0) > 10000 and result.get("volume_points", 0) > 100000
    assert result.get("cloud_visible") and result.get("cloud_pixels", 0) > 500
    for name in test_gui.DOWNSTREAM:
        assert result["downstream_" + name]["points"] > 0, name
    assert os.path.getsize(screenshot) > 0
    test_gui.test_panel_shows_what_the_run_chose((result, screenshot))
    test_gui.test_camera_framed_where_the_cloud_drew_nothing(test_gui.run_gui(
        python_plugin, trefoil, with_xvfb, NV_MEND_GETARGSPEC="1", NV_POINTS_PLY=test_gui.points_ply(trefoil)))


@pytest.mark.mpi
def test_mpi_same_as_one_rank(python_plugin, cloud, work, records):
    """Under mpiexec -n 2 pvbatch --symmetric: the pieces hold the one-rank
    result bit for bit; a source that gives each rank its own share is refused
    with the error that names the compiled plugin."""
    mpiexec, pvbatch = shutil.which("mpiexec"), shutil.which("pvbatch")
    if not mpiexec or not pvbatch:
        pytest.skip("no mpiexec or pvbatch")
    base = os.path.join(work, "mpi")
    command = [mpiexec, "-n", "2"]
    if os.geteuid() == 0:
        command += ["--allow-run-as-root", "--oversubscribe"]
    # pvpython may itself be an MPI singleton: its Open MPI variables must not reach mpiexec.
    env = {k: v for k, v in os.environ.items() if not k.startswith(("OMPI_", "PMIX_", "OPAL_", "PMI_"))}
    _, arrays = record(command + [pvbatch, "--symmetric", SCRIPT, "python", python_plugin, cloud, base, "mpi"], base,
                       env)
    _, one_rank = records[1]
    for name in ("dimensions", "phi", "points", "triangles"):
        assert np.array_equal(arrays[name], one_rank[name]), name
    assert arrays["shares_surface_points"][0] == 0 and arrays["shares_errors"][0] >= 1
    with open(base + ".txt") as f:
        assert "compiled plugin" in f.read()
