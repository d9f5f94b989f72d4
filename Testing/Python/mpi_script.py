# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Run by test_mpi.py under `mpiexec -np N pvbatch`. Each rank's piece of the
cloud is an uneven share of the points (in shuffled order, so every piece is
spread over the whole shape), with one rank empty when there are several.
The filter runs distributed; its outputs are written by ParaView's parallel
writers, one piece per rank: OUT/phi.pvti and OUT/surface.pvtp.

    mpi_script.py PLUGIN OUT CLOUD OUTPUT_VOLUME(0|1)
"""
import sys

import paraview.simple as pvs

import nvtesting

plugin, out, cloud, output_volume = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
pvs.LoadPlugin(plugin, ns=globals())

# Runs on every rank: piece p of n gets an uneven share of the points.
split = pvs.ProgrammableSource(OutputDataSetType="vtkPolyData")
split.Script = nvtesting.split_cloud_script(cloud)

shell = NarrowVolumeReconstruction(Input=split, OffsetDistance=0.08, MaximumDimension=90,  # noqa: F821
                                   OutputVolume=output_volume)
shell.UpdatePipeline()
pvs.SaveData(out + "/phi.pvti", proxy=pvs.OutputPort(shell, 0), DataMode="Binary")
pvs.SaveData(out + "/surface.pvtp", proxy=pvs.OutputPort(shell, 1), DataMode="Binary")
