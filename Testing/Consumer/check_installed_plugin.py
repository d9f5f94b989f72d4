# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Run by run_consumer_test.cmake in pvpython, with PV_PLUGIN_CONFIG_FILE set
to the installed narrowvolume.plugins.xml and no LoadPlugin call: ParaView
loaded the installed plugin at start-up, and with it the installed Python
readers (NarrowVolumeScanReaders.py); its filter and readers run, and the
plugin (and, with a second argument, the narrowvolume package) use the
installed libNarrowVolumeFilters and libNarrowVolumeReaders, not the build
tree's.

    pvpython check_installed_plugin.py PREFIX [PYTHONPATH_DIR]
"""
import os
import sys

from paraview import servermanager
import paraview.simple as pvs
from paraview.modules.vtkRemotingCore import vtkPVPluginTracker

prefix = os.path.realpath(sys.argv[1])
failures = []


def check(condition, what):
    if not condition:
        failures.append(what)
        print("FAILED: %s" % what)


def inside_prefix(path):
    return os.path.realpath(path).startswith(prefix + os.sep)


# The plugin tracker lists what ParaView knows: NarrowVolume, loaded, from the prefix.
tracker = vtkPVPluginTracker.GetInstance()
plugins = {tracker.GetPluginName(i): (tracker.GetPluginFileName(i), tracker.GetPluginLoaded(i))
           for i in range(tracker.GetNumberOfPlugins())}
check("NarrowVolume" in plugins, "ParaView knows the plugin NarrowVolume: %s" % sorted(plugins))
filename, loaded = plugins.get("NarrowVolume", ("", False))
check(loaded, "the plugin was loaded at start-up")
check(inside_prefix(filename), "the plugin %s is the installed one (under %s)" % (filename, prefix))

# The Python readers it loads, from beside the installed plugin.
filename, loaded = plugins.get("NarrowVolumeScanReaders", ("", False))
check(loaded and inside_prefix(filename), "the plugin loaded the installed Python readers (%s)" % filename)
for reader in ("PointCloudTextReader", "LASPointCloudReader", "PCDPointCloudReader", "LAZPointCloudReader",
               "E57PointCloudReader"):
    check(hasattr(pvs, reader), "paraview.simple.%s exists" % reader)
filename = plugins.get("NarrowVolume", ("", False))[0]

# Its filter, without LoadPlugin.
check(hasattr(pvs, "NarrowVolumeReconstruction"), "paraview.simple.NarrowVolumeReconstruction exists")
if hasattr(pvs, "NarrowVolumeReconstruction"):
    import tempfile
    folder = tempfile.TemporaryDirectory(prefix="nv-installed-")  # removed at the end
    cloud_file = os.path.join(folder.name, "sphere.pcd")
    sphere = pvs.Sphere(Radius=0.5, ThetaResolution=24, PhiResolution=24)
    sphere.UpdatePipeline()
    xyz = [servermanager.Fetch(sphere).GetPoint(i) for i in range(servermanager.Fetch(sphere).GetNumberOfPoints())]
    with open(cloud_file, "w") as f:
        f.write("FIELDS x y z\nSIZE 8 8 8\nTYPE F F F\nPOINTS %d\nDATA ascii\n" % len(xyz))
        f.writelines("%.17g %.17g %.17g\n" % p for p in xyz)
    cloud = pvs.OpenDataFile(cloud_file)
    check(cloud is not None and cloud.GetXMLName() == "PCDPointCloudReader", "a .pcd opens with the PCD reader")
    cloud.UpdatePipeline()  # as Apply does: the filter's defaults follow the input's size
    check(cloud.GetDataInformation().GetNumberOfPoints() == len(xyz), "the PCD reader reads the sphere's points")
    shell = pvs.NarrowVolumeReconstruction(Input=cloud)
    shell.OffsetDistance = 0.1
    shell.MaximumDimension = 40
    shell.UpdatePipeline()
    surface = servermanager.Fetch(shell, idx=1)
    volume = servermanager.Fetch(shell, idx=0)
    check(surface.GetNumberOfPolys() > 0, "the filter's surface has triangles")
    check(volume.GetPointData().GetArray("phi") is not None, "the filter's volume has phi")

# The Python package from the installed tree.
if len(sys.argv) > 2:
    import narrowvolume
    check(inside_prefix(narrowvolume.__file__), "narrowvolume %s is the installed one" % narrowvolume.__file__)
    check(narrowvolume.vtkNarrowVolumeReconstruction().GetNumberOfOutputPorts() == 2, "narrowvolume's filter")
    check(narrowvolume.vtkLASPointCloudReader().GetNumberOfInputPorts() == 0, "narrowvolume's readers")

# Every libNarrowVolumeFilters and libNarrowVolumeReaders this process mapped is the installed one.
with open("/proc/self/maps") as maps:
    libraries = {line.split()[-1] for line in maps if "libNarrowVolume" in line}
for name in ("libNarrowVolumeFilters", "libNarrowVolumeReaders"):
    check(any(name in library for library in libraries), "%s is loaded" % name)
for library in sorted(libraries):
    check(inside_prefix(library), "%s is the installed library" % library)

print("check_installed_plugin: %s (plugin %s; libraries %s)"
      % ("FAILED" if failures else "ok", filename, " ".join(sorted(libraries))))
sys.exit(1 if failures else 0)
