// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// A program built against an installed NarrowVolume: 400 points of a sphere
// written as a PCD file, read by vtkPCDPointCloudReader (module
// NarrowVolume::Readers), and the filter (NarrowVolume::Filters) on them.
// Exit code 0 when the reader gives the 400 points and the surface has
// triangles and the volume a "phi" array.
#include <vtkNarrowVolumeReconstruction.h>
#include <vtkPCDPointCloudReader.h>

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

int main(int argc, char* argv[])
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
  // The PCD file goes into the folder given as the argument (default: here).
  const std::string path = std::string(argc > 1 ? argv[1] : ".") + "/nv_consumer_sphere.pcd";
  {
    std::ofstream pcd(path);
    pcd << "VERSION 0.7\nFIELDS x y z\nSIZE 8 8 8\nTYPE F F F\nCOUNT 1 1 1\nWIDTH " << n
        << "\nHEIGHT 1\nPOINTS " << n << "\nDATA ascii\n";
    pcd.precision(17);
    for (vtkIdType i = 0; i < n; ++i)
    {
      double p[3];
      points->GetPoint(i, p);
      pcd << p[0] << " " << p[1] << " " << p[2] << "\n";
    }
  }
  vtkNew<vtkPCDPointCloudReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  const vtkIdType read = reader->GetOutput()->GetNumberOfPoints();

  vtkNew<vtkNarrowVolumeReconstruction> filter;
  filter->SetInputConnection(reader->GetOutputPort());
  filter->SetOffsetDistance(0.1); // points are about 0.09 apart
  filter->SetMaximumDimension(50);
  filter->Update();

  vtkImageData* volume = filter->GetVolumeOutput();
  vtkPolyData* surface = filter->GetSurfaceOutput();
  const vtkIdType triangles = surface->GetNumberOfPolys();
  vtkDataArray* phi = volume->GetPointData()->GetArray("phi");
  const bool ok = read == n && triangles > 0 && surface->GetPolys()->IsHomogeneous() == 3 && phi != nullptr &&
    phi->GetNumberOfTuples() == volume->GetNumberOfPoints();
  std::printf("nv_consumer: %lld points read, %lld triangles, phi on %lld of %lld nodes: %s\n",
    static_cast<long long>(read), static_cast<long long>(triangles), static_cast<long long>(phi ? phi->GetNumberOfTuples() : 0),
    static_cast<long long>(volume->GetNumberOfPoints()), ok ? "ok" : "FAILED");
  return ok ? 0 : 1;
}
