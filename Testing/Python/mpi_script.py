"""Run by test_mpi.py under `mpiexec -np N pvbatch`. Each rank's piece of the
cloud is an uneven share of the points (in shuffled order, so every piece is
spread over the whole shape), with one rank empty when there are several.
The filter runs distributed; its outputs are written by ParaView's parallel
writers, one piece per rank: OUT/phi.pvti and OUT/surface.pvtp.

    mpi_script.py PLUGIN OUT CLOUD OUTPUT_VOLUME(0|1)
"""
import sys

import paraview.simple as pvs

plugin, out, cloud, output_volume = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
pvs.LoadPlugin(plugin, ns=globals())

# Runs on every rank: piece p of n gets shares[p] of the shuffled points.
split = pvs.ProgrammableSource(OutputDataSetType="vtkPolyData")
split.Script = """
import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as sddp
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
info = self.GetOutputInformation(0)
piece, pieces = info.Get(sddp.UPDATE_PIECE_NUMBER()), info.Get(sddp.UPDATE_NUMBER_OF_PIECES())
reader = vtkXMLPolyDataReader()
reader.SetFileName(%r)
reader.Update()
xyz = vtk_to_numpy(reader.GetOutput().GetPoints().GetData()).astype(float)
xyz = xyz[np.random.default_rng(7).permutation(len(xyz))]
weights = np.array([[1.0], [3.0, 0.0], [5.0, 1.0, 0.0, 2.0]][pieces.bit_length() - 1])
ends = np.round(np.cumsum(weights) / weights.sum() * len(xyz)).astype(int)
begin = 0 if piece == 0 else ends[piece - 1]
points = vtkPoints()
points.SetData(numpy_to_vtk(np.ascontiguousarray(xyz[begin:ends[piece]]), deep=1))
self.GetOutput().SetPoints(points)
""" % cloud

shell = NarrowVolumeReconstruction(Input=split, OffsetDistance=0.08, MaximumDimension=90,  # noqa: F821
                                   OutputVolume=output_volume)
shell.UpdatePipeline()
pvs.SaveData(out + "/phi.pvti", proxy=pvs.OutputPort(shell, 0))
pvs.SaveData(out + "/surface.pvtp", proxy=pvs.OutputPort(shell, 1))
