# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""narrowvolume: reconstruct the narrow volume (thick shell) around a point cloud file.

    narrowvolume scan.ply -o shell.stl
    narrowvolume scan.xyz --offset-distance 0.02 --sample-spacing 0.005 -o shell.vtp -o phi.vti
    pvpython -m narrowvolume scan.ply -o shell.stl      (the CMake build's package)

The cloud: any file VTK reads as a point set (by extension: .vtp .vtu .vts
.vtk .ply .stl .obj .pts, and their parallel .pvtp .pvtu; a .ply is checked
before VTK reads it), plain-text clouds .xyz .txt .csv (x y z in the first
three columns), LiDAR .las and .laz, PCL's .pcd, and .e57 scans (.las and
.pcd with the C++ readers' parsers; .laz and .e57 through the Python
modules laspy with lazrs, and pye57: an error names the pip package a file
needs when its module is missing). Each output is
written by its extension: .stl, .vtp or .ply the surface, .vti the volume (VTK
XML files in Binary mode). Every property of the filter is an option, with the
filter's default. Exit status: 0 done, 1 the run or a file failed (the message
says why), 2 a wrong command line, 130 interrupted (Ctrl-C).
"""
from __future__ import annotations

import argparse
import os
import signal
import sys
import threading
import time
import warnings
from typing import TYPE_CHECKING, Any, Dict, List, Optional

from . import _properties

if TYPE_CHECKING:
    from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPointSet, vtkPolyData  # noqa: F401

# Readers by extension: (module of vtkmodules, class).
READERS = {
    ".vtp": ("vtkIOXML", "vtkXMLPolyDataReader"),
    ".vtu": ("vtkIOXML", "vtkXMLUnstructuredGridReader"),
    ".vts": ("vtkIOXML", "vtkXMLStructuredGridReader"),
    ".pvtp": ("vtkIOParallelXML", "vtkXMLPPolyDataReader"),
    ".pvtu": ("vtkIOParallelXML", "vtkXMLPUnstructuredGridReader"),
    ".vtk": ("vtkIOLegacy", "vtkDataSetReader"),
    ".ply": ("vtkIOPLY", "vtkPLYReader"),
    ".stl": ("vtkIOGeometry", "vtkSTLReader"),
    ".obj": ("vtkIOGeometry", "vtkOBJReader"),
    ".pts": ("vtkIOGeometry", "vtkPTSReader"),
}
TEXT = (".xyz", ".txt", ".csv")
# Clouds the project's readers read: the CMake build's C++ readers (.las,
# .pcd), else the wheel's binding of their parsers (.las and .pcd:
# narrowvolume._core), and the ParaView plugin's Python readers' functions
# (.laz through laspy, .e57 through pye57).
SCANS = (".las", ".laz", ".pcd", ".e57")
CLOUDS = sorted(set(READERS) | set(TEXT) | set(SCANS))
# Writers by extension: (module, class, which output, binary file).
WRITERS = {
    ".stl": ("vtkIOGeometry", "vtkSTLWriter", "surface"),
    ".ply": ("vtkIOPLY", "vtkPLYWriter", "surface"),
    ".vtp": ("vtkIOXML", "vtkXMLPolyDataWriter", "surface"),
    ".vti": ("vtkIOXML", "vtkXMLImageDataWriter", "volume"),
}


class Failure(Exception):
    """A file that cannot be read or written: the message says which and why."""


def _vtk_class(module, name):
    import importlib
    return getattr(importlib.import_module("vtkmodules." + module), name)


def _errors_of(algorithm, event="ErrorEvent"):
    """Collects the error (or warning) messages of a VTK algorithm instead of
    printing them."""
    from vtkmodules.util.misc import calldata_type
    from vtkmodules.util.vtkConstants import VTK_STRING

    errors = []
    # VTK hands over None for a message that is not valid UTF-8 (a line of
    # binary bytes quoted in it).
    algorithm.AddObserver(event, calldata_type(VTK_STRING)(lambda caller, event, text: errors.append(
        text if text is not None else "(a message with bytes that are not text)")))
    return errors


def _read_text(path):
    """A plain-text cloud's points as a vtkPolyData: the wheel's parser
    (narrowvolume._core.read_text_cloud, Readers/Formats/nvTextCloud.cxx).
    The CMake build's package reads these files with vtkPointCloudTextReader
    instead."""
    from . import _core
    from ._reconstruct import point_cloud
    try:
        return point_cloud(_core.read_text_cloud(path))
    except ValueError as error:  # the line that is not a point, named
        raise Failure(str(error))


def _named(path, message):
    """A reader's message, with the file's name in front unless it names it already."""
    return message if path in message else "%s: %s" % (path, message)


def _read_scan(path, extension):
    """.las and .pcd with the parsers of the C++ readers
    (narrowvolume._core.read_las and read_pcd), .laz and .e57 through laspy
    and pye57 (the ParaView plugin's Python readers' functions): what the
    pip package reads without C++ readers, and the CMake build's package for
    .laz and .e57."""
    from . import _scanreaders
    if extension in (".las", ".pcd"):
        from . import _core
        try:
            return _scanreaders.point_cloud(*(_core.read_las if extension == ".las" else _core.read_pcd)(path))
        except ValueError as error:  # the parser's sentence, naming the file
            raise Failure(_named(path, str(error)))
    try:
        return (_scanreaders.read_e57 if extension == ".e57" else _scanreaders.read_laz)(path)
    except _scanreaders.MissingModule as error:
        raise Failure("%s: %s" % (path, error))
    except Exception as error:  # the modules' own errors on a damaged file
        raise Failure("%s: cannot read it: %s: %s" % (path, type(error).__name__, error))


def _check_ply(path):
    """The pip package's check of a .ply file before vtk's vtkPLYReader
    reads it (nv::ply::CheckFile, which the CMake build's
    vtkPLYPointCloudReader runs itself)."""
    from . import _core
    problem = _core.check_ply_file(path)
    if problem:
        raise Failure("%s: %s." % (path, problem))


def read_cloud(path: str) -> vtkPointSet:
    """The point set of a cloud file."""
    if not os.path.isfile(path):
        raise Failure("%s: no such file" % path)
    extension = os.path.splitext(path)[1].lower()
    import narrowvolume

    # The CMake build's package has the project's C++ readers (None in the wheel).
    ours = {".las": narrowvolume.vtkLASPointCloudReader, ".pcd": narrowvolume.vtkPCDPointCloudReader,
            ".ply": narrowvolume.vtkPLYPointCloudReader}
    if extension in TEXT or (extension == ".pts" and narrowvolume.vtkPointCloudTextReader is not None):
        if narrowvolume.vtkPointCloudTextReader is None:
            return _read_text(path)
        reader = narrowvolume.vtkPointCloudTextReader()
    elif ours.get(extension) is not None:
        reader = ours[extension]()
    elif extension in SCANS:
        cloud = _read_scan(path, extension)
        if cloud.GetNumberOfPoints() == 0:
            raise Failure("%s: holds no points" % path)
        return cloud
    elif extension in READERS:
        if extension == ".ply":
            _check_ply(path)
        reader = _vtk_class(*READERS[extension])()
    else:
        raise Failure("%s: unknown cloud format %r; known: %s" % (path, extension, " ".join(CLOUDS)))
    reader.SetFileName(path)
    from ._reconstruct import _message_of

    errors = _errors_of(reader)
    warnings = _errors_of(reader, "WarningEvent")  # vtkPLYReader reports an unreadable file as a warning
    _errors_of(reader.GetExecutive())  # a failed request's dump of the pipeline: the reader's error says why
    reader.Update()
    data = reader.GetOutputDataObject(0)
    if errors:
        raise Failure(_named(path, _message_of(errors[-1])))
    if warnings and (data is None or data.GetNumberOfPoints() == 0):
        raise Failure(_named(path, _message_of(warnings[-1])))
    from vtkmodules.vtkCommonDataModel import vtkPointSet
    if not isinstance(data, vtkPointSet):
        raise Failure("%s: holds a %s, not a point set" % (path, data.GetClassName() if data else "nothing"))
    if data.GetNumberOfPoints() == 0:
        raise Failure("%s: holds no points" % path)
    return data


def write(path: str, volume: vtkImageData, surface: vtkPolyData) -> str:
    """Writes the volume or the surface, by the file's extension."""
    module, name, which = WRITERS[os.path.splitext(path)[1].lower()]
    writer = _vtk_class(module, name)()
    writer.SetFileName(path)
    writer.SetInputData(volume if which == "volume" else surface)
    if hasattr(writer, "SetDataModeToBinary"):
        writer.SetDataModeToBinary()  # not Appended: see the README
    if hasattr(writer, "SetFileTypeToBinary"):
        writer.SetFileTypeToBinary()
    errors = _errors_of(writer)
    if not writer.Write() or errors:
        raise Failure("%s: cannot write it%s" % (path, (": " + errors[-1].strip()) if errors else ""))
    return which


