// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// A program built against an installed NarrowVolume: the filter on 400 points
// of a sphere. Exit code 0 when the surface has triangles and the volume a
// "phi" array.
#include <vtkNarrowVolumeReconstruction.h>

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <cmath>
#include <cstdio>

int main()
{
  // 400 points spread evenly over a sphere of radius 0.5 (Fibonacci lattice).
  const int n = 400;
  const double pi = std::acos(-1.0);
  vtkNew<vtkPoints> points;
  for (int i = 0; i < n; ++i)
  {
    const double polar = std::acos(1.0 - 2.0 * (i + 0.5) / n);
    const double azimuth = pi * (1.0 + std::sqrt(5.0)) * (i + 0.5);
    points->InsertNextPoint(0.5 * std::cos(azimuth) * std::sin(polar),
      0.5 * std::sin(azimuth) * std::sin(polar), 0.5 * std::cos(polar));
  }
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(points);

  vtkNew<vtkNarrowVolumeReconstruction> filter;
  filter->SetInputData(cloud);
  filter->SetOffsetDistance(0.1); // points are about 0.09 apart
  filter->SetMaximumDimension(50);
  filter->Update();

  vtkImageData* volume = filter->GetVolumeOutput();
  vtkPolyData* surface = filter->GetSurfaceOutput();
  const vtkIdType triangles = surface->GetNumberOfPolys();
  vtkDataArray* phi = volume->GetPointData()->GetArray("phi");
  const bool ok = triangles > 0 && surface->GetPolys()->IsHomogeneous() == 3 && phi != nullptr &&
    phi->GetNumberOfTuples() == volume->GetNumberOfPoints();
  std::printf("nv_consumer: %lld triangles, phi on %lld of %lld nodes: %s\n",
    static_cast<long long>(triangles), static_cast<long long>(phi ? phi->GetNumberOfTuples() : 0),
    static_cast<long long>(volume->GetNumberOfPoints()), ok ? "ok" : "FAILED");
  return ok ? 0 : 1;
}
