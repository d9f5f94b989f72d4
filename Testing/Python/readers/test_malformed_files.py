# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Malformed cloud files (issue 37): truncated data, a missing element or
coordinate, text in binary data and binary bytes in text, empty files, and
negative or huge counts. Each reader of the package refuses each file with
an error that names it and an empty output, and the command line ends with
status 1 and one message naming the file: no crash, abort or traceback.
With the plugin, OpenDataFile picks the plugin's readers.

    pvpython -m pytest test_malformed_files.py --plugin PLUGIN
"""
import os
import struct
import subprocess

import numpy as np
import pytest

import nvpointfiles
import nvtesting

PLY_XYZ = "property float x\nproperty float y\nproperty float z\n"
ASCII_PLY = "ply\nformat ascii 1.0\nelement vertex 3\n" + PLY_XYZ + "end_header\n"
BINARY_PLY = "ply\nformat binary_little_endian 1.0\nelement vertex 100\n" + PLY_XYZ + "end_header\n"
FACE = "element face 1\nproperty list uchar int vertex_indices\n"
NOISE = bytes(np.random.default_rng(37).integers(0, 256, 600, dtype=np.uint8))

# name -> (bytes, words the error must hold). Each breaks one thing the
# reader trusted before (the comment says what it did then, where it crashed).
MALFORMED = {
    # vtkPLYReader: SIGSEGV
    "faces_no_vertex.ply": ("ply\nformat ascii 1.0\n" + FACE + "end_header\n3 0 1 2\n", "no vertex element"),
    # std::length_error: abort
    "header_only.ply": (ASCII_PLY, "truncated"),
    "negative_count.ply": (ASCII_PLY.replace("vertex 3", "vertex -3") + "0 0 0\n", "negative"),
    "huge_count.ply": (ASCII_PLY.replace("vertex 3", "vertex 9000000000000000000") + "0 0 0\n", "truncated"),
    # SIGSEGV
    "missing_z.ply": ("ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
                      "end_header\n0 0\n1 1\n", "no z"),
    # read as 100 points, 90 of them made up
    "truncated_binary.ply": (BINARY_PLY.encode() + struct.pack("<30f", *range(30)), "truncated"),
    "text_in_binary.ply": (BINARY_PLY.encode() + b"0 0 0\n1 0 0\n0 1 0\n", "truncated"),
    "binary_in_ascii.ply": (ASCII_PLY.encode() + b"\x00\x01\x02" + NOISE, "not a number"),
    "negative_list_count.ply": (ASCII_PLY.replace("end_header", FACE + "end_header").replace(
        "format ascii", "format binary_little_endian").encode() + struct.pack("<9f", *range(9))
        + struct.pack("<bi", -1, 0), "negative"),
    "face_index_out_of_range.ply": (ASCII_PLY.replace("end_header", FACE + "end_header")
                                    + "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n", "vertex 7"),
    # a pipeline dump, then "Could not open PLY file"
    "headerless_text.ply": ("0 0 0\n1 0 0\n0 1 0\n", "rename it .xyz"),
    "empty.ply": (b"", "empty"),
    # a TypeError traceback from the error path
    "binary_noise.xyz": (b"x y z\n1 2 3\n" + NOISE, "binary"),
    "all_noise.xyz": (NOISE, "x y z"),
    "empty.xyz": (b"", "empty"),
    "missing_z.xyz": ("1 2\n3 4\n", "line 1: not a point (x y z)"),
    "huge_count.pcd": ("VERSION .7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 1000000000000\n"
                       "HEIGHT 1\nPOINTS 1000000000000\nDATA binary\n", "points"),
    "empty.pcd": (b"", ""),
}


def _write(folder, name, content):
    path = os.path.join(folder, name)
    with open(path, "wb") as f:
        f.write(content.encode() if isinstance(content, str) else content)
    return path


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    """The malformed files, and a LAS and a PCD cut short."""
    folder = str(tmp_path_factory.mktemp("malformed"))
    paths = {name: _write(folder, name, content) for name, (content, _) in MALFORMED.items()}
    xyz = np.random.default_rng(1).random((200, 3))
    whole = os.path.join(folder, "whole.las")
    nvpointfiles.write_las(whole, 2, 0, xyz)
    with open(whole, "rb") as f:
        las = f.read()
    paths["truncated.las"] = _write(folder, "truncated.las", las[:len(las) // 2])
    paths["header_cut.las"] = _write(folder, "header_cut.las", las[:100])
    pcd = os.path.join(folder, "whole.pcd")
    nvpointfiles.write_pcd(pcd, [("x", "F", 4, 1), ("y", "F", 4, 1), ("z", "F", 4, 1)],
                           {"x": xyz[:, 0], "y": xyz[:, 1], "z": xyz[:, 2]}, "binary")
    with open(pcd, "rb") as f:
        data = f.read()
    paths["truncated.pcd"] = _write(folder, "truncated.pcd", data[:len(data) - 100])
    return paths


def _words(name):
    return MALFORMED[name][1] if name in MALFORMED else ""


def _reader_class(name):
    import narrowvolume
    return {".ply": narrowvolume.vtkPLYPointCloudReader, ".xyz": narrowvolume.vtkPointCloudTextReader,
            ".pcd": narrowvolume.vtkPCDPointCloudReader, ".las": narrowvolume.vtkLASPointCloudReader
            }[os.path.splitext(name)[1]]


NAMES = sorted(MALFORMED) + ["truncated.las", "header_cut.las", "truncated.pcd"]


@pytest.mark.parametrize("name", NAMES)
def test_reader_refuses(files, name, flavour):
    """The package's reader of the extension: an error naming the file and
    what is wrong, and no points."""
    if flavour == "wheel":
        pytest.skip("the pip package has no C++ readers (the command line's test covers it)")
    path = files[name]
    _, cloud, errors = nvpointfiles.read(_reader_class(name), path)
    assert cloud.GetNumberOfPoints() == 0, "%s: no points from a malformed file" % name
    named = [e for e in errors if path in str(e)]
    assert named, "%s: an error naming the file (%s)" % (name, errors)
    assert _words(name).lower() in str(named[0]).lower(), "%s: the error says %r: %s" % (
        name, _words(name), named[0])


@pytest.mark.parametrize("name", NAMES)
def test_command_line_refuses(files, name, tmp_path):
    """narrowvolume FILE: exit status 1 and one error naming the file; no
    signal (a crash or abort), traceback or pipeline dump."""
    output = str(tmp_path / "shell.stl")
    run = subprocess.run(nvtesting.python_command() + ["-m", "narrowvolume", "-q", files[name], "-o", output],
                         capture_output=True, text=True, errors="replace", timeout=120)
    said = run.stdout + run.stderr
    assert run.returncode == 1, "%s: exit status 1 (got %s, a negative one or 134/139 is a crash): %s" % (
        name, run.returncode, said[-600:])
    errors = [line for line in said.splitlines() if line.startswith("narrowvolume: error:")]
    assert len(errors) == 1 and files[name] in errors[0], "%s: one error naming the file: %s" % (name, said[-600:])
    assert _words(name).lower() in errors[0].lower(), "%s: the error says %r: %s" % (name, _words(name), errors[0])
    for noise in ("Traceback", "returned failure for request", "ERR|"):
        assert noise not in said, "%s: no %r in the output: %s" % (name, noise, said[-600:])
    assert not os.path.exists(output), "%s: nothing written" % name


def test_command_line_lists_every_format(tmp_path):
    """An unknown extension: the message lists every format the command line reads."""
    path = _write(str(tmp_path), "cloud.unknown", "1 2 3\n")
    run = subprocess.run(nvtesting.python_command() + ["-m", "narrowvolume", path], capture_output=True, text=True)
    assert run.returncode == 1, nvtesting.explain(run)
    for extension in (".las", ".laz", ".pcd", ".e57", ".ply", ".xyz", ".csv", ".vtp"):
        assert extension in run.stderr, "%s among the known formats: %s" % (extension, run.stderr)


@pytest.fixture(scope="module")
def opened(pvs, tmp_path_factory):
    """OpenDataFile on clouds that ParaView's own readers also claim: the XML name of the reader it picks."""
    folder = str(tmp_path_factory.mktemp("open"))
    points = "".join("%g %g %g\n" % tuple(p) for p in np.random.default_rng(2).random((20, 3)))
    clouds = {"cloud.xyz": "x y z\n" + points, "cloud.txt": points, "cloud.csv": "x,y,z\n" + points.replace(" ", ","),
              "table.csv": "name,value\na,1\nb,2\n", "cloud.ply": ASCII_PLY + "0 0 0\n1 0 0\n0 1 0\n",
              "damaged.xyz": "1 2 3\n4 5 x\n" + points,
              # Binary bytes that cannot begin a PLOT3D grid, and a grid's start (one block of 2 x 2 x 1 nodes).
              "noise.xyz": b"\xff\xfe\x00\xfc" + np.random.default_rng(3).bytes(4000),
              "grid.xyz": np.array([1, 2, 2, 1], "<i4").tobytes() + np.zeros(12, "<f4").tobytes()}
    return {name: pvs.OpenDataFile(_write(folder, name, text)).GetXMLName() for name, text in clouds.items()}


@pytest.mark.parametrize("name,reader", [("cloud.xyz", "ASCIIPointCloudReader"),
                                         ("cloud.txt", "ASCIIPointCloudReader"),
                                         ("cloud.csv", "ASCIIPointCloudReader"),
                                         ("table.csv", "CSVReader"),
                                         ("cloud.ply", "PLYPointCloudReader"),
                                         ("damaged.xyz", "ASCIIPointCloudReader"),
                                         ("noise.xyz", "ASCIIPointCloudReader"),
                                         ("grid.xyz", "P3DReader")])
def test_open_data_file_picks(opened, name, reader):
    """.xyz, .txt and .csv of numbers open with the plugin's text reader (not
    PLOT3D's, which aborted, or the CSV reader's table), a cloud with a
    damaged line too (the reader names the line), and binary bytes that
    cannot begin a PLOT3D grid (the reader says they are binary; PLOT3D's
    reader aborted on them), while a PLOT3D grid's start still goes to the
    PLOT3D reader; a table with text columns still opens with the CSV
    reader; .ply with the checked reader."""
    assert opened[name] == reader, "OpenDataFile(%s): %s, not %s" % (name, reader, opened[name])
