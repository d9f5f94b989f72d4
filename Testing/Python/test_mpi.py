# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch under MPI gives the serial result. With 1, 2 and 4 ranks, the cloud
split unevenly between them (one rank empty), the filter runs distributed
(mpi_script.py) and ParaView's parallel writers save one piece per rank. Here
the pieces are read back and compared with a serial run of the same filter:
phi equal to the Gauss-Seidel tolerance on every node, and the surface made of
the pieces closed (no cracks, no duplicate triangles at the seams) with the
serial area and triangles. Also with OutputVolume off (surface by slabs), the
plain VTK filter with 3 ranks and ghost levels, pvserver with a pvpython
client, and the example script.
(The pieces are read one by one: ParaView's .pvti header gets the first
piece's extent as the whole extent, see the README.)"""
import json
import os
import socket
import subprocess
import sys
import tempfile

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import (vtkXMLImageDataReader, vtkXMLPImageDataReader, vtkXMLPPolyDataReader,
                                 vtkXMLPolyDataReader)

import narrowvolume
import nvtesting

plugin, cloud = sys.argv[1], sys.argv[2]
t = nvtesting.Checker("test_mpi")
here = os.path.dirname(os.path.abspath(__file__))
# pvpython may itself be an MPI singleton: its Open MPI variables must not
# leak into the mpiexec it starts.
env = {k: v for k, v in os.environ.items() if not k.startswith(("OMPI_", "PMIX_", "OPAL_", "PMI_"))}

# The serial reference: the same filter and parameters, all points at once.
reader = vtkXMLPolyDataReader()
reader.SetFileName(cloud)
serial = narrowvolume.vtkNarrowVolumeReconstruction()
serial.SetInputConnection(reader.GetOutputPort())
serial.SetOffsetDistance(0.08)
serial.SetMaximumDimension(90)
serial.Update()
serial_phi = vtk_to_numpy(serial.GetVolumeOutput().GetPointData().GetArray("phi"))
serial_dims = serial.GetVolumeOutput().GetDimensions()


s_triangles, s_open, s_area = nvtesting.merged_surface(serial.GetSurfaceOutput())
print("serial: grid %s, %d band nodes, %d triangles, %d open edges, area %.6f"
      % (serial_dims, serial.GetNumberOfBandNodes(), s_triangles, s_open, s_area))
t.check(s_open == 0 and s_triangles > 1000, "the serial surface is closed")

for ranks, output_volume in ((1, 1), (2, 1), (4, 1), (4, 0)):
    out = tempfile.mkdtemp()
    command = ["mpiexec", "--allow-run-as-root", "--oversubscribe", "-np", str(ranks), "pvbatch",
               os.path.join(here, "mpi_script.py"), plugin, out, cloud, str(output_volume)]
    run = subprocess.run(command, capture_output=True, text=True, timeout=600, env=env)
    label = "%d ranks, OutputVolume %d" % (ranks, output_volume)
    if not t.check(run.returncode == 0 and os.path.exists(out + "/surface.pvtp"), "%s ran: %s" % (
            label, nvtesting.explain(run))):
        continue
    surface_reader = vtkXMLPPolyDataReader()
    surface_reader.SetFileName(out + "/surface.pvtp")
    surface_reader.Update()
    pieces = surface_reader.GetNumberOfPieces()
    triangles, open_edges, area = nvtesting.merged_surface(surface_reader.GetOutput())
    print("%s: %d pieces, %d triangles, %d open edges, area %.6f" % (label, pieces, triangles, open_edges, area))
    t.check(pieces == ranks, "%s: one surface piece per rank" % label)
    t.check(open_edges == 0, "%s: the merged surface is closed (%d open edges)" % (label, open_edges))
    t.check(triangles == s_triangles, "%s: serial triangles (%d vs %d)" % (label, triangles, s_triangles))
    t.check(abs(area - s_area) <= 1e-6 * s_area, "%s: serial area (%.9f vs %.9f)" % (label, area, s_area))
    if output_volume:
        # phi, piece by piece: each piece file holds its extent of the grid.
        phi = np.full(serial_phi.shape, np.nan)
        nx, ny, nz = serial_dims
        slabs = []
        for index in range(ranks):
            piece_reader = vtkXMLImageDataReader()
            piece_reader.SetFileName("%s/phi/phi_%d.vti" % (out, index))
            piece_reader.Update()
            piece = piece_reader.GetOutput()
            extent = piece.GetExtent()
            if piece.GetNumberOfPoints() == 0:
                continue
            t.check(extent[:4] == (0, nx - 1, 0, ny - 1), "%s: piece %d spans x and y" % (label, index))
            slabs.append(extent[4:])
            values = vtk_to_numpy(piece.GetPointData().GetArray("phi"))
            phi[extent[4] * nx * ny:(extent[5] + 1) * nx * ny] = values
            band = piece.GetFieldData().GetArray("NarrowBandNodes").GetValue(0)
            t.check(band == serial.GetNumberOfBandNodes(), "%s: the serial band (%d nodes)" % (label, band))
        # The work was shared: one slab of z layers per rank, each starting
        # where the one below ends (the layer they share).
        print("%s: slabs %s" % (label, slabs))
        t.check(len(slabs) == ranks and slabs[0][0] == 0 and slabs[-1][1] == nz - 1 and
                all(slabs[i][1] == slabs[i + 1][0] for i in range(len(slabs) - 1)),
                "%s: one slab per rank, tiling z" % label)
        covered = not np.isnan(phi).any()
        t.check(covered, "%s: the pieces cover the grid" % label)
        if covered:
            difference = float(np.max(np.abs(phi - serial_phi)))
            print("%s: max |phi - serial phi| = %.3g" % (label, difference))
            t.check(difference <= 1e-6, "%s: phi equals the serial phi to the Gauss-Seidel tolerance" % label)
# The plain VTK filter under MPI, updated piece by piece with ghost levels
# (mpi_vtk_script.py checks each rank's piece against a serial run).
command = ["mpiexec", "--allow-run-as-root", "--oversubscribe", "-np", "3", "env",
           "PYTHONPATH=" + os.environ.get("PYTHONPATH", ""), "pvbatch", "--symmetric",
           os.path.join(here, "mpi_vtk_script.py"), cloud]
run = subprocess.run(command, capture_output=True, text=True, timeout=600, env=env)
print(run.stdout)
t.check(run.returncode == 0 and run.stdout.count("0 failed checks") == 3 and "FAILED" not in run.stdout,
        "VTK filter with 3 ranks and 2 ghost levels: %s" % nvtesting.explain(run))

# pvserver on 2 ranks with a pvpython client, as the GUI would use it
# (pvserver_client.py): the plugin loaded on the server, the surface fetched.
with socket.socket() as probe:
    probe.bind(("localhost", 0))
    port = probe.getsockname()[1]
server = subprocess.Popen(["mpiexec", "--allow-run-as-root", "--oversubscribe", "-np", "2", "pvserver",
                           "--server-port=%d" % port, "--force-offscreen-rendering"],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env)
ready = False
for line in server.stdout:
    if "Accepting connection" in line:
        ready = True
        break
if t.check(ready, "pvserver started"):
    result_file = tempfile.mktemp(suffix=".json")
    run = subprocess.run(["pvpython",
                          os.path.join(here, "pvserver_client.py"), plugin, cloud, str(port), result_file],
                         capture_output=True, text=True, timeout=300, env=env)
    if t.check(run.returncode == 0 and os.path.exists(result_file), "pvserver client ran: %s"
               % nvtesting.explain(run)):
        result = json.load(open(result_file))
        print("pvserver, 2 ranks:", result)
        t.check(result["ranks"] == 2 and result["extent"] == [0, serial_dims[0] - 1, 0, serial_dims[1] - 1, 0,
                                                               serial_dims[2] - 1],
                "pvserver: 2 ranks, the volume's pieces make the serial grid")
        t.check(result["triangles"] == s_triangles and result["open_edges"] == 0 and
                abs(result["area"] - s_area) <= 1e-6 * s_area, "pvserver: the serial surface, closed")
try:
    server.wait(timeout=60)
except subprocess.TimeoutExpired:
    server.kill()

# The example script, as a user runs it: with 2 ranks it writes a .pvti that
# reads back as the serial .vti.
example = os.path.join(here, "..", "..", "examples", "reconstruct.py")
volumes = {}
for ranks in (1, 2):
    out = tempfile.mkdtemp()
    command = ["mpiexec", "--allow-run-as-root", "--oversubscribe", "-np", str(ranks), "pvbatch", example, cloud,
               "--plugin", plugin, "--max-dim", "60", "--no-picture", "--out", out]
    run = subprocess.run(command, capture_output=True, text=True, timeout=600, env=env)
    name = os.path.splitext(os.path.basename(cloud))[0] + ("_phi.pvti" if ranks > 1 else "_phi.vti")
    if t.check(run.returncode == 0 and os.path.exists(os.path.join(out, name)), "example script, %d ranks: %s"
               % (ranks, nvtesting.explain(run))):
        volume_reader = vtkXMLPImageDataReader() if ranks > 1 else vtkXMLImageDataReader()
        volume_reader.SetFileName(os.path.join(out, name))
        volume_reader.Update()
        volumes[ranks] = volume_reader.GetOutput()
if len(volumes) == 2:
    one, two = volumes[1], volumes[2]
    print("example script: %s (1 rank) and %s (2 ranks)" % (one.GetDimensions(), two.GetDimensions()))
    t.check(one.GetDimensions() == two.GetDimensions(), "example script: the .pvti has the serial grid")
    if one.GetDimensions() == two.GetDimensions():
        a = vtk_to_numpy(one.GetPointData().GetArray("phi"))
        b = vtk_to_numpy(two.GetPointData().GetArray("phi"))
        t.check(float(np.max(np.abs(a - b))) <= 1e-6, "example script: the .pvti holds the serial phi")
t.finish()
