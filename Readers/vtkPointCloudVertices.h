// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// One vertex cell per point, which every reader of the module gives its
// output so that ParaView draws the points at once (a vtkPolyData with points
// only shows nothing in the Surface representation).
#ifndef vtkPointCloudVertices_h
#define vtkPointCloudVertices_h

#include "vtkSmartPointer.h"
#include "vtkType.h"

class vtkCellArray;

namespace nv
{
/// Vertex cells 0, 1, ..., count - 1, stored in 32 bits when the count allows
/// (half the memory of 64-bit ids).
vtkSmartPointer<vtkCellArray> VertexCells(vtkIdType count);
} // namespace nv

#endif
