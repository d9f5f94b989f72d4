# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The Python readers the plugin loads (NarrowVolumeScanReaders.py): LAZ
through laspy and lazrs, E57 through pye57, on files laspy and pye57 write
here.

- Without the modules, each reader's error gives the pip command that
  installs them (InstallScanModules ran that very command to set this test
  up); with them:
- LAZ in every point format 0-10: the LAZ Point Cloud Reader gives laspy's
  values, in double precision, with the arrays of the LAS reader; the same
  points written uncompressed by laspy read identically with the C++ LAS
  reader (an independent writer), and laspy reads our own LAS writer's files
  as the LAS test expects them (an independent reader);
- E57 with two scans, one of them moved by its pose: every point in the
  file's coordinates, Intensity, Colors, ScanIndex;
- ParaView picks these readers for .laz and .e57, and damaged files give an
  error, not a traceback.
The reading checks skip when the modules are not installed and could not be
(ctest: skipped).

    pvpython -m pytest test_scan_readers.py --plugin PLUGIN
"""
import os
import shutil
import subprocess
import sys
import types

import numpy as np
import pytest
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkCommand

from narrowvolume import vtkLASPointCloudReader
import nvclouds
import nvpointfiles as pf
import nvtesting

pytestmark = pytest.mark.readers


@pytest.fixture(scope="module")
def readers(pvs):
    """The plugin's Python readers (NarrowVolumeScanReaders, loaded with the plugin)."""
    import NarrowVolumeScanReaders
    return NarrowVolumeScanReaders


# 1. Without the modules: the error says how to install them. A child
# process where importing them fails whatever is installed.
CHILD = """
import sys
sys.modules["laspy"] = None
sys.modules["pye57"] = None
import paraview.simple as pvs
from paraview import servermanager
pvs.LoadPlugin(%r, ns={})
import NarrowVolumeScanReaders as readers
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.vtkConstants import VTK_STRING
from vtkmodules.vtkCommonCore import vtkCommand
for reader in (readers.LAZPointCloudReader(), readers.E57PointCloudReader()):
    reader.SetFileName(%r)
    errors = []
    reader.AddObserver(vtkCommand.ErrorEvent, calldata_type(VTK_STRING)(lambda c, e, m: errors.append(m)))
    reader.GetExecutive().AddObserver(vtkCommand.ErrorEvent, lambda c, e: None)
    reader.Update()
    print("MESSAGE:", errors[0] if errors else "(none)")
"""


def test_without_the_modules_the_error_gives_the_pip_command(plugin_path, readers):
    run = subprocess.run([shutil.which("pvpython") or "pvpython", "-c", CHILD % (plugin_path, plugin_path)],
                         capture_output=True, text=True, timeout=120)
    messages = [line[len("MESSAGE: "):] for line in run.stdout.splitlines() if line.startswith("MESSAGE: ")]
    laz_command = readers.install_command("laspy[lazrs]")
    e57_command = readers.install_command("pye57")
    print("without laspy:", messages[0] if messages else nvtesting.explain(run))
    assert len(messages) == 2 and laz_command in messages[0] and "laspy and lazrs" in messages[0], \
        "without laspy the LAZ reader says: %s" % laz_command
    assert len(messages) == 2 and e57_command in messages[1], "without pye57 the E57 reader says: %s" % e57_command
    assert "-m pip install --user" in laz_command and laz_command.startswith(
        os.path.join(sys.base_prefix, "bin", "python")), "the command runs ParaView's own Python: %s" % laz_command


@pytest.fixture(scope="module")
def modules(readers):
    """laspy and pye57, or the test skipped (they did not import, and
    InstallScanModules could not install them)."""
    try:
        import laspy
        import pye57
        laspy.LazBackend.detect_available()[0]
    except (ImportError, IndexError) as error:
        pytest.skip("skipped the reading checks: laspy, lazrs and pye57 do not import (%s); install them with %s "
                    "and %s" % (error, readers.install_command("laspy[lazrs]"), readers.install_command("pye57")))
    print("laspy %s with %s, pye57 from %s" % (laspy.__version__, laspy.LazBackend.detect_available()[0],
                                              os.path.dirname(pye57.__file__)))
    return types.SimpleNamespace(laspy=laspy, pye57=pye57)


def caught(reader):
    errors = []
    reader.AddObserver(vtkCommand.ErrorEvent, lambda c, e: errors.append(e))
    reader.GetExecutive().AddObserver(vtkCommand.ErrorEvent, lambda c, e: errors.append(e))
    return errors


def read_with(reader_class, path):
    reader = reader_class()
    errors = caught(reader)
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutputDataObject(0), errors


