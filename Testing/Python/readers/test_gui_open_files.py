# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""File > Open in the real ParaView client (under Xvfb, driven by a Qt test
script of recorded GUI events, as ParaView's own GUI tests are): with the
plugin auto-loaded, a plain x y z file named .xyz opens with the Point Cloud
Text Reader at once, although ParaView's PLOT3D and molecular XYZ readers
claim .xyz too (without the plugin's default a dialog asks which of the
three to use), also after the Settings dialog was applied (which writes the
settings proxies' values over the user's settings); .las, .pcd, .laz and
.e57 files open with the plugin's readers, the last two Python readers
loaded with the plugin.

Two runs: the plugin auto-loaded at start-up, and loaded from the client's
Python shell once it runs (as Tools > Manage Plugins loads it). The client
runs with --dr (no user settings), so a user's own default readers cannot
change the outcome. A dialog left open fails the test: the event that
follows the Open finds no reader.

    pvpython -m pytest test_gui_open_files.py --plugins-xml PLUGINS_XML [--with-xvfb WITH_XVFB]
"""
import json
import os
import subprocess
import types
from xml.sax.saxutils import quoteattr

import numpy as np
import pytest

import nvclouds
import nvpointfiles as pf
import nvtesting

pytestmark = [pytest.mark.gui, pytest.mark.readers]


@pytest.fixture(scope="module")
def files(plugins_xml):
    """The files to open (name -> path), the scratch folder, the plugin beside the plugins' XML."""
    folder = nvtesting.scratch_folder(prefix="nv-gui-open-")
    xyz = nvclouds.sphere_points(500, 0.5)
    paths = {"xyz": os.path.join(folder, "plain.xyz"), "las": os.path.join(folder, "cloud.las"),
             "pcd": os.path.join(folder, "cloud.pcd"), "laz": os.path.join(folder, "cloud.laz"),
             "e57": os.path.join(folder, "cloud.e57")}
    np.savetxt(paths["xyz"], xyz, fmt="%.6f")
    pf.write_las(paths["las"], 2, 3, xyz)
    pf.write_pcd(paths["pcd"], [("x", "F", 4, 1), ("y", "F", 4, 1), ("z", "F", 4, 1)],
                 {"x": xyz[:, 0], "y": xyz[:, 1], "z": xyz[:, 2]}, "binary")
    for name in ("laz", "e57"):  # only opened, never read: the reader's choice is what is tested
        with open(paths[name], "wb") as f:
            f.write(b"not read")
    plugin_dir = os.path.dirname(os.path.abspath(plugins_xml))
    return types.SimpleNamespace(folder=folder, paths=paths,
                                 plugin=os.path.join(plugin_dir, "NarrowVolume", "NarrowVolume.so"))


RECORD = """import json, os, traceback
result = {}
try:
    from paraview import servermanager
    from paraview.simple import GetSources
    settings = servermanager.vtkSMSettings.GetInstance()
    # The setting's group: IOSettings from ParaView 5.12 on.
    version = (servermanager.vtkSMProxyManager.GetVersionMajor(), servermanager.vtkSMProxyManager.GetVersionMinor())
    group = "IOSettings" if version >= (5, 12) else "RepresentedArrayListSettings"
    name = ".settings." + group + ".ReaderDetails"
    result["settings"] = {"file": "", "reader": [settings.GetSettingAsString(name, k, "")
                                                 for k in range(settings.GetSettingNumberOfElements(name))]}
    for (name, _), proxy in GetSources().items():
        filename = proxy.FileName if isinstance(proxy.FileName, str) else proxy.FileName[0]
        entry = {"reader": proxy.GetXMLName(), "file": os.path.basename(filename)}
        if entry["file"].endswith((".xyz", ".las", ".pcd")):
            proxy.UpdatePipeline()
            entry["points"] = proxy.GetDataInformation().GetNumberOfPoints()
        result[name] = entry
except Exception:
    result["error"] = {"file": "", "reader": traceback.format_exc()}
json.dump(result, open(%r, "w"))
os._exit(0)
"""


