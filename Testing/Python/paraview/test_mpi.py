# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch under MPI gives the serial result. With 1, 2, 3 and 4 ranks, the
cloud split unevenly between them (one rank empty), the filter runs
distributed (mpi_script.py) and ParaView's parallel writers save one piece per
rank. Every rank's information pass declares the serial grid before the run.
Here the files are read back and compared with a serial run of the same
filter: the .pvti, read whole, has the serial grid (its header's whole extent
as SaveData wrote it) and phi equal to the Gauss-Seidel tolerance on every
node; the surface made of the pieces is closed (no cracks, no duplicate
triangles at the seams) with the serial area and triangles; ParaView's Slice,
Clip, Threshold, Contour, ResampleToImage and PlotOverLine on the distributed
volume give the cells of the 1-rank run. Also with OutputVolume off (surface
by slabs), with PreserveOffset on (10 steps; phi bit for bit the serial
phi, whose multiplier sums bricks across the slabs), a sphere with holes
(gap closing: the serial points added, gaps, surface and phi on 2 and 3
ranks), the plain VTK filter
with 3 ranks and ghost levels, pvserver with a pvpython client, and the
example script.

    pvpython -m pytest test_mpi.py --plugin PLUGIN [--trefoil CLOUD]
"""
import ast
import json
import os
import re
import socket
import subprocess
import types
import xml.etree.ElementTree as ElementTree

import numpy as np
import pytest
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import (vtkXMLImageDataReader, vtkXMLPImageDataReader, vtkXMLPPolyDataReader,
                                 vtkXMLPolyDataReader, vtkXMLPolyDataWriter)

import narrowvolume
import nvclouds
import nvtesting

pytestmark = [pytest.mark.mpi, pytest.mark.slow]
HERE = os.path.dirname(os.path.abspath(__file__))
# pvpython may itself be an MPI singleton: its Open MPI variables must not
# leak into the mpiexec it starts.
ENV = {k: v for k, v in os.environ.items() if not k.startswith(("OMPI_", "PMIX_", "OPAL_", "PMI_"))}
MPIEXEC = ["mpiexec", "--allow-run-as-root", "--oversubscribe", "-np"]


def serial_run(cloud, preserve):
    """The serial reference: the same filter and parameters, all points at
    once: (filter, phi, triangles, area)."""
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(cloud)
    f = narrowvolume.vtkNarrowVolumeReconstruction()
    f.SetInputConnection(reader.GetOutputPort())
    f.SetOffsetDistance(0.08)
    f.SetMaximumDimension(90)
    if preserve:
        f.SetPreserveOffset(True)
        f.SetMaximumNumberOfIterations(10)
    f.Update()
    triangles, open_edges, area = nvtesting.merged_surface(f.GetSurfaceOutput())
    print("serial%s: grid %s, %d band nodes, %d triangles, %d open edges, area %.6f"
          % (", PreserveOffset" if preserve else "", f.GetVolumeOutput().GetDimensions(), f.GetNumberOfBandNodes(),
             triangles, open_edges, area))
    assert open_edges == 0 and triangles > 1000, "the serial surface is closed"
    return f, vtk_to_numpy(f.GetVolumeOutput().GetPointData().GetArray("phi")), triangles, area


@pytest.fixture(scope="module")
def serial(trefoil):
    """The serial runs on the demo cloud: the filter, its grid, and {PreserveOffset: (phi, triangles, area)}."""
    f, phi, triangles, area = serial_run(trefoil, False)
    dims = f.GetVolumeOutput().GetDimensions()
    return types.SimpleNamespace(
        f=f, dims=dims, phi=phi, triangles=triangles, area=area,
        extent=(0, dims[0] - 1, 0, dims[1] - 1, 0, dims[2] - 1), origin=f.GetVolumeOutput().GetOrigin(),
        spacing=f.GetVolumeOutput().GetSpacing(),
        references={False: (phi, triangles, area), True: serial_run(trefoil, True)[1:]})


@pytest.fixture(scope="module")
def pvbatch(plugin_path):
    """pvbatch(ranks, cloud, output_volume, preserve): mpi_script.py under
    mpiexec, each configuration run once: (its output folder, the run)."""
    runs = {}

    def run(ranks, cloud, output_volume, preserve):
        key = (ranks, cloud, output_volume, preserve)
        if key not in runs:
            out = nvtesting.scratch_folder(prefix="nv-mpi-")
            command = MPIEXEC + [str(ranks), "pvbatch", os.path.join(HERE, "mpi_script.py"), plugin_path, out, cloud,
                                 str(output_volume), str(preserve)]
            runs[key] = out, subprocess.run(command, capture_output=True, text=True, timeout=600, env=ENV)
        return runs[key]
    return run


DECLARED = re.compile(r"information pass, rank (\d+) of (\d+): whole extent (\(.*?\)), origin (\(.*?\)), "
                      r"spacing (\(.*?\)), scalar type (\w+), points (\d+)")
CONFIGURATIONS = [(1, 1, 0), (2, 1, 0), (3, 1, 0), (4, 1, 0), (4, 0, 0), (3, 1, 1)]


def downstream_of(out):
    return json.load(open(out + "/downstream.json")) if os.path.exists(out + "/downstream.json") else {}


def figures_of(field, names):
    return {name: [field.GetArray(name).GetValue(c) for c in range(field.GetArray(name).GetNumberOfValues())]
            if field.GetArray(name) else None for name in names}


@pytest.mark.parametrize("ranks, output_volume, preserve", CONFIGURATIONS,
                         ids=["%d ranks, OutputVolume %d%s" % (r, v, ", PreserveOffset" if p else "")
                              for r, v, p in CONFIGURATIONS])
def test_pvbatch_gives_the_serial_result(serial, pvbatch, trefoil, ranks, output_volume, preserve):
    out, run = pvbatch(ranks, trefoil, output_volume, preserve)
    label = "%d ranks, OutputVolume %d%s" % (ranks, output_volume, ", PreserveOffset" if preserve else "")
    ref_phi, ref_triangles, ref_area = serial.references[bool(preserve)]
    assert run.returncode == 0 and os.path.exists(out + "/surface.pvtp"), "%s ran: %s" % (
        label, nvtesting.explain(run))
    # The information pass: every rank declares the serial grid, float
    # scalars (VTK_FLOAT = 10), before the filter has run (no points yet).
    passes = {int(m.group(1)): m for m in DECLARED.finditer(run.stdout)}
    print("%s: information pass on ranks %s: whole extent %s" % (
        label, sorted(passes), sorted({m.group(3) for m in passes.values()})))
    assert sorted(passes) == list(range(ranks)) and all(int(m.group(2)) == ranks for m in passes.values()), \
        "%s: every rank ran the information pass" % label
    for rank, m in sorted(passes.items()):
        assert ast.literal_eval(m.group(3)) == serial.extent and ast.literal_eval(m.group(4)) == serial.origin and \
            ast.literal_eval(m.group(5)) == serial.spacing and m.group(6) == "10" and m.group(7) == "0", \
            "%s: rank %d declares the serial grid before the run: %s" % (label, rank, m.group(0))
    surface_reader = vtkXMLPPolyDataReader()
    surface_reader.SetFileName(out + "/surface.pvtp")
    surface_reader.Update()
    pieces = surface_reader.GetNumberOfPieces()
    triangles, open_edges, area = nvtesting.merged_surface(surface_reader.GetOutput())
    print("%s: %d pieces, %d triangles, %d open edges, area %.6f" % (label, pieces, triangles, open_edges, area))
    assert pieces == ranks, "%s: one surface piece per rank" % label
    assert open_edges == 0, "%s: the merged surface is closed (%d open edges)" % (label, open_edges)
    assert triangles == ref_triangles, "%s: serial triangles (%d vs %d)" % (label, triangles, ref_triangles)
    assert abs(area - ref_area) <= 1e-6 * ref_area, "%s: serial area (%.9f vs %.9f)" % (label, area, ref_area)
    if not output_volume:
        return
    # The .pvti as SaveData wrote it: the serial whole extent, origin and
    # spacing in its header, one piece per rank, each a slab of z layers
    # starting where the one below ends (the layer they share).
    header = ElementTree.parse(out + "/phi.pvti").getroot().find("PImageData")
    whole = tuple(int(v) for v in header.get("WholeExtent").split())
    slabs = [tuple(int(v) for v in piece.get("Extent").split()) for piece in header.findall("Piece")]
    print("%s: .pvti whole extent %s, pieces %s" % (label, whole, [piece[4:] for piece in slabs]))
    assert whole == serial.extent, "%s: the .pvti's whole extent is the serial grid's (%s)" % (label, whole)
    assert np.allclose([float(v) for v in header.get("Origin").split()], serial.origin, rtol=0, atol=1e-12) and \
        np.allclose([float(v) for v in header.get("Spacing").split()], serial.spacing, rtol=0, atol=1e-15), \
        "%s: the .pvti's origin and spacing are the serial grid's" % label
    assert len(slabs) == ranks and all(piece[:4] == serial.extent[:4] for piece in slabs) and slabs[0][4] == 0 and \
        slabs[-1][5] == serial.extent[5] and all(slabs[i][5] == slabs[i + 1][4] for i in range(len(slabs) - 1)), \
        "%s: one slab per rank, tiling z" % label
    # Read whole, as any reader of a .pvti does.
    volume_reader = vtkXMLPImageDataReader()
    volume_reader.SetFileName(out + "/phi.pvti")
    volume_reader.Update()
    volume = volume_reader.GetOutput()
    assert tuple(volume.GetExtent()) == serial.extent and volume.GetNumberOfPoints() == len(ref_phi), \
        "%s: the .pvti reads back as the serial grid (%s)" % (label, volume.GetExtent())
    phi_array = volume.GetPointData().GetArray("phi")
    assert phi_array is not None and phi_array.GetNumberOfTuples() == len(ref_phi), \
        "%s: the .pvti holds phi on every node" % label
    difference = float(np.max(np.abs(vtk_to_numpy(phi_array) - ref_phi)))
    print("%s: max |phi - serial phi| = %.3g" % (label, difference))
    assert difference <= 1e-6, "%s: phi equals the serial phi to the Gauss-Seidel tolerance" % label
    if preserve:
        assert difference == 0.0, "%s: phi is the serial phi, bit for bit" % label
        assert float(np.max(np.abs(vtk_to_numpy(phi_array) - serial.references[False][0]))) > 1e-3, \
            "%s: the correction changed phi" % label
    # The points' spacing, measured slab by slab (each rank holds its slab
    # and asks its neighbours about points near the faces): the serial figures.
    names = ("MedianPointSpacing", "NumberOfGaps", "LargestGap", "LargestGapCenter")
    spacing, serial_spacing_figures = figures_of(volume.GetFieldData(), names), figures_of(
        serial.f.GetVolumeOutput().GetFieldData(), names)
    print("%s: spacing figures %s" % (label, spacing))
    assert spacing == serial_spacing_figures and None not in spacing.values(), \
        "%s: the serial spacing, gaps and largest gap (%s vs %s)" % (label, spacing, serial_spacing_figures)
    band = volume.GetFieldData().GetArray("NarrowBandNodes")
    assert band is not None and band.GetValue(0) == serial.f.GetNumberOfBandNodes(), \
        "%s: the serial band (%d nodes)" % (label, band.GetValue(0) if band else -1)
    # ParaView's filters on the distributed volume: the cells of the 1-rank
    # run (each slab brings its own cells; the node layer two slabs share
    # counts once per slab in points, never in cells), the same phi range;
    # the contour is the serial surface (see test_pipeline_pvpython.py: no
    # node has phi exactly 0 here).
    if preserve:
        return
    downstream = downstream_of(out)
    print("%s: downstream %s" % (label, ", ".join("%s %d points %d cells" % (name, d["points"], d["cells"])
                                                  for name, d in downstream.items())))
    assert len(downstream) == 6 and all(d["cells"] > 0 and -1.0 <= d["phi_range"][0] <= d["phi_range"][1] <= 1.0
                                        for d in downstream.values()), \
        "%s: Slice, Clip, Threshold, Contour, ResampleToImage, PlotOverLine give cells, phi in [-1, 1]" % label
    assert downstream["Contour"]["cells"] == ref_triangles and np.count_nonzero(ref_phi == 0) == 0, \
        "%s: Contour phi = 0 gives the serial surface's triangles" % label
    assert downstream["Threshold"]["phi_range"][0] >= 0.0, "%s: Threshold keeps phi >= 0" % label
    assert downstream["PlotOverLine"]["points"] == 1001, "%s: PlotOverLine samples the line once" % label
    # The 1-rank run's (this run's own when that one wrote none).
    downstream_reference = downstream_of(pvbatch(1, trefoil, 1, 0)[0]) or downstream
    for name, d in downstream.items():
        reference = downstream_reference[name]
        assert d["cells"] == reference["cells"] and \
            np.allclose(d["phi_range"], reference["phi_range"], rtol=0, atol=1e-6), \
            "%s: %s gives the 1-rank run's cells and phi range (%d vs %d)" % (
                label, name, d["cells"], reference["cells"])


def test_vtk_filter_with_ghost_levels(trefoil):
    """The plain VTK filter under MPI, updated piece by piece with ghost levels
    (mpi_vtk_script.py checks each rank's piece against a serial run)."""
    command = MPIEXEC + ["3", "env", "PYTHONPATH=" + os.environ.get("PYTHONPATH", ""), "pvbatch", "--symmetric",
                         os.path.join(HERE, "mpi_vtk_script.py"), trefoil]
    run = subprocess.run(command, capture_output=True, text=True, timeout=600, env=ENV)
    print(run.stdout)
    assert run.returncode == 0 and run.stdout.count("0 failed checks") == 3 and "FAILED" not in run.stdout, \
        "VTK filter with 3 ranks and 2 ghost levels: %s" % nvtesting.explain(run)


def test_pvserver_with_a_pvpython_client(serial, plugin_path, trefoil):
    """pvserver on 2 ranks with a pvpython client, as the GUI would use it
    (pvserver_client.py): the plugin loaded on the server, the surface fetched."""
    with socket.socket() as probe:
        probe.bind(("localhost", 0))
        port = probe.getsockname()[1]
    server = subprocess.Popen(MPIEXEC + ["2", "pvserver", "--server-port=%d" % port, "--force-offscreen-rendering"],
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=ENV)
    try:
        ready = False
        for line in server.stdout:
            if "Accepting connection" in line:
                ready = True
                break
        assert ready, "pvserver started"
        result_file = os.path.join(nvtesting.scratch_folder(prefix="nv-pvserver-"), "result.json")
        run = subprocess.run(["pvpython", os.path.join(HERE, "pvserver_client.py"), plugin_path, trefoil, str(port),
                              result_file], capture_output=True, text=True, timeout=300, env=ENV)
        assert run.returncode == 0 and os.path.exists(result_file), "pvserver client ran: %s" % (
            nvtesting.explain(run))
        result = json.load(open(result_file))
        print("pvserver, 2 ranks:", result)
        assert result["ranks"] == 2 and result["extent"] == [0, serial.dims[0] - 1, 0, serial.dims[1] - 1, 0,
                                                             serial.dims[2] - 1], \
            "pvserver: 2 ranks, the volume's pieces make the serial grid"
        assert result["triangles"] == serial.triangles and result["open_edges"] == 0 and \
            abs(result["area"] - serial.area) <= 1e-6 * serial.area, "pvserver: the serial surface, closed"
    finally:
        try:
            server.wait(timeout=60)
        except subprocess.TimeoutExpired:
            server.kill()


# Gap closing (issue 27) under MPI: a sphere of radius 1 sampled 0.6 l apart
# with holes of radius 1.5 l to 3 l at several heights (some across the
# faces between slabs), and one of 4 l left open. With 2 and 3 ranks: the
# serial points added, gaps, surface and phi.
CLOSING_NAMES = ("AddedPoints", "NumberOfGaps", "PiercedGaps", "LargestGap", "LargestGapCenter", "ClosingRadius")


@pytest.fixture(scope="module")
def holey():
    """The holey sphere's file and its serial run: (path, phi, triangles, area, closing figures)."""
    sphere = nvclouds.sphere_points(5500, radius=1.0)
    for center, radius in (((1.0, 0.0, 0.0), 0.12), ((0.0, 0.0, 1.0), 0.2), ((0.0, 0.0, -1.0), 0.24),
                           ((0.0, 1.0, 0.0), 0.16), ((-0.7, 0.0, 0.71), 0.2), ((0.0, -0.8, -0.6), 0.32)):
        sphere = sphere[np.linalg.norm(sphere - np.array(center), axis=1) > radius]
    path = os.path.join(nvtesting.scratch_folder(prefix="nv-mpi-"), "holey_sphere.vtp")
    writer = vtkXMLPolyDataWriter()
    writer.SetInputData(nvclouds.cloud(sphere))
    writer.SetDataModeToBinary()
    writer.SetFileName(path)
    writer.Write()
    gap_serial, gap_phi, gap_triangles, gap_area = serial_run(path, False)
    gap_figures = figures_of(gap_serial.GetVolumeOutput().GetFieldData(), CLOSING_NAMES)
    print("holey sphere, serial: %s" % gap_figures)
    return types.SimpleNamespace(path=path, phi=gap_phi, triangles=gap_triangles, area=gap_area, figures=gap_figures)


def test_holey_sphere_serial(holey):
    assert holey.figures["AddedPoints"][0] > 0 and holey.figures["NumberOfGaps"] == [1.0], \
        "holey sphere: points added, the 4 l hole left open"
    assert holey.figures["PiercedGaps"] == [1.0], "holey sphere: the hole left open pierces the shell"


@pytest.mark.parametrize("ranks", [2, 3])
def test_holey_sphere_under_mpi(holey, pvbatch, ranks):
    out, run = pvbatch(ranks, holey.path, 1, 0)
    label = "holey sphere, %d ranks" % ranks
    assert run.returncode == 0 and os.path.exists(out + "/phi.pvti"), "%s ran: %s" % (label, nvtesting.explain(run))
    surface_reader = vtkXMLPPolyDataReader()
    surface_reader.SetFileName(out + "/surface.pvtp")
    surface_reader.Update()
    triangles, open_edges, area = nvtesting.merged_surface(surface_reader.GetOutput())
    volume_reader = vtkXMLPImageDataReader()
    volume_reader.SetFileName(out + "/phi.pvti")
    volume_reader.Update()
    volume = volume_reader.GetOutput()
    difference = float(np.max(np.abs(vtk_to_numpy(volume.GetPointData().GetArray("phi")) - holey.phi)))
    figures = figures_of(volume.GetFieldData(), CLOSING_NAMES)
    print("%s: %s; %d triangles, %d open edges, max |phi - serial phi| = %.3g" % (
        label, figures, triangles, open_edges, difference))
    assert figures == holey.figures, "%s: the serial points added and gaps" % label
    assert open_edges == 0 and triangles == holey.triangles and abs(area - holey.area) <= 1e-6 * holey.area, \
        "%s: the serial surface (%d vs %d triangles)" % (label, triangles, holey.triangles)
    assert difference <= 1e-6, "%s: phi equals the serial phi to the Gauss-Seidel tolerance" % label


def test_example_script_under_mpi(plugin_path, trefoil):
    """The example script, as a user runs it: with 2 ranks it writes a .pvti
    that reads back as the serial .vti (the file as SaveData wrote it)."""
    example = os.path.join(HERE, "..", "..", "..", "examples", "reconstruct.py")
    volumes = {}
    for ranks in (1, 2):
        out = nvtesting.scratch_folder(prefix="nv-mpi-")
        command = MPIEXEC + [str(ranks), "pvbatch", example, trefoil, "--plugin", plugin_path, "--max-dim", "60",
                             "--no-picture", "--out", out]
        run = subprocess.run(command, capture_output=True, text=True, timeout=600, env=ENV)
        name = os.path.splitext(os.path.basename(trefoil))[0] + ("_phi.pvti" if ranks > 1 else "_phi.vti")
        assert run.returncode == 0 and os.path.exists(os.path.join(out, name)), "example script, %d ranks: %s" % (
            ranks, nvtesting.explain(run))
        volume_reader = vtkXMLPImageDataReader() if ranks > 1 else vtkXMLImageDataReader()
        volume_reader.SetFileName(os.path.join(out, name))
        volume_reader.Update()
        volumes[ranks] = volume_reader.GetOutput()
    one, two = volumes[1], volumes[2]
    print("example script: %s (1 rank) and %s (2 ranks)" % (one.GetDimensions(), two.GetDimensions()))
    assert one.GetDimensions() == two.GetDimensions(), "example script: the .pvti has the serial grid"
    a = vtk_to_numpy(one.GetPointData().GetArray("phi"))
    b = vtk_to_numpy(two.GetPointData().GetArray("phi"))
    assert float(np.max(np.abs(a - b))) <= 1e-6, "example script: the .pvti holds the serial phi"
