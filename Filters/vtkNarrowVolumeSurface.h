// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The output surface as a vtkPolyData: the core makes it brick layer by brick
// layer (nvSurface.h) into room this sink makes at the end of VTK arrays
// (double world coordinates, float "Normals", triangles), which grow in
// place: the surface is never held twice.
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
  void AddPoints(std::int64_t n, double*& xyz, float*& normals) override;
  VertexId* AddTriangles(std::int64_t n) override;
  SurfaceArrays View() override;
  void Truncate(const SurfaceArrays& kept) override;
  /// The surface received so far.
  vtkSmartPointer<vtkPolyData> Finish();

private:
  vtkNew<vtkDoubleArray> Points;
  vtkNew<vtkFloatArray> Normals;
  vtkNew<vtkIdTypeArray> Connectivity;
};

} // namespace nv

#endif
