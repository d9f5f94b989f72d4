# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""NarrowVolume: narrow volume (thick shell) reconstruction from point clouds.

    from narrowvolume import vtkNarrowVolumeReconstruction

The filter is a VTK algorithm: set its input to any vtkPointSet and read the
phase field (output port 0, vtkImageData) and the offset surfaces (output
port 1, vtkPolyData). vtkPointCloudTextReader reads .xyz / .pts text clouds.
"""
from .NarrowVolumeFilters import vtkNarrowVolumeReconstruction, vtkPointCloudTextReader

__all__ = ["vtkNarrowVolumeReconstruction", "vtkPointCloudTextReader"]