CENTRE = np.array([500123.4567, 4001234.5678, 312.25])
XYZ = nvclouds.sphere_points(400, 50.0, CENTRE)
FORMATS = range(11)
QUARTER = np.array([np.cos(np.pi / 4), 0.0, 0.0, np.sin(np.pi / 4)])  # w, x, y, z


@pytest.fixture(scope="module")
def files(modules):
    """The files laspy and pye57 write, from one random generator in this
    order: LAZ (and the same points as LAS) in every point format, then E57
    with two scans, the second translated and rotated 90 degrees about z by
    its pose."""
    laspy, pye57 = modules.laspy, modules.pye57
    folder = nvtesting.scratch_folder(prefix="nv-scan-")
    rng = np.random.default_rng(5)
    written = types.SimpleNamespace(folder=folder, laz={})
    for point_format in FORMATS:
        header = laspy.LasHeader(point_format=point_format,
                                 version="1.4" if point_format >= 6 else ("1.3" if point_format >= 4 else "1.2"))
        header.scales = [0.001, 0.001, 0.001]
        header.offsets = [500000.0, 4000000.0, 0.0]
        las = laspy.LasData(header)
        las.x, las.y, las.z = XYZ[:, 0], XYZ[:, 1], XYZ[:, 2]
        las.intensity = rng.integers(0, 65536, len(XYZ))
        las.classification = rng.integers(0, 32 if point_format < 6 else 256, len(XYZ))
        names = set(las.point_format.dimension_names)
        if "red" in names:
            las.red, las.green, las.blue = (rng.integers(0, 65536, len(XYZ)) for _ in range(3))
        if "gps_time" in names:
            las.gps_time = 1e8 + rng.random(len(XYZ))
        if "nir" in names:
            las.nir = rng.integers(0, 65536, len(XYZ))
        laz_path = os.path.join(folder, "format%d.laz" % point_format)
        las_path = os.path.join(folder, "format%d.las" % point_format)
        las.write(laz_path)
        las.write(las_path)
        written.laz[point_format] = (laz_path, las_path, names)
    written.e57 = os.path.join(folder, "two-scans.e57")
    written.first = nvclouds.sphere_points(300, 0.5)
    written.second = nvclouds.sphere_points(200, 0.25)
    written.intensity = [rng.random(300).astype(np.float32), rng.random(200).astype(np.float32)]
    written.colours = [rng.integers(0, 256, (300, 3)), rng.integers(0, 256, (200, 3))]
    e57 = pye57.E57(written.e57, mode="w")
    for points, values, rgb, pose in ((written.first, written.intensity[0], written.colours[0], None),
                                      (written.second, written.intensity[1], written.colours[1], QUARTER)):
        data = {"cartesianX": points[:, 0], "cartesianY": points[:, 1], "cartesianZ": points[:, 2],
                "intensity": values, "colorRed": rgb[:, 0].astype(np.uint8), "colorGreen": rgb[:, 1].astype(np.uint8),
                "colorBlue": rgb[:, 2].astype(np.uint8)}
        if pose is None:
            e57.write_scan_raw(data)
        else:
            e57.write_scan_raw(data, rotation=pose, translation=np.array([10.0, 20.0, 30.0]))
    e57.close()
    return written


# 2. LAZ in every point format, written by laspy.
@pytest.mark.parametrize("point_format", FORMATS)
def test_laz_point_format(modules, readers, files, point_format):
    laz_path, las_path, names = files.laz[point_format]
    truth = modules.laspy.read(laz_path)
    label = "LAZ format %d" % point_format
    cloud, errors = read_with(readers.LAZPointCloudReader, laz_path)
    assert not errors and cloud.GetNumberOfPoints() == len(XYZ) and cloud.GetNumberOfVerts() == len(XYZ), \
        "%s: %d points as vertices (%s)" % (label, len(XYZ), errors)
    got = vtk_to_numpy(cloud.GetPoints().GetData())
    assert got.dtype == np.float64 and np.array_equal(got, np.c_[truth.x, truth.y, truth.z]), \
        "%s: laspy's coordinates, in double precision" % label
    assert np.array_equal(pf.array(cloud, "Intensity"), np.asarray(truth.intensity)), "%s: Intensity" % label
    assert np.array_equal(pf.array(cloud, "Classification"), np.asarray(truth.classification)), \
        "%s: Classification" % label
    if "gps_time" in names:
        assert np.array_equal(pf.array(cloud, "GpsTime"), np.asarray(truth.gps_time)), "%s: GpsTime" % label
    if "red" in names:
        assert np.array_equal(pf.array(cloud, "Colors"), np.c_[truth.red, truth.green, truth.blue] >> 8), \
            "%s: Colors" % label
    # The C++ reader on laspy's uncompressed file: the same arrays, the same values.
    native, errors = pf.read(vtkLASPointCloudReader, las_path)[1:]
    native_pd, laz_pd = native.GetPointData(), cloud.GetPointData()
    native_names = sorted(native_pd.GetArrayName(i) for i in range(native_pd.GetNumberOfArrays()))
    laz_names = sorted(laz_pd.GetArrayName(i) for i in range(laz_pd.GetNumberOfArrays()))
    assert not errors and native_names == laz_names, "%s: the LAS reader's arrays (%s vs %s)" % (
        label, native_names, laz_names)
    assert np.array_equal(vtk_to_numpy(native.GetPoints().GetData()), got) and all(
        np.array_equal(pf.array(native, name), pf.array(cloud, name)) for name in set(native_names) & set(laz_names)), \
        "%s: laspy's .las through the C++ reader gives the same cloud" % label


