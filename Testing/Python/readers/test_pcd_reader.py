# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""vtkPCDPointCloudReader on files this test writes (nvpointfiles.py, from
PCL's description of the format): the same fields in ascii, binary and
binary_compressed (LZF by our own compressor, with and without padding
columns, and by liblzf itself when it is installed) read back value for
value, with their types and counts; packed colours and normals; organized
clouds with NaN holes; then damaged files, each of which must give its own
error, an empty output, and no large allocation."""
import os
import resource
import struct
import types

import numpy as np
import pytest
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.util.vtkConstants import (VTK_DOUBLE, VTK_FLOAT, VTK_LONG_LONG, VTK_SHORT, VTK_SIGNED_CHAR,
                                          VTK_UNSIGNED_CHAR, VTK_UNSIGNED_INT, VTK_UNSIGNED_LONG_LONG,
                                          VTK_UNSIGNED_SHORT)

from narrowvolume import vtkPCDPointCloudReader
import nvclouds
import nvpointfiles as pf
import nvtesting

pytestmark = pytest.mark.readers
n = 300
rng = np.random.default_rng(3)
xyz = nvclouds.sphere_points(n, 0.5, (1.0, -2.0, 3.0)).astype(np.float32)
rgb = rng.integers(0, 256, (n, 3))
alpha = np.where(np.arange(n) % 2 == 0, 255, 0)  # opaque colours are NaN as floats
packed = ((alpha << 24) | (rgb[:, 0] << 16) | (rgb[:, 1] << 8) | rgb[:, 2]).astype(np.uint32)
normals = (xyz - np.array([1.0, -2.0, 3.0], dtype=np.float32)) * 2
FIELDS = [("x", "F", 4, 1), ("y", "F", 4, 1), ("z", "F", 4, 1), ("_", "U", 1, 4), ("rgb", "F", 4, 1),
          ("normal_x", "F", 4, 1), ("normal_y", "F", 4, 1), ("normal_z", "F", 4, 1), ("intensity", "U", 2, 1),
          ("label", "U", 4, 1), ("curvature", "F", 8, 1), ("histogram", "F", 4, 5), ("ring", "I", 1, 1),
          ("stamp", "I", 8, 1), ("id", "U", 8, 1), ("offset16", "I", 2, 1)]
COLUMNS = {"x": xyz[:, 0], "y": xyz[:, 1], "z": xyz[:, 2], "rgb": packed.view(np.float32),
           "normal_x": normals[:, 0], "normal_y": normals[:, 1], "normal_z": normals[:, 2],
           "intensity": rng.integers(0, 65536, n), "label": np.full(n, 7),  # a constant: long LZF matches
           "curvature": rng.random(n) * 1e-3, "histogram": rng.random((n, 5)).astype(np.float32),
           "ring": rng.integers(-128, 128, n), "stamp": rng.integers(-2 ** 62, 2 ** 62, n),
           "id": rng.integers(0, 2 ** 63, n, dtype=np.uint64) * 2 + 1, "offset16": rng.integers(-32768, 32768, n)}
ARRAYS = {"intensity": VTK_UNSIGNED_SHORT, "label": VTK_UNSIGNED_INT, "curvature": VTK_DOUBLE,
          "histogram": VTK_FLOAT, "ring": VTK_SIGNED_CHAR, "stamp": VTK_LONG_LONG, "id": VTK_UNSIGNED_LONG_LONG,
          "offset16": VTK_SHORT}


# The organized cloud's NaN holes (drawn after the columns).
holes = rng.choice(n, 37, replace=False)


@pytest.fixture(scope="module")
def folder():
    return nvtesting.scratch_folder(prefix="nv-pcd-")


def check_cloud(label, cloud, errors, keep=None, components_of_colors=3):
    """The cloud holds the points `keep` (default all) of COLUMNS."""
    keep = np.arange(n) if keep is None else keep
    assert not errors and cloud.GetNumberOfPoints() == len(keep), "%s: %d points, no error (got %d, %s)" % (
        label, len(keep), cloud.GetNumberOfPoints(), errors)
    assert cloud.GetNumberOfVerts() == len(keep), "%s: one vertex cell per point" % label
    assert np.array_equal(vtk_to_numpy(cloud.GetPoints().GetData()), xyz[keep].astype(np.float64)), \
        "%s: coordinates" % label
    pd = cloud.GetPointData()
    names = {pd.GetArrayName(i) for i in range(pd.GetNumberOfArrays())}
    assert names == set(ARRAYS) | {"Colors", "Normals"}, "%s: arrays %s" % (label, sorted(names))
    for name, kind in ARRAYS.items():
        values = pd.GetArray(name)
        assert values is not None and values.GetDataType() == kind, "%s: %s of its type" % (label, name)
        expected = np.asarray(COLUMNS[name])[keep]
        assert np.array_equal(vtk_to_numpy(values), expected.astype(vtk_to_numpy(values).dtype)), \
            "%s: %s values" % (label, name)
    assert pd.GetArray("histogram").GetNumberOfComponents() == 5, "%s: COUNT 5 gives 5 components" % label
    colors = pd.GetScalars()
    rgba = np.c_[rgb, alpha][keep][:, :components_of_colors]
    assert colors is not None and colors.GetName() == "Colors" and np.array_equal(vtk_to_numpy(colors), rgba), \
        "%s: packed rgb as the Colors scalars" % label
    assert pd.GetNormals() is not None and np.array_equal(vtk_to_numpy(pd.GetNormals()), normals[keep]), \
        "%s: normal_x/y/z as the Normals" % label


def read(path, **settings):
    return pf.read(vtkPCDPointCloudReader, path, **settings)


# 1. The three encodings, and the variants of binary_compressed (the last
# with liblzf's own compressor, when liblzf is installed).
VARIANTS = [("ascii", {}), ("binary", {}), ("binary_compressed", {}),
            ("binary_compressed", {"padding_in_columns": False}),
            ("binary_compressed", {"compress": "liblzf", "padding_in_columns": False})]


def variant_label(data, options):
    return data + "".join(" " + ("liblzf" if k == "compress" else "without padding columns") for k in options)


@pytest.mark.parametrize("data, options", VARIANTS, ids=[variant_label(*v) for v in VARIANTS])
def test_encoding(folder, data, options):
    if options.get("compress") == "liblzf":
        liblzf = pf.liblzf_compress()
        if not liblzf:
            pytest.skip("liblzf is not installed: the cross-check against liblzf's own compressor is skipped")
        options = dict(options, compress=liblzf)
    label = variant_label(data, options)
    path = os.path.join(folder, label.replace(" ", "-") + ".pcd")
    pf.write_pcd(path, FIELDS, COLUMNS, data, **options)
    print("%-48s %7d bytes" % (label, os.path.getsize(path)))
    check_cloud(label, *read(path)[1:])


def test_lzf_long_overlapping_references():
    """The files above hold the constant "label" column, which LZF stores as a
    few long back references that overlap what they copy (a 4-byte pattern
    copied 264 bytes at a time): the decoder's hardest case."""
    label_column = np.full(n, 7, dtype=np.uint32).tobytes()
    assert len(pf.lzf_compress(label_column)) < len(label_column) / 50, \
        "the label column compresses to %d of %d bytes" % (len(pf.lzf_compress(label_column)), len(label_column))


