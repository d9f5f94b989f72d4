// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The filter in a VTK C++ pipeline on a sampled sphere: phi stays in [-1, 1],
// the surface is closed, and it has two sheets at radii R - l and R + l with
// normals pointing out of the shell.
#include "vtkNarrowVolumeReconstruction.h"

#include "nvTestClouds.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkFeatureEdges.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataConnectivityFilter.h>
#include <vtkUnstructuredGrid.h>

#include <cmath>

namespace
{
const double Center[3] = { 0.3, -0.2, 0.1 };
const double Radius = 0.5;
const double Offset = 0.1;
const double Spacing = 0.02;

vtkIdType Edges(vtkPolyData* surface, bool boundary, bool nonManifold)
{
  vtkNew<vtkFeatureEdges> edges;
  edges->SetInputData(surface);
  edges->SetBoundaryEdges(boundary);
  edges->SetNonManifoldEdges(nonManifold);
  edges->FeatureEdgesOff();
  edges->ManifoldEdgesOff();
  edges->Update();
  return edges->GetOutput()->GetNumberOfCells();
}

void CheckSheets(vtkPolyData* surface)
{
  NV_CHECK(surface->GetNumberOfPolys() > 1000);
  NV_CHECK(Edges(surface, true, false) == 0); // closed
  NV_CHECK(Edges(surface, false, true) == 0); // manifold

  vtkNew<vtkPolyDataConnectivityFilter> connectivity;
  connectivity->SetInputData(surface);
  connectivity->SetExtractionModeToAllRegions();
  connectivity->ColorRegionsOn();
  connectivity->Update();
  NV_CHECK(connectivity->GetNumberOfExtractedRegions() == 2);

  // Radii of the vertices of each sheet; normals point out of the shell:
  // away from the centre on the outer sheet, towards it on the inner one.
  vtkDataArray* normals = surface->GetPointData()->GetNormals();
  NV_CHECK(normals != nullptr);
  double sum[2] = { 0, 0 }, worst[2] = { 0, 0 };
  vtkIdType count[2] = { 0, 0 }, wrongNormals = 0;
  for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
  {
    double x[3], n[3] = { 0, 0, 0 };
    surface->GetPoint(i, x);
    if (normals)
      normals->GetTuple(i, n);
    const double r = std::hypot(x[0] - Center[0], x[1] - Center[1], x[2] - Center[2]);
    const int outer = r > Radius ? 1 : 0;
    const double exact = outer ? Radius + Offset : Radius - Offset;
    sum[outer] += r - exact;
    worst[outer] = std::max(worst[outer], std::fabs(r - exact));
    ++count[outer];
    const double radial = (n[0] * (x[0] - Center[0]) + n[1] * (x[1] - Center[1]) + n[2] * (x[2] - Center[2])) / r;
    wrongNormals += outer ? radial < 0.9 : radial > -0.9;
  }
  NV_CHECK(count[0] > 100 && count[1] > 100);
  NV_CHECK(wrongNormals == 0);
  // Within half a cell on average and one cell at worst (h = 0.02; the
  // sampling of 6000 points leaves dips of about 0.001 between points).
  NV_CHECK_NEAR(sum[0] / count[0], 0.0, 0.5 * Spacing);
  NV_CHECK_NEAR(sum[1] / count[1], 0.0, 0.5 * Spacing);
  NV_CHECK(worst[0] < Spacing);
  NV_CHECK(worst[1] < Spacing);
}

void CheckVolume(vtkNarrowVolumeReconstruction* filter)
{
  vtkImageData* volume = filter->GetVolumeOutput();
  vtkFloatArray* phi = vtkFloatArray::SafeDownCast(volume->GetPointData()->GetArray("phi"));
  NV_CHECK(phi != nullptr);
  if (!phi)
    return;
  NV_CHECK(phi->GetNumberOfTuples() == volume->GetNumberOfPoints());
  NV_CHECK(volume->GetNumberOfPoints() == filter->GetNumberOfGridNodes());
  double range[2];
  phi->GetRange(range);
  NV_CHECK(range[0] >= -1.0 && range[1] <= 1.0);
  NV_CHECK(range[0] < -0.99 && range[1] > 0.99);
  // The centre of the sphere is outside the shell, a node at radius R inside.
  double centre[3] = { Center[0], Center[1], Center[2] };
  double onSphere[3] = { Center[0] + Radius, Center[1], Center[2] };
  NV_CHECK(phi->GetValue(volume->FindPoint(centre)) < -0.99);
  NV_CHECK(phi->GetValue(volume->FindPoint(onSphere)) > 0.9);
  // Band: far fewer nodes than the grid.
  NV_CHECK(filter->GetNumberOfBandNodes() > 0);
  NV_CHECK(filter->GetNumberOfBandNodes() < filter->GetNumberOfGridNodes() / 2);
  NV_CHECK(filter->GetNumberOfIterations() == filter->GetMaximumNumberOfIterations());
}

} // namespace

