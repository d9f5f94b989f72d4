# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""What the two flavours of the package narrowvolume must agree on.

pip_reference.py records it for the C++ filter (the CMake build's package,
in pvpython) and test_python_api.py compares the wheel's Python filter with
the record: the public methods, each property's default and clamping, and
the outputs of the same runs on the same points (bit for bit).
"""
import hashlib

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.util.vtkAlgorithm import VTKPythonAlgorithmBase
from vtkmodules.vtkCommonExecutionModel import vtkAlgorithm

# The C++ filter's only member the wheel's has not: distributed runs need MPI.
CPP_ONLY = {"SetController", "GetController"}

# Runs compared between the flavours: name -> properties (the input: the
# points saved by pip_reference.py, with lone points that make gaps and
# loose pieces). Every property's path is in one run at least: the
# automatic offset and grid, PreserveOffset, RemoveSmallPieces on and off
# (with the dense phi, and without it), one sheet from the dense phi, the
# scan surface.
CASES = {
    "default": {"MaximumDimension": 80, "OffsetDistance": 0.12},
    "outputs": {"MaximumDimension": 80, "OffsetDistance": 0.12, "OutputInitialPhi": True, "OutputDistance": True,
                "OutputNarrowBand": True, "NumberOfThreads": 1},
    "whole-eq3": {"MaximumDimension": 60, "OffsetDistance": 0.12, "Domain": 1, "EdgeStoppingFunction": 3,
                  "XiCells": 3.0, "MaximumNumberOfIterations": 5},
    "outer-sheet": {"SampleSpacing": 0.03, "OffsetDistance": 0.12, "Sheets": 1},
    "volume-off": {"SampleSpacing": 0.02, "OffsetDistance": 0.1, "OutputVolume": False},
    "fine": {"SampleSpacing": 0.008, "OffsetDistance": 0.06},
    "automatic": {},
    "preserve-offset": {"MaximumDimension": 80, "OffsetDistance": 0.12, "PreserveOffset": True,
                        "MaximumNumberOfIterations": 5},
    "keep-pieces": {"MaximumDimension": 80, "OffsetDistance": 0.12, "RemoveSmallPieces": False},
    "inner-sheet-volume-off": {"SampleSpacing": 0.03, "OffsetDistance": 0.12, "Sheets": 2, "OutputVolume": False},
    "scan-surface": {"SampleSpacing": 0.03, "OffsetDistance": 0.12, "Sheets": 3},
    # A part to print with a drain hole placed on the sphere's +x side, one
    # leaning within DrainHoleAngle: the printing mode's route through the wheel.
    "part": {"SampleSpacing": 0.03, "OffsetDistance": 0.09, "WallThickness": 0.09, "CavityClosingDistance": 0.05,
             "DrainHoleAngle": 45.0, "DrainHolePositions": [(2.9, 0.0, 0.0), (2.5, 0.0, 0.0)]},
}


def public_api(cls):
    """The filter's own public names (without vtkAlgorithm's and VTKPythonAlgorithmBase's)."""
    return sorted({n for n in dir(cls) if not n.startswith("_")} - set(dir(vtkAlgorithm))
                  - set(dir(VTKPythonAlgorithmBase)))


def property_report(cls, properties):
    """{name: [default, value after setting a very low one, after a very high one]}."""
    report = {}
    for prop in properties:
        f = cls()
        row = [_plain(getattr(f, "Get" + prop.name)())]
        for probe in ((-10 ** 7, 10 ** 7) if prop.kind is int else (-1e13, 1e13) if prop.kind is float else (0, 5)):
            getattr(f, "Set" + prop.name)(probe)
            row.append(_plain(getattr(f, "Get" + prop.name)()))
        report[prop.name] = row
    return report


def _plain(value):
    return value if isinstance(value, (bool, float)) else int(value)


def run_case(cls, cloud, properties):
    """The outputs of one run, as arrays: the volume's grid, point arrays and
    field data (every array, with its class), and the surface (points, normals, triangles: the core makes
    it in both flavours)."""
    f = cls()
    f.SetInputData(cloud)
    for key, value in properties.items():
        if hasattr(f, "RemoveAll" + key):  # a list property: its points
            for point in value:
                getattr(f, "Add" + key[:-1])(*point)
        else:
            getattr(f, "Set" + key)(value)
    f.Update()
    volume, surface = f.GetOutputDataObject(0), f.GetOutputDataObject(1)
    out = {"extent": np.array(volume.GetExtent()), "origin": np.array(volume.GetOrigin()),
           "spacing": np.array(volume.GetSpacing())}
    for i in range(volume.GetPointData().GetNumberOfArrays()):
        array = volume.GetPointData().GetArray(i)
        out["point:" + array.GetName()] = vtk_to_numpy(array).copy()
    fields = volume.GetFieldData()
    for i in range(fields.GetNumberOfArrays()):
        array = fields.GetArray(i)
        if array.GetName() == "StageSeconds":
            # Timings differ from run to run: their stages, not their values.
            names = ",".join(array.GetComponentName(c) for c in range(array.GetNumberOfComponents()))
            out["field:StageSeconds:names"] = np.frombuffer(names.encode(), dtype=np.uint8).copy()
            continue
        out["field:%s:%s" % (array.GetName(), array.GetClassName())] = vtk_to_numpy(array).copy()
    out["triangles"] = np.array([surface.GetNumberOfPolys()])
    if surface.GetNumberOfPoints():
        out["surface:points"] = vtk_to_numpy(surface.GetPoints().GetData()).astype(np.float64)
        out["surface:normals"] = vtk_to_numpy(surface.GetPointData().GetNormals()).copy()
        out["surface:connectivity"] = vtk_to_numpy(surface.GetPolys().GetConnectivityArray()).astype(np.int64)
    return out


def summary(outputs):
    """{key: [dtype, shape, SHA-256 of the bytes, sum]} of run_case's arrays:
    equal dtypes, shapes and digests mean equal arrays, bit for bit (the sum,
    for a reader, depends on numpy's summation order, which its versions
    change)."""
    return {key: [str(a.dtype), list(a.shape), hashlib.sha256(np.ascontiguousarray(a).tobytes()).hexdigest(),
                  float(np.sum(a, dtype=np.float64))] for key, a in sorted(outputs.items())}
