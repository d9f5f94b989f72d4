# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""examples/reconstruct.py runs in pvpython and in pvbatch and writes a
watertight shell (STL), the phi volume and a picture.

    pvpython -m pytest test_example_script.py --plugin PLUGIN [--source-dir SOURCE] [--with-xvfb WITH_XVFB]
"""
import os
import subprocess

import pytest
from vtkmodules.vtkIOGeometry import vtkSTLReader
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkIOXML import vtkXMLImageDataReader, vtkXMLPolyDataReader

import nvtesting

pytestmark = pytest.mark.gui


@pytest.fixture(scope="module")
def script(source_dir):
    return os.path.join(source_dir, "examples", "reconstruct.py")


@pytest.mark.parametrize("program", ["pvpython", "pvbatch"])
def test_example_script(script, plugin_path, with_xvfb, program):
    out = nvtesting.scratch_folder(prefix="nv-example-")
    command = [with_xvfb, program, script, "--plugin", plugin_path, "--max-dim", "60", "--out", out]
    result = subprocess.run(command, capture_output=True, text=True, timeout=600)
    print(result.stdout)
    assert result.returncode == 0, "%s ran: %s" % (program, nvtesting.explain(result))
    for suffix in ("_phi.vti", "_shell.vtp", "_shell.stl", ".png"):
        assert os.path.exists(os.path.join(out, "trefoil" + suffix)), "%s wrote trefoil%s" % (program, suffix)
    stl = vtkSTLReader()
    stl.SetFileName(os.path.join(out, "trefoil_shell.stl"))
    stl.Update()
    shell = stl.GetOutput()
    assert shell.GetNumberOfCells() > 1000, "%s: STL has triangles" % program
    assert nvtesting.boundary_edges(shell) == 0, "%s: STL is watertight" % program
    vti = vtkXMLImageDataReader()
    vti.SetFileName(os.path.join(out, "trefoil_phi.vti"))
    vti.Update()
    assert vti.GetOutput().GetPointData().GetArray("phi") is not None, "%s: phi in the .vti" % program
    vtp = vtkXMLPolyDataReader()
    vtp.SetFileName(os.path.join(out, "trefoil_shell.vtp"))
    vtp.Update()
    assert vtp.GetOutput().GetNumberOfCells() == shell.GetNumberOfCells(), \
        "%s: the .vtp reads back with the STL's %d triangles (%d)" % (
            program, shell.GetNumberOfCells(), vtp.GetOutput().GetNumberOfCells())
    picture = os.path.join(out, "trefoil.png")
    assert os.path.exists(picture), "%s: no picture written" % program
    png = vtkPNGReader()
    png.SetFileName(picture)
    png.Update()
    scalars = png.GetOutput().GetPointData().GetScalars()
    # The picture has content: more than one colour.
    lo, hi = scalars.GetRange(0) if scalars else (0, 0)
    assert hi - lo > 50, "%s: picture has content (red channel %g..%g)" % (program, lo, hi)


def test_without_a_display(script, plugin_path):
    """Without a display, the script writes its data and skips the picture
    with a message; it never crashes (Debian's ParaView renders through X)."""
    out = nvtesting.scratch_folder(prefix="nv-example-nodisplay-")
    env = {k: v for k, v in os.environ.items() if k != "DISPLAY"}
    result = subprocess.run(["pvpython", script, "--plugin", plugin_path, "--max-dim", "40", "--out", out],
                            capture_output=True, text=True, timeout=600, env=env)
    print(result.stdout)
    assert result.returncode == 0, "without a display: the script ran: %s" % nvtesting.explain(result)
    assert os.path.exists(os.path.join(out, "trefoil_shell.stl")) and \
        os.path.exists(os.path.join(out, "trefoil_phi.vti")), "without a display: the data files are written"
    assert "no picture" in result.stdout or os.path.exists(os.path.join(out, "trefoil.png")), \
        "without a display: a picture (offscreen) or a message that says why not"


def test_finds_the_plugin_itself(script, plugin_path):
    """Run as the README gives it, without --plugin or PV_PLUGIN_PATH, from
    another folder: it finds the build's plugin (BUILD_DIR, as
    scripts/build.sh takes it, or build/ beside the source)."""
    out = nvtesting.scratch_folder(prefix="nv-example-find-")
    env = {k: v for k, v in os.environ.items() if k != "PV_PLUGIN_PATH"}
    env["BUILD_DIR"] = nvtesting.build_of(plugin_path)
    result = subprocess.run(["pvpython", script, "--max-dim", "40", "--no-picture", "--out", out], cwd=out, env=env,
                            capture_output=True, text=True, timeout=600)
    print(result.stdout)
    assert result.returncode == 0, nvtesting.explain(result)
    assert "plugin: %s" % os.path.normpath(plugin_path) in result.stdout, "found the build's plugin"
    assert os.path.exists(os.path.join(out, "trefoil_shell.stl"))
