# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Writers of the point cloud files the reader tests read: LAS 1.0-1.4 in
every point format, PCD in ascii, binary and binary_compressed (with an LZF
compressor of our own), written from the formats' specifications with
struct and numpy, so that the tests need no LAS or PCD library; and a
reader runner that collects the errors a reader reports."""
import ctypes
import ctypes.util
import struct

import numpy as np
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.util.vtkConstants import VTK_STRING
from vtkmodules.vtkCommonCore import vtkCommand

# --- LAS (ASPRS LAS 1.4 R15, tables 3 and 7-17).

HEADER_SIZE = {0: 227, 1: 227, 2: 227, 3: 235, 4: 375}
STANDARD_LENGTH = [20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67]
# The point formats each version defines.
FORMATS = {0: range(0, 2), 1: range(0, 2), 2: range(0, 4), 3: range(0, 6), 4: range(0, 11)}


def record_dtype(point_format, extra_bytes=0):
    """The numpy dtype of one point record of `point_format`."""
    fields = [("X", "<i4"), ("Y", "<i4"), ("Z", "<i4"), ("intensity", "<u2")]
    if point_format <= 5:
        fields += [("returns", "u1"), ("classification", "u1"), ("scan_angle_rank", "i1"), ("user_data", "u1"),
                   ("point_source_id", "<u2")]
        if point_format in (1, 3, 4, 5):
            fields.append(("gps_time", "<f8"))
        if point_format in (2, 3, 5):
            fields += [("red", "<u2"), ("green", "<u2"), ("blue", "<u2")]
        if point_format in (4, 5):
            fields.append(("wave_packet", "V29"))
    else:
        fields += [("returns", "u1"), ("flags", "u1"), ("classification", "u1"), ("user_data", "u1"),
                   ("scan_angle", "<i2"), ("point_source_id", "<u2"), ("gps_time", "<f8")]
        if point_format in (7, 8, 10):
            fields += [("red", "<u2"), ("green", "<u2"), ("blue", "<u2")]
        if point_format in (8, 10):
            fields.append(("nir", "<u2"))
        if point_format in (9, 10):
            fields.append(("wave_packet", "V29"))
    if extra_bytes:
        fields.append(("extra", "V%d" % extra_bytes))
    dtype = np.dtype(fields)
    assert dtype.itemsize == STANDARD_LENGTH[point_format] + extra_bytes, (point_format, dtype.itemsize)
    return dtype


def las_points(xyz, point_format, scale, offset, seed=0, colour_bits=16, extra_bytes=0):
    """Point records at the coordinates `xyz` with random values in every
    other field, and what a reader should give for them (name -> array, the
    arrays of vtkLASPointCloudReader, and "xyz": the coordinates the
    integers stand for)."""
    rng = np.random.default_rng(seed)
    n = len(xyz)
    records = np.zeros(n, dtype=record_dtype(point_format, extra_bytes))
    integers = np.round((np.asarray(xyz) - offset) / scale).astype(np.int64)
    records["X"], records["Y"], records["Z"] = integers[:, 0], integers[:, 1], integers[:, 2]
    expected = {"xyz": integers * np.asarray(scale) + np.asarray(offset)}
    expected["Intensity"] = records["intensity"] = rng.integers(0, 65536, n)
    expected["UserData"] = records["user_data"] = rng.integers(0, 256, n)
    expected["PointSourceId"] = records["point_source_id"] = rng.integers(0, 65536, n)
    scan_direction = rng.integers(0, 2, n)
    edge = rng.integers(0, 2, n)
    expected["ScanDirectionFlag"], expected["EdgeOfFlightLine"] = scan_direction, edge
    if point_format <= 5:
        number = rng.integers(1, 8, n)
        ret = np.minimum(rng.integers(1, 8, n), number)
        records["returns"] = ret | (number << 3) | (scan_direction << 6) | (edge << 7)
        cls = rng.integers(0, 32, n)
        flags = rng.integers(0, 8, n)  # synthetic, key-point, withheld
        records["classification"] = cls | (flags << 5)
        angle = rng.integers(-90, 91, n)
        records["scan_angle_rank"] = angle
        expected["ScanAngle"] = angle.astype(np.float32)
    else:
        number = rng.integers(1, 16, n)
        ret = np.minimum(rng.integers(1, 16, n), number)
        records["returns"] = ret | (number << 4)
        flags = rng.integers(0, 16, n)  # synthetic, key-point, withheld, overlap
        channel = rng.integers(0, 4, n)
        records["flags"] = flags | (channel << 4) | (scan_direction << 6) | (edge << 7)
        cls = rng.integers(0, 256, n)
        records["classification"] = cls
        angle = rng.integers(-30000, 30001, n)
        records["scan_angle"] = angle
        expected["ScanAngle"] = (angle * 0.006).astype(np.float32)
        expected["ScannerChannel"] = channel
    expected["ReturnNumber"], expected["NumberOfReturns"] = ret, number
    expected["Classification"], expected["ClassificationFlags"] = cls, flags
    if "gps_time" in records.dtype.names:
        expected["GpsTime"] = records["gps_time"] = 3.0e8 + rng.random(n) * 1000.0
    if "red" in records.dtype.names:
        top = 65536 if colour_bits == 16 else 256
        rgb = rng.integers(0, top, (n, 3))
        rgb[0] = top - 1  # the largest value occurs
        records["red"], records["green"], records["blue"] = rgb[:, 0], rgb[:, 1], rgb[:, 2]
        expected["Colors"] = (rgb >> 8) if colour_bits == 16 else rgb
    if "nir" in records.dtype.names:
        expected["NearInfrared"] = records["nir"] = rng.integers(0, 65536, n)
    if "wave_packet" in records.dtype.names:
        records["wave_packet"] = np.void(bytes(range(29)))
    return records, expected


def las_header(minor, point_format, records, scale, offset, vlr_bytes=0, legacy_count=None, **overrides):
    """The public header block of a LAS 1.`minor` file holding `records`
    after `vlr_bytes` of variable length records. `overrides` replace
    fields by name (header_size, point_offset, record_length, count,
    legacy_count, format_byte, scale_field, signature, version)."""
    size = HEADER_SIZE[minor]
    n = len(records)
    header = bytearray(size)
    header[0:4] = overrides.get("signature", b"LASF")
    major, minor_field = overrides.get("version", (1, minor))
    struct.pack_into("<BB", header, 24, major, minor_field)
    header[26:58] = b"NarrowVolume tests".ljust(32, b"\0")
    header[58:90] = b"nvpointfiles.py".ljust(32, b"\0")
    if legacy_count is None:
        legacy_count = n if point_format <= 5 else 0  # formats 6-10 must leave it 0
    struct.pack_into("<HHHIIBHI", header, 90, 330, 2026, overrides.get("header_size", size),
                     overrides.get("point_offset", size + vlr_bytes), 1 if vlr_bytes else 0,
                     overrides.get("format_byte", point_format),
                     overrides.get("record_length", records.dtype.itemsize),
                     overrides.get("legacy_count", legacy_count))
    xyz = np.c_[records["X"], records["Y"], records["Z"]] * np.asarray(scale) + np.asarray(offset)
    lo = xyz.min(axis=0) if n else np.zeros(3)
    hi = xyz.max(axis=0) if n else np.zeros(3)
    struct.pack_into("<3d", header, 131, *overrides.get("scale_field", scale))
    struct.pack_into("<3d", header, 155, *offset)
    struct.pack_into("<6d", header, 179, hi[0], lo[0], hi[1], lo[1], hi[2], lo[2])
    if minor >= 4:
        struct.pack_into("<Q", header, 247, overrides.get("count", n))
    return bytes(header)


def vlr(payload=b"nothing to see"):
    """A variable length record: 54 bytes of header, then its payload."""
    head = struct.pack("<H16sHH32s", 0, b"NarrowVolume".ljust(16, b"\0"), 1, len(payload),
                       b"a test record".ljust(32, b"\0"))
    return head + payload


def write_las(path, minor, point_format, xyz, scale=(0.001, 0.001, 0.001), offset=(0.0, 0.0, 0.0), seed=0,
              colour_bits=16, extra_bytes=0, with_vlr=False, **overrides):
    """Writes a LAS 1.`minor` file of `xyz` in `point_format`; returns what a
    reader should give (see las_points)."""
    records, expected = las_points(xyz, point_format, scale, offset, seed, colour_bits, extra_bytes)
    record = vlr() if with_vlr else b""
    if minor == 0 and with_vlr:
        record += b"\xdd\xcc"  # LAS 1.0's point data start signature
    with open(path, "wb") as f:
        f.write(las_header(minor, point_format, records, scale, offset, len(record), **overrides))
        f.write(record)
        f.write(records.tobytes())
    return expected


# --- PCD (PCL's pcd_file_format tutorial, and pcd_io.cpp's layouts).

PCD_TYPES = {("F", 4): "<f4", ("F", 8): "<f8", ("U", 1): "u1", ("U", 2): "<u2", ("U", 4): "<u4", ("U", 8): "<u8",
             ("I", 1): "i1", ("I", 2): "<i2", ("I", 4): "<i4", ("I", 8): "<i8"}


def pcd_header(fields, width, height, data, points=None, viewpoint="0 0 0 1 0 0 0", extra_lines=()):
    """The header text. `fields`: (name, type, size, count) tuples."""
    lines = ["# .PCD v0.7 - Point Cloud Data file format", "VERSION 0.7",
             "FIELDS " + " ".join(f[0] for f in fields),
             "SIZE " + " ".join(str(f[2]) for f in fields),
             "TYPE " + " ".join(f[1] for f in fields),
             "COUNT " + " ".join(str(f[3]) for f in fields),
             "WIDTH %d" % width, "HEIGHT %d" % height, "VIEWPOINT " + viewpoint,
             "POINTS %d" % (width * height if points is None else points)] + list(extra_lines) + ["DATA " + data]
    return ("\n".join(lines) + "\n").encode()


def pcd_records(fields, columns):
    """A structured array with one record per point: `columns` maps each
    field name to its values (n, or n x count; "_" fields are zero)."""
    n = len(next(iter(columns.values())))
    dtype = np.dtype([("%s%d" % (name, k), PCD_TYPES[(t, s)], (c,) if c > 1 else ())
                      for k, (name, t, s, c) in enumerate(fields)])
    records = np.zeros(n, dtype=dtype)
    for k, (name, t, s, c) in enumerate(fields):
        if name != "_":
            records["%s%d" % (name, k)] = columns[name]
    return records


def format_ascii(value, kind):
    if kind == "F":
        return repr(float(value)) if np.isfinite(value) else "nan"
    return str(int(value))


def write_pcd(path, fields, columns, data, width=None, height=1, compress=None, padding_in_columns=True,
              **header_options):
    """Writes a PCD file of `columns` in `data` (ascii, binary,
    binary_compressed). binary_compressed stores the fields column by column,
    LZF-compressed by `compress` (lzf_compress by default); with
    padding_in_columns False the "_" fields are left out of the columns."""
    records = pcd_records(fields, columns)
    n = len(records)
    width = n // height if width is None else width
    header = pcd_header(fields, width, height, data, **header_options)
    with open(path, "wb") as f:
        f.write(header)
        if data == "ascii":
            for record in records:
                values = []
                for k, (name, t, s, c) in enumerate(fields):
                    v = np.atleast_1d(record["%s%d" % (name, k)])
                    if name in ("rgb", "rgba") and t == "F":
                        # As PCL writes them: the packed colour's bits as an unsigned integer.
                        values += [str(int(x)) for x in v.view(np.uint32)]
                    else:
                        values += [format_ascii(x, t) for x in v]
                f.write((" ".join(values) + "\n").encode())
        elif data == "binary":
            f.write(records.tobytes())
        else:
            raw = b"".join(np.ascontiguousarray(records["%s%d" % (name, k)]).tobytes()
                           for k, (name, t, s, c) in enumerate(fields) if padding_in_columns or name != "_")
            packed = (compress or lzf_compress)(raw)
            f.write(struct.pack("<II", len(packed), len(raw)) + packed)
    return records


def lzf_compress(data):
    """LZF compression (the format liblzf writes and PCD's binary_compressed
    holds), greedy: each position looks up the last place its next three
    bytes occurred, at most 8192 bytes back, and extends the match to at most
    264 bytes; what matches nothing goes out as literal runs of up to 32."""
    data = bytes(data)
    out = bytearray()
    literals = bytearray()
    last_seen = {}

    def flush():
        for k in range(0, len(literals), 32):
            run = literals[k:k + 32]
            out.append(len(run) - 1)
            out.extend(run)
        literals.clear()

    i, n = 0, len(data)
    while i < n:
        match = None
        if i + 3 <= n:
            key = data[i:i + 3]
            previous = last_seen.get(key)
            last_seen[key] = i
            if previous is not None and i - previous <= 8192:
                match = previous
        if match is None:
            literals.append(data[i])
            i += 1
            continue
        length = 3
        while length < min(264, n - i) and data[match + length] == data[i + length]:
            length += 1
        flush()
        distance, code = i - match - 1, length - 2
        if code < 7:
            out.append((code << 5) | (distance >> 8))
        else:
            out.append((7 << 5) | (distance >> 8))
            out.append(code - 7)
        out.append(distance & 255)
        i += length
    flush()
    return bytes(out)


def liblzf_compress():
    """liblzf's own lzf_compress (Debian's liblzf1), as a compress function
    for write_pcd, or None when the library is not installed."""
    name = ctypes.util.find_library("lzf") or "liblzf.so.1"
    try:
        library = ctypes.CDLL(name)
    except OSError:
        return None
    library.lzf_compress.restype = ctypes.c_uint
    library.lzf_compress.argtypes = [ctypes.c_void_p, ctypes.c_uint, ctypes.c_void_p, ctypes.c_uint]

    def compress(data):
        output = ctypes.create_string_buffer(len(data) + len(data) // 16 + 64)
        size = library.lzf_compress(data, len(data), output, len(output))
        assert size > 0
        return output.raw[:size]
    return compress


# --- Running a reader.

def read(reader_class, path, **settings):
    """Runs a reader on `path`; returns (reader, output, errors): the errors
    it and its executive reported (caught, so they do not print)."""
    reader = reader_class()
    reader.SetFileName(path)
    for name, value in settings.items():
        getattr(reader, "Set" + name)(value)
    errors = []

    @calldata_type(VTK_STRING)
    def on_error(caller, event, message):
        errors.append(message)

    reader.AddObserver(vtkCommand.ErrorEvent, on_error)
    reader.GetExecutive().AddObserver(vtkCommand.ErrorEvent, on_error)
    reader.Update()
    return reader, reader.GetOutput(), errors


def array(cloud, name):
    values = cloud.GetPointData().GetArray(name)
    return None if values is None else vtk_to_numpy(values)
