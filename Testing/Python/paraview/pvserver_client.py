# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Run by test_mpi.py in pvpython, connected to `mpiexec -np N pvserver`: the
plugin loaded on the server, the demo cloud split unevenly across the server's
ranks (one rank empty), the filter applied as a GUI user would, and the surface fetched to the
client. Writes the result to the JSON file argv[4].

    pvserver_client.py PLUGIN CLOUD PORT OUT
"""
import json
import sys

from paraview import servermanager
import paraview.simple as pvs

import nvtesting

plugin, cloud, port, out = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
pvs.Connect("localhost", port)
pvs.LoadPlugin(plugin, remote=True, ns=globals())
split = pvs.ProgrammableSource(OutputDataSetType="vtkPolyData")
split.Script = nvtesting.split_cloud_script(cloud)
shell = NarrowVolumeReconstruction(Input=split, OffsetDistance=0.08, MaximumDimension=90)  # noqa: F821
shell.UpdatePipeline()
surface = servermanager.Fetch(shell, idx=1)
triangles, open_edges, area = nvtesting.merged_surface(surface)
volume = shell.GetDataInformation(0)
result = dict(ranks=servermanager.ActiveConnection.GetNumberOfDataPartitions(),
              extent=list(volume.GetExtent()), volume_points=volume.GetNumberOfPoints(),
              triangles=triangles, open_edges=open_edges, area=area)
with open(out, "w") as f:
    json.dump(result, f)
print(result)
