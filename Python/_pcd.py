# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""PCL's .pcd files in numpy, for the pip package (which has no C++
readers): the Python plugin's PCDPointCloudReader (_readers.py) and the
command line read with read_pcd. ascii, binary and binary_compressed data;
x y z, and the other fields as point arrays ("rgb" / "rgba" as the colours
"Colors")."""
import struct

import numpy as np

from ._scanreaders import point_cloud

PCD_TYPES = {("F", 4): "<f4", ("F", 8): "<f8", ("U", 1): "u1", ("U", 2): "<u2", ("U", 4): "<u4", ("U", 8): "<u8",
             ("I", 1): "i1", ("I", 2): "<i2", ("I", 4): "<i4", ("I", 8): "<i8"}


class PCDError(ValueError):
    """A file these readers cannot read: the message says why."""


def lzf_decompress(data, size):
    """LZF (liblzf's format, PCD's binary_compressed) into `size` bytes."""
    out = bytearray(size)
    i = o = 0
    n = len(data)
    while i < n:
        control = data[i]
        i += 1
        if control < 32:  # a literal run of control + 1 bytes
            length = control + 1
            if i + length > n or o + length > size:
                raise PCDError("the compressed data is damaged (a literal run past its end)")
            out[o:o + length] = data[i:i + length]
            i += length
            o += length
        else:  # a back reference
            length = control >> 5
            if length == 7:
                length += data[i]
                i += 1
            reference = o - ((control & 0x1F) << 8) - data[i] - 1
            i += 1
            length += 2
            if reference < 0 or o + length > size:
                raise PCDError("the compressed data is damaged (a reference out of bounds)")
            for k in range(length):  # overlapping copies repeat bytes
                out[o + k] = out[reference + k]
            o += length
    if o != size:
        raise PCDError("the compressed data gives %d bytes, not the %d announced" % (o, size))
    return bytes(out)


def read_pcd(filename):
    """A .pcd file as a vtkPolyData: x y z, and the other fields as arrays."""
    with open(filename, "rb") as f:
        content = f.read()
    header, position = {}, 0
    while "DATA" not in header:
        end = content.find(b"\n", position)
        if end < 0:
            raise PCDError("the header has no DATA line")
        line = content[position:end].decode("ascii", "replace").strip()
        position = end + 1
        if line and not line.startswith("#"):
            key, _, value = line.partition(" ")
            header[key.upper()] = value.split()
    try:
        names = header["FIELDS"]
        sizes = [int(v) for v in header["SIZE"]]
        types = [v.upper() for v in header["TYPE"]]
        counts = [int(v) for v in header.get("COUNT", ["1"] * len(names))]
        points = int(header["POINTS"][0]) if "POINTS" in header else \
            int(header["WIDTH"][0]) * int(header["HEIGHT"][0])
        data = header["DATA"][0].lower()
    except (KeyError, IndexError, ValueError) as error:
        raise PCDError("the header is incomplete or malformed (%s)" % error)
    if not (len(names) == len(sizes) == len(types) == len(counts)):
        raise PCDError("FIELDS, SIZE, TYPE and COUNT have different lengths")
    if not all(n in names for n in "xyz"):
        raise PCDError("the fields have no x, y and z")
    try:
        dtype = np.dtype([("f%d" % k, PCD_TYPES[(t, s)], (c,) if c > 1 else ())
                          for k, (t, s, c) in enumerate(zip(types, sizes, counts))])
    except KeyError as error:
        raise PCDError("unknown field type and size %s" % (error,))
    body = content[position:]
    if data == "ascii":
        values = np.array(body.decode("ascii", "replace").split()[:points * sum(counts)], dtype=np.float64)
        if values.size != points * sum(counts):
            raise PCDError("the ascii data holds fewer values than %d points need" % points)
        values = values.reshape(points, sum(counts))
        records = np.zeros(points, dtype=dtype)
        column = 0
        for k, (name, t, c) in enumerate(zip(names, types, counts)):
            part = values[:, column:column + c]
            if name in ("rgb", "rgba") and t == "F":  # PCL writes the packed colour's bits as an integer
                part = part.astype(np.uint32).view(np.float32)
            records["f%d" % k] = part.reshape(records["f%d" % k].shape)
            column += c
    elif data == "binary":
        if len(body) < points * dtype.itemsize:
            raise PCDError("the file ends before its %d points" % points)
        records = np.frombuffer(body, dtype=dtype, count=points)
    elif data == "binary_compressed":
        if len(body) < 8:
            raise PCDError("the compressed data has no sizes")
        packed, unpacked = struct.unpack("<II", body[:8])
        raw = lzf_decompress(body[8:8 + packed], unpacked)
        # Field by field; some writers leave the "_" padding fields out.
        keep = [k for k, name in enumerate(names) if name != "_" or unpacked == points * dtype.itemsize]
        records = np.zeros(points, dtype=dtype)
        offset = 0
        for k in keep:
            column = np.dtype((dtype["f%d" % k].base, dtype["f%d" % k].shape))
            records["f%d" % k] = np.frombuffer(raw, dtype=column, count=points, offset=offset)
            offset += points * column.itemsize
    else:
        raise PCDError("unknown DATA %r (ascii, binary or binary_compressed)" % data)
    field = {name: records["f%d" % k] for k, name in enumerate(names) if name != "_"}
    xyz = np.c_[field["x"], field["y"], field["z"]].astype(np.float64)
    arrays, scalars = {}, None
    for name, values in field.items():
        if name in "xyz":
            continue
        if name in ("rgb", "rgba"):
            packed_colours = np.ascontiguousarray(values).view(np.uint32)
            arrays["Colors"] = np.c_[(packed_colours >> 16) & 255, (packed_colours >> 8) & 255,
                                     packed_colours & 255].astype(np.uint8)
            scalars = "Colors"
        else:
            arrays[name] = np.ascontiguousarray(values)
    return point_cloud(xyz, arrays, scalars)
