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
#include <type_traits>

namespace nv
{
namespace
{
/// Room for n more tuples at the end of the array. The array's own Resize
/// shrinks to the size asked for, so it is called only when the capacity is
/// short (it then leaves room for as many again).
template <class Array>
auto* Extend(Array* array, vtkIdType n)
{
  const vtkIdType components = array->GetNumberOfComponents();
  const vtkIdType old = array->GetNumberOfTuples();
  if ((old + n) * components > array->GetSize())
  {
    array->Resize(old + n);
  }
  array->SetNumberOfTuples(old + n);
  return array->GetPointer(old * components);
}
} // namespace

PolyDataSink::PolyDataSink()
{
  this->Points->SetNumberOfComponents(3);
  this->Normals->SetNumberOfComponents(3);
  this->Normals->SetName("Normals");
}

PolyDataSink::~PolyDataSink() = default;

void PolyDataSink::AddPoints(std::int64_t n, double*& xyz, float*& normals)
{
  xyz = Extend(this->Points.GetPointer(), n);
  normals = Extend(this->Normals.GetPointer(), n);
}

VertexId* PolyDataSink::AddTriangles(std::int64_t n)
{
  static_assert(std::is_same<vtkIdType, VertexId>::value, "VTK's ids are the core's");
  return Extend(this->Connectivity.GetPointer(), 3 * n);
}

SurfaceArrays PolyDataSink::View()
{
  SurfaceArrays arrays;
  arrays.Points = this->Points->GetPointer(0);
  arrays.Normals = this->Normals->GetPointer(0);
  arrays.Triangles = this->Connectivity->GetPointer(0);
  arrays.NumberOfPoints = this->Points->GetNumberOfTuples();
  arrays.NumberOfTriangles = this->Connectivity->GetNumberOfTuples() / 3;
  return arrays;
}

void PolyDataSink::Truncate(const SurfaceArrays& kept)
{
  this->Points->SetNumberOfTuples(kept.NumberOfPoints);
  this->Normals->SetNumberOfTuples(kept.NumberOfPoints);
  this->Connectivity->SetNumberOfTuples(3 * kept.NumberOfTriangles);
}

vtkSmartPointer<vtkPolyData> PolyDataSink::Finish()
{
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
