// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNarrowVolumeSurface.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>

namespace nv
{
namespace
{
/// Appends n tuples. The array's own Resize shrinks to the size asked for,
/// so it is called only when the capacity is short (it then leaves room).
template <class Array, class Value>
void Append(Array* array, const Value* values, vtkIdType n)
{
  const vtkIdType components = array->GetNumberOfComponents();
  const vtkIdType old = array->GetNumberOfTuples();
  if ((old + n) * components > array->GetSize())
  {
    array->Resize(old + n);
  }
  array->SetNumberOfTuples(old + n);
  std::copy(values, values + n * components, array->GetPointer(old * components));
}
} // namespace

PolyDataSink::PolyDataSink()
{
  this->Points->SetNumberOfComponents(3);
  this->Normals->SetNumberOfComponents(3);
  this->Normals->SetName("Normals");
}

PolyDataSink::~PolyDataSink() = default;

void PolyDataSink::AddPoints(const double* xyz, const float* normals, std::int64_t n)
{
  Append(this->Points.GetPointer(), xyz, n);
  Append(this->Normals.GetPointer(), normals, n);
}

void PolyDataSink::AddTriangles(const std::int64_t* ids, std::int64_t n)
{
  Append(this->Connectivity.GetPointer(), ids, 3 * n);
}

vtkSmartPointer<vtkPolyData> PolyDataSink::Finish()
{
  static_assert(sizeof(vtkIdType) == sizeof(std::int64_t), "vertex ids are 64-bit");
  this->Points->Squeeze();
  this->Normals->Squeeze();
  this->Connectivity->Squeeze();
  const vtkIdType triangles = this->Connectivity->GetNumberOfTuples() / 3;
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfTuples(triangles + 1);
  for (vtkIdType t = 0; t <= triangles; ++t)
  {
    offsets->SetValue(t, 3 * t);
  }
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, this->Connectivity);
  vtkNew<vtkPoints> points;
  points->SetData(this->Points);
  auto surface = vtkSmartPointer<vtkPolyData>::New();
  surface->SetPoints(points);
  surface->SetPolys(polys);
  surface->GetPointData()->SetNormals(this->Normals);
  return surface;
}

} // namespace nv
