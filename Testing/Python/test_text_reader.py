# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""vtkPointCloudTextReader: plain .xyz / .pts point clouds, with the optional
columns users' files carry, straight into the filter; malformed files give
a clear error naming the line."""
import os
import tempfile

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkCommand

from narrowvolume import vtkNarrowVolumeReconstruction, vtkPointCloudTextReader
import nvpointfiles
import nvtesting

t = nvtesting.Checker("test_text_reader")
folder = tempfile.mkdtemp(prefix="nv-text-")
xyz = nvtesting.sphere_points(400, 0.5)


def write(name, text):
    path = os.path.join(folder, name)
    with open(path, "w") as f:
        f.write(text)
    return path


def read(path):
    reader = vtkPointCloudTextReader()
    reader.SetFileName(path)
    errors = []
    reader.AddObserver(vtkCommand.ErrorEvent, lambda o, e, *a: errors.append(e))
    reader.GetExecutive().AddObserver(vtkCommand.ErrorEvent, lambda o, e, *a: errors.append(e))
    reader.Update()
    return reader, reader.GetOutput(), errors


plain = write("plain.xyz", "# a comment\n" + "\n".join("%.9f %.9f %.9f" % tuple(p) for p in xyz) + "\n")
reader, cloud, errors = read(plain)
t.check(cloud.GetNumberOfPoints() == 400 and cloud.GetNumberOfVerts() == 400, "plain xyz: 400 points as vertices")
t.check(np.allclose(nvtesting.points_of(cloud), xyz, atol=1e-8), "coordinates read back")
t.check(reader.CanReadFile(plain) == 1, "CanReadFile on xyz")

rgb = (np.arange(400)[:, None] * [1, 2, 3]) % 256
pts = write("scan.pts", "400\n" + "\n".join("%.6f,%.6f,%.6f,%d,%d,%d,%d" % (p[0], p[1], p[2], 7, c[0], c[1], c[2])
                                             for p, c in zip(xyz, rgb)))
_, cloud, _ = read(pts)
pd = cloud.GetPointData()
t.check(cloud.GetNumberOfPoints() == 400, "pts with a count line: 400 points")
t.check(pd.GetArray("Intensity") is not None and pd.GetArray("Intensity").GetValue(5) == 7, "pts intensity")
t.check(pd.GetScalars() is not None and pd.GetScalars().GetName() == "Colors", "pts colours")
t.check(np.array_equal(vtk_to_numpy(pd.GetScalars()), rgb), "colour values")

normals = xyz / np.linalg.norm(xyz, axis=1)[:, None]
with_normals = write("normals.xyz", "\n".join("%.6f\t%.6f\t%.6f\t%.6f\t%.6f\t%.6f" % (tuple(p) + tuple(n))
                                              for p, n in zip(xyz, normals)))
_, cloud, _ = read(with_normals)
t.check(cloud.GetPointData().GetNormals() is not None, "xyz with normals")

# Straight into the filter.
f = vtkNarrowVolumeReconstruction()
f.SetInputConnection(reader.GetOutputPort())
f.SetOffsetDistance(0.1)
f.SetSampleSpacing(0.03)
f.Update()
t.check(nvtesting.regions(f.GetOutput(1)) == 2, "the filter reads the reader's output")

csv = write("cloud.csv", "x,y,z,nx,ny,nz\n" + "\n".join("%.6f,%.6f,%.6f,%.6f,%.6f,%.6f" % (tuple(p) + tuple(n))
                                                      for p, n in zip(xyz, normals)))
_, cloud, errors = read(csv)
t.check(cloud.GetNumberOfPoints() == 400 and not errors, "CSV with a header line")
t.check(cloud.GetPointData().GetNormals() is not None, "CSV normals")

bad = write("bad.xyz", "0 0 0\n1 1 1\n2 two 2\n")
_, cloud, errors = read(bad)
t.check(cloud.GetNumberOfPoints() == 0, "malformed file: empty output")
t.check(len(errors) > 0, "malformed file: an error")
ragged = write("ragged.xyz", "0 0 0\n1 1 1 5\n")
_, cloud, errors = read(ragged)
t.check(cloud.GetNumberOfPoints() == 0 and errors, "ragged columns: an error and an empty output")
# A molecular XYZ file (ParaView's XYZ Reader's format, which shares the
# extension): the error says which reader to pick instead.
molecule = write("water.xyz", "3\nwater\nO 0.0 0.0 0.117\nH 0.0 0.757 -0.467\nH 0.0 -0.757 -0.467\n")
_, cloud, errors = nvpointfiles.read(vtkPointCloudTextReader, molecule)
t.check(cloud.GetNumberOfPoints() == 0 and any("ParaView's XYZ Reader" in str(e) and "line 3" in str(e)
                                               for e in errors),
        "molecular XYZ: an empty output and an error naming line 3 and the XYZ Reader (%s)" % errors)
t.finish()