def _stdout():
    """Standard output. pvpython replaces sys.stdout by VTK's capture, which
    keeps what it is given until the process ends when standard output is a
    pipe or a file (flush does not reach it): there the command's lines go to
    the stream Python opened, so that they come as the run goes."""
    if type(sys.stdout).__name__ == "vtkPythonStdStreamCaptureHelper" and sys.__stdout__ is not None:
        return sys.__stdout__
    return sys.stdout


class Progress:
    """A progress bar on a terminal (standard error); nothing elsewhere."""

    def __init__(self, stream, enabled):
        self.stream = stream
        self.enabled = enabled
        self.shown = -1

    def __call__(self, fraction):
        percent = int(100 * fraction)
        if self.enabled and percent != self.shown:
            self.shown = percent
            bar = "#" * (percent // 4)
            self.stream.write("\rnarrowvolume: [%-25s] %3d %%" % (bar, percent))
            self.stream.flush()

    def done(self):
        if self.enabled and self.shown >= 0:
            self.stream.write("\n")
            self.stream.flush()


def _option(prop):
    return _properties.option(prop.name)


def _choice_type(prop):
    names = {_properties.snake_case(suffix).replace("_", "-"): value for _, suffix, value, _ in prop.choices}

    def parse(text):
        if text.lower() in names:
            return names[text.lower()]
        try:
            return int(text)
        except ValueError:
            raise argparse.ArgumentTypeError("%r: one of %s" % (text, ", ".join(
                "%s (%d)" % item for item in names.items())))
    return parse, names


PYTHON_PLUGIN = os.path.join(os.path.dirname(os.path.abspath(__file__)), "plugin", "NarrowVolumePythonPlugin.py")


class _PrintPythonPlugin(argparse.Action):
    """--paraview-plugin: the absolute path of the ParaView Python plugin, and nothing else."""

    def __init__(self, option_strings, dest, **kwargs):
        super().__init__(option_strings, dest, nargs=0, default=argparse.SUPPRESS, **kwargs)

    def __call__(self, parser, namespace, values, option_string=None):
        if not os.path.isfile(PYTHON_PLUGIN):
            parser.exit(1, "narrowvolume: error: this package is the CMake build's (pvpython's), which has no "
                           "Python plugin: load its compiled plugin, NarrowVolume%s, in ParaView\n" % (
                               ".dll" if os.name == "nt" else ".so"))
        print(PYTHON_PLUGIN)
        parser.exit(0)


def default_text(prop: Any, value: Any) -> str:
    """A default as the option takes it: an enumerated one by its name."""
    for _, suffix, number, _ in prop.choices:
        if number == value:
            return _properties.snake_case(suffix).replace("_", "-")
    return str(value)


def in_option_words(text: str) -> str:
    """A message of the filter with the properties' names as the command
    line's options (OffsetDistance -> --offset-distance)."""
    return _properties.in_words(text, _properties.option)


def chosen(volume: vtkImageData) -> str:
    """What the run chose: the offset, the spacing and their ratio, the grid, the band."""
    field = volume.GetFieldData()

    def value(name):
        array = field.GetArray(name)
        return array.GetValue(0) if array is not None and array.GetNumberOfTuples() else 0

    offset, spacing = value("OffsetDistance"), value("SampleSpacing")
    return "offset distance %.6g, spacing %.6g (offset / spacing %.2f), grid %d x %d x %d, %d band nodes" % (
        (offset, spacing, offset / spacing if spacing else 0.0) + tuple(volume.GetDimensions())
        + (int(value("NarrowBandNodes")),))


def scaled(cloud, factor: float):
    """The cloud with its coordinates multiplied by factor (--scale), as doubles."""
    import numpy as np
    from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
    from vtkmodules.vtkCommonCore import vtkPoints
    if cloud.GetPoints() is None:
        return cloud
    xyz = factor * vtk_to_numpy(cloud.GetPoints().GetData()).astype(np.float64)
    points = vtkPoints()
    points.SetData(numpy_to_vtk(np.ascontiguousarray(xyz), deep=1))
    cloud.SetPoints(points)
    return cloud


def part(volume: vtkImageData) -> str:
    """The part to print, in one line (WallThickness above 0), else ""."""
    field = volume.GetFieldData()
    if field.GetArray("MaterialVolume") is None:
        return ""

    def value(name, component=0):
        return field.GetArray(name).GetComponent(0, component)

    bounds = [value("PartBounds", c) for c in range(6)]
    kept, removed, holes = int(value("KeptCavities")), int(value("RemovedCavities")), int(value("DrainHoles"))
    return ("part to print: %.6g x %.6g x %.6g, wall %.6g (at least %.6g measured), material %.6g, "
            "%d %s kept (%.6g), %d smaller than %.6g merged into the wall%s" % (
                bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4], value("WallThickness"),
                value("MinimumWallThickness"), value("MaterialVolume"), kept, "cavity" if kept == 1 else "cavities",
                value("CavityVolume"), removed, value("MinimumCavityVolume"),
                ", %d drain %s" % (holes, "hole" if holes == 1 else "holes") if holes else ""))