# 2. An organized cloud (20 x 15) with NaN holes: skipped, or kept on demand.
@pytest.mark.parametrize("data", ["ascii", "binary", "binary_compressed"])
def test_organized_cloud_with_holes(folder, data):
    with_holes = dict(COLUMNS)
    with_holes["x"] = COLUMNS["x"].copy()
    with_holes["x"][holes] = np.nan
    path = os.path.join(folder, "organized-%s.pcd" % data)
    pf.write_pcd(path, FIELDS, with_holes, data, width=20, height=15)
    _, cloud, errors = read(path)
    kept = np.setdiff1d(np.arange(n), holes)
    assert cloud.GetNumberOfPoints() == n - 37 and not errors, "%s organized: the 37 NaN points skipped" % data
    assert np.array_equal(vtk_to_numpy(cloud.GetPointData().GetArray("intensity")), COLUMNS["intensity"][kept]), \
        "%s organized: the arrays follow the kept points" % data
    _, cloud, errors = read(path, SkipInvalidPoints=False)
    assert cloud.GetNumberOfPoints() == n and np.isnan(vtk_to_numpy(cloud.GetPoints().GetData())[holes, 0]).all(), \
        "%s organized: all 300 points with SkipInvalidPoints off" % data


# 3. rgba (4 components), double-precision coordinates, a header without
# COUNT, HEIGHT and POINTS, ascii colours written as floats (older PCL), no points.
def test_rgba(folder):
    rgba_fields = [("rgba", "U", 4, 1) if f[0] == "rgb" else f for f in FIELDS]
    rgba_columns = dict(COLUMNS, rgba=packed)
    path = os.path.join(folder, "rgba.pcd")
    pf.write_pcd(path, rgba_fields, rgba_columns, "binary")
    check_cloud("rgba", *read(path)[1:], components_of_colors=4)


