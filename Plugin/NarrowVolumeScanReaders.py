# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""NarrowVolume's Python readers for ParaView: LAZ (compressed LAS) through
laspy with its lazrs backend, and E57 (terrestrial scanners) through pye57.

The NarrowVolume plugin loads this file when ParaView loads the plugin (it
sits in python/ below NarrowVolume.so); it also loads on its own with
LoadPlugin(".../NarrowVolumeScanReaders.py"). laspy and pye57 are imported
only when a file is read: without them the readers are still listed, and
reading a file ends in an error that gives the pip command installing them
for this ParaView's Python. The command line of both packages reads these
files with read_laz and read_e57, importing this file as
narrowvolume._scanreaders.

Both readers give what the C++ readers give: a vtkPolyData with the points
in double precision and one vertex cell per point. LAZ files have the point
data arrays of vtkLASPointCloudReader (Intensity, Classification, ...,
Colors); E57 files Intensity and Colors when the scans have them, and
ScanIndex (which scan of the file each point comes from), every scan in the
file's common coordinate system (each scan's pose applied).
"""
import os
import sys
import sysconfig

import numpy as np

try:
    from paraview.util.vtkAlgorithm import VTKPythonAlgorithmBase, smdomain, smhint, smproperty, smproxy
except ImportError:
    # Without ParaView: the command line of the pip package reads .las, .laz
    # and .e57 files with read_laz and read_e57 (it imports this file as
    # narrowvolume._scanreaders); the reader classes below are then plain
    # classes that nothing registers.
    class _Undecorated:
        """ParaView's decorators as no-ops."""

        def __getattr__(self, name):
            return lambda *args, **kwargs: (lambda decorated: decorated)

    VTKPythonAlgorithmBase = object
    smdomain = smhint = smproperty = smproxy = _Undecorated()
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.util.vtkConstants import VTK_ID_TYPE
from vtkmodules.vtkCommonCore import vtkCommand, vtkOutputWindow, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData

paraview_plugin_name = "NarrowVolumeScanReaders"
paraview_plugin_version = "0.1.0"


class MissingModule(Exception):
    """A Python module a reader needs does not import here."""


def install_command(*requirements):
    """The pip command that installs `requirements` where this ParaView's
    Python finds them: the user's site-packages of the interpreter it embeds
    (pvpython and paraview run /usr/bin/python3.11's on Debian 12). Debian
    marks its Python externally managed, so pip wants
    --break-system-packages even for a --user install there."""
    if sys.prefix != sys.base_prefix:  # a virtual environment (the pip package's command line)
        return "%s -m pip install %s" % (sys.executable, " ".join("'%s'" % r for r in requirements))
    python = os.path.join(sys.base_prefix, "bin", "python%d.%d" % sys.version_info[:2])
    managed = os.path.exists(os.path.join(sysconfig.get_path("stdlib"), "EXTERNALLY-MANAGED"))
    return "%s -m pip install --user%s %s" % (python, " --break-system-packages" if managed else "",
                                              " ".join("'%s'" % r for r in requirements))


def import_laspy(compressed=True):
    """laspy, with a LAZ backend (lazrs or laszip) for `compressed` files."""
    try:
        import laspy
    except ImportError as error:
        raise MissingModule("reading .%s files needs the Python modules laspy and lazrs, which do not import "
                            "here (%s). Install them with: %s" % ("laz" if compressed else "las", error,
                                                                  install_command("laspy[lazrs]")))
    if compressed and not laspy.LazBackend.detect_available():
        raise MissingModule("laspy imports but has no LAZ backend to decompress with. Install lazrs with: %s"
                            % install_command("lazrs"))
    return laspy


def import_pye57():
    try:
        import pye57
    except ImportError as error:
        raise MissingModule("reading .e57 files needs the Python module pye57, which does not import here (%s). "
                            "Install it with: %s" % (error, install_command("pye57")))
    return pye57


