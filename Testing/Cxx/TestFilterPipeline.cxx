// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// VTK's filters on the Volume output (port 0) in a C++ pipeline. The filter,
// with only its input and offset set, declares in the information pass the
// grid that the run then produces (whole extent, origin, spacing, float
// scalars); vtkFlyingEdges3D, vtkImageShiftScale, vtkImageGaussianSmooth and
// vtkImageReslice connected to port 0 run without error and give what phi
// on that grid implies.
#include "vtkNarrowVolumeReconstruction.h"

#include "nvTestClouds.h"
#include "nvTestSurfaces.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkDataObject.h>
#include <vtkDataSetAttributes.h>
#include <vtkFlyingEdges3D.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkImageGaussianSmooth.h>
#include <vtkImageReslice.h>
#include <vtkImageShiftScale.h>
#include <vtkInformation.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace
{
const double Center[3] = { 0.3, -0.2, 0.1 };
const double Radius = 0.5;
const double Offset = 0.1;

using SDDP = vtkStreamingDemandDrivenPipeline;

bool SameExtent(const int* a, const int* b)
{
  return std::equal(a, a + 6, b);
}

double Range(vtkDataArray* array, int end)
{
  double range[2] = { 0.0, 0.0 };
  if (array)
  {
    array->GetRange(range);
  }
  return range[end];
}

/// phi of the volume at node (i, j, k).
double PhiAt(vtkImageData* volume, int i, int j, int k)
{
  int ijk[3] = { i, j, k };
  return volume->GetPointData()->GetScalars()->GetTuple1(volume->ComputePointId(ijk));
}

} // namespace