def test_double_precision_coordinates(folder):
    double_fields = [(f[0], "F", 8, 1) if f[0] in "xyz" else f for f in FIELDS]
    path = os.path.join(folder, "double.pcd")
    pf.write_pcd(path, double_fields, COLUMNS, "binary_compressed")
    check_cloud("F8 coordinates", *read(path)[1:])


def test_minimal_header(folder):
    path = os.path.join(folder, "minimal.pcd")
    with open(path, "w") as f:
        f.write("FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 3\nDATA ascii\n0 0 0\n1 0 0\n0 1 0.5\n")
    _, cloud, errors = read(path)
    assert cloud.GetNumberOfPoints() == 3 and not errors and \
        vtk_to_numpy(cloud.GetPoints().GetData())[2].tolist() == [0, 1, 0.5], "a minimal header (no COUNT, POINTS)"


def test_ascii_rgb_written_as_floats(folder):
    opaque_free = dict(COLUMNS, rgb=(packed & 0x00FFFFFF).view(np.float32))  # alpha 0: small finite floats
    path = os.path.join(folder, "float-rgb.pcd")
    header = pf.pcd_header([("x", "F", 4, 1), ("y", "F", 4, 1), ("z", "F", 4, 1), ("rgb", "F", 4, 1)], n, 1, "ascii")
    with open(path, "wb") as f:
        f.write(header)
        for k in range(n):
            f.write(("%r %r %r %r\n" % (float(xyz[k, 0]), float(xyz[k, 1]), float(xyz[k, 2]),
                                        float(opaque_free["rgb"][k]))).encode())
    _, cloud, errors = read(path)
    assert not errors and np.array_equal(vtk_to_numpy(cloud.GetPointData().GetScalars()), rgb), \
        "ascii rgb written as floats (older PCL): the colours"


def test_no_points_and_can_read_file(folder):
    path = os.path.join(folder, "nothing.pcd")
    with open(path, "wb") as f:
        f.write(pf.pcd_header(FIELDS, 0, 1, "binary_compressed").rstrip(b"\n"))
    _, cloud, errors = read(path)
    assert cloud.GetNumberOfPoints() == 0 and not errors, "a PCD of no points: empty, no error (%s)" % errors
    binary = os.path.join(folder, "binary.pcd")
    pf.write_pcd(binary, FIELDS, COLUMNS, "binary")
    assert vtkPCDPointCloudReader().CanReadFile(binary) == 1, "CanReadFile on PCD"
    assert vtkPCDPointCloudReader().CanReadFile(os.path.join(folder, "nothing.pcd")) == 1, "CanReadFile on PCD"
    not_pcd = os.path.join(folder, "cloud.xyz")
    with open(not_pcd, "w") as f:
        f.write("0 0 0\n")
    assert vtkPCDPointCloudReader().CanReadFile(not_pcd) == 0, "CanReadFile on text: 0"


