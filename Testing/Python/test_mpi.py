"""pvbatch under MPI (1, 2 and 4 ranks, the cloud read in pieces) gives the
serial result: the filter asks each rank for the whole cloud, the first rank
computes the shell and the others leave their pieces empty, so the gathered
surface has the same triangles and area and no duplicates. (Work is not
shared between ranks yet.)"""
import json
import os
import subprocess
import sys
import tempfile

import nvtesting

plugin, cloud = sys.argv[1], sys.argv[2]
t = nvtesting.Checker("test_mpi")
here = os.path.dirname(os.path.abspath(__file__))
# pvpython may itself be an MPI singleton: its Open MPI variables must not
# leak into the mpiexec it starts.
env = {k: v for k, v in os.environ.items() if not k.startswith(("OMPI_", "PMIX_", "OPAL_", "PMI_"))}
results = {}
for ranks in (1, 2, 4):
    out = tempfile.mktemp(suffix=".json")
    command = ["mpiexec", "--allow-run-as-root", "--oversubscribe", "-np", str(ranks), "pvbatch",
               os.path.join(here, "mpi_script.py"), plugin, out, cloud]
    run = subprocess.run(command, capture_output=True, text=True, timeout=600, env=env)
    t.check(run.returncode == 0 and os.path.exists(out), "%d ranks ran (exit %d): %s %s" % (
        ranks, run.returncode, run.stdout[-1000:], run.stderr[-2000:]))
    if os.path.exists(out):
        results[ranks] = json.load(open(out))
        print(ranks, "ranks:", results[ranks])
if 1 in results:
    for ranks in (2, 4):
        if ranks in results:
            a, b = results[1], results[ranks]
            t.check(b["ranks"] == ranks, "%d ranks in the run" % ranks)
            t.check(b["triangles"] == a["triangles"] and b["points"] == a["points"],
                    "%d ranks: same surface size as 1 (%d vs %d triangles)" % (ranks, b["triangles"], a["triangles"]))
            t.check(abs(b["area"] - a["area"]) < 1e-9 * a["area"], "%d ranks: same area" % ranks)
            # Every rank reads the whole cloud (the filter asks for it), so the
            # reader's gathered size is ranks times the cloud.
            t.check(b["cloud_points"] == ranks * a["cloud_points"], "%d ranks: each has the whole cloud" % ranks)
t.finish()
