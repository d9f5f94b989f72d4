# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""vtkLASPointCloudReader on files this test writes (nvpointfiles.py, from
the LAS specification): every point format of every version from 1.0 to 1.4,
with variable length records and extra bytes, read back value for value at
UTM-sized coordinates in double precision; then damaged files, each of which
must give its own error, an empty output, and no large allocation."""
import os
import resource
import types

import numpy as np
import pytest
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.util.vtkConstants import VTK_DOUBLE, VTK_FLOAT, VTK_UNSIGNED_CHAR, VTK_UNSIGNED_SHORT

from narrowvolume import vtkLASPointCloudReader
import nvclouds
import nvpointfiles as pf
import nvtesting

pytestmark = pytest.mark.readers
# A sphere of radius 50 m in UTM zone coordinates (easting 500 km, northing
# 4000 km): a float32 holds 4000000 m to 0.25 m only.
CENTRE = (500123.4567, 4001234.5678, 312.25)
XYZ = nvclouds.sphere_points(300, 50.0, CENTRE)
SCALE = (0.001, 0.001, 0.001)
OFFSET = (500000.0, 4000000.0, 0.0)
TYPES = {"Intensity": VTK_UNSIGNED_SHORT, "Classification": VTK_UNSIGNED_CHAR, "ReturnNumber": VTK_UNSIGNED_CHAR,
         "NumberOfReturns": VTK_UNSIGNED_CHAR, "ClassificationFlags": VTK_UNSIGNED_CHAR,
         "ScanDirectionFlag": VTK_UNSIGNED_CHAR, "EdgeOfFlightLine": VTK_UNSIGNED_CHAR, "UserData": VTK_UNSIGNED_CHAR,
         "ScanAngle": VTK_FLOAT, "PointSourceId": VTK_UNSIGNED_SHORT, "ScannerChannel": VTK_UNSIGNED_CHAR,
         "GpsTime": VTK_DOUBLE, "Colors": VTK_UNSIGNED_CHAR, "NearInfrared": VTK_UNSIGNED_SHORT}
# Every point format of every version.
PAIRS = [(minor, point_format) for minor, formats in pf.FORMATS.items() for point_format in formats]


@pytest.fixture(scope="module")
def folder():
    return nvtesting.scratch_folder(prefix="nv-las-")


def check_cloud(label, cloud, errors, expected):
    n = len(expected["xyz"])
    assert not errors and cloud.GetNumberOfPoints() == n, "%s: %d points, no error (got %d, %s)" % (
        label, n, cloud.GetNumberOfPoints(), errors)
    assert cloud.GetNumberOfVerts() == n, "%s: one vertex cell per point" % label
    assert cloud.GetPoints().GetDataType() == VTK_DOUBLE, "%s: double-precision points" % label
    got = vtk_to_numpy(cloud.GetPoints().GetData())
    # The reader computes integer * scale + offset in double, as numpy does here.
    assert np.abs(got - expected["xyz"]).max() <= 1e-9, "%s: coordinates = X * scale + offset (max error %g)" % (
        label, np.abs(got - expected["xyz"]).max())
    names = {cloud.GetPointData().GetArrayName(i) for i in range(cloud.GetPointData().GetNumberOfArrays())}
    wanted = set(expected) - {"xyz"}
    assert names == wanted, "%s: the arrays %s (got %s)" % (label, sorted(wanted), sorted(names))
    for name in wanted & names:
        values = cloud.GetPointData().GetArray(name)
        assert values.GetDataType() == TYPES[name], "%s: %s of type %s" % (label, name,
                                                                            values.GetDataTypeAsString())
        assert np.array_equal(vtk_to_numpy(values), expected[name]), "%s: %s values" % (label, name)
    if "Colors" in wanted:
        assert cloud.GetPointData().GetScalars().GetName() == "Colors", "%s: Colors are the scalars" % label


# 1. Every point format of every version, with a variable length record
# before the points and 3 extra bytes after each record's standard fields.
def test_every_version_and_point_format():
    assert len(PAIRS) == 2 + 2 + 4 + 6 + 11, "25 version / format pairs read (%d)" % len(PAIRS)
    print("read %d LAS version / point format pairs" % len(PAIRS))


@pytest.mark.parametrize("minor, point_format", PAIRS, ids=["1.%d-format%d" % pair for pair in PAIRS])
def test_version_and_point_format(folder, minor, point_format):
    path = os.path.join(folder, "v1%d-format%d.las" % (minor, point_format))
    expected = pf.write_las(path, minor, point_format, XYZ, SCALE, OFFSET, seed=minor * 11 + point_format,
                            extra_bytes=3, with_vlr=True)
    reader, cloud, errors = pf.read(vtkLASPointCloudReader, path)
    check_cloud("LAS 1.%d format %d" % (minor, point_format), cloud, errors, expected)


def test_coordinates_need_double_precision():
    """Double precision matters: float32 would be off by decimetres here."""
    float_error = np.abs(XYZ.astype(np.float32) - XYZ).max()
    assert float_error > 0.01, "the test's coordinates need double precision (float32 error %.3f m)" % float_error


# 2. Variants: 8-bit colours kept as they are, LAS 1.4's 64-bit count with
# the legacy count 0 in a legacy format, no records between header and points,
# a file of no points, CanReadFile.
def test_8_bit_colours(folder):
    path = os.path.join(folder, "colours8.las")
    expected = pf.write_las(path, 2, 3, XYZ, SCALE, OFFSET, colour_bits=8)
    check_cloud("8-bit colours", *pf.read(vtkLASPointCloudReader, path)[1:], expected)


@pytest.fixture(scope="module")
def count64(folder):
    path = os.path.join(folder, "count64.las")
    return path, pf.write_las(path, 4, 1, XYZ, SCALE, OFFSET, legacy_count=0)


def test_las_1_4_legacy_count_0(count64):
    path, expected = count64
    check_cloud("LAS 1.4, legacy count 0", *pf.read(vtkLASPointCloudReader, path)[1:], expected)


def test_no_points(folder):
    path = os.path.join(folder, "empty.las")
    pf.write_las(path, 2, 0, np.zeros((0, 3)), SCALE, OFFSET)
    _, cloud, errors = pf.read(vtkLASPointCloudReader, path)
    assert cloud.GetNumberOfPoints() == 0 and not errors, "a LAS file of no points: empty, no error (%s)" % errors


def test_can_read_file(folder, count64):
    assert vtkLASPointCloudReader().CanReadFile(count64[0]) == 1, "CanReadFile on LAS"
    text = os.path.join(folder, "cloud.xyz")
    with open(text, "w") as f:
        f.write("0 0 0\n1 1 1\n")
    assert vtkLASPointCloudReader().CanReadFile(text) == 0, "CanReadFile on text: 0"


# 3. Damaged files: a clear error each, an empty output, no large allocation.
# (label, file name, its content made from `f` (f.good: a good file's
# bytes, f.header_with(...): a header with fields replaced, then the
# points), the error's words); a content of None: the file is missing.
DAMAGED = [
    ("empty file", "empty0.las", lambda f: b"", "not a LAS file"),
    ("other signature", "sig.las", lambda f: b"LASX" + f.good[4:], "not a LAS file"),
    ("truncated header", "short.las", lambda f: f.good[:100], "ends inside its header"),
    ("header size too small", "hs.las", lambda f: f.header_with(header_size=100), "header size field says 100"),
    ("header size beyond the file", "hs2.las", lambda f: f.header_with(header_size=60000)[:2000],
     "ends inside its header"),
    ("1.4 header of 1.2 size", "hs3.las", lambda f: f.header_with(minor=2, version=(1, 4)),
     "header has at least 375"),
    ("point offset inside the header", "po.las", lambda f: f.header_with(point_offset=100),
     "lies inside the header"),
    ("point offset beyond the file", "po2.las", lambda f: f.header_with(point_offset=10 ** 9),
     "beyond the end of the file"),
    ("unknown point format", "pf.las", lambda f: f.header_with(format_byte=11), "not a LAS format"),
    ("compressed (LAZ) points", "laz.las", lambda f: f.header_with(format_byte=0x81), "compressed (LAZ"),
    ("record shorter than the format", "rl.las", lambda f: f.header_with(record_length=12),
     "shorter than point format 1"),
    ("version 2.0", "v2.las", lambda f: f.header_with(version=(2, 0)), "version 2.0 is not supported"),
    ("version 1.5", "v15.las", lambda f: f.header_with(version=(1, 5)), "version 1.5 is not supported"),
    ("zero scale", "scale.las", lambda f: f.header_with(scale_field=(0.001, 0.0, 0.001)), "y scale factor"),
    ("NaN scale", "nan.las", lambda f: f.header_with(scale_field=(float("nan"), 0.001, 0.001)), "x scale factor"),
    ("truncated points", "cut.las", lambda f: f.good[:len(f.good) - 1000], "announces 300 points"),
    ("absurd legacy count", "count.las", lambda f: f.header_with(legacy_count=4000000000),
     "announces 4000000000 points"),
    ("absurd 64-bit count", "count64bad.las", lambda f: f.header_with(minor=4, count=2 ** 62),
     "announces %d points" % 2 ** 62),
    ("count one beyond the file", "plus1.las", lambda f: f.header_with(legacy_count=301), "announces 301 points"),
    ("missing file", "no-such-file.las", None, "Cannot open"),
]


@pytest.fixture(scope="module")
def damaged(folder):
    """Each damaged file written and read: {label: (output, errors)}, and how
    much the process's peak memory grew while they were read."""
    good = os.path.join(folder, "good.las")
    pf.write_las(good, 2, 1, XYZ, SCALE, OFFSET)
    records, _ = pf.las_points(XYZ, 1, SCALE, OFFSET)

    def header_with(minor=2, point_format=1, **overrides):
        return pf.las_header(minor, point_format, records, SCALE, OFFSET, **overrides) + records.tobytes()

    with open(good, "rb") as f:
        parts = types.SimpleNamespace(good=f.read(), header_with=header_with)
    paths = {}
    for label, name, content, _ in DAMAGED:
        paths[label] = os.path.join(folder, name)
        if content is not None:
            with open(paths[label], "wb") as f:
                f.write(content(parts))
    peak_before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    outputs = {label: pf.read(vtkLASPointCloudReader, path)[1:] for label, path in paths.items()}
    peak_growth = (resource.getrusage(resource.RUSAGE_SELF).ru_maxrss - peak_before) / 1024.0
    return outputs, peak_growth


@pytest.mark.parametrize("label, message", [(c[0], c[3]) for c in DAMAGED], ids=[c[0] for c in DAMAGED])
def test_damaged_file(damaged, label, message):
    cloud, errors = damaged[0][label]
    said = " | ".join(str(e) for e in errors)
    print("%-32s -> %s" % (label, str(errors[0]).strip().splitlines()[-1] if errors else "(no error)"))
    assert any(message in str(e) for e in errors), "%s: an error saying \"%s\" (got: %s)" % (label, message, said)
    assert cloud.GetNumberOfPoints() == 0 and cloud.GetNumberOfCells() == 0, "%s: empty output" % label


def test_damaged_files_allocate_nothing_large(damaged):
    peak_growth = damaged[1]
    assert peak_growth < 50, "the damaged files allocate nothing large (peak grew by %.1f MB)" % peak_growth
