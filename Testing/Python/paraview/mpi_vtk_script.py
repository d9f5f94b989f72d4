# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Run by test_mpi.py under `mpiexec -np N pvbatch --symmetric`: the plain VTK
filter (no ParaView proxies) on every rank, each rank holding a different
share of the cloud, updated as piece `rank` of N with 2 ghost levels. Each
rank checks the grid its information pass declares (UpdateInformation, before
the run) and its piece against a serial run of the filter
(SetController(None)), and prints FAILED lines for the test to catch.

    mpi_vtk_script.py CLOUD
"""
import sys

import numpy as np
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import VTK_FLOAT, VTK_STRING, vtkCommand
from vtkmodules.vtkCommonDataModel import vtkDataObject, vtkDataSetAttributes
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as sddp
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
from vtkmodules.vtkParallelCore import vtkMultiProcessController

import narrowvolume
import nvclouds
import nvtesting

controller = vtkMultiProcessController.GetGlobalController()
rank, size = controller.GetLocalProcessId(), controller.GetNumberOfProcesses()
t = nvtesting.Checker("mpi_vtk_script rank %d of %d" % (rank, size))
reader = vtkXMLPolyDataReader()
reader.SetFileName(sys.argv[1])
reader.Update()
xyz = nvtesting.points_of(reader.GetOutput())


def shell(points, distributed):
    f = narrowvolume.vtkNarrowVolumeReconstruction()
    f.SetInputData(nvclouds.cloud(points))
    f.SetOffsetDistance(0.08)
    f.SetMaximumDimension(70)
    if not distributed:
        f.SetController(None)
    # The information pass first: the grid port 0 declares before the run.
    f.UpdateInformation()
    info = f.GetOutputInformation(0)
    scalars = vtkDataObject.GetActiveFieldInformation(info, vtkDataObject.FIELD_ASSOCIATION_POINTS,
                                                      vtkDataSetAttributes.SCALARS)
    declared = (tuple(info.Get(sddp.WHOLE_EXTENT())), tuple(info.Get(vtkDataObject.ORIGIN())),
                tuple(info.Get(vtkDataObject.SPACING())),
                scalars.Get(vtkDataObject.FIELD_ARRAY_TYPE()) if scalars else None)
    f.UpdatePiece(rank, size, 2)
    return f, declared


# Rank r holds the points with index = r (mod size), sorted by x: pieces
# that overlap in space and do not follow the z slabs.
share = xyz[rank::size]
share = share[np.argsort(share[:, 0])]
distributed, declared = shell(share, True)
alone, declared_alone = shell(xyz, False)
piece, whole = distributed.GetVolumeOutput(), alone.GetVolumeOutput()
# Every rank's information pass, from its own share of the points, declares
# the grid of the serial run's data.
print("rank %d: information pass: whole extent %s, origin %s, spacing %s, scalar type %s" % ((rank,) + declared))
t.check(declared == (tuple(whole.GetExtent()), tuple(whole.GetOrigin()), tuple(whole.GetSpacing()), VTK_FLOAT),
        "rank %d: the information pass declares the serial grid" % rank)
t.check(declared_alone == declared, "rank %d: the same as a serial information pass" % rank)
nx, ny, nz = whole.GetDimensions()
extent = piece.GetExtent()
print("rank %d: piece extent %s of %s" % (rank, extent, whole.GetExtent()))
t.check(extent[:4] == whole.GetExtent()[:4] and 0 <= extent[4] < extent[5] <= nz - 1,
        "rank %d: a slab of the grid" % rank)
phi = vtk_to_numpy(piece.GetPointData().GetArray("phi"))
serial = vtk_to_numpy(whole.GetPointData().GetArray("phi"))[extent[4] * nx * ny:(extent[5] + 1) * nx * ny]
t.check(phi.shape == serial.shape and float(np.max(np.abs(phi - serial))) <= 1e-6,
        "rank %d: phi, ghost layers included, is the serial phi" % rank)
# Ghost layers: 2 below (unless at the grid's start) and 2 above (unless at its end).
ghosts = piece.GetPointData().GetArray(vtkDataSetAttributes.GhostArrayName())
expected = (2 if extent[4] > 0 else 0) + (2 if extent[5] < nz - 1 else 0)
if expected:
    marked = int(np.count_nonzero(vtk_to_numpy(ghosts))) if ghosts else 0
    t.check(marked == expected * nx * ny, "rank %d: %d ghost point layers marked (%d points)"
            % (rank, expected, marked))
    cells = piece.GetCellData().GetArray(vtkDataSetAttributes.GhostArrayName())
    t.check(cells is not None and np.count_nonzero(vtk_to_numpy(cells)) == expected * (nx - 1) * (ny - 1),
            "rank %d: the ghost cell layers are marked" % rank)
# The scan surface needs the whole grid: a distributed run keeps both sheets
# (the same surface as the run above) and the first rank says so.
said = []
scan = narrowvolume.vtkNarrowVolumeReconstruction()
scan.SetInputData(nvclouds.cloud(share))
scan.SetOffsetDistance(0.08)
scan.SetMaximumDimension(70)
scan.SetSheetsToScan()
scan.AddObserver(vtkCommand.WarningEvent, calldata_type(VTK_STRING)(lambda caller, event, text: said.append(text)))
scan.UpdatePiece(rank, size, 2)
t.check(scan.GetVolumeOutput().GetFieldData().GetArray("ScanSurface") is None,
        "rank %d: no scan surface in a distributed run" % rank)
t.check(scan.GetSurfaceOutput().GetNumberOfPolys() == distributed.GetSurfaceOutput().GetNumberOfPolys(),
        "rank %d: both sheets kept" % rank)
if rank == 0:
    t.check(any("A distributed run outputs both sheets: keeping one, or the scan surface, needs the whole grid" in w
                for w in said), "rank 0: the warning says why: %s" % said)
print("rank %d: %d failed checks" % (rank, t.failures))
