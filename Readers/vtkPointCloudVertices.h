// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// What every reader of the module does alike: one vertex cell per point,
// which it gives its output so that ParaView draws the points at once (a
// vtkPolyData with points only shows nothing in the Surface
// representation), and its answer to a file it cannot read.
#ifndef vtkPointCloudVertices_h
#define vtkPointCloudVertices_h

#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkType.h"

class vtkCellArray;

namespace nv
{
/// Vertex cells 0, 1, ..., count - 1, stored in 32 bits when the count allows
/// (half the memory of 64-bit ids).
vtkSmartPointer<vtkCellArray> VertexCells(vtkIdType count);

/// A reader's answer to a file it cannot read, once its error said why: the
/// output empty and the request done. 1, not 0: a failed request would add
/// the executive's dump of the pipeline's state after the message.
inline int ReadFailed(vtkPolyData* output)
{
  output->Initialize();
  return 1;
}
} // namespace nv

#endif
