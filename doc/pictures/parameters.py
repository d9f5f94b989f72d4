# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Renders doc/images/parameters/<Property>.png for each property the
ParaView panel shows without the gear (advanced) button: a strip of panels
showing what the setting does, on the demo cloud (Data/trefoil.vtp) or a
synthetic one.

    scripts/with-xvfb.sh pvpython doc/pictures/parameters.py [Property ...]

Without arguments it renders all of them: OffsetDistance, CloseGaps,
MaximumNumberOfIterations, PreserveOffset, Sheets, RemoveSmallPieces,
OutputVolume.
"""
import argparse

import numpy as np

import nvpictures as nv

pvs = nv.plugin()
TREFOIL = nv.trefoil_points()
CENTER = (TREFOIL.min(axis=0) + TREFOIL.max(axis=0)) / 2
H = 0.012  # the grid spacing of these pictures (about 200 cells across the demo cloud): fast
FROM_ABOVE = [0.25, -0.55, 1.0]  # the camera for the trefoil, cut at z = 0
Y_UP = [0, 1, 0]
_sources = {}


def source(name, xyz):
    if name not in _sources:
        _sources[name] = nv.cloud_source(xyz)
    return _sources[name]


def trefoil():
    return source("trefoil", TREFOIL)


def sparse_trefoil():
    """Every 6th point of the demo cloud: a wrinkled shell after few steps."""
    return source("sparse", TREFOIL[::6])


def panel(strip, title, shell, cut=True, points=None, slab=0.0, sheet_only=False, zoom=1.2, direction=FROM_ABOVE,
          center=CENTER, extra=None):
    view = nv.new_view()
    if cut:
        nv.show_cut_open(view, shell, center, [0, 0, 1], points=points, slab=slab, point_size=2,
                         sheet_only=sheet_only)
    else:
        shown = pvs.Show(pvs.OutputPort(shell, 1), view)
        nv._solid(shown, nv.SHELL)
    if extra:
        extra(view)
    nv.look(view, center, direction, Y_UP, zoom=zoom)
    strip.add(view, title)
    pvs.Delete(view)


def offset_distance():
    strip = nv.Strip()
    automatic = None
    for factor in (0, 2, 5):
        offset = factor * automatic if factor else 0.0
        shell = nv.reconstruct(trefoil(), OffsetDistance=offset, SampleSpacing=H)
        shell.UpdatePipeline()
        used = nv.field_value(shell, "OffsetDistance")
        automatic = automatic or used
        panel(strip, "0 (automatic): l = %.3f" % used if not factor else "%.3f (%d x automatic)" % (used, factor),
              shell, points=TREFOIL, slab=0.25 * used)
    strip.save("parameters/OffsetDistance.png", title="Offset Distance: the wall's half-thickness l (cut open)")


def close_gaps():
    strip = nv.Strip()
    offset = 0.04
    xyz = nv.holey_sphere(offset, holes=(1.5, 2.0, 2.5))
    for value in (0, 1):
        shell = nv.reconstruct(source("holey", xyz), OffsetDistance=offset, SampleSpacing=offset / 4, CloseGaps=value)
        shell.UpdatePipeline()
        gaps = int(nv.field_value(shell, "NumberOfGaps") or 0)
        panel(strip, "%s: %d hole%s open" % ("off" if not value else "on (default)", gaps, "" if gaps == 1 else "s"),
              shell,
              points=xyz, slab=0.5 * offset, center=[0, 0, -0.1], direction=[0.0, -0.45, 1.0], zoom=1.45)
    strip.save("parameters/CloseGaps.png",
               title="Close Gaps: holes in the sampling (radius 1.5 l to 2.5 l)\nbridged, or piercing the wall")


def iterations():
    strip = nv.Strip()
    for steps in (0, 3, 10, 30):
        shell = nv.reconstruct(sparse_trefoil(), OffsetDistance=3 * H, SampleSpacing=H, Sheets="Outer",
                               MaximumNumberOfIterations=steps)
        shell.UpdatePipeline()
        panel(strip, "%d steps%s" % (steps, " (default)" if steps == 3 else ""), shell, cut=False,
              direction=[0.3, -0.8, 3.2], zoom=2.2, center=[0.55, 0.3, 0.0])
    strip.save("parameters/MaximumNumberOfIterations.png",
               title="Maximum Number Of Iterations: each step smooths the sheets "
                     "(outer sheet, every 6th point of the demo cloud, l = 3h)")


def preserve_offset():
    """The sheets' mean distance from the points against the number of steps,
    off and on, on a sphere of radius 0.15 (l = 0.04, h = 0.01): a plot, as
    the drift (a few tenths of h) is too small to see in a rendering."""
    radius, offset, spacing = 0.15, 0.04, 0.01
    xyz = nv.nvclouds.sphere_points(int(4 * np.pi * radius ** 2 / (0.5 * spacing) ** 2), radius)
    steps = [0, 1, 2, 3, 5, 10, 15, 20, 30]
    drift = {}
    for value in (0, 1):
        for n in steps:
            shell = nv.reconstruct(source("small sphere", xyz), OffsetDistance=offset, SampleSpacing=spacing,
                                   MaximumNumberOfIterations=n, PreserveOffset=value)
            shell.UpdatePipeline()
            surface = shell.GetClientSideObject().GetOutputDataObject(1)
            from vtkmodules.util.numpy_support import vtk_to_numpy
            r = np.linalg.norm(vtk_to_numpy(surface.GetPoints().GetData()), axis=1)
            drift[value, n] = (((radius + offset) - r[r > radius].mean()) / spacing,
                               ((radius - offset) - r[r < radius].mean()) / spacing)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(9, 3.4), sharey=True)
    for ax, sheet, name in zip(axes, (0, 1), ("outer sheet (radius 0.19)", "inner sheet (radius 0.11)")):
        for value, color, label in ((0, "tab:orange", "off (the paper's scheme)"), (1, "tab:blue", "on")):
            ax.plot(steps, [drift[value, n][sheet] for n in steps], "o-", color=color, label=label)
        ax.axvline(3, color="0.6", lw=0.8, ls=":")
        ax.set_title(name, fontsize=10)
        ax.set_xlabel("Maximum Number Of Iterations (steps)")
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("inward drift of the sheet (cells h)")
    axes[0].legend(fontsize=9, title="Preserve Offset", title_fontsize=9)
    fig.suptitle("Preserve Offset: the sheets stay at distance l while more steps smooth them\n"
                 "(a sphere of radius 0.15, l = 0.04, h = 0.01; the default is 3 steps)", fontsize=11)
    fig.tight_layout()
    nv.save_figure(fig, "parameters/PreserveOffset.png")
    plt.close(fig)


def sheets():
    strip = nv.Strip()
    for value in ("Both", "Outer", "Inner"):
        shell = nv.reconstruct(trefoil(), SampleSpacing=H, Sheets=value, OutputVolume=0)
        shell.UpdatePipeline()
        panel(strip, value + (" (default)" if value == "Both" else ""), shell, sheet_only=True)
    strip.save("parameters/Sheets.png", title="Sheets: which phi = 0 sheets the Surface holds (cut open)")


def remove_small_pieces():
    strip = nv.Strip()
    rng = np.random.default_rng(5)
    lone = CENTER + rng.uniform(-1.0, 1.0, size=(400, 3)) * [1.3, 1.2, 0.6]
    # 40 outliers at least 0.15 (five times the automatic offset) from the tube's points
    far = [p for p in lone if np.min(np.linalg.norm(TREFOIL - p, axis=1)) > 0.15]
    lone = np.array(far[:40])
    xyz = np.vstack([TREFOIL, lone])
    for value in (0, 1):
        shell = nv.reconstruct(source("outliers", xyz), OffsetDistance=0.03, SampleSpacing=H / 1.5,
                               RemoveSmallPieces=value)  # the demo cloud's automatic offset: outliers raise it
        shell.UpdatePipeline()
        pieces = int(nv.field_value(shell, "RemovedPieces") or 0)

        def outliers(view):
            nv.show_points(view, nv.cloud_source(lone), size=4)
        panel(strip, "off" if not value else "on (default): %d loose pieces removed" % pieces, shell, cut=False,
              extra=outliers, direction=[0.3, -0.8, 3.2], zoom=1.0)
    strip.save("parameters/RemoveSmallPieces.png",
               title="Remove Small Pieces: the balls around 40 outliers (blue) go")


def output_volume():
    strip = nv.Strip()
    shell = nv.reconstruct(trefoil(), SampleSpacing=H)
    shell.UpdatePipeline()

    def phi_on_slice(view):
        section = pvs.Slice(Input=pvs.OutputPort(shell, 0), SliceType="Plane")
        section.SliceType.Origin = list(CENTER)
        section.SliceType.Normal = [0, 0, 1]
        shown = pvs.Show(section, view)
        pvs.ColorBy(shown, ("POINTS", "phi"))
        lut = pvs.GetColorTransferFunction("phi")
        lut.ApplyPreset("Cool to Warm", True)
        lut.RescaleTransferFunction(-1.0, 1.0)
        shown.SetScalarBarVisibility(view, True)
        bar = pvs.GetScalarBar(lut, view)
        bar.Title = "phi"
        bar.ComponentTitle = ""
        bar.TitleColor = bar.LabelColor = [0, 0, 0]
        bar.TitleFontSize = bar.LabelFontSize = 14
        bar.ScalarBarLength = 0.5
        bar.AutomaticLabelFormat = 0
        bar.LabelFormat = bar.RangeLabelFormat = "%.1f"
        bar.WindowLocation = "Any Location"
        bar.Position = [0.84, 0.25]
        lines = pvs.Contour(Input=section, ContourBy=["POINTS", "phi"], Isosurfaces=[0.0])
        drawn = pvs.Show(lines, view)
        nv._solid(drawn, [0, 0, 0], 0.0)
        drawn.LineWidth = 1.5

    view = nv.new_view()
    phi_on_slice(view)
    nv.look(view, CENTER, [0, 0, 1], Y_UP, zoom=1.3)
    strip.add(view, "on (default): phi on the grid,\na slice at z = 0 (black: phi = 0)")
    pvs.Delete(view)
    off = nv.reconstruct(trefoil(), SampleSpacing=H, OutputVolume=0)
    off.UpdatePipeline()
    panel(strip, "off: the Surface alone\n(memory follows the band)", off, sheet_only=True, zoom=1.3,
          direction=[0, 0, 1])
    strip.save("parameters/OutputVolume.png", panel_inches=3.6,
               title="Output Volume: the phase field phi on the grid (+1 in the wall, -1 outside)")


PICTURES = {"OffsetDistance": offset_distance, "CloseGaps": close_gaps, "MaximumNumberOfIterations": iterations,
            "PreserveOffset": preserve_offset, "Sheets": sheets, "RemoveSmallPieces": remove_small_pieces,
            "OutputVolume": output_volume}

parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
parser.add_argument("names", nargs="*", choices=[[]] + list(PICTURES), default=[], metavar="Property",
                    help="the properties to draw (default: all): %s" % ", ".join(PICTURES))
args = parser.parse_args()
for name in args.names or PICTURES:
    PICTURES[name]()
