# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""vtkLASPointCloudReader on files this test writes (nvpointfiles.py, from
the LAS specification): every point format of every version from 1.0 to 1.4,
with variable length records and extra bytes, read back value for value at
UTM-sized coordinates in double precision; then damaged files, each of which
must give its own error, an empty output, and no large allocation."""
import os
import resource
import tempfile

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.util.vtkConstants import VTK_DOUBLE, VTK_FLOAT, VTK_UNSIGNED_CHAR, VTK_UNSIGNED_SHORT

from narrowvolume import vtkLASPointCloudReader
import nvpointfiles as pf
import nvtesting

t = nvtesting.Checker("test_las_reader")
folder = tempfile.mkdtemp(prefix="nv-las-")
# A sphere of radius 50 m in UTM zone coordinates (easting 500 km, northing
# 4000 km): a float32 holds 4000000 m to 0.25 m only.
centre = (500123.4567, 4001234.5678, 312.25)
xyz = nvtesting.sphere_points(300, 50.0, centre)
scale = (0.001, 0.001, 0.001)
offset = (500000.0, 4000000.0, 0.0)
TYPES = {"Intensity": VTK_UNSIGNED_SHORT, "Classification": VTK_UNSIGNED_CHAR, "ReturnNumber": VTK_UNSIGNED_CHAR,
         "NumberOfReturns": VTK_UNSIGNED_CHAR, "ClassificationFlags": VTK_UNSIGNED_CHAR,
         "ScanDirectionFlag": VTK_UNSIGNED_CHAR, "EdgeOfFlightLine": VTK_UNSIGNED_CHAR, "UserData": VTK_UNSIGNED_CHAR,
         "ScanAngle": VTK_FLOAT, "PointSourceId": VTK_UNSIGNED_SHORT, "ScannerChannel": VTK_UNSIGNED_CHAR,
         "GpsTime": VTK_DOUBLE, "Colors": VTK_UNSIGNED_CHAR, "NearInfrared": VTK_UNSIGNED_SHORT}


def check_cloud(label, cloud, errors, expected):
    n = len(expected["xyz"])
    if not t.check(not errors and cloud.GetNumberOfPoints() == n, "%s: %d points, no error (got %d, %s)"
                   % (label, n, cloud.GetNumberOfPoints(), errors)):
        return
    t.check(cloud.GetNumberOfVerts() == n, "%s: one vertex cell per point" % label)
    t.check(cloud.GetPoints().GetDataType() == VTK_DOUBLE, "%s: double-precision points" % label)
    got = vtk_to_numpy(cloud.GetPoints().GetData())
    # The reader computes integer * scale + offset in double, as numpy does here.
    t.check(np.abs(got - expected["xyz"]).max() <= 1e-9, "%s: coordinates = X * scale + offset (max error %g)"
            % (label, np.abs(got - expected["xyz"]).max()))
    names = {cloud.GetPointData().GetArrayName(i) for i in range(cloud.GetPointData().GetNumberOfArrays())}
    wanted = set(expected) - {"xyz"}
    t.check(names == wanted, "%s: the arrays %s (got %s)" % (label, sorted(wanted), sorted(names)))
    for name in wanted & names:
        values = cloud.GetPointData().GetArray(name)
        t.check(values.GetDataType() == TYPES[name], "%s: %s of type %s" % (label, name, values.GetDataTypeAsString()))
        t.check(np.array_equal(vtk_to_numpy(values), expected[name]), "%s: %s values" % (label, name))
    if "Colors" in wanted:
        t.check(cloud.GetPointData().GetScalars().GetName() == "Colors", "%s: Colors are the scalars" % label)


# 1. Every point format of every version, with a variable length record
# before the points and 3 extra bytes after each record's standard fields.
formats_read = 0
for minor, formats in pf.FORMATS.items():
    for point_format in formats:
        path = os.path.join(folder, "v1%d-format%d.las" % (minor, point_format))
        expected = pf.write_las(path, minor, point_format, xyz, scale, offset, seed=minor * 11 + point_format,
                                extra_bytes=3, with_vlr=True)
        reader, cloud, errors = pf.read(vtkLASPointCloudReader, path)
        check_cloud("LAS 1.%d format %d" % (minor, point_format), cloud, errors, expected)
        formats_read += 1
t.check(formats_read == 2 + 2 + 4 + 6 + 11, "25 version / format pairs read (%d)" % formats_read)
print("read %d LAS version / point format pairs" % formats_read)

# Double precision matters: float32 would be off by decimetres here.
float_error = np.abs(xyz.astype(np.float32) - xyz).max()
t.check(float_error > 0.01, "the test's coordinates need double precision (float32 error %.3f m)" % float_error)

# 2. Variants: 8-bit colours kept as they are, LAS 1.4's 64-bit count with
# the legacy count 0 in a legacy format, no records between header and points,
# a file of no points, CanReadFile.
path = os.path.join(folder, "colours8.las")
expected = pf.write_las(path, 2, 3, xyz, scale, offset, colour_bits=8)
check_cloud("8-bit colours", *pf.read(vtkLASPointCloudReader, path)[1:], expected)
path = os.path.join(folder, "count64.las")
expected = pf.write_las(path, 4, 1, xyz, scale, offset, legacy_count=0)
check_cloud("LAS 1.4, legacy count 0", *pf.read(vtkLASPointCloudReader, path)[1:], expected)
path = os.path.join(folder, "empty.las")
pf.write_las(path, 2, 0, np.zeros((0, 3)), scale, offset)
_, cloud, errors = pf.read(vtkLASPointCloudReader, path)
t.check(cloud.GetNumberOfPoints() == 0 and not errors, "a LAS file of no points: empty, no error (%s)" % errors)
t.check(vtkLASPointCloudReader().CanReadFile(os.path.join(folder, "count64.las")) == 1, "CanReadFile on LAS")
text = os.path.join(folder, "cloud.xyz")
with open(text, "w") as f:
    f.write("0 0 0\n1 1 1\n")
t.check(vtkLASPointCloudReader().CanReadFile(text) == 0, "CanReadFile on text: 0")

# 3. Damaged files: a clear error each, an empty output, no large allocation.
good = os.path.join(folder, "good.las")
pf.write_las(good, 2, 1, xyz, scale, offset)
good_bytes = open(good, "rb").read()
records, _ = pf.las_points(xyz, 1, scale, offset)


def damaged(name, content):
    path = os.path.join(folder, name)
    with open(path, "wb") as f:
        f.write(content)
    return path


def header_with(minor=2, point_format=1, **overrides):
    return pf.las_header(minor, point_format, records, scale, offset, **overrides) + records.tobytes()


cases = [
    ("empty file", damaged("empty0.las", b""), "not a LAS file"),
    ("other signature", damaged("sig.las", b"LASX" + good_bytes[4:]), "not a LAS file"),
    ("truncated header", damaged("short.las", good_bytes[:100]), "ends inside its header"),
    ("header size too small", damaged("hs.las", header_with(header_size=100)), "header size field says 100"),
    ("header size beyond the file", damaged("hs2.las", header_with(header_size=60000)[:2000]),
     "ends inside its header"),
    ("1.4 header of 1.2 size", damaged("hs3.las", header_with(minor=2, version=(1, 4))), "header has at least 375"),
    ("point offset inside the header", damaged("po.las", header_with(point_offset=100)), "lies inside the header"),
    ("point offset beyond the file", damaged("po2.las", header_with(point_offset=10 ** 9)),
     "beyond the end of the file"),
    ("unknown point format", damaged("pf.las", header_with(format_byte=11)), "not a LAS format"),
    ("compressed (LAZ) points", damaged("laz.las", header_with(format_byte=0x81)), "compressed (LAZ"),
    ("record shorter than the format", damaged("rl.las", header_with(record_length=12)),
     "shorter than point format 1"),
    ("version 2.0", damaged("v2.las", header_with(version=(2, 0))), "version 2.0 is not supported"),
    ("version 1.5", damaged("v15.las", header_with(version=(1, 5))), "version 1.5 is not supported"),
    ("zero scale", damaged("scale.las", header_with(scale_field=(0.001, 0.0, 0.001))), "y scale factor"),
    ("NaN scale", damaged("nan.las", header_with(scale_field=(float("nan"), 0.001, 0.001))), "x scale factor"),
    ("truncated points", damaged("cut.las", good_bytes[:len(good_bytes) - 1000]), "announces 300 points"),
    ("absurd legacy count", damaged("count.las", header_with(legacy_count=4000000000)),
     "announces 4000000000 points"),
    ("absurd 64-bit count", damaged("count64bad.las", header_with(minor=4, count=2 ** 62)),
     "announces %d points" % 2 ** 62),
    ("count one beyond the file", damaged("plus1.las", header_with(legacy_count=301)), "announces 301 points"),
    ("missing file", os.path.join(folder, "no-such-file.las"), "Cannot open"),
]
peak_before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
for label, path, message in cases:
    reader, cloud, errors = pf.read(vtkLASPointCloudReader, path)
    said = " | ".join(str(e) for e in errors)
    t.check(any(message in str(e) for e in errors), "%s: an error saying \"%s\" (got: %s)" % (label, message, said))
    t.check(cloud.GetNumberOfPoints() == 0 and cloud.GetNumberOfCells() == 0, "%s: empty output" % label)
    print("%-32s -> %s" % (label, str(errors[0]).strip().splitlines()[-1] if errors else "(no error)"))
peak_growth = (resource.getrusage(resource.RUSAGE_SELF).ru_maxrss - peak_before) / 1024.0
t.check(peak_growth < 50, "the damaged files allocate nothing large (peak grew by %.1f MB)" % peak_growth)
t.finish()