def scan_surface(volume: vtkImageData) -> str:
    """The scan surface (Sheets SCAN_SURFACE), in one line, else ""."""
    field = volume.GetFieldData()
    if field.GetArray("ScanSurface") is None:
        return ""

    def value(name):
        return field.GetArray(name).GetValue(0)

    closed, opened = int(value("ScanSurfacePieces")), int(value("ScanSurfaceOpenPieces"))
    if closed + opened == 0:
        return "scan surface: empty"
    return "scan surface: %d closed %s (volume %.6g), %d open %s; the points %.3g cells from it on average, " \
        "95 %% within %.3g" % (closed, "piece" if closed == 1 else "pieces", value("ScanSurfaceVolume"), opened,
                                "piece" if opened == 1 else "pieces", value("ScanDistanceMean"),
                                value("ScanDistance95"))


def timings(volume: vtkImageData) -> str:
    """The seconds of the run's stages (field data StageSeconds), one line each."""
    array = volume.GetFieldData().GetArray("StageSeconds")
    if array is None or array.GetNumberOfTuples() == 0:
        return ""
    stages = [(array.GetComponentName(c), array.GetComponent(0, c)) for c in range(array.GetNumberOfComponents())]
    width = max(len(name) for name, _ in stages)
    total = sum(seconds for _, seconds in stages)
    lines = ["narrowvolume:   %s %9s %6s" % ("stage".ljust(width), "seconds", "share")]
    for name, seconds in stages:
        lines.append("narrowvolume:   %s %9.3f %5.1f%%" % (name.ljust(width), seconds,
                                                          100.0 * seconds / total if total else 0.0))
    lines.append("narrowvolume:   %s %9.3f" % ("(stages)".ljust(width), total))
    return "\n".join(lines)


