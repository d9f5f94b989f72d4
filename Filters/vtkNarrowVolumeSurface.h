// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The output surface as a vtkPolyData: the core makes it brick layer by brick
// layer (nvSurface.h); this sink appends each layer's vertices (double
// world coordinates, float "Normals") and triangles to VTK arrays, which grow
// in place, so the surface is never held twice.
#ifndef vtkNarrowVolumeSurface_h
#define vtkNarrowVolumeSurface_h

#include "nvSurface.h"

#include "vtkNew.h"
#include "vtkSmartPointer.h"

class vtkDoubleArray;
class vtkFloatArray;
class vtkIdTypeArray;
class vtkPolyData;

namespace nv
{

class PolyDataSink : public SurfaceSink
{
public:
  PolyDataSink();
  ~PolyDataSink() override;
  void AddPoints(const double* xyz, const float* normals, std::int64_t n) override;
  void AddTriangles(const std::int64_t* ids, std::int64_t n) override;
  /// The surface received so far.
  vtkSmartPointer<vtkPolyData> Finish();

private:
  vtkNew<vtkDoubleArray> Points;
  vtkNew<vtkFloatArray> Normals;
  vtkNew<vtkIdTypeArray> Connectivity;
};

} // namespace nv

#endif