# 4. Damaged files: (label, file name, its content made from `f` (the
# small files' bytes and text, f.header(...): the small binary file's header
# with lines replaced, f.compressed(...): the small compressed file with its
# sizes or stream replaced), the error's words (or made from `f`)); a
# content of None: the file is missing.
DAMAGED = [
    ("empty file", "empty.pcd", lambda f: b"", "without a DATA line"),
    ("no DATA line", "nodata.pcd", lambda f: f.header(DATA=None), "without a DATA line"),
    ("unknown DATA", "kind.pcd", lambda f: f.header(DATA="DATA binary_lzma") .encode() + f.body,
     "is not ascii, binary or binary_compressed"),
    ("SIZE entries", "sizes.pcd", lambda f: f.header(SIZE="SIZE 4 4").encode() + f.body,
     "2 SIZE entries for 3 FIELDS"),
    ("SIZE 3", "size3.pcd", lambda f: f.header(SIZE="SIZE 4 3 4").encode() + f.body, "SIZE 3 of field y"),
    ("TYPE X", "typex.pcd", lambda f: f.header(TYPE="TYPE F X F").encode() + f.body, "TYPE X of field y"),
    ("2-byte floats", "f2.pcd", lambda f: f.header(SIZE="SIZE 4 4 2").encode() + f.body, "floating point values"),
    ("COUNT 0", "count0.pcd", lambda f: f.header(COUNT="COUNT 1 0 1").encode() + f.body, "COUNT 0 of field y"),
    ("SIZE before FIELDS", "order.pcd", lambda f: "SIZE 4 4 4\n" + f.header(), "SIZE comes before FIELDS"),
    ("unknown keyword", "kw.pcd", lambda f: f.header(VERSION="COLOUR blue").encode() + f.body, "unknown keyword"),
    ("no z", "noz.pcd", lambda f: f.header(FIELDS="FIELDS x y w").encode() + f.body, "no z coordinate"),
    ("POINTS not WIDTH x HEIGHT", "pts.pcd", lambda f: f.header(POINTS="POINTS 299").encode() + f.body,
     "is not WIDTH x HEIGHT"),
    ("WIDTH x HEIGHT overflows", "ovf.pcd", lambda f: f.header(WIDTH="WIDTH %d" % 2 ** 62, HEIGHT="HEIGHT 16",
                                                               POINTS=None).encode() + f.body, "overflows"),
    ("absurd POINTS (binary)", "huge.pcd", lambda f: f.header(WIDTH="WIDTH %d" % 10 ** 15,
                                                              POINTS="POINTS %d" % 10 ** 15).encode() + f.body,
     "announces 1000000000000000 points"),
    ("absurd POINTS (ascii)", "hugea.pcd", lambda f: f.ascii_text.replace("WIDTH 300", "WIDTH 1000000000")
     .replace("POINTS 300", "POINTS 1000000000"), "announces 1000000000 points"),
    ("truncated binary", "cutb.pcd", lambda f: f.binary_bytes[:-100], "announces 300 points"),
    ("truncated ascii", "cuta.pcd", lambda f: "".join(f.ascii_text.splitlines(True)[:-10]),
     "ends after 290 of the 300 points"),
    ("ascii non-number", "word.pcd", lambda f: f.ascii_text.replace("\n0.", "\nzero", 1),
     "is not a value of field x"),
    ("ascii values missing", "few.pcd", lambda f: f.ascii_text[:f.ascii_text.rindex(" ")] + "\n", "holds 2 values"),
    ("ascii out of range", "u1.pcd", lambda f: "FIELDS x y z c\nSIZE 4 4 4 1\nTYPE F F F U\nPOINTS 1\nDATA ascii\n"
     "0 0 0 300\n", "\"300\" is not a value of field c (U1)"),
    ("compressed size beyond the file", "csize.pcd", lambda f: f.compressed((10 ** 9, f.raw_size)),
     "is said to take 1000000000 bytes"),
    ("uncompressed size wrong", "rsize.pcd", lambda f: f.compressed((f.compressed_size, f.raw_size - 4)),
     lambda f: "decompresses to %d bytes" % (f.raw_size - 4)),
    ("uncompressed size beyond LZF", "ratio.pcd", lambda f: f.compressed_bytes[:f.header_end].replace(
        b"WIDTH 300", b"WIDTH 3000000").replace(b"POINTS 300", b"POINTS 3000000") +
        struct.pack("<II", 10, 36000000) + bytes(10), "cannot decompress to the 36000000 bytes"),
    ("LZF reference before the start", "ref.pcd", lambda f: f.compressed(body=b"\xe0\x05\x10" + f.stream[3:]),
     "the compressed (LZF) data is damaged"),
    ("LZF stream cut short", "lzfcut.pcd", lambda f: f.compressed((f.compressed_size - 20, f.raw_size),
                                                                  f.stream[:-20]),
     "the compressed (LZF) data is damaged"),
    ("ends before the sizes", "nosizes.pcd", lambda f: f.compressed_bytes[:f.header_end + 3],
     "ends before the sizes"),
    ("missing file", "no-such-file.pcd", None, "Cannot open"),
]