def point_cloud(xyz, arrays, scalars=None):
    """A vtkPolyData: points `xyz` (n x 3, kept in double precision), one
    vertex cell per point, and the point data `arrays` (name -> numpy array
    of n values or n tuples); `scalars` names the active scalars."""
    xyz = np.ascontiguousarray(xyz, dtype=np.float64).reshape(-1, 3)
    n = len(xyz)
    cloud = vtkPolyData()
    points = vtkPoints()
    points.SetData(numpy_to_vtk(xyz, deep=1))
    cloud.SetPoints(points)
    ids = np.arange(n + 1, dtype=np.int64)
    cells = vtkCellArray()
    cells.SetData(numpy_to_vtk(ids, deep=1, array_type=VTK_ID_TYPE),
                  numpy_to_vtk(ids[:n].copy(), deep=1, array_type=VTK_ID_TYPE))
    cloud.SetVerts(cells)
    for name, values in arrays.items():
        array = numpy_to_vtk(np.ascontiguousarray(values), deep=1)
        array.SetName(name)
        if name == scalars:
            cloud.GetPointData().SetScalars(array)
        else:
            cloud.GetPointData().AddArray(array)
    return cloud


def read_laz(filename):
    """A .laz (or .las) file as a vtkPolyData with the arrays of
    vtkLASPointCloudReader."""
    laspy = import_laspy(compressed=not filename.lower().endswith(".las"))
    las = laspy.read(filename)
    point_format = las.header.point_format.id
    names = set(las.point_format.dimension_names)
    extended = point_format >= 6

    def u8(values):
        return np.asarray(values).astype(np.uint8)

    arrays = {
        "Intensity": np.asarray(las.intensity, dtype=np.uint16),
        "Classification": u8(las.classification),
        "ReturnNumber": u8(las.return_number),
        "NumberOfReturns": u8(las.number_of_returns),
        "ScanDirectionFlag": u8(las.scan_direction_flag),
        "EdgeOfFlightLine": u8(las.edge_of_flight_line),
        "UserData": u8(las.user_data),
        "PointSourceId": np.asarray(las.point_source_id, dtype=np.uint16),
    }
    # Bit 0 synthetic, 1 key-point, 2 withheld, 3 overlap (formats 6-10).
    flags = u8(las.synthetic) | (u8(las.key_point) << 1) | (u8(las.withheld) << 2)
    if extended:
        flags |= u8(las.overlap) << 3
        arrays["ScannerChannel"] = u8(las.scanner_channel)
        arrays["ScanAngle"] = (np.asarray(las.scan_angle, dtype=np.float64) * 0.006).astype(np.float32)
    else:
        arrays["ScanAngle"] = np.asarray(las.scan_angle_rank, dtype=np.float32)
    arrays["ClassificationFlags"] = flags
    if "gps_time" in names:
        arrays["GpsTime"] = np.asarray(las.gps_time, dtype=np.float64)
    if "nir" in names:
        arrays["NearInfrared"] = np.asarray(las.nir, dtype=np.uint16)
    scalars = None
    if {"red", "green", "blue"} <= names:
        rgb = np.c_[las.red, las.green, las.blue].astype(np.uint16)
        # 16-bit colours to 8 bits, unless the file stores 8-bit values (as the C++ reader).
        arrays["Colors"] = (rgb >> 8 if rgb.size and rgb.max() > 255 else rgb).astype(np.uint8)
        scalars = "Colors"
    xyz = np.c_[np.asarray(las.x, dtype=np.float64), np.asarray(las.y, dtype=np.float64),
                np.asarray(las.z, dtype=np.float64)]
    return point_cloud(xyz, arrays, scalars)


