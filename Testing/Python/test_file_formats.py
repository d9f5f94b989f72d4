# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Every file format the project writes reads back, written the way the
project writes it: ParaView's SaveData in Binary mode (the example script,
the MPI tests) for .vti, .vtp, .pvti and .pvtp, STL, and VTK's XML writer in
Binary mode (Data/make_demo_cloud.py). A platform change that breaks one of
them (as Debian 12's libexpat update broke Appended mode for VTK 9.2's
readers) shows up here as one failure that names the format.

    pvpython test_file_formats.py PLUGIN
"""
import os
import sys

import numpy as np
import paraview.simple as pvs
from paraview import servermanager
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkObject
from vtkmodules.vtkIOGeometry import vtkSTLReader
from vtkmodules.vtkIOXML import (vtkXMLImageDataReader, vtkXMLPImageDataReader, vtkXMLPolyDataReader,
                                 vtkXMLPolyDataWriter, vtkXMLPPolyDataReader)

import nvtesting

plugin = sys.argv[1]
t = nvtesting.Checker("test_file_formats")
folder = nvtesting.scratch_folder(prefix="nv-formats-")
pvs.LoadPlugin(plugin, ns=globals())

# A cloud written as Data/make_demo_cloud.py writes the demo cloud.
cloud_file = os.path.join(folder, "cloud.vtp")
writer = vtkXMLPolyDataWriter()
writer.SetInputData(nvtesting.cloud(nvtesting.sphere_points(2000, radius=0.5)))
writer.SetFileName(cloud_file)
writer.SetDataModeToBinary()
writer.Write()
points = vtkXMLPolyDataReader()
points.SetFileName(cloud_file)
points.Update()
t.check(points.GetOutput().GetNumberOfPoints() == 2000,
        ".vtp from vtkXMLPolyDataWriter (Binary) reads back its 2000 points (%d)"
        % points.GetOutput().GetNumberOfPoints())

source = pvs.XMLPolyDataReader(FileName=[cloud_file])
shell = NarrowVolumeReconstruction(Input=source, OffsetDistance=0.08, MaximumDimension=50)  # noqa: F821
shell.UpdatePipeline()
volume = servermanager.Fetch(shell, idx=0)
surface = servermanager.Fetch(shell, idx=1)
phi = vtk_to_numpy(volume.GetPointData().GetArray("phi"))
triangles = surface.GetNumberOfCells()
print("in memory: %d nodes, %d triangles" % (len(phi), triangles))
t.check(len(phi) > 1000 and triangles > 1000, "the filter ran")


def read(reader_class, path):
    reader = reader_class()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def check_volume(path, reader_class):
    name = os.path.basename(path)
    pvs.SaveData(path, proxy=pvs.OutputPort(shell, 0), DataMode="Binary")
    data = read(reader_class, path)
    array = data.GetPointData().GetArray("phi")
    if t.check(array is not None and data.GetNumberOfPoints() == len(phi),
               "%s reads back: %d of %d nodes, phi %s" % (name, data.GetNumberOfPoints(), len(phi),
                                                         "present" if array is not None else "missing")):
        t.check(np.array_equal(vtk_to_numpy(array), phi), "%s: phi equal to the filter's" % name)
        t.check(data.GetFieldData().GetArray("NarrowBandNodes") is not None, "%s: field data kept" % name)


def check_surface(path, reader_class, **options):
    name = os.path.basename(path)
    pvs.SaveData(path, proxy=pvs.OutputPort(shell, 1), **options)
    data = read(reader_class, path)
    t.check(data.GetNumberOfCells() == triangles, "%s reads back: %d of %d triangles"
            % (name, data.GetNumberOfCells(), triangles))
    return data


check_volume(os.path.join(folder, "phi.vti"), vtkXMLImageDataReader)
check_volume(os.path.join(folder, "phi.pvti"), vtkXMLPImageDataReader)
vtp = check_surface(os.path.join(folder, "shell.vtp"), vtkXMLPolyDataReader, DataMode="Binary")
t.check(vtp.GetPointData().GetNormals() is not None, "shell.vtp: normals kept")
check_surface(os.path.join(folder, "shell.pvtp"), vtkXMLPPolyDataReader, DataMode="Binary")
stl = check_surface(os.path.join(folder, "shell.stl"), vtkSTLReader)
t.check(nvtesting.boundary_edges(stl) == 0, "shell.stl is watertight")

# Not a format the project writes, but what users get from SaveData's
# default: say whether this platform reads it, so a change shows up here.
appended = os.path.join(folder, "appended.vti")
pvs.SaveData(appended, proxy=pvs.OutputPort(shell, 0), DataMode="Appended")
vtkObject.GlobalWarningDisplayOff()  # the reader's parse errors are the expected answer here
appended_ok = read(vtkXMLImageDataReader, appended).GetNumberOfPoints() == len(phi)
vtkObject.GlobalWarningDisplayOn()
print("platform note: VTK XML files in Appended mode %s on this machine (the project writes Binary)"
      % ("read back" if appended_ok else "do NOT read back"))
t.finish()
