# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""From each file format to a shell: 1500 points on a sphere of radius 0.5,
written as plain text, LAS (1.2 format 3 and 1.4 format 6, at UTM
coordinates), PCD (ascii, binary, binary_compressed), and LAZ (at UTM
coordinates) and E57 (a scan placed at UTM coordinates by its pose) when
laspy and pye57 import, read back by the format's reader and reconstructed
by vtkNarrowVolumeReconstruction with OffsetDistance 0.08 and SampleSpacing
0.02 (set explicitly: the defaults may change). Every shell must be closed
(no open edge once coincident points are merged), have its two sheets, and
the area of the text file's shell within 0.5 % (the formats round the
coordinates differently: LAS to 0.1 mm, PCD to float).

    pvpython -m pytest test_reader_roundtrip.py --plugin PLUGIN
"""
import os

import numpy as np
import pytest
from vtkmodules.util.numpy_support import vtk_to_numpy

from narrowvolume import (vtkLASPointCloudReader, vtkNarrowVolumeReconstruction, vtkPCDPointCloudReader,
                          vtkPointCloudTextReader)
import nvclouds
import nvpointfiles as pf
import nvtesting

pytestmark = pytest.mark.readers
UNIT = nvclouds.sphere_points(1500, 0.5)
UTM = np.array([500000.25, 4000000.75, 120.0])  # airborne data sits about here
NATIVE = ["text .xyz", "LAS 1.2 format 3", "LAS 1.4 format 6", "PCD ascii", "PCD binary", "PCD binary_compressed"]
PYTHON_READERS = ["LAZ (laspy)", "E57 (pye57)"]


@pytest.fixture(scope="module")
def clouds(pvs):
    """{label: (vtkPolyData, the centre it was written at, the reader's
    errors)}: the sphere written in each format and read back; LAZ and E57
    when laspy and pye57 import."""
    import NarrowVolumeScanReaders as scan_readers  # loaded by the plugin
    folder = nvtesting.scratch_folder(prefix="nv-roundtrip-")
    clouds = {}

    def add(label, reader_class, path, centre):
        reader, cloud, errors = pf.read(reader_class, path)
        clouds[label] = (cloud, centre, errors)

    path = os.path.join(folder, "sphere.xyz")
    np.savetxt(path, UNIT, fmt="%.9f")
    add("text .xyz", vtkPointCloudTextReader, path, np.zeros(3))
    for minor, point_format in ((2, 3), (4, 6)):
        path = os.path.join(folder, "sphere-1%d-%d.las" % (minor, point_format))
        pf.write_las(path, minor, point_format, UNIT + UTM, scale=(1e-4,) * 3, offset=tuple(np.floor(UTM)))
        add("LAS 1.%d format %d" % (minor, point_format), vtkLASPointCloudReader, path, UTM)
    xyz_fields = [("x", "F", 4, 1), ("y", "F", 4, 1), ("z", "F", 4, 1), ("intensity", "U", 2, 1)]
    columns = {"x": UNIT[:, 0], "y": UNIT[:, 1], "z": UNIT[:, 2], "intensity": np.arange(len(UNIT)) % 65536}
    for data in ("ascii", "binary", "binary_compressed"):
        path = os.path.join(folder, "sphere-%s.pcd" % data)
        pf.write_pcd(path, xyz_fields, columns, data)
        add("PCD " + data, vtkPCDPointCloudReader, path, np.zeros(3))
    try:
        import laspy
        import pye57
        laspy.LazBackend.detect_available()[0]
        header = laspy.LasHeader(point_format=1, version="1.2")
        header.scales, header.offsets = [1e-4] * 3, list(np.floor(UTM))
        las = laspy.LasData(header)
        las.x, las.y, las.z = (UNIT + UTM).T
        path = os.path.join(folder, "sphere.laz")
        las.write(path)
        clouds["LAZ (laspy)"] = (scan_readers.read_laz(path), UTM, [])
        path = os.path.join(folder, "sphere.e57")
        e57 = pye57.E57(path, mode="w")
        # As terrestrial scanners do: points in the scanner's frame (pye57 writes
        # them in single precision), the scan placed in the world by its pose.
        e57.write_scan_raw({"cartesianX": UNIT[:, 0], "cartesianY": UNIT[:, 1], "cartesianZ": UNIT[:, 2]},
                           rotation=np.array([1.0, 0.0, 0.0, 0.0]), translation=UTM)
        e57.close()
        clouds["E57 (pye57)"] = (scan_readers.read_e57(path), UTM, [])
    except (ImportError, IndexError) as error:
        clouds["missing"] = "laspy, lazrs and pye57 do not import here (%s); install them with %s and %s" % (
            error, scan_readers.install_command("laspy[lazrs]"), scan_readers.install_command("pye57"))
        print("LAZ and E57 skipped: " + clouds["missing"])
    return clouds


@pytest.fixture(scope="module")
def shells(clouds):
    """{label: (triangles, open edges, area, sheets)} of each cloud's shell, one line each printed."""
    shells = {}
    for label in NATIVE + PYTHON_READERS:
        if label not in clouds:
            continue
        cloud = clouds[label][0]
        shell = vtkNarrowVolumeReconstruction()
        shell.SetInputData(cloud)
        shell.SetOffsetDistance(0.08)
        shell.SetSampleSpacing(0.02)
        shell.Update()
        surface = shell.GetOutput(1)
        triangles, open_edges, area = nvtesting.merged_surface(surface)
        sheets = nvtesting.regions(surface)
        print("%-24s %6d points -> %6d triangles, %d open edges, %d sheets, area %.4f"
              % (label, cloud.GetNumberOfPoints(), triangles, open_edges, sheets, area))
        shells[label] = (triangles, open_edges, area, sheets)
    return shells


@pytest.mark.parametrize("label", NATIVE + PYTHON_READERS)
def test_format_to_shell(clouds, shells, label):
    if label not in clouds:
        pytest.skip("LAZ and E57 skipped: " + clouds["missing"])
    cloud, centre, errors = clouds[label]
    if label in NATIVE:
        assert not errors and cloud.GetNumberOfPoints() == len(UNIT), "%s: read back (%s)" % (label, errors)
    assert np.abs(vtk_to_numpy(cloud.GetPoints().GetData()) - centre - UNIT).max() < 1e-4, \
        "%s: the sphere's points (within 0.1 mm)" % label
    triangles, open_edges, area, sheets = shells[label]
    reference_area = shells["text .xyz"][2]
    assert triangles > 1000 and open_edges == 0, "%s: a closed surface (%d open edges)" % (label, open_edges)
    assert sheets == 2, "%s: two sheets (%d)" % (label, sheets)
    assert abs(area - reference_area) < 0.005 * reference_area, \
        "%s: the text file's area within 0.5 %% (%.4f, %.4f)" % (label, area, reference_area)


def test_every_native_format(shells):
    assert len(shells) >= 6, "at least the six native formats reconstructed (%d)" % len(shells)
