# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""examples/reconstruct.py runs in pvpython and in pvbatch and writes a
watertight shell (STL), the phi volume and a picture."""
import os
import subprocess
import sys

from vtkmodules.vtkIOGeometry import vtkSTLReader
from vtkmodules.vtkIOXML import vtkXMLImageDataReader, vtkXMLPolyDataReader
from vtkmodules.vtkIOImage import vtkPNGReader

import nvtesting

source_dir, plugin, with_xvfb = sys.argv[1], sys.argv[2], sys.argv[3]
t = nvtesting.Checker("test_example_script")
script = os.path.join(source_dir, "examples", "reconstruct.py")

for program in ("pvpython", "pvbatch"):
    out = nvtesting.scratch_folder(prefix="nv-example-")
    command = [with_xvfb, program, script, "--plugin", plugin, "--max-dim", "60", "--out", out]
    result = subprocess.run(command, capture_output=True, text=True, timeout=600)
    print(result.stdout)
    t.check(result.returncode == 0, "%s ran: %s" % (program, nvtesting.explain(result)))
    for suffix in ("_phi.vti", "_shell.vtp", "_shell.stl", ".png"):
        t.check(os.path.exists(os.path.join(out, "trefoil" + suffix)), "%s wrote trefoil%s" % (program, suffix))
    stl = vtkSTLReader()
    stl.SetFileName(os.path.join(out, "trefoil_shell.stl"))
    stl.Update()
    shell = stl.GetOutput()
    t.check(shell.GetNumberOfCells() > 1000, "%s: STL has triangles" % program)
    t.check(nvtesting.boundary_edges(shell) == 0, "%s: STL is watertight" % program)
    vti = vtkXMLImageDataReader()
    vti.SetFileName(os.path.join(out, "trefoil_phi.vti"))
    vti.Update()
    t.check(vti.GetOutput().GetPointData().GetArray("phi") is not None, "%s: phi in the .vti" % program)
    vtp = vtkXMLPolyDataReader()
    vtp.SetFileName(os.path.join(out, "trefoil_shell.vtp"))
    vtp.Update()
    t.check(vtp.GetOutput().GetNumberOfCells() == shell.GetNumberOfCells(),
            "%s: the .vtp reads back with the STL's %d triangles (%d)"
            % (program, shell.GetNumberOfCells(), vtp.GetOutput().GetNumberOfCells()))
    picture = os.path.join(out, "trefoil.png")
    if t.check(os.path.exists(picture), "%s: no picture written" % program):
        png = vtkPNGReader()
        png.SetFileName(picture)
        png.Update()
        scalars = png.GetOutput().GetPointData().GetScalars()
        # The picture has content: more than one colour.
        lo, hi = scalars.GetRange(0) if scalars else (0, 0)
        t.check(hi - lo > 50, "%s: picture has content (red channel %g..%g)" % (program, lo, hi))

# Without a display, the script writes its data and skips the picture with a
# message; it never crashes (Debian's ParaView renders through X).
out = nvtesting.scratch_folder(prefix="nv-example-nodisplay-")
env = {k: v for k, v in os.environ.items() if k != "DISPLAY"}
result = subprocess.run(["pvpython", script, "--plugin", plugin, "--max-dim", "40", "--out", out],
                        capture_output=True, text=True, timeout=600, env=env)
print(result.stdout)
t.check(result.returncode == 0, "without a display: the script ran: %s" % nvtesting.explain(result))
t.check(os.path.exists(os.path.join(out, "trefoil_shell.stl")) and os.path.exists(os.path.join(out, "trefoil_phi.vti")),
        "without a display: the data files are written")
t.check("no picture" in result.stdout or os.path.exists(os.path.join(out, "trefoil.png")),
        "without a display: a picture (offscreen) or a message that says why not")
t.finish()