def make_parser(defaults: Dict[str, Any]) -> argparse.ArgumentParser:
    """The command line's parser; `defaults`: the filter's {property: default}."""
    parser = argparse.ArgumentParser(
        prog="narrowvolume", description=__doc__.split("\n")[0],
        epilog="Outputs by extension: .stl .ply .vtp (surface), .vti (volume). Clouds: %s." % " ".join(CLOUDS))
    parser.add_argument("--paraview-plugin", action=_PrintPythonPlugin,
                        help="print the path of the ParaView Python plugin (load it in ParaView) and exit")
    from ._version import __version__
    parser.add_argument("--version", action="version", version="narrowvolume %s" % __version__)
    parser.add_argument("cloud", help="the point cloud file")
    parser.add_argument("-o", "--output", action="append", default=[], metavar="FILE",
                        help="a file to write (repeat for several); default: CLOUD's name with _shell.stl, or "
                             "_part.stl with --wall-thickness")
    parser.add_argument("--scale", type=float, default=1.0, metavar="FACTOR",
                        help="multiply the cloud's coordinates by FACTOR before the run, about the origin: to "
                             "print size first (0.1: a model in millimetres at 1:10); the outputs are at that size")
    parser.add_argument("-q", "--quiet", action="store_true", help="no progress bar and no summary")
    parser.add_argument("--timings", action="store_true",
                        help="print the seconds of the run's stages (field data StageSeconds) in the summary")
    group = parser.add_argument_group("the filter's properties (vtkNarrowVolumeReconstruction)")
    for prop in _properties.PROPERTIES:
        help_text = "%s (default: %s)" % (_properties.describe(prop, _properties.option).replace("%", "%%"),
                                          default_text(prop, defaults[prop.name]))
        if prop.kind is bool:
            group.add_argument(_option(prop), dest=prop.name, action=argparse.BooleanOptionalAction,
                               default=None, help=help_text)
        elif prop.choices:
            parse, names = _choice_type(prop)
            group.add_argument(_option(prop), dest=prop.name, type=parse, default=None,
                               metavar="{%s}" % ",".join(names), help=help_text)
        else:
            group.add_argument(_option(prop), dest=prop.name, type=prop.kind, default=None,
                               metavar=prop.kind.__name__.upper(), help=help_text)
        for listed in _properties.LIST_PROPERTIES:
            if listed.after == prop.name:
                help_text = ("%s Repeat the option for each point; the coordinates are the cloud file's, "
                             "multiplied by --scale with it." % _properties.describe(listed, _properties.option))
                group.add_argument(_option(listed), dest=listed.name, type=float, nargs=3, action="append",
                                   default=None, metavar=("X", "Y", "Z"), help=help_text.replace("%", "%%"))
    return parser


