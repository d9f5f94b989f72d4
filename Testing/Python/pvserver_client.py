"""Run by test_mpi.py in pvpython, connected to `mpiexec -np N pvserver`: the
plugin loaded on the server, the demo cloud split unevenly across the server's
ranks, the filter applied as a GUI user would, and the surface fetched to the
client. Writes the result to the JSON file argv[4].

    pvserver_client.py PLUGIN CLOUD PORT OUT
"""
import json
import sys

from paraview import servermanager
import paraview.simple as pvs
from vtkmodules.vtkFiltersCore import vtkCleanPolyData, vtkMassProperties

import nvtesting

plugin, cloud, port, out = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
pvs.Connect("localhost", port)
pvs.LoadPlugin(plugin, remote=True, ns=globals())
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
keep = np.arange(len(xyz)) %% 3 != 0 if piece == 0 else np.arange(len(xyz)) %% 3 == 0
points = vtkPoints()
points.SetData(numpy_to_vtk(np.ascontiguousarray(xyz[keep]), deep=1))
self.GetOutput().SetPoints(points)
""" % cloud
shell = NarrowVolumeReconstruction(Input=split, OffsetDistance=0.08, MaximumDimension=90)  # noqa: F821
shell.UpdatePipeline()
surface = servermanager.Fetch(shell, idx=1)
clean = vtkCleanPolyData()
clean.SetInputData(surface)
clean.SetTolerance(0.0)
clean.Update()
mass = vtkMassProperties()
mass.SetInputData(clean.GetOutput())
mass.Update()
volume = shell.GetDataInformation(0)
result = dict(ranks=servermanager.ActiveConnection.GetNumberOfDataPartitions(),
              extent=list(volume.GetExtent()), volume_points=volume.GetNumberOfPoints(),
              triangles=clean.GetOutput().GetNumberOfPolys(), open_edges=nvtesting.boundary_edges(clean.GetOutput()),
              area=mass.GetSurfaceArea())
with open(out, "w") as f:
    json.dump(result, f)
print(result)
