// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// Point clouds as VTK point sets, for the filter's tests (the core's tests
// use the plain xyz arrays of nvTestUtilities.h).
#ifndef nvTestClouds_h
#define nvTestClouds_h

#include "nvTestUtilities.h"

#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>

namespace nvtest
{

/// n points spread over a sphere, as a point set of type DataSet (points, no cells).
template <class DataSet>
vtkSmartPointer<DataSet> SphereCloud(int n, double radius, const double center[3])
{
  const std::vector<double> xyz = SpherePoints(n, radius, center);
  vtkNew<vtkPoints> points;
  for (std::size_t p = 0; p < xyz.size(); p += 3)
  {
    points->InsertNextPoint(&xyz[p]);
  }
  auto cloud = vtkSmartPointer<DataSet>::New();
  cloud->SetPoints(points);
  return cloud;
}

} // namespace nvtest

#endif
