# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Reconstruct a narrow volume (thick shell) around a point cloud and save it.

    pvpython examples/reconstruct.py [cloud] [--offset L] [--spacing H | --max-dim N] [--out DIR]
    mpiexec -np 2 pvbatch examples/reconstruct.py cloud.ply --out shell

cloud: any point file ParaView opens (.vtp, .ply, .vtk, .csv, ...); default:
the project's demo cloud Data/trefoil.vtp. Writes, in DIR (default out/):
  NAME_phi.vti      the phase field phi on the grid (output port 0; .pvti under MPI)
  NAME_shell.vtp    the phi = 0 surfaces with normals (output port 1; .pvtp under MPI)
  NAME_shell.stl    the same surfaces, watertight, for 3D printing
  NAME.png          a picture: the shell cut open, with the input points
                  (skipped with a message when ParaView cannot render here:
                  no X display for an X-only build; use scripts/with-xvfb.sh)
The plugin: --plugin PATH, or found in PV_PLUGIN_PATH, this source tree's
build (BUILD_DIR, default build/) or this ParaView's plugin folders; nothing
to do where ParaView loads it already (Auto Load).

The VTK XML files are written in Binary mode, not in ParaView's default
Appended mode: with Debian 12's current libexpat, VTK 9.2's XML readers
(ParaView 5.11) read nothing from Appended files.
"""
import argparse
import os
import sys
import time

from paraview import servermanager
import paraview.simple as pvs

HERE = os.path.dirname(os.path.realpath(__file__))


def plugin_places():
    """Where NarrowVolume.so may be (glob patterns), in the order tried: the
    folders of PV_PLUGIN_PATH, this source tree's build (BUILD_DIR, default
    build/, for any ParaView version), and this ParaView's plugin folders."""
    places = []
    for folder in [f for f in os.environ.get("PV_PLUGIN_PATH", "").split(os.pathsep) if f]:
        places += [os.path.join(folder, "NarrowVolume.so"), os.path.join(folder, "NarrowVolume", "NarrowVolume.so")]
    builds = [b for b in (os.environ.get("BUILD_DIR", ""), os.path.join(HERE, "..", "build")) if b]
    prefixes = [os.path.dirname(os.path.dirname(os.path.realpath(sys.executable))), "/usr", "/usr/local"]
    for root in builds + prefixes:
        places += [os.path.join(root, "lib", "paraview-*", "plugins", "NarrowVolume", "NarrowVolume.so"),
                   os.path.join(root, "lib*", "*", "paraview-*", "plugins", "NarrowVolume", "NarrowVolume.so")]
    return list(dict.fromkeys(os.path.normpath(p) for p in places))


def load_plugin(explicit):
    """Loads the plugin (--plugin's path, else the first one found; none
    when ParaView loaded it already: Auto Load, PV_PLUGIN_PATH)."""
    import glob
    if not explicit and hasattr(pvs, "NarrowVolumeReconstruction"):
        return
    found = [path for place in plugin_places() for path in sorted(glob.glob(place))]
    path = explicit or (found[0] if found else None)
    if path is None:
        sys.exit("NarrowVolume.so not found. Build it (./scripts/build.sh in the source folder), then pass its path "
                 "with --plugin PATH or put its folder in PV_PLUGIN_PATH. Looked in:\n  " +
                 "\n  ".join(plugin_places()))
    pvs.LoadPlugin(path)  # defines paraview.simple.NarrowVolumeReconstruction
    report("plugin: %s" % path)


def can_render():
    """Whether a render window can open here. A ParaView that renders through
    X (Debian's) crashes in XSync without a display; EGL and OSMesa builds
    render without one."""
    from vtkmodules.vtkRenderingCore import vtkRenderWindow
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (registers the window class)

    if "XOpenGL" not in vtkRenderWindow().GetClassName():
        return True
    import ctypes
    import ctypes.util

    library = ctypes.util.find_library("X11")
    if not library:
        return False
    x11 = ctypes.CDLL(library)
    x11.XOpenDisplay.restype = ctypes.c_void_p
    x11.XOpenDisplay.argtypes = [ctypes.c_char_p]
    x11.XCloseDisplay.argtypes = [ctypes.c_void_p]
    display = x11.XOpenDisplay(None)
    if not display:
        return False
    x11.XCloseDisplay(display)
    return True