def main(argv: Optional[List[str]] = None) -> int:
    """Runs the command line; returns the exit status."""
    import narrowvolume

    if threading.current_thread() is threading.main_thread():
        # Ctrl-C as Python's KeyboardInterrupt, which stops the run (pvpython
        # leaves SIGINT to ParaView's logger, which ends the process with a stack trace).
        signal.signal(signal.SIGINT, signal.default_int_handler)
    defaults = _properties.defaults_of(narrowvolume.vtkNarrowVolumeReconstruction())
    parser = make_parser(defaults)
    args = parser.parse_args(argv)
    outputs = args.output or [os.path.splitext(os.path.basename(args.cloud))[0] +
                              ("_part.stl" if (args.WallThickness or 0.0) > 0.0 else "_shell.stl")]
    for path in outputs:
        if os.path.splitext(path)[1].lower() not in WRITERS:
            parser.error("%s: unknown output format; known: %s" % (path, " ".join(sorted(WRITERS))))
    if not (args.scale > 0.0 and args.scale < float("inf")):
        parser.error("--scale must be a finite factor above 0, not %s" % args.scale)
    properties = {p.name: getattr(args, p.name) for p in _properties.PROPERTIES + _properties.LIST_PROPERTIES
                  if getattr(args, p.name) is not None}
    for listed in _properties.LIST_PROPERTIES:  # points, at the cloud's scale
        if listed.name in properties:
            properties[listed.name] = [[args.scale * x for x in point] for point in properties[listed.name]]
    # File descriptor 2 itself: pvpython's sys.stderr answers isatty() for standard input.
    progress = Progress(sys.stderr, not args.quiet and os.isatty(2))
    start = time.perf_counter()
    started = []  # output files begun
    try:
        cloud = read_cloud(args.cloud)
        if args.scale != 1.0:
            cloud = scaled(cloud, args.scale)
        if not args.quiet:
            print("narrowvolume: %d points from %s" % (cloud.GetNumberOfPoints(), args.cloud), file=_stdout(),
                  flush=True)
        import warnings
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always", narrowvolume.ReconstructionWarning)
            try:
                volume, surface = narrowvolume.reconstruct(cloud, progress=progress, **properties)
            finally:
                progress.done()
        for warning in caught:
            print("narrowvolume: warning: %s" % in_option_words(str(warning.message)), file=sys.stderr)
        if not args.quiet:
            print("narrowvolume: %s" % chosen(volume), file=_stdout(), flush=True)
            for printed in (part(volume), scan_surface(volume)):
                if printed:
                    print("narrowvolume: %s" % printed, file=_stdout(), flush=True)
        if args.timings:
            print(timings(volume), file=_stdout(), flush=True)
        empty = [p for p in outputs if WRITERS[os.path.splitext(p)[1].lower()][2] == "surface"
                 and surface.GetNumberOfPolys() == 0]
        if empty:
            raise Failure("the surface is empty (see the warning above); nothing written to %s" % ", ".join(empty))
        written = []
        for path in outputs:
            started.append(path)
            written.append((path, write(path, volume, surface)))
    except (Failure, narrowvolume.ReconstructionError) as failure:
        print("narrowvolume: error: %s" % in_option_words(str(failure)), file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        # Python sees Ctrl-C when a writer returns: no output of an interrupted command stays.
        for path in started:
            if os.path.exists(path):
                os.remove(path)
        print("narrowvolume: interrupted", file=sys.stderr)
        return 130
    if not args.quiet:
        dims = volume.GetDimensions()
        for path, which in written:
            what = ("%d x %d x %d grid" % dims) if which == "volume" else ("%d triangles" % surface.GetNumberOfPolys())
            print("narrowvolume: wrote %s (%s)" % (path, what), file=_stdout())
        print("narrowvolume: done in %.2f s" % (time.perf_counter() - start), file=_stdout(), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
