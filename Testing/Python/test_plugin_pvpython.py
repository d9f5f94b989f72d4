# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The ParaView plugin in pvpython: LoadPlugin, then NarrowVolumeReconstruction."""
import sys

import numpy as np
from paraview import servermanager

import paraview.simple as pvs
from vtkmodules.util.numpy_support import vtk_to_numpy

import nvtesting

plugin = sys.argv[1]
pvs.LoadPlugin(plugin, ns=globals())
t = nvtesting.Checker("test_plugin_pvpython")

source = pvs.Sphere(Radius=0.5, ThetaResolution=80, PhiResolution=80)
source.UpdatePipeline()  # as Apply does in the GUI: the offset slider then follows the input's size
f = NarrowVolumeReconstruction(Input=source)  # noqa: F821 (defined by LoadPlugin)
t.check(f.GetXMLLabel() == "Narrow Volume Reconstruction", "label %s" % f.GetXMLLabel())
defaults = dict(MaximumNumberOfIterations=3, OffsetDistance=0.0, SampleSpacing=0.0, MaximumDimension=0, XiCells=2.0,
                EpsilonCells=6.0, TimeStep=0.0, ConvergenceTolerance=0.0, GaussSeidelTolerance=1e-6, PreserveOffset=0)
for name, value in defaults.items():
    t.check(abs(f.GetPropertyValue(name) - value) < 1e-12, "default %s = %s" % (name, f.GetPropertyValue(name)))
t.check(f.Domain == "Narrow Band", "Domain default %s" % f.Domain)
# Every property of the XML is reachable in pvpython under its XML name.
for name in f.ListProperties():
    t.check(f.GetProperty(name) is not None, "property %s" % name)
for name in ("OffsetDistance", "SampleSpacing", "MaximumDimension", "XiCells", "EpsilonCells", "TimeStep",
             "MaximumNumberOfIterations", "ConvergenceTolerance", "Domain", "EdgeStoppingFunction",
             "GaussSeidelTolerance", "RemoveSmallPieces", "PreserveOffset", "OutputVolume", "OutputInitialPhi", "OutputDistance", "OutputNarrowBand"):
    t.check(name in f.ListProperties(), "pvpython name %s" % name)
f.OffsetDistance = 0.1
f.SampleSpacing = 0.025
f.UpdatePipeline()

volume = servermanager.Fetch(f)
surface = servermanager.Fetch(f, idx=1)
t.check(volume.IsA("vtkImageData"), "port 0 is image data: %s" % volume.GetClassName())
t.check(surface.IsA("vtkPolyData"), "port 1 is polydata: %s" % surface.GetClassName())
phi = vtk_to_numpy(volume.GetPointData().GetArray("phi"))
t.check(phi.min() >= -1 and phi.max() <= 1, "phi in [-1, 1]")
t.check(nvtesting.boundary_edges(surface) == 0, "closed surface")
t.check(nvtesting.regions(surface) == 2, "two sheets")
r = np.linalg.norm(nvtesting.points_of(surface), axis=1)
t.check(abs(r[r < 0.5].mean() - 0.4) < 0.0125 and abs(r[r > 0.5].mean() - 0.6) < 0.0125, "sheet radii")

# Enumerations by name, as a pvpython user writes them.
f.Domain = "Whole Domain"
f.EdgeStoppingFunction = "Eq. (3): 1-phi0^2"
f.UpdatePipeline()
t.check(servermanager.Fetch(f, idx=1).GetNumberOfPoints() > 0, "whole domain, eq. 3")

# Plain-text clouds open through the plugin's reader and go straight into the filter.
import os
import tempfile
folder = tempfile.mkdtemp(prefix="nv-pv-")
for name in ("ball.pts", "ball.xyz"):
    with open(os.path.join(folder, name), "w") as f:
        f.write("\n".join("%.6f %.6f %.6f" % tuple(p) for p in nvtesting.sphere_points(500, 0.5)))
# .pts opens with ParaView's own PTSReader; .xyz is also claimed by ParaView's
# PLOT3D and molecular XYZ readers, and OpenDataFile takes the first of them
# (ParaView 5.11 consults the default-reader setting the plugin adds only in
# the GUI's File > Open, see GUIOpenFiles), so scripts name ours.
reader = pvs.OpenDataFile(os.path.join(folder, "ball.pts"))
t.check(reader is not None and reader.GetXMLName() == "PTSReader", "pts opens with ParaView's reader")
xyz_reader = PointCloudTextReader(FileName=os.path.join(folder, "ball.xyz"))  # noqa: F821
xyz_reader.UpdatePipeline()
t.check(xyz_reader.GetDataInformation().GetNumberOfPoints() == 500, "xyz read by name")
if reader is not None:
    reader.UpdatePipeline()
    shell = NarrowVolumeReconstruction(Input=reader, SampleSpacing=0.02, OffsetDistance=0.08, Sheets="Outer")  # noqa: F821
    shell.UpdatePipeline()
    t.check(shell.GetDataInformation(1).GetNumberOfCells() > 100, "shell from a pts file")
    from_xyz = NarrowVolumeReconstruction(Input=xyz_reader, SampleSpacing=0.02, OffsetDistance=0.08)  # noqa: F821
    from_xyz.UpdatePipeline()
    t.check(from_xyz.GetDataInformation(1).GetNumberOfCells() > 100, "shell from an xyz file")
    # The offset's default is 0 (automatic); its slider reaches a quarter of the input's largest side.
    fresh = NarrowVolumeReconstruction(Input=reader)  # noqa: F821
    slider = fresh.GetProperty("OffsetDistance").SMProperty.GetDomain("bounds")
    t.check(fresh.OffsetDistance == 0.0 and slider.GetMinimum(0) == 0.0 and abs(slider.GetMaximum(0) - 0.25) < 1e-3,
            "offset default 0, slider [0, 0.25 x the largest side]: %g, [%g, %g]" % (
                fresh.OffsetDistance, slider.GetMinimum(0), slider.GetMaximum(0)))
t.finish()
