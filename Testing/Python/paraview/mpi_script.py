# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Run by test_mpi.py under `mpiexec -np N pvbatch`. Each rank's piece of the
cloud is an uneven share of the points (in shuffled order, so every piece is
spread over the whole shape), with one rank empty when there are several.
Every rank prints the Volume's grid as its information pass declares it,
before the run. The filter runs distributed; its outputs are written by
ParaView's parallel writers, one piece per rank: OUT/phi.pvti and
OUT/surface.pvtp. With the volume on, ParaView's Slice, Clip, Threshold,
Contour, ResampleToImage and PlotOverLine run on the Volume output and what
they give goes to OUT/downstream.json.

    mpi_script.py PLUGIN OUT CLOUD OUTPUT_VOLUME(0|1) [PRESERVE_OFFSET(0|1)]

With PRESERVE_OFFSET 1 the filter runs 10 steps with PreserveOffset on.
"""
import json
import sys

import paraview.simple as pvs

import nvtesting

plugin, out, cloud, output_volume = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
preserve = len(sys.argv) > 5 and int(sys.argv[5])
pvs.LoadPlugin(plugin, ns=globals())

# Runs on every rank: piece p of n gets an uneven share of the points.
split = pvs.ProgrammableSource(OutputDataSetType="vtkPolyData")
split.Script = nvtesting.split_cloud_script(cloud)

shell = NarrowVolumeReconstruction(Input=split, OffsetDistance=0.08, MaximumDimension=90,  # noqa: F821
                                   OutputVolume=output_volume)
if preserve:
    shell.PreserveOffset = 1
    shell.MaximumNumberOfIterations = 10

# The information pass on every rank (this script runs on rank 0 only; a
# ProgrammableFilter's information script runs on each): the grid port 0
# declares, before the filter has run.
inspector = pvs.ProgrammableFilter(Input=pvs.OutputPort(shell, 0), OutputDataSetType="Same as Input")
inspector.RequestInformationScript = """
from vtkmodules.vtkCommonDataModel import vtkDataObject
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as sddp
from vtkmodules.vtkParallelCore import vtkMultiProcessController
controller = vtkMultiProcessController.GetGlobalController()
info = self.GetInputInformation(0, 0)
scalars = vtkDataObject.GetActiveFieldInformation(info, vtkDataObject.FIELD_ASSOCIATION_POINTS, 0)
print("information pass, rank %d of %d: whole extent %s, origin %s, spacing %s, scalar type %s, points %d" % (
    controller.GetLocalProcessId(), controller.GetNumberOfProcesses(), info.Get(sddp.WHOLE_EXTENT()),
    info.Get(vtkDataObject.ORIGIN()), info.Get(vtkDataObject.SPACING()),
    scalars.Get(vtkDataObject.FIELD_ARRAY_TYPE()) if scalars else None,
    self.GetInputDataObject(0, 0).GetNumberOfPoints()), flush=True)
"""
inspector.UpdatePipelineInformation()

shell.UpdatePipeline()
pvs.SaveData(out + "/phi.pvti", proxy=pvs.OutputPort(shell, 0), DataMode="Binary")
pvs.SaveData(out + "/surface.pvtp", proxy=pvs.OutputPort(shell, 1), DataMode="Binary")

if output_volume:
    # ParaView's filters on the distributed Volume: planes through the
    # centre of the bounds, across the z slabs.
    volume = pvs.OutputPort(shell, 0)
    slice_ = pvs.Slice(Input=volume)
    slice_.SliceType.Normal = [0.0, 0.0, 1.0]
    clip = pvs.Clip(Input=volume)
    clip.ClipType.Normal = [0.0, 0.0, 1.0]
    # A third of a cell above the centre: a plane through a layer of nodes
    # (the centre is one when the grid has an even number of cells in z)
    # leaves the side of those nodes to rounding, and the pieces' cells next
    # to it then fall on either side (one layer of cells more on 2 ranks
    # than on 1).
    bounds, extent = volume.GetDataInformation().GetBounds(), volume.GetDataInformation().GetExtent()
    clip.ClipType.Origin = [(bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2,
                            (bounds[4] + bounds[5]) / 2 + (bounds[5] - bounds[4]) / (extent[5] - extent[4]) / 3]
    threshold = pvs.Threshold(Input=volume)
    threshold.Scalars = ["POINTS", "phi"]
    threshold.LowerThreshold = 0.0
    threshold.UpperThreshold = 1.0
    contour = pvs.Contour(Input=volume)
    contour.ContourBy = ["POINTS", "phi"]
    contour.Isosurfaces = [0.0]
    resample = pvs.ResampleToImage(Input=volume)
    resample.SamplingDimensions = [40, 30, 20]
    line = pvs.PlotOverLine(Input=volume)  # the bounds' diagonal
    downstream = {}
    for name, proxy in (("Slice", slice_), ("Clip", clip), ("Threshold", threshold), ("Contour", contour),
                        ("ResampleToImage", resample), ("PlotOverLine", line)):
        proxy.UpdatePipeline()
        information = proxy.GetDataInformation()
        downstream[name] = {"points": information.GetNumberOfPoints(), "cells": information.GetNumberOfCells(),
                            "phi_range": list(proxy.PointData["phi"].GetRange())}
    with open(out + "/downstream.json", "w") as f:
        json.dump(downstream, f)