def report(*values):
    """print, flushed at once: pvpython's stdout holds a pipe's lines until it exits."""
    print(*values, flush=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("cloud", nargs="?", default=os.path.join(HERE, "..", "Data", "trefoil.vtp"))
    parser.add_argument("--offset", type=float, default=0.0,
                        help="offset distance l (world units); default 0: the filter's automatic offset, "
                             "from the distances between neighbouring points")
    parser.add_argument("--spacing", type=float, default=0.0,
                        help="grid spacing h (world units); default 0: the filter's, l / 4")
    parser.add_argument("--max-dim", type=int, default=0,
                        help="cells along the longest side when --spacing is not given (default 0: the filter's)")
    parser.add_argument("--iterations", type=int, default=3, help="time steps (default 3)")
    parser.add_argument("--out", default="out", help="output folder (default out/)")
    parser.add_argument("--plugin", default="", help="path of NarrowVolume.so")
    parser.add_argument("--no-picture", action="store_true", help="skip the PNG")
    parser.add_argument("--up", choices="xyz", default="z", help="the model's up axis, for the picture (default z)")
    args = parser.parse_args()

    load_plugin(args.plugin)
    name = os.path.splitext(os.path.basename(args.cloud))[0]
    os.makedirs(args.out, exist_ok=True)

    reader = pvs.OpenDataFile(args.cloud)
    if reader is None:
        sys.exit("ParaView cannot open %s" % args.cloud)
    reader.UpdatePipeline()
    bounds = reader.GetDataInformation().GetBounds()
    longest = max(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4])

    # The filter's own defaults (the same in the GUI, pvpython and VTK); only
    # what was given on the command line is set.
    shell = pvs.NarrowVolumeReconstruction(Input=reader)
    shell.MaximumNumberOfIterations = args.iterations
    shell.OffsetDistance = args.offset
    shell.SampleSpacing = args.spacing
    shell.MaximumDimension = args.max_dim
    start = time.time()
    shell.UpdatePipeline()
    elapsed = time.time() - start

    volume_info = shell.GetDataInformation(0)
    surface_info = shell.GetDataInformation(1)
    report("input: %s, %d points" % (args.cloud, reader.GetDataInformation().GetNumberOfPoints()))
    field = volume_info.GetFieldDataInformation()
    used = {name: field.GetArrayInformation(name).GetComponentRange(0)[0]
            for name in ("OffsetDistance", "SampleSpacing", "AddedPoints", "NumberOfGaps", "RemovedPieces")
            if field.GetArrayInformation(name)}
    report("offset distance l = %g, spacing h = %g, grid %s nodes" % (
        used.get("OffsetDistance", shell.OffsetDistance), used.get("SampleSpacing", 0.0), volume_info.GetExtent()))
    report("points added in holes: %d, gaps left open: %d, loose pieces removed: %d" % (
        used.get("AddedPoints", 0), used.get("NumberOfGaps", 0), used.get("RemovedPieces", 0)))
    report("surface: %d triangles, %.2f s" % (surface_info.GetNumberOfCells(), elapsed))

    # Under MPI, ParaView writes image data as a parallel .pvti (one piece a rank).
    ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
    volume_file = name + ("_phi.pvti" if ranks > 1 else "_phi.vti")
    pvs.SaveData(os.path.join(args.out, volume_file), proxy=shell, PointDataArrays=["phi"], DataMode="Binary")
    surface = pvs.OutputPort(shell, 1)
    surface_file = name + ("_shell.pvtp" if ranks > 1 else "_shell.vtp")
    pvs.SaveData(os.path.join(args.out, surface_file), proxy=surface, DataMode="Binary")
    pvs.SaveData(os.path.join(args.out, name + "_shell.stl"), proxy=surface)

    picture = not args.no_picture
    if picture and not can_render():
        report("no picture: ParaView cannot open a window here (no X display); run the script under "
              "scripts/with-xvfb.sh, or pass --no-picture")
        picture = False
    if picture:
        view = pvs.CreateView("RenderView")
        pvs.SetActiveView(view)
        view.ViewSize = [1200, 900]
        view.OrientationAxesVisibility = 0
        view.Background = [1, 1, 1]
        try:
            view.UseColorPaletteForBackground = 0
        except AttributeError:
            pass
        center = [(bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2, (bounds[4] + bounds[5]) / 2]
        # Cut the shell open to show its thickness, with the input points inside.
        clip = pvs.Clip(Input=surface, ClipType="Plane")
        clip.ClipType.Origin = center
        up = [1.0 if args.up == a else 0.0 for a in "xyz"]
        clip.ClipType.Normal = up
        clip.Invert = 1
        shown = pvs.Show(clip, view)
        shown.ColorArrayName = ["POINTS", ""]
        shown.DiffuseColor = [0.85, 0.55, 0.3]
        shown.Specular = 0.3
        points = pvs.Show(reader, view)
        points.ColorArrayName = ["POINTS", ""]
        points.SetRepresentationType("Points")
        points.PointSize = 2
        points.DiffuseColor = [0.1, 0.2, 0.6]
        points.AmbientColor = [0.1, 0.2, 0.6]
        pvs.Render(view)  # the first render resets the camera; place it after
        # Look from the front, a little from above the cut.
        front = {"x": [0.0, -1.4, 0.6], "y": [0.6, 1.6, 1.4], "z": [0.6, -1.4, 1.6]}[args.up]
        view.CameraPosition = [center[a] + front[a] * longest for a in range(3)]
        view.CameraFocalPoint = center
        view.CameraViewUp = up
        view.ResetCamera()
        pvs.GetActiveCamera().Dolly(1.5)
        pvs.Render(view)
        pvs.SaveScreenshot(os.path.join(args.out, name + ".png"), view, ImageResolution=[1200, 900])
    report("wrote %s/%s, %s, %s_shell.stl%s" %
          (args.out, volume_file, surface_file, name, ", %s.png" % name if picture else ""))


if __name__ == "__main__":
    main()
