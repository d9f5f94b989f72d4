# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Every file format the project writes reads back, written the way the
project writes it: ParaView's SaveData in Binary mode (the example script,
the MPI tests) for .vti, .vtp, .pvti and .pvtp, STL, and VTK's XML writer in
Binary mode (Data/make_demo_cloud.py). A platform change that breaks one of
them (as Debian 12's libexpat update broke Appended mode for VTK 9.2's
readers) shows up here as one failure that names the format.

    pvpython -m pytest test_file_formats.py --plugin PLUGIN
"""
import os
import types

import numpy as np
import pytest
from paraview import servermanager
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkObject
from vtkmodules.vtkIOGeometry import vtkSTLReader
from vtkmodules.vtkIOXML import (vtkXMLImageDataReader, vtkXMLPImageDataReader, vtkXMLPolyDataReader,
                                 vtkXMLPolyDataWriter, vtkXMLPPolyDataReader)

import nvclouds
import nvtesting


@pytest.fixture(scope="module")
def folder():
    return nvtesting.scratch_folder(prefix="nv-formats-")


@pytest.fixture(scope="module")
def cloud_file(folder):
    """A cloud written as Data/make_demo_cloud.py writes the demo cloud."""
    path = os.path.join(folder, "cloud.vtp")
    writer = vtkXMLPolyDataWriter()
    writer.SetInputData(nvclouds.cloud(nvclouds.sphere_points(2000, radius=0.5)))
    writer.SetFileName(path)
    writer.SetDataModeToBinary()
    writer.Write()
    return path


def read(reader_class, path):
    reader = reader_class()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def test_vtk_xml_writer_binary(cloud_file):
    points = read(vtkXMLPolyDataReader, cloud_file)
    assert points.GetNumberOfPoints() == 2000, \
        ".vtp from vtkXMLPolyDataWriter (Binary) reads back its 2000 points (%d)" % points.GetNumberOfPoints()


@pytest.fixture(scope="module")
def shell(pvs, cloud_file):
    """The filter in ParaView on the cloud: the proxy, phi and the surface's triangles."""
    source = pvs.XMLPolyDataReader(FileName=[cloud_file])
    proxy = pvs.NarrowVolumeReconstruction(Input=source, OffsetDistance=0.08, MaximumDimension=50)
    proxy.UpdatePipeline()
    volume = servermanager.Fetch(proxy, idx=0)
    surface = servermanager.Fetch(proxy, idx=1)
    phi = vtk_to_numpy(volume.GetPointData().GetArray("phi"))
    triangles = surface.GetNumberOfCells()
    print("in memory: %d nodes, %d triangles" % (len(phi), triangles))
    return types.SimpleNamespace(proxy=proxy, phi=phi, triangles=triangles)


def test_the_filter_ran(shell):
    assert len(shell.phi) > 1000 and shell.triangles > 1000, "the filter ran"


@pytest.mark.parametrize("name, reader_class", [("phi.vti", vtkXMLImageDataReader),
                                                ("phi.pvti", vtkXMLPImageDataReader)], ids=["vti", "pvti"])
def test_volume_by_save_data(pvs, folder, shell, name, reader_class):
    path = os.path.join(folder, name)
    pvs.SaveData(path, proxy=pvs.OutputPort(shell.proxy, 0), DataMode="Binary")
    data = read(reader_class, path)
    array = data.GetPointData().GetArray("phi")
    assert array is not None and data.GetNumberOfPoints() == len(shell.phi), \
        "%s reads back: %d of %d nodes, phi %s" % (name, data.GetNumberOfPoints(), len(shell.phi),
                                                  "present" if array is not None else "missing")
    assert np.array_equal(vtk_to_numpy(array), shell.phi), "%s: phi equal to the filter's" % name
    assert data.GetFieldData().GetArray("NarrowBandNodes") is not None, "%s: field data kept" % name


def save_surface(pvs, folder, shell, name, reader_class, **options):
    path = os.path.join(folder, name)
    pvs.SaveData(path, proxy=pvs.OutputPort(shell.proxy, 1), **options)
    data = read(reader_class, path)
    assert data.GetNumberOfCells() == shell.triangles, "%s reads back: %d of %d triangles" % (
        name, data.GetNumberOfCells(), shell.triangles)
    return data


def test_vtp_by_save_data(pvs, folder, shell):
    vtp = save_surface(pvs, folder, shell, "shell.vtp", vtkXMLPolyDataReader, DataMode="Binary")
    assert vtp.GetPointData().GetNormals() is not None, "shell.vtp: normals kept"


def test_pvtp_by_save_data(pvs, folder, shell):
    save_surface(pvs, folder, shell, "shell.pvtp", vtkXMLPPolyDataReader, DataMode="Binary")


def test_stl_by_save_data(pvs, folder, shell):
    stl = save_surface(pvs, folder, shell, "shell.stl", vtkSTLReader)
    assert nvtesting.boundary_edges(stl) == 0, "shell.stl is watertight"


def test_appended_mode_platform_note(pvs, folder, shell):
    """Not a format the project writes, but what users get from SaveData's
    default: say whether this platform reads it, so a change shows up here."""
    appended = os.path.join(folder, "appended.vti")
    pvs.SaveData(appended, proxy=pvs.OutputPort(shell.proxy, 0), DataMode="Appended")
    vtkObject.GlobalWarningDisplayOff()  # the reader's parse errors are the expected answer here
    appended_ok = read(vtkXMLImageDataReader, appended).GetNumberOfPoints() == len(shell.phi)
    vtkObject.GlobalWarningDisplayOn()
    print("platform note: VTK XML files in Appended mode %s on this machine (the project writes Binary)"
          % ("read back" if appended_ok else "do NOT read back"))
