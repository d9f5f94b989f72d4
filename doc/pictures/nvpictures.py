# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""What the documentation's pictures share: the plugin, the clouds, one look
(white background, the same colours and lights), the shell cut open, and the
strips of panels with their titles, written small (a PNG of 256 colours).

Imported by the pvpython scripts of doc/pictures/; scripts/pictures.sh runs
them all under scripts/with-xvfb.sh. The build is $BUILD_DIR, or build/.
The scans are read where they are (../shared/data/scans, or $NV_SCANS_DIR),
never copied: the pictures are renderings of the filter's output.
"""
import os
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.normpath(os.path.join(HERE, "..", ".."))
BUILD = os.environ.get("BUILD_DIR") or os.path.join(SOURCE, "build")
PLUGIN = os.path.join(BUILD, "lib", "paraview-5.11", "plugins", "NarrowVolume", "NarrowVolume.so")
IMAGES = os.path.join(SOURCE, "doc", "images")
sys.path.insert(0, os.path.join(SOURCE, "Data"))  # nvclouds, nvshapes: the clouds the tests and benchmarks share

import nvclouds  # noqa: E402

SCANS_DIR = nvclouds.SCANS_DIR

# One look for every picture.
SHELL = [0.85, 0.55, 0.30]     # the shell's sheets (orange, as in the README's pictures)
SECTION = [0.72, 0.22, 0.16]   # the cut through the wall (red)
POINTS = [0.10, 0.20, 0.60]    # the input points (dark blue)
ADDED = [0.0, 0.62, 0.25]      # points added by gap closing (green)
PANEL = (480, 400)             # one panel's pixels

_loaded = {"__name__": "nvpictures"}  # not empty: LoadPlugin fills a namespace only if it is true


def plugin():
    """Loads the compiled plugin once; returns paraview.simple with the filter in it."""
    import paraview.simple as pvs

    if "NarrowVolumeReconstruction" not in _loaded:
        if not os.path.exists(PLUGIN):
            sys.exit("NarrowVolume.so not found at %s: build the project first (scripts/build.sh)" % PLUGIN)
        pvs.LoadPlugin(PLUGIN, ns=_loaded)
    return pvs


def reconstruct(source, **properties):
    """The filter on a source proxy, with these properties."""
    plugin()
    return _loaded["NarrowVolumeReconstruction"](Input=source, **properties)


def producer(polydata):
    """A source proxy holding a vtkPolyData made here (a builtin session)."""
    pvs = plugin()
    source = pvs.PVTrivialProducer()
    source.GetClientSideObject().SetOutput(polydata)
    source.UpdatePipeline()
    return source


def cloud_source(xyz):
    """A source proxy of points, with a vertex cell each (drawn as they are), from an (n, 3) array."""
    from vtkmodules.util.numpy_support import numpy_to_vtkIdTypeArray
    from vtkmodules.vtkCommonDataModel import vtkCellArray

    data = nvclouds.cloud(np.asarray(xyz, dtype=float))
    n = data.GetNumberOfPoints()
    cells = vtkCellArray()
    cells.SetData(numpy_to_vtkIdTypeArray(np.arange(n + 1, dtype=np.int64), deep=1),
                  numpy_to_vtkIdTypeArray(np.arange(n, dtype=np.int64), deep=1))
    data.SetVerts(cells)
    return producer(data)


def holey_sphere(offset, holes=(1.5, 2.5, 3.5), seed=27):
    """Points on a sphere of radius 0.5, 0.6 `offset` apart, slightly
    jittered, with empty caps of the radii `holes` (in units of `offset`)
    around directions below the equator (azimuths 90, 210 and 330 degrees)."""
    import math

    rng = np.random.default_rng(seed)
    xyz = nvclouds.sphere_points(int(4 * math.pi * 0.25 / (0.6 * offset) ** 2), 0.5)
    xyz += rng.normal(scale=0.06 * offset, size=xyz.shape)
    xyz = 0.5 * xyz / np.linalg.norm(xyz, axis=1)[:, None]
    for azimuth, radius in zip((90.0, 210.0, 330.0), holes):
        a = math.radians(azimuth)
        direction = np.array([math.cos(a), math.sin(a), -0.9])
        direction /= np.linalg.norm(direction)
        xyz = xyz[np.linalg.norm(xyz - 0.5 * direction, axis=1) > radius * offset]
    return xyz


def scan_points(name):
    """The (n, 3) points of a scan of ../shared/data/scans, or None (with a message) when it is missing."""
    try:
        return nvclouds.scan_points(name)
    except (LookupError, OSError) as error:
        print("skipped %s: %s" % (name, error), flush=True)
        return None


def trefoil_points():
    return nvclouds.points_of_file(nvclouds.data_file("trefoil.vtp"))


def field_value(shell, name):
    """A value of the Volume output's field data ("OffsetDistance", "SampleSpacing", ...)."""
    info = shell.GetDataInformation(0).GetFieldDataInformation().GetArrayInformation(name)
    return info.GetComponentRange(0)[0] if info else None


def new_view(size=PANEL):
    pvs = plugin()
    view = pvs.CreateView("RenderView")
    view.ViewSize = list(size)
    view.OrientationAxesVisibility = 0
    view.Background = [1, 1, 1]
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    return view


