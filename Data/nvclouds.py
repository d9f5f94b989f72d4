# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The point clouds the tests, the benchmarks and the doc pictures share,
in one place (Data/, outside Testing: each puts this folder on sys.path).

- Synthetic: `sphere_points(n)`, n points spread evenly on a sphere (a
  Fibonacci lattice); the paper's Table 1 shapes sampled h apart
  (`shape_points`, from nvshapes.py, which also holds their exact offset
  surfaces); the Fig. 6 noisy spheres (`fig6_spheres`); the demo cloud's
  trefoil tube with N points scattered at random (`trefoil_tube`, from
  make_demo_cloud.py beside this file).
- The files in Data/ (`data_file`: the demo cloud Data/trefoil.vtp).
- The real scans of ../shared/data/scans by name (`scan`, `scan_points`),
  read where they are, never copied; `ScansMissing` (a LookupError whose
  message says where they were looked for) when ../shared is not beside the
  source tree. $NV_SCANS_DIR, or a `folder` argument, points elsewhere.

`cloud(xyz)` makes a vtkPolyData of points. The tests reach this module
through the fixtures of Testing/Python/conftest.py, the benchmarks through
benchmarks/clouds.py, the pictures through doc/pictures/nvpictures.py. It
needs numpy, and VTK's Python modules to read files or make VTK data, not
ParaView (the pip wheel's tests import it too).
"""
import math
import os

import numpy as np

import nvshapes

DATA_DIR = os.path.dirname(os.path.abspath(__file__))
SOURCE_DIR = os.path.dirname(DATA_DIR)
SCANS_DIR = os.environ.get("NV_SCANS_DIR") or os.path.normpath(
    os.path.join(SOURCE_DIR, "..", "shared", "data", "scans"))
# The scans of ../shared/data/scans, each NAME.ply (and NAME.txt, its provenance).
SCANS = ("armadillo", "armadillo_decimated", "bunny", "bunny_rangescan_bun000", "demosthenes", "dragon", "teacup",
         "teapot")


class ScansMissing(LookupError):
    """A scan is not in its folder (../shared/data/scans is not beside the source tree)."""

    def __init__(self, folder):
        super().__init__("no scans in %s (../shared/data/scans is not beside the source tree)" % folder)
        self.folder = folder


# --- Synthetic clouds.

def sphere_points(n, radius=0.5, center=(0.0, 0.0, 0.0)):
    """n points spread evenly on a sphere (Fibonacci lattice), as an (n, 3) array."""
    i = np.arange(n) + 0.5
    polar = np.arccos(1.0 - 2.0 * i / n)
    azimuth = math.pi * (1.0 + 5.0 ** 0.5) * i
    unit = np.c_[np.cos(azimuth) * np.sin(polar), np.sin(azimuth) * np.sin(polar), np.cos(polar)]
    return unit * radius + np.asarray(center)


def shape_points(shape, spacing):
    """A Table 1 shape of nvshapes.SHAPES ("cube", "rotated cube", "sphere",
    "cylinder") sampled about `spacing` apart."""
    return nvshapes.SHAPES[shape]["points"](spacing)


FIG5_POINTS = 2964  # the paper's sphere (Fig. 5)
FIG6_NOISE = (0.05, 0.10)


def fig6_spheres(spacing=0.01, radius=0.5):
    """The paper's Fig. 6 noisy spheres, as [(points, noise, xyz)]: 2,964
    points (the paper's Fig. 5 density) and points `spacing` apart, each
    with 5 % and 10 % noise: every point's radius multiplied by 1 + a u, u
    uniform in [-1, 1] (seed 6 for each number of points, the 5 % cloud
    drawn first)."""
    spheres = []
    for points in (FIG5_POINTS, len(nvshapes.sphere_points(spacing, radius))):
        clean = nvshapes.sphere_points(spacing, radius, count=points)
        rng = np.random.default_rng(6)
        for noise in FIG6_NOISE:
            radial = (clean - nvshapes.CENTER) * (1.0 + noise * rng.uniform(-1.0, 1.0, len(clean)))[:, None]
            spheres.append((points, noise, nvshapes.CENTER + radial))
    return spheres


def trefoil_tube(n, **options):
    """n points scattered at random over the demo cloud's tube around a
    trefoil knot (Data/make_demo_cloud.py's trefoil_tube)."""
    import make_demo_cloud  # beside this file; imported when asked for (it loads VTK's writers)
    return make_demo_cloud.trefoil_tube(n, **options)


# --- Files.

def data_file(name):
    """The path of a file in Data/ (e.g. "trefoil.vtp", the demo cloud)."""
    return os.path.join(DATA_DIR, name)


def read(path):
    """The vtkPolyData of a .ply or .vtp file."""
    if path.endswith(".vtp"):
        from vtkmodules.vtkIOXML import vtkXMLPolyDataReader as Reader
    else:
        from vtkmodules.vtkIOPLY import vtkPLYReader as Reader
    reader = Reader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def points_of_file(path):
    """The points of a .ply or .vtp file, as an (n, 3) float array. Without
    VTK (a GPU machine's Python), a binary little-endian .ply is read with
    numpy (ply_points)."""
    try:
        from vtkmodules.util.numpy_support import vtk_to_numpy
    except ImportError:
        if path.endswith(".ply"):
            return ply_points(path)
        raise
    return vtk_to_numpy(read(path).GetPoints().GetData()).astype(float)


PLY_TYPES = {"char": "i1", "uchar": "u1", "short": "<i2", "ushort": "<u2", "int": "<i4", "uint": "<u4",
             "float": "<f4", "double": "<f8", "int8": "i1", "uint8": "u1", "int16": "<i2", "uint16": "<u2",
             "int32": "<i4", "uint32": "<u4", "float32": "<f4", "float64": "<f8"}


def ply_points(path):
    """x, y, z of the vertices of a binary little-endian .ply whose first
    element is the vertices, with scalar properties only (as the scans of
    ../shared), by numpy: for machines without VTK."""
    with open(path, "rb") as f:
        header = []
        while not header or header[-1] != "end_header":
            line = f.readline()
            if not line:
                raise ValueError("%s: no end_header" % path)
            header.append(line.decode("ascii").strip())
        if "format binary_little_endian 1.0" not in header:
            raise ValueError("%s: only binary little-endian PLY is read without VTK" % path)
        count, fields = None, []
        for line in header:
            words = line.split()
            if words[:2] == ["element", "vertex"]:
                count = int(words[2])
            elif words[:1] == ["element"] and count is not None:
                break
            elif words[:1] == ["property"] and count is not None:
                if words[1] == "list":
                    raise ValueError("%s: a list property among the vertices" % path)
                fields.append((words[2], PLY_TYPES[words[1]]))
        data = np.fromfile(f, dtype=np.dtype(fields), count=count)
    return np.stack([data["x"], data["y"], data["z"]], axis=1).astype(float)


def have_scans(names=SCANS, folder=None):
    """Whether every scan of `names` is in `folder` (default SCANS_DIR)."""
    return all(os.path.isfile(os.path.join(folder or SCANS_DIR, name + ".ply")) for name in names)


def scan_path(name, folder=None):
    """The path of the scan NAME.ply; ScansMissing when it is not there."""
    folder = folder or SCANS_DIR
    path = os.path.join(folder, name + ".ply")
    if not os.path.isfile(path):
        raise ScansMissing(folder)
    return path


def scan(name, folder=None):
    """The scan NAME as a vtkPolyData (its points, as the PLY file holds them)."""
    return read(scan_path(name, folder))


def scan_points(name, folder=None):
    """The scan NAME's points as an (n, 3) float array."""
    return points_of_file(scan_path(name, folder))


# --- As VTK data.

def cloud(xyz):
    """A vtkPolyData holding only points."""
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkPolyData
    points = vtkPoints()
    points.SetData(numpy_to_vtk(np.ascontiguousarray(xyz, dtype=float), deep=1))
    data = vtkPolyData()
    data.SetPoints(points)
    return data
