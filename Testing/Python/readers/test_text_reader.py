# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""vtkPointCloudTextReader: plain .xyz / .pts point clouds, with the optional
columns users' files carry, straight into the filter; malformed files give
a clear error naming the line."""
import os

import numpy as np
import pytest
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkCommand

from narrowvolume import vtkNarrowVolumeReconstruction, vtkPointCloudTextReader
import nvclouds
import nvpointfiles
import nvtesting

pytestmark = pytest.mark.readers
XYZ = nvclouds.sphere_points(400, 0.5)
NORMALS = XYZ / np.linalg.norm(XYZ, axis=1)[:, None]


@pytest.fixture(scope="module")
def write():
    """write(name, text): the path of a file of the scratch folder holding text."""
    folder = nvtesting.scratch_folder(prefix="nv-text-")

    def write(name, text):
        path = os.path.join(folder, name)
        with open(path, "w") as f:
            f.write(text)
        return path
    return write


def read(path):
    reader = vtkPointCloudTextReader()
    reader.SetFileName(path)
    errors = []
    reader.AddObserver(vtkCommand.ErrorEvent, lambda o, e, *a: errors.append(e))
    reader.GetExecutive().AddObserver(vtkCommand.ErrorEvent, lambda o, e, *a: errors.append(e))
    reader.Update()
    return reader, reader.GetOutput(), errors


@pytest.fixture(scope="module")
def plain(write):
    """A plain .xyz file with a comment line, and its reader after reading it."""
    path = write("plain.xyz", "# a comment\n" + "\n".join("%.9f %.9f %.9f" % tuple(p) for p in XYZ) + "\n")
    return path, read(path)[0]


def test_plain_xyz(plain):
    path, reader = plain
    cloud = reader.GetOutput()
    assert cloud.GetNumberOfPoints() == 400 and cloud.GetNumberOfVerts() == 400, "plain xyz: 400 points as vertices"
    assert np.allclose(nvtesting.points_of(cloud), XYZ, atol=1e-8), "coordinates read back"
    assert reader.CanReadFile(path) == 1, "CanReadFile on xyz"


def test_pts_with_count_line_intensity_and_colours(write):
    rgb = (np.arange(400)[:, None] * [1, 2, 3]) % 256
    pts = write("scan.pts", "400\n" + "\n".join("%.6f,%.6f,%.6f,%d,%d,%d,%d" % (p[0], p[1], p[2], 7, c[0], c[1], c[2])
                                                 for p, c in zip(XYZ, rgb)))
    _, cloud, _ = read(pts)
    pd = cloud.GetPointData()
    assert cloud.GetNumberOfPoints() == 400, "pts with a count line: 400 points"
    assert pd.GetArray("Intensity") is not None and pd.GetArray("Intensity").GetValue(5) == 7, "pts intensity"
    assert pd.GetScalars() is not None and pd.GetScalars().GetName() == "Colors", "pts colours"
    assert np.array_equal(vtk_to_numpy(pd.GetScalars()), rgb), "colour values"


def test_xyz_with_normals(write):
    with_normals = write("normals.xyz", "\n".join("%.6f\t%.6f\t%.6f\t%.6f\t%.6f\t%.6f" % (tuple(p) + tuple(n))
                                                  for p, n in zip(XYZ, NORMALS)))
    _, cloud, _ = read(with_normals)
    assert cloud.GetPointData().GetNormals() is not None, "xyz with normals"


def test_straight_into_the_filter(plain):
    f = vtkNarrowVolumeReconstruction()
    f.SetInputConnection(plain[1].GetOutputPort())
    f.SetOffsetDistance(0.1)
    f.SetSampleSpacing(0.03)
    f.Update()
    assert nvtesting.regions(f.GetOutput(1)) == 2, "the filter reads the reader's output"


def test_csv_with_a_header_line(write):
    csv = write("cloud.csv", "x,y,z,nx,ny,nz\n" + "\n".join("%.6f,%.6f,%.6f,%.6f,%.6f,%.6f" % (tuple(p) + tuple(n))
                                                          for p, n in zip(XYZ, NORMALS)))
    _, cloud, errors = read(csv)
    assert cloud.GetNumberOfPoints() == 400 and not errors, "CSV with a header line"
    assert cloud.GetPointData().GetNormals() is not None, "CSV normals"


def test_malformed_file(write):
    _, cloud, errors = read(write("bad.xyz", "0 0 0\n1 1 1\n2 two 2\n"))
    assert cloud.GetNumberOfPoints() == 0, "malformed file: empty output"
    assert len(errors) > 0, "malformed file: an error"


def test_ragged_columns(write):
    # A column that not every row has is dropped (every route reads the
    # points alike, nvTextCloud.h); the columns every row has stay arrays.
    _, cloud, errors = read(write("ragged.xyz", "0 0 0 7\n1 1 1 8 5\n"))
    assert cloud.GetNumberOfPoints() == 2 and not errors
    assert list(vtk_to_numpy(cloud.GetPointData().GetArray("Intensity"))) == [7, 8]


# The one rule of every route (nvTextCloud.h, the formats page): the texts
# the pip package's test (test_python_api.test_cli_text_layouts) reads to
# the same two points, and semicolons; and the lines it refuses.
SAME_POINTS = ["1 2 3\n4 5 6\n", "x y z\n1,2,3\n4,5,6", "2\n1 2 3 0.5\n4 5 6 0.5\n",
               "1\t2\t3\r\n4\t5\t6\r\n\n", "1 2 3\n# a comment\n4 5 6\n", "1 2 3\n\n4 5 6 7\n",
               "1 2 3 red\n4 5 6 blue\n", "x;y;z;name\n1;2;3;a\n4;5;6;b\n", "1;2;3\n4;5;6\n"]


@pytest.mark.parametrize("number", range(len(SAME_POINTS)))
def test_the_rule_of_every_route(write, number):
    _, cloud, errors = read(write("rule%d.csv" % number, SAME_POINTS[number]))
    assert not errors and np.array_equal(nvtesting.points_of(cloud), [[1, 2, 3], [4, 5, 6]]), errors


@pytest.mark.parametrize("text,line", [("1 2 3\n4 5 six\n", 2), ("1 2\n1 2 3\n", 1), ("1 2 3\n4 5\n", 2)])
def test_lines_that_are_no_point(write, text, line):
    _, cloud, errors = nvpointfiles.read(vtkPointCloudTextReader, write("bad.xyz", text))
    assert cloud.GetNumberOfPoints() == 0
    assert any(", line %d: not a point (x y z)" % line in str(e) for e in errors), errors


def test_molecular_xyz(write):
    """A molecular XYZ file (ParaView's XYZ Reader's format, which shares the
    extension): the error says which reader to pick instead."""
    molecule = write("water.xyz", "3\nwater\nO 0.0 0.0 0.117\nH 0.0 0.757 -0.467\nH 0.0 -0.757 -0.467\n")
    _, cloud, errors = nvpointfiles.read(vtkPointCloudTextReader, molecule)
    assert cloud.GetNumberOfPoints() == 0 and any("ParaView's XYZ Reader" in str(e) and "line 3" in str(e)
                                                  for e in errors), \
        "molecular XYZ: an empty output and an error naming line 3 and the XYZ Reader (%s)" % errors


@pytest.mark.parametrize("text", ["", "hello world\nfoo bar\n", "3\nwater\nO 0 0 0\nH 0.75 0.58 0\nH -0.75 0.58 0\n"])
def test_text_xyz_that_is_no_cloud_is_this_readers(write, text):
    # An empty, a worded or a molecular .xyz is this reader's (CanReadFile
    # 1), which says what is wrong, not the PLOT3D reader's, the other of
    # the extension, which crashed pvpython on them; words in a .csv are
    # left to the readers of tables.
    path = write("not-a-cloud.xyz", text)
    assert vtkPointCloudTextReader().CanReadFile(path) == 1
    _, cloud, errors = read(path)
    assert errors and cloud.GetNumberOfPoints() == 0
    if text.startswith("hello"):
        assert vtkPointCloudTextReader().CanReadFile(write("not-a-cloud.csv", text)) == 0