def console(folder, code, name):
    """An event that runs `code` in the client's Python shell. The shell takes
    one line at a time, as typed: the code runs from a file."""
    path = os.path.join(folder, name + ".py")
    with open(path, "w") as f:
        f.write(code)
    return ('  <pqevent object="pqClientMainWindow/pythonShellDock/pythonShell/consoleWidget" '
            'command="executeCommand" arguments=%s />' % quoteattr("exec(open(%r).read())" % path))


@pytest.mark.parametrize("label, autoload", [("auto-loaded", True), ("loaded-from-python", False)],
                         ids=["auto-loaded", "loaded-from-python"])
def test_file_open(files, plugins_xml, with_xvfb, label, autoload):
    """Runs the client: the plugin auto-loaded at start-up (its settings
    proxies are created after it), or loaded from the Python shell once the
    client runs (as Tools > Manage Plugins does: the proxies exist already);
    then Edit > Settings and OK, which writes every settings proxy's values
    over the user's settings, and File > Open of each file."""
    folder = files.folder
    result_path = os.path.join(folder, label + ".json")
    events = ['<?xml version="1.0" ?>', "<pqevents>"]
    if not autoload:
        events.append(console(folder, "from paraview.simple import LoadPlugin\nLoadPlugin(%r)\n" % files.plugin,
                              label + "-load"))
    events.append('  <pqevent object="pqClientMainWindow/menubar" command="activate" arguments="menu_Edit" />')
    events.append('  <pqevent object="pqClientMainWindow/menubar/menu_Edit" command="activate" '
                  'arguments="actionEditSettings" />')
    events.append('  <pqevent object="pqClientMainWindow/ApplicationSettings/buttonBox/1QPushButton0" '
                  'command="activate" arguments="" />')
    for name in ("las", "pcd", "laz", "e57", "xyz"):  # xyz last: a dialog there blocks what follows
        events.append('  <pqevent object="pqClientMainWindow/MainControlsToolbar/actionOpenData" '
                      'command="activate" arguments="" />')
        events.append('  <pqevent object="pqClientMainWindow/FileOpenDialog" command="filesSelected" '
                      'arguments=%s />' % quoteattr(files.paths[name]))
    events.append(console(folder, RECORD % result_path, label + "-record"))
    events.append("</pqevents>")
    script = os.path.join(folder, label + ".xml")
    with open(script, "w") as f:
        f.write("\n".join(events) + "\n")
    env = dict(os.environ, NV_FORCE_XVFB="1")
    env.pop("PV_PLUGIN_CONFIG_FILE", None)
    if autoload:
        env["PV_PLUGIN_CONFIG_FILE"] = plugins_xml
    try:
        run = subprocess.run([with_xvfb, "paraview", "--dr", "--test-script=" + script, "--exit"], env=env,
                             capture_output=True, text=True, timeout=240)
        explanation = nvtesting.explain(run)
    except subprocess.TimeoutExpired:
        explanation = "the client did not finish within 240 s (a dialog waiting for an answer?)"
    assert os.path.exists(result_path), "%s: the client opened the files and ran the check: %s" % (
        label, explanation)
    opened = json.load(open(result_path))
    print("%s: %s" % (label, json.dumps(opened)))
    by_file = {entry["file"]: entry for entry in opened.values()}
    expected = {"plain.xyz": "ASCIIPointCloudReader", "cloud.las": "LASPointCloudReader",
                "cloud.pcd": "PCDPointCloudReader", "cloud.laz": "LAZPointCloudReader",
                "cloud.e57": "E57PointCloudReader"}
    for name, reader in expected.items():
        got = by_file.get(name, {}).get("reader")
        assert got == reader, "%s: File > Open %s: %s, without a dialog (got %s)" % (label, name, reader, got)
    for name in ("plain.xyz", "cloud.las", "cloud.pcd"):
        assert by_file.get(name, {}).get("points") == 500, "%s: %s: 500 points in the GUI" % (label, name)