def read_e57(filename):
    """Every scan of an .e57 file, in the file's coordinate system, as one
    vtkPolyData with Intensity, Colors (when the scans have them) and
    ScanIndex."""
    pye57 = import_pye57()
    e57 = pye57.E57(filename)
    try:
        scans = [e57.read_scan(i, intensity=True, colors=True, ignore_missing_fields=True, transform=True)
                 for i in range(e57.scan_count)]
    finally:
        e57.close()
    if not scans:
        return point_cloud(np.zeros((0, 3)), {})
    xyz = np.concatenate([np.c_[s["cartesianX"], s["cartesianY"], s["cartesianZ"]] for s in scans])
    counts = [len(s["cartesianX"]) for s in scans]
    arrays = {"ScanIndex": np.repeat(np.arange(len(scans), dtype=np.int32), counts)}
    # A field some scans lack is 0 on their points.
    if any("intensity" in s for s in scans):
        arrays["Intensity"] = np.concatenate(
            [np.asarray(s.get("intensity", np.zeros(c)), dtype=np.float32) for s, c in zip(scans, counts)])
    scalars = None
    if any("colorRed" in s for s in scans):
        arrays["Colors"] = np.concatenate(
            [np.c_[s["colorRed"], s["colorGreen"], s["colorBlue"]].astype(np.uint8) if "colorRed" in s
             else np.zeros((c, 3), dtype=np.uint8) for s, c in zip(scans, counts)])
        scalars = "Colors"
    return point_cloud(xyz, arrays, scalars)


def report_error(algorithm, message):
    """As vtkErrorMacro does: to the algorithm's ErrorEvent observers if it
    has some, else to VTK's output window (ParaView's Output Messages)."""
    text = "%s: %s" % (type(algorithm).__name__, message)
    if algorithm.HasObserver(vtkCommand.ErrorEvent):
        algorithm.InvokeEvent(vtkCommand.ErrorEvent, text)
    else:
        vtkOutputWindow.GetInstance().DisplayErrorText("ERROR: %s\n" % text)


class ScanFileReader(VTKPythonAlgorithmBase):
    """A reader of one file into a vtkPolyData by `self.read(filename)`."""

    def __init__(self):
        VTKPythonAlgorithmBase.__init__(self, nInputPorts=0, nOutputPorts=1, outputType="vtkPolyData")
        self._filename = None

    def set_file_name(self, name):
        if name != self._filename:
            self._filename = name
            self.Modified()

    def RequestData(self, request, inInfo, outInfo):
        output = vtkPolyData.GetData(outInfo, 0)
        if not self._filename:
            report_error(self, "no file name is set.")
            return 0
        if not os.path.isfile(self._filename):
            report_error(self, "cannot open \"%s\": no such file." % self._filename)
            return 0
        try:
            cloud = self.read(self._filename)
        except MissingModule as error:
            report_error(self, str(error))
            return 0
        except Exception as error:  # the modules' own errors on a damaged file
            report_error(self, "cannot read \"%s\": %s: %s" % (self._filename, type(error).__name__, error))
            return 0
        output.ShallowCopy(cloud)
        return 1


@smproxy.reader(name="LAZPointCloudReader", label="LAZ Point Cloud Reader",
                extensions="laz", file_description="LAZ Point Clouds (compressed LAS, via laspy)")
class LAZPointCloudReader(ScanFileReader):
    """Reads LAZ (compressed LAS) files through laspy and lazrs, with the
    arrays of the LAS Point Cloud Reader."""

    @staticmethod
    def read(filename):
        return read_laz(filename)

    @smproperty.stringvector(name="FileName", panel_visibility="never")
    @smdomain.filelist()
    @smhint.filechooser(extensions="laz", file_description="LAZ Point Clouds")
    def SetFileName(self, name):
        self.set_file_name(name)


@smproxy.reader(name="E57PointCloudReader", label="E57 Point Cloud Reader",
                extensions="e57", file_description="E57 Point Clouds (terrestrial scans, via pye57)")
class E57PointCloudReader(ScanFileReader):
    """Reads every scan of an E57 file through pye57, in the file's
    coordinate system, with Intensity, Colors and ScanIndex."""

    @staticmethod
    def read(filename):
        return read_e57(filename)

    @smproperty.stringvector(name="FileName", panel_visibility="never")
    @smdomain.filelist()
    @smhint.filechooser(extensions="e57", file_description="E57 Point Clouds")
    def SetFileName(self, name):
        self.set_file_name(name)
