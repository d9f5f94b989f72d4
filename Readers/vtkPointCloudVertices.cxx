// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkPointCloudVertices.h"

#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"

#include <limits>

namespace
{
template <typename ArrayT>
vtkSmartPointer<vtkCellArray> Fill(vtkIdType count)
{
  vtkNew<ArrayT> offsets, connectivity;
  offsets->SetNumberOfValues(count + 1);
  connectivity->SetNumberOfValues(count);
  for (vtkIdType i = 0; i < count; ++i)
  {
    offsets->SetValue(i, i);
    connectivity->SetValue(i, i);
  }
  offsets->SetValue(count, count);
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsets, connectivity);
  return cells;
}
} // namespace

vtkSmartPointer<vtkCellArray> nv::VertexCells(vtkIdType count)
{
  if (count < std::numeric_limits<vtkTypeInt32>::max())
  {
    return Fill<vtkTypeInt32Array>(count);
  }
  return Fill<vtkTypeInt64Array>(count);
}
