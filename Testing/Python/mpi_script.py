"""Run by test_mpi.py under `mpiexec -np N pvbatch`: the demo cloud, read in
pieces across the ranks, through the filter; the first rank writes the
gathered surface's size and area, and the volume's, to the JSON file argv[2]."""
import json
import sys

from paraview import servermanager
import paraview.simple as pvs
from vtkmodules.vtkFiltersCore import vtkMassProperties, vtkTriangleFilter

plugin, out, cloud = sys.argv[1], sys.argv[2], sys.argv[3]
pvs.LoadPlugin(plugin, ns=globals())
reader = pvs.XMLPolyDataReader(FileName=[cloud])
shell = NarrowVolumeReconstruction(Input=reader, OffsetDistance=0.08, MaximumDimension=80)  # noqa: F821
shell.UpdatePipeline()
surface = servermanager.Fetch(shell, idx=1)
triangles = vtkTriangleFilter()
triangles.SetInputData(surface)
mass = vtkMassProperties()
mass.SetInputConnection(triangles.GetOutputPort())
mass.Update()
info = shell.GetDataInformation(0)
result = dict(ranks=servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions(),
              triangles=surface.GetNumberOfPolys(), points=surface.GetNumberOfPoints(),
              area=mass.GetSurfaceArea(), volume_points=info.GetNumberOfPoints(),
              cloud_points=reader.GetDataInformation().GetNumberOfPoints())
if servermanager.vtkProcessModule.GetProcessModule().GetPartitionId() == 0:
    with open(out, "w") as f:
        json.dump(result, f)