def _solid(display, color, specular=0.25):
    display.ColorArrayName = ["POINTS", ""]
    display.DiffuseColor = color
    display.AmbientColor = color
    display.Specular = specular


def show_points(view, source, color=POINTS, size=2.0):
    pvs = plugin()
    shown = pvs.Show(source, view)
    shown.SetRepresentationType("Points")
    _solid(shown, color, 0.0)
    shown.PointSize = size
    shown.RenderPointsAsSpheres = 0
    return shown


def show_cut_open(view, shell, origin, normal, points=None, slab=0.0, point_size=3.0, sheet_only=False,
                  color=SHELL):
    """The shell's surface with the half on the side of `normal` cut away, the
    wall's section in the cut plane (phi >= 0 on a slice of the Volume), and
    the input points `points` ((n, 3)) that lie within `slab` in front of the
    plane, drawn on the section. sheet_only: no section (the Volume output is off)."""
    pvs = plugin()
    clip = pvs.Clip(Input=pvs.OutputPort(shell, 1), ClipType="Plane")
    clip.ClipType.Origin = list(origin)
    clip.ClipType.Normal = list(normal)
    clip.Invert = 1
    shown = pvs.Show(clip, view)
    _solid(shown, color)
    if not sheet_only:
        section = pvs.Slice(Input=pvs.OutputPort(shell, 0), SliceType="Plane")
        section.SliceType.Origin = list(origin)
        section.SliceType.Normal = list(normal)
        wall = pvs.Clip(Input=section, ClipType="Scalar", Scalars=["POINTS", "phi"], Value=0.0)
        wall.Invert = 0
        cut = pvs.Show(wall, view)
        _solid(cut, SECTION, 0.0)
    if points is not None and slab > 0:
        d = (np.asarray(points) - np.asarray(origin)) @ (np.asarray(normal) / np.linalg.norm(normal))
        near = np.asarray(points)[(d > 0) & (d < slab)]
        if len(near):
            show_points(view, cloud_source(near), size=point_size)
    return clip


def look(view, center, direction, up, zoom=1.0):
    """Camera on `center` from `direction` (relative), `up` up, the scene
    fitted to the view, then zoomed."""
    pvs = plugin()
    pvs.Render(view)  # the first render resets the camera: place it after
    view.CameraFocalPoint = list(center)
    view.CameraPosition = [c + d for c, d in zip(center, direction)]
    view.CameraViewUp = list(up)
    view.CameraParallelProjection = 0
    view.ResetCamera()
    camera = view.GetActiveCamera()
    camera.Zoom(zoom)
    pvs.Render(view)


class Strip:
    """Panels rendered one by one, then laid out in rows with their titles."""

    def __init__(self):
        self._scratch = tempfile.TemporaryDirectory()
        self.panels = []  # (title, path)

    def add(self, view, title):
        pvs = plugin()
        path = os.path.join(self._scratch.name, "%d.png" % len(self.panels))
        pvs.SaveScreenshot(path, view, ImageResolution=list(view.ViewSize))
        self.panels.append((title, path))

    def blank(self, title):
        self.panels.append((title, None))

    def save(self, name, columns=None, title=None, caption=None, panel_inches=3.0, dpi=100):
        """Writes doc/images/<name> (256 colours); columns: panels a row."""
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.image as mpimg
        import matplotlib.pyplot as plt

        count = len(self.panels)
        columns = columns or count
        rows = (count + columns - 1) // columns
        aspect = PANEL[1] / PANEL[0]
        head = 0.45 if title else 0.0
        foot = 0.35 * (caption.count("\n") + 1) if caption else 0.0
        width = columns * panel_inches
        height = rows * (panel_inches * aspect + 0.35) + head + foot
        fig, axes = plt.subplots(rows, columns, figsize=(width, height), squeeze=False)
        for ax in axes.ravel():
            ax.axis("off")
        for ax, (text, path) in zip(axes.ravel(), self.panels):
            if path:
                ax.imshow(mpimg.imread(path))
            ax.set_title(text, fontsize=10)
        if title:
            fig.suptitle(title, fontsize=12)
        if caption:
            fig.text(0.5, 0.01, caption, ha="center", va="bottom", fontsize=9, color="0.25")
        fig.tight_layout(rect=(0, foot / height, 1, 1 - head / height), pad=0.4, h_pad=0.6, w_pad=0.3)
        path = save_figure(fig, name, dpi)
        plt.close(fig)
        return path


def save_figure(fig, name, dpi=100):
    """Saves a matplotlib figure as doc/images/<name>, quantized to 256 colours."""
    path = os.path.join(IMAGES, name)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    fig.savefig(path, dpi=dpi, facecolor="white")
    small(path)
    from PIL import Image

    with Image.open(path) as image:
        size = image.size
    print("wrote %s (%d x %d px, %d kB)" % (os.path.relpath(path, SOURCE), size[0], size[1],
                                            os.path.getsize(path) // 1024), flush=True)
    return path


def small(path):
    """Rewrites a PNG with 256 colours (a third of the bytes, no visible change on these renderings)."""
    from PIL import Image

    with Image.open(path) as image:
        rgb = image.convert("RGB")
    rgb.quantize(colors=256, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE).save(path, optimize=True)