int main()
{
  // Any vtkPointSet: an unstructured grid with points and no cells.
  const auto cloud = nvtest::SphereCloud<vtkUnstructuredGrid>(6000, Radius, Center);

  vtkNew<vtkNarrowVolumeReconstruction> filter;
  filter->SetInputData(cloud);
  filter->SetOffsetDistance(Offset);
  filter->SetSampleSpacing(Spacing);
  filter->OutputInitialPhiOn();
  filter->OutputDistanceOn();
  filter->OutputNarrowBandOn();
  filter->Update();

  CheckVolume(filter);
  CheckSheets(filter->GetSurfaceOutput());

  // Optional arrays are consistent with each other and with the band.
  vtkImageData* volume = filter->GetVolumeOutput();
  vtkDataArray* band = volume->GetPointData()->GetArray("NarrowBand");
  vtkDataArray* distance = volume->GetPointData()->GetArray("Distance");
  vtkDataArray* initial = volume->GetPointData()->GetArray("InitialPhi");
  NV_CHECK(band && distance && initial);
  if (band && distance && initial)
  {
    vtkIdType bandNodes = 0;
    for (vtkIdType i = 0; i < volume->GetNumberOfPoints(); ++i)
    {
      const double d = distance->GetTuple1(i);
      const double phi0 = std::tanh((Offset - d) / (std::sqrt(2.0) * 2 * Spacing / (std::sqrt(2.0) * std::atanh(0.99))));
      NV_CHECK_NEAR(initial->GetTuple1(i), phi0, 1e-6);
      const bool inBand = std::fabs(phi0) < 0.99;
      // Nodes exactly at the band's edge may round either way in float.
      if (std::fabs(std::fabs(phi0) - 0.99) > 1e-5)
      {
        NV_CHECK((band->GetTuple1(i) == 1.0) == inBand);
      }
      bandNodes += band->GetTuple1(i) == 1.0;
    }
    NV_CHECK(bandNodes == filter->GetNumberOfBandNodes());
  }

  // Whole Domain mode: the same sheets, every node updated.
  filter->SetDomainToWholeDomain();
  filter->Update();
  NV_CHECK(filter->GetNumberOfBandNodes() == filter->GetNumberOfGridNodes());
  CheckSheets(filter->GetSurfaceOutput());

  // The scan surface: one closed, manifold surface at the sphere's radius,
  // its normals outward, where the points are.
  filter->SetDomainToNarrowBand();
  filter->SetSheetsToScan();
  filter->Update();
  vtkPolyData* scan = filter->GetSurfaceOutput();
  NV_CHECK(scan->GetNumberOfPolys() > 1000);
  NV_CHECK(Edges(scan, true, false) == 0);
  NV_CHECK(Edges(scan, false, true) == 0);
  {
    vtkNew<vtkPolyDataConnectivityFilter> connectivity;
    connectivity->SetInputData(scan);
    connectivity->SetExtractionModeToAllRegions();
    connectivity->Update();
    NV_CHECK(connectivity->GetNumberOfExtractedRegions() == 1);
  }
  double radii = 0.0, outward = 0.0;
  vtkDataArray* scanNormals = scan->GetPointData()->GetNormals();
  NV_CHECK(scanNormals != nullptr);
  for (vtkIdType p = 0; scanNormals && p < scan->GetNumberOfPoints(); ++p)
  {
    double x[3], n[3], r = 0.0, along = 0.0;
    scan->GetPoint(p, x);
    scanNormals->GetTuple(p, n);
    for (int a = 0; a < 3; ++a)
    {
      r += (x[a] - Center[a]) * (x[a] - Center[a]);
    }
    r = std::sqrt(r);
    for (int a = 0; a < 3; ++a)
    {
      along += n[a] * (x[a] - Center[a]) / r;
    }
    radii += r;
    outward += along > 0.9 ? 1.0 : 0.0;
  }
  const double points = static_cast<double>(scan->GetNumberOfPoints());
  NV_CHECK_NEAR(radii / points, Radius, 0.25 * Spacing);
  NV_CHECK(outward == points);
  NV_CHECK(filter->GetVolumeOutput()->GetFieldData()->GetArray("ScanSurface") != nullptr);
  return nvtest::Result("TestFilterSphere");
}