OURS = [(0, 1), (2, 3), (3, 5), (4, 6), (4, 10)]


@pytest.mark.parametrize("minor, point_format", OURS, ids=["1.%d-format%d" % pair for pair in OURS])
def test_laspy_reads_our_las_files(modules, files, minor, point_format):
    """Our LAS writer's files (those of the LAS test) read by laspy: its values are ours."""
    path = os.path.join(files.folder, "ours-1%d-%d.las" % (minor, point_format))
    expected = pf.write_las(path, minor, point_format, XYZ, (0.001,) * 3, (500000.0, 4000000.0, 0.0),
                            seed=point_format, extra_bytes=3, with_vlr=True)
    theirs = modules.laspy.read(path)
    ok = np.allclose(np.c_[theirs.x, theirs.y, theirs.z], expected["xyz"], rtol=0, atol=1e-9) and \
        np.array_equal(theirs.intensity, expected["Intensity"]) and \
        np.array_equal(theirs.classification, expected["Classification"]) and \
        np.array_equal(theirs.return_number, expected["ReturnNumber"])
    assert ok, "laspy reads our LAS 1.%d format %d file as the LAS test expects it" % (minor, point_format)


# 3. E57: two scans, the second translated and rotated 90 degrees about z by its pose.
def test_e57_two_scans(readers, files):
    cloud, errors = read_with(readers.E57PointCloudReader, files.e57)
    moved = files.second @ np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]).T + [10.0, 20.0, 30.0]
    assert not errors and cloud.GetNumberOfPoints() == 500 and cloud.GetNumberOfVerts() == 500, \
        "E57: both scans' 500 points as vertices (%s)" % errors
    got = vtk_to_numpy(cloud.GetPoints().GetData())
    # 1e-6: the pose goes through pye57's quaternion arithmetic (1.5e-8 off
    # here); a pose not applied would be off by 10 or more.
    assert np.abs(got - np.r_[files.first, moved]).max() < 1e-6, \
        "E57: the second scan moved by its pose (max error %g)" % np.abs(got - np.r_[files.first, moved]).max()
    assert np.array_equal(pf.array(cloud, "ScanIndex"), np.r_[np.zeros(300), np.ones(200)]), "E57: ScanIndex"
    assert np.allclose(pf.array(cloud, "Intensity"), np.r_[files.intensity[0], files.intensity[1]], atol=1e-6), \
        "E57: Intensity"
    assert np.array_equal(pf.array(cloud, "Colors"), np.r_[files.colours[0], files.colours[1]]) and \
        cloud.GetPointData().GetScalars().GetName() == "Colors", "E57: Colors as the scalars"


# 4. ParaView picks the readers by extension; damaged files give an error.
@pytest.mark.parametrize("kind, name", [("laz", "LAZPointCloudReader"), ("e57", "E57PointCloudReader")],
                         ids=["laz", "e57"])
def test_paraview_picks_the_reader(pvs, files, kind, name):
    path = files.laz[3][0] if kind == "laz" else files.e57
    opened = pvs.OpenDataFile(path)
    assert opened is not None and opened.GetXMLName() == name, "OpenDataFile(%s) uses %s" % (
        os.path.basename(path), name)
    opened.UpdatePipeline()
    assert opened.GetDataInformation().GetNumberOfPoints() > 0, "%s through the proxy: points" % name


@pytest.mark.parametrize("name", ["cut.laz", "cut.e57"])
def test_half_a_file(readers, files, name):
    reader_class, source = ((readers.LAZPointCloudReader, files.laz[6][0]) if name == "cut.laz" else
                            (readers.E57PointCloudReader, files.e57))
    content = open(source, "rb").read()
    path = os.path.join(files.folder, name)
    with open(path, "wb") as f:
        f.write(content[:len(content) // 2])
    cloud, errors = read_with(reader_class, path)
    assert errors and cloud.GetNumberOfPoints() == 0, "%s (half the file): an error, no points" % name