@pytest.fixture(scope="module")
def damaged(folder):
    """Each damaged file written and read: {label: (output, errors, the
    error's words)}, and how much the process's peak memory grew while they
    were read."""
    XYZ = [("x", "F", 4, 1), ("y", "F", 4, 1), ("z", "F", 4, 1)]
    small = {"x": xyz[:, 0], "y": xyz[:, 1], "z": xyz[:, 2]}
    f = types.SimpleNamespace()
    binary_path = os.path.join(folder, "small-binary.pcd")
    pf.write_pcd(binary_path, XYZ, small, "binary")
    f.binary_bytes = open(binary_path, "rb").read()
    ascii_path = os.path.join(folder, "small-ascii.pcd")
    pf.write_pcd(ascii_path, XYZ, small, "ascii")
    f.ascii_text = open(ascii_path).read()
    compressed_path = os.path.join(folder, "small-compressed.pcd")
    pf.write_pcd(compressed_path, XYZ, small, "binary_compressed")
    f.compressed_bytes = open(compressed_path, "rb").read()
    f.header_end = f.compressed_bytes.index(b"DATA binary_compressed\n") + len(b"DATA binary_compressed\n")
    f.compressed_size, f.raw_size = struct.unpack("<II", f.compressed_bytes[f.header_end:f.header_end + 8])
    f.stream = f.compressed_bytes[f.header_end + 8:]
    f.body = f.binary_bytes[f.binary_bytes.index(b"DATA binary\n") + len(b"DATA binary\n"):]

    def header(**changes):
        """The small binary file's header with lines replaced (KEY -> text, or None to drop)."""
        lines = pf.pcd_header(XYZ, n, 1, "binary").decode().splitlines()
        out = []
        for line in lines:
            key = line.split()[0]
            if key in changes:
                if changes[key] is not None:
                    out.append(changes[key])
            else:
                out.append(line)
        return "\n".join(out) + "\n"

    def compressed(sizes=None, body=None):
        c, r = sizes or (f.compressed_size, f.raw_size)
        return f.compressed_bytes[:f.header_end] + struct.pack("<II", c, r) + (f.stream if body is None else body)

    f.header, f.compressed = header, compressed
    paths, messages = {}, {}
    for label, name, content, message in DAMAGED:
        paths[label] = os.path.join(folder, name)
        messages[label] = message(f) if callable(message) else message
        if content is not None:
            made = content(f)
            with open(paths[label], "wb") as out:
                out.write(made.encode() if isinstance(made, str) else made)
    peak_before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    outputs = {label: read(path)[1:] + (messages[label],) for label, path in paths.items()}
    peak_growth = (resource.getrusage(resource.RUSAGE_SELF).ru_maxrss - peak_before) / 1024.0
    return outputs, peak_growth


@pytest.mark.parametrize("label", [c[0] for c in DAMAGED])
def test_damaged_file(damaged, label):
    cloud, errors, message = damaged[0][label]
    said = " | ".join(str(e) for e in errors)
    print("%-32s -> %s" % (label, str(errors[0]).strip().splitlines()[-1] if errors else "(no error)"))
    assert any(message in str(e) for e in errors), "%s: an error saying \"%s\" (got: %s)" % (label, message, said)
    assert cloud.GetNumberOfPoints() == 0 and cloud.GetNumberOfCells() == 0, "%s: empty output" % label


def test_damaged_files_allocate_nothing_large(damaged):
    peak_growth = damaged[1]
    assert peak_growth < 50, "the damaged files allocate nothing large (peak grew by %.1f MB)" % peak_growth