int main()
{
  const auto cloud = nvtest::SphereCloud<vtkPolyData>(6000, Radius, Center);

  vtkNew<vtkNarrowVolumeReconstruction> filter;
  filter->SetInputData(cloud);
  filter->SetOffsetDistance(Offset);

  // --- The information pass, before anything runs.
  filter->UpdateInformation();
  vtkInformation* info = filter->GetOutputInformation(0);
  NV_CHECK(info->Has(SDDP::WHOLE_EXTENT()) && info->Has(vtkDataObject::ORIGIN()) &&
    info->Has(vtkDataObject::SPACING()));
  int whole[6] = { 0, -1, 0, -1, 0, -1 };
  double origin[3] = { 0, 0, 0 }, spacing[3] = { 0, 0, 0 };
  info->Get(SDDP::WHOLE_EXTENT(), whole);
  info->Get(vtkDataObject::ORIGIN(), origin);
  info->Get(vtkDataObject::SPACING(), spacing);
  vtkInformation* scalars = vtkDataObject::GetActiveFieldInformation(
    info, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
  NV_CHECK(scalars != nullptr);
  NV_CHECK(scalars && scalars->Get(vtkDataObject::FIELD_ARRAY_TYPE()) == VTK_FLOAT);
  NV_CHECK(scalars && scalars->Get(vtkDataObject::FIELD_NUMBER_OF_COMPONENTS()) == 1);
  std::printf("information pass: whole extent %d %d %d %d %d %d, origin %.6f %.6f %.6f, spacing %.6f\n", whole[0],
    whole[1], whole[2], whole[3], whole[4], whole[5], origin[0], origin[1], origin[2], spacing[0]);
  NV_CHECK(whole[0] == 0 && whole[2] == 0 && whole[4] == 0);
  NV_CHECK(whole[1] > 10 && whole[3] > 10 && whole[5] > 10);
  NV_CHECK(spacing[0] > 0 && spacing[0] == spacing[1] && spacing[1] == spacing[2]);
  NV_CHECK(filter->GetNumberOfGridNodes() == 0); // not run yet
  NV_CHECK(filter->GetVolumeOutput()->GetNumberOfPoints() == 0);

  // --- vtkFlyingEdges3D on port 0 drives the run. The filter's surface is
  // the zero level of the same phi, contoured from the distance it implies
  // (TestSurfaceContour): the same cut edges, hence the same points and
  // triangles, each vertex moved along its edge by a few hundredths of h.
  vtkNew<vtkFlyingEdges3D> flyingEdges;
  flyingEdges->SetInputConnection(filter->GetOutputPort(0));
  flyingEdges->SetValue(0, 0.0);
  flyingEdges->Update();

  vtkImageData* volume = filter->GetVolumeOutput();
  NV_CHECK(SameExtent(volume->GetExtent(), whole));
  double dataOrigin[3], dataSpacing[3];
  volume->GetOrigin(dataOrigin);
  volume->GetSpacing(dataSpacing);
  for (int a = 0; a < 3; ++a)
  {
    NV_CHECK(dataOrigin[a] == origin[a]);
    NV_CHECK(dataSpacing[a] == spacing[a]);
  }
  vtkDataArray* phi = volume->GetPointData()->GetScalars();
  NV_CHECK(phi && phi->GetDataType() == VTK_FLOAT && phi->GetNumberOfComponents() == 1);
  NV_CHECK(phi && std::string(phi->GetName()) == "phi");
  if (!phi)
  {
    return nvtest::Result("TestFilterPipeline");
  }
  const double h = spacing[0];
  const int dims[3] = { whole[1] + 1, whole[3] + 1, whole[5] + 1 };
  std::printf("grid %d x %d x %d, h = %.6f, phi in [%.4f, %.4f]\n", dims[0], dims[1], dims[2], h,
    Range(phi, 0), Range(phi, 1));

  vtkPolyData* surface = filter->GetSurfaceOutput();
  vtkPolyData* isosurface = flyingEdges->GetOutput();
  const auto ours = nvtest::VerticesByEdge(surface, origin, h);
  const auto reference = nvtest::VerticesByEdge(isosurface, origin, h);
  double shift = 0.0, turn = 0.0;
  const bool sameEdges = nvtest::SameEdges(ours, reference, shift, turn, 1e-3);
  std::printf("vtkFlyingEdges3D: %lld triangles, %lld points; port 1: %lld triangles, %lld points; same cut "
              "edges %d, vertices moved by %.3g h at most\n",
    static_cast<long long>(isosurface->GetNumberOfPolys()), static_cast<long long>(isosurface->GetNumberOfPoints()),
    static_cast<long long>(surface->GetNumberOfPolys()), static_cast<long long>(surface->GetNumberOfPoints()),
    sameEdges, shift);
  NV_CHECK(surface->GetNumberOfPolys() > 1000);
  NV_CHECK(isosurface->GetNumberOfPolys() == surface->GetNumberOfPolys());
  NV_CHECK(isosurface->GetNumberOfPoints() == surface->GetNumberOfPoints());
  NV_CHECK(sameEdges && ours.Stray == 0 && reference.Stray == 0);
  NV_CHECK(shift < 0.025); // 0.022 h at most on spheres (issue 13)

  // Downstream filters see the grid in their own information pass.
  vtkNew<vtkImageShiftScale> shiftScale;
  shiftScale->SetInputConnection(filter->GetOutputPort(0));
  shiftScale->SetShift(1.0);
  shiftScale->SetScale(0.5);
  shiftScale->UpdateInformation();
  int seen[6] = { 0, -1, 0, -1, 0, -1 };
  shiftScale->GetOutputInformation(0)->Get(SDDP::WHOLE_EXTENT(), seen);
  NV_CHECK(SameExtent(seen, whole));

  // --- vtkImageShiftScale: (phi + 1) / 2, float, so [-1, 1] maps to [0, 1].
  shiftScale->Update();
  vtkImageData* shifted = shiftScale->GetOutput();
  vtkDataArray* mapped = shifted->GetPointData()->GetScalars();
  NV_CHECK(mapped && mapped->GetDataType() == VTK_FLOAT);
  NV_CHECK(SameExtent(shifted->GetExtent(), whole));
  double worst = 0.0;
  for (vtkIdType p = 0; mapped && p < volume->GetNumberOfPoints(); ++p)
  {
    worst = std::max(worst, std::fabs(mapped->GetTuple1(p) - 0.5 * (phi->GetTuple1(p) + 1.0)));
  }
  std::printf("vtkImageShiftScale: range [%.4f, %.4f], max |value - (phi + 1) / 2| = %.3g\n", Range(mapped, 0),
    Range(mapped, 1), worst);
  NV_CHECK(mapped && mapped->GetNumberOfTuples() == phi->GetNumberOfTuples());
  NV_CHECK_NEAR(Range(mapped, 0), 0.5 * (Range(phi, 0) + 1.0), 1e-6);
  NV_CHECK_NEAR(Range(mapped, 1), 0.5 * (Range(phi, 1) + 1.0), 1e-6);
  NV_CHECK(Range(mapped, 0) >= 0.0 && Range(mapped, 1) <= 1.0);
  NV_CHECK(worst < 1e-6);

  // --- vtkImageGaussianSmooth (standard deviation 2 cells): the same grid,
  // values averages of phi, so within its range; far from the shell (the
  // sphere's centre) still -1.
  vtkNew<vtkImageGaussianSmooth> gaussian;
  gaussian->SetInputConnection(filter->GetOutputPort(0));
  gaussian->SetStandardDeviations(2.0, 2.0, 2.0);
  gaussian->Update();
  vtkImageData* smooth = gaussian->GetOutput();
  vtkDataArray* smoothed = smooth->GetPointData()->GetScalars();
  double centre[3] = { Center[0], Center[1], Center[2] };
  const vtkIdType centreNode = smooth->FindPoint(centre);
  std::printf("vtkImageGaussianSmooth: dimensions %d %d %d, range [%.4f, %.4f], at the centre %.4f\n",
    smooth->GetDimensions()[0], smooth->GetDimensions()[1], smooth->GetDimensions()[2], Range(smoothed, 0),
    Range(smoothed, 1), smoothed && centreNode >= 0 ? smoothed->GetTuple1(centreNode) : 0.0);
  NV_CHECK(SameExtent(smooth->GetExtent(), whole));
  NV_CHECK(smoothed && smoothed->GetNumberOfTuples() == phi->GetNumberOfTuples());
  NV_CHECK(Range(smoothed, 0) >= Range(phi, 0) - 1e-6 && Range(smoothed, 1) <= Range(phi, 1) + 1e-6);
  NV_CHECK(Range(smoothed, 0) >= -1.0 && Range(smoothed, 1) <= 1.0);
  NV_CHECK(Range(smoothed, 0) < -0.99 && Range(smoothed, 1) > 0.5);
  NV_CHECK(smoothed && centreNode >= 0 && smoothed->GetTuple1(centreNode) < -0.99);

  // --- vtkImageReslice with its defaults: the output grid comes from the
  // input's information (extent, origin, spacing), so it is the volume,
  // value for value.
  vtkNew<vtkImageReslice> identity;
  identity->SetInputConnection(filter->GetOutputPort(0));
  identity->Update();
  vtkImageData* same = identity->GetOutput();
  vtkDataArray* sameValues = same->GetPointData()->GetScalars();
  worst = 0.0;
  for (vtkIdType p = 0; sameValues && p < volume->GetNumberOfPoints(); ++p)
  {
    worst = std::max(worst, std::fabs(sameValues->GetTuple1(p) - phi->GetTuple1(p)));
  }
  std::printf("vtkImageReslice, defaults: dimensions %d %d %d, origin %.6f %.6f %.6f, max |value - phi| = %.3g\n",
    same->GetDimensions()[0], same->GetDimensions()[1], same->GetDimensions()[2], same->GetOrigin()[0],
    same->GetOrigin()[1], same->GetOrigin()[2], worst);
  NV_CHECK(SameExtent(same->GetExtent(), whole));
  NV_CHECK(same->GetOrigin()[0] == origin[0] && same->GetOrigin()[1] == origin[1] &&
    same->GetOrigin()[2] == origin[2]);
  NV_CHECK(same->GetSpacing()[0] == h);
  NV_CHECK(sameValues && sameValues->GetNumberOfTuples() == phi->GetNumberOfTuples() && worst == 0.0);

  // --- vtkImageReslice onto every other node, linear: its own grid
  // (origin, spacing 2h, extent), values phi at those nodes.
  vtkNew<vtkImageReslice> coarse;
  coarse->SetInputConnection(filter->GetOutputPort(0));
  coarse->SetInterpolationModeToLinear();
  coarse->SetOutputOrigin(origin);
  coarse->SetOutputSpacing(2 * h, 2 * h, 2 * h);
  const int half[3] = { (dims[0] - 1) / 2, (dims[1] - 1) / 2, (dims[2] - 1) / 2 };
  coarse->SetOutputExtent(0, half[0], 0, half[1], 0, half[2]);
  coarse->Update();
  vtkImageData* resliced = coarse->GetOutput();
  vtkDataArray* reslicedValues = resliced->GetPointData()->GetScalars();
  worst = 0.0;
  for (int k = 0; reslicedValues && k <= half[2]; ++k)
  {
    for (int j = 0; j <= half[1]; ++j)
    {
      for (int i = 0; i <= half[0]; ++i)
      {
        int ijk[3] = { i, j, k };
        worst = std::max(worst,
          std::fabs(reslicedValues->GetTuple1(resliced->ComputePointId(ijk)) - PhiAt(volume, 2 * i, 2 * j, 2 * k)));
      }
    }
  }
  std::printf("vtkImageReslice, every other node: dimensions %d %d %d, origin %.6f %.6f %.6f, spacing %.6f, "
              "max |value - phi| = %.3g\n",
    resliced->GetDimensions()[0], resliced->GetDimensions()[1], resliced->GetDimensions()[2],
    resliced->GetOrigin()[0], resliced->GetOrigin()[1], resliced->GetOrigin()[2], resliced->GetSpacing()[0], worst);
  NV_CHECK(resliced->GetDimensions()[0] == half[0] + 1 && resliced->GetDimensions()[1] == half[1] + 1 &&
    resliced->GetDimensions()[2] == half[2] + 1);
  NV_CHECK_NEAR(resliced->GetOrigin()[0], origin[0], 1e-12);
  NV_CHECK_NEAR(resliced->GetOrigin()[1], origin[1], 1e-12);
  NV_CHECK_NEAR(resliced->GetOrigin()[2], origin[2], 1e-12);
  NV_CHECK_NEAR(resliced->GetSpacing()[0], 2 * h, 1e-12);
  NV_CHECK(reslicedValues && worst < 1e-5);
  return nvtest::Result("TestFilterPipeline");
}
