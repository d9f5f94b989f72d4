# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""NarrowVolume: narrow volume (thick shell) reconstruction from point clouds.

    from narrowvolume import vtkNarrowVolumeReconstruction

The filter is a VTK algorithm: set its input to any vtkPointSet and read the
phase field (output port 0, vtkImageData) and the offset surfaces (output
port 1, vtkPolyData). The readers (module NarrowVolume::Readers) give
vtkPolyData clouds with a vertex per point: vtkPointCloudTextReader reads
.xyz / .pts text, vtkLASPointCloudReader LAS 1.0-1.4, vtkPCDPointCloudReader
PCD (ascii, binary, binary_compressed).
"""
from .NarrowVolumeFilters import vtkNarrowVolumeReconstruction
from .NarrowVolumeReaders import vtkLASPointCloudReader, vtkPCDPointCloudReader, vtkPointCloudTextReader

__all__ = ["vtkNarrowVolumeReconstruction", "vtkLASPointCloudReader", "vtkPCDPointCloudReader",
           "vtkPointCloudTextReader"]
