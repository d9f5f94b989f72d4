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

/// xyz triples as a point set of type DataSet (points, no cells).
template <class DataSet>
vtkSmartPointer<DataSet> Cloud(const std::vector<double>& xyz)
{
  vtkNew<vtkPoints> points;
  for (std::size_t p = 0; p < xyz.size(); p += 3)
  {
    points->InsertNextPoint(&xyz[p]);
  }
  auto cloud = vtkSmartPointer<DataSet>::New();
  cloud->SetPoints(points);
  return cloud;
}

/// n points spread over a sphere, as a point set of type DataSet.
template <class DataSet>
vtkSmartPointer<DataSet> SphereCloud(int n, double radius, const double center[3])
{
  return Cloud<DataSet>(SpherePoints(n, radius, center));
}

} // namespace nvtest

#endif
