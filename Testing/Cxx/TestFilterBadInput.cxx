// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// Bad input gets a clear error, an empty output and no crash.
#include "vtkNarrowVolumeReconstruction.h"

#include "nvTestClouds.h"

#include <vtkCommand.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <cmath>
#include <limits>
#include <string>

namespace
{

/// Records the error messages a filter sends.
class ErrorCatcher : public vtkCommand
{
public:
  static ErrorCatcher* New() { return new ErrorCatcher; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    this->Messages += static_cast<const char*>(data);
    this->Messages += "\n";
  }
  std::string Messages;
};

vtkSmartPointer<vtkPolyData> Cloud(const std::vector<double>& xyz)
{
  return nvtest::Cloud<vtkPolyData>(xyz);
}

/// Runs the filter and checks it reported an error containing `expected`
/// and left both outputs empty.
void ExpectError(vtkNarrowVolumeReconstruction* filter, vtkDataObject* input, const std::string& expected)
{
  vtkNew<ErrorCatcher> catcher;
  const unsigned long tag = filter->AddObserver(vtkCommand::ErrorEvent, catcher);
  filter->SetInputData(input);
  filter->Modified();
  filter->Update();
  filter->RemoveObserver(tag);
  const bool found = catcher->Messages.find(expected) != std::string::npos;
  if (!found)
  {
    std::printf("expected an error with \"%s\", got \"%s\"\n", expected.c_str(), catcher->Messages.c_str());
  }
  NV_CHECK(found);
  NV_CHECK(filter->GetVolumeOutput()->GetNumberOfPoints() == 0);
  NV_CHECK(filter->GetSurfaceOutput()->GetNumberOfPoints() == 0);
}

vtkSmartPointer<vtkNarrowVolumeReconstruction> Filter()
{
  auto filter = vtkSmartPointer<vtkNarrowVolumeReconstruction>::New();
  filter->SetOffsetDistance(0.1);
  filter->SetSampleSpacing(0.05);
  return filter;
}

} // namespace

int main()
{
  const double origin[3] = { 0, 0, 0 };
  const std::vector<double> good = nvtest::SpherePoints(200, 0.5, origin);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();

  // A good run first, so that every failure below must also clear old output.
  auto filter = Filter();
  filter->SetInputData(Cloud(good));
  filter->Update();
  NV_CHECK(filter->GetSurfaceOutput()->GetNumberOfPoints() > 0);

  ExpectError(filter, Cloud({}), "no points");
  ExpectError(filter, vtkNew<vtkPolyData>(), "no points");

  std::vector<double> withNaN = good;
  withNaN[3 * 17 + 1] = nan;
  filter->SetInputData(Cloud(good));
  filter->Update();
  ExpectError(filter, Cloud(withNaN), "Input point 17 has a non-finite coordinate");
  std::vector<double> withInf = good;
  withInf[3 * 5 + 2] = -inf;
  ExpectError(filter, Cloud(withInf), "Input point 5 has a non-finite coordinate");

  for (double offset : { -0.1, nan, inf })
  {
    auto f = Filter();
    f->SetOffsetDistance(offset);
    ExpectError(f, Cloud(good), "OffsetDistance must be a finite value > 0");
  }
  {
    // OffsetDistance 0 follows the points' spacing, which one point (or
    // copies of one point) does not have.
    auto f = Filter();
    f->SetOffsetDistance(0.0);
    ExpectError(f, Cloud({ 0.5, 0.5, 0.5, 0.5, 0.5, 0.5 }), "An automatic OffsetDistance needs at least two distinct points");
  }
  for (double spacing : { nan, inf, -inf })
  {
    auto f = Filter();
    f->SetSampleSpacing(spacing);
    ExpectError(f, Cloud(good), "SampleSpacing must be finite");
  }
  {
    auto f = Filter();
    f->SetTimeStep(nan);
    ExpectError(f, Cloud(good), "TimeStep must be finite");
  }
  for (double xi : { 0.5, 0.0, -1.0, 100.0, nan })
  {
    auto f = Filter();
    f->SetXiCells(xi);
    ExpectError(f, Cloud(good), "XiCells must be in [1, 64]");
  }
  for (double eps : { 0.1, -3.0, 1000.0, nan })
  {
    auto f = Filter();
    f->SetEpsilonCells(eps);
    ExpectError(f, Cloud(good), "EpsilonCells must be in [0.5, 256]");
  }
  {
    // 1e-5 spacing over a unit cloud: 10^15 nodes, refused before allocating.
    auto f = Filter();
    f->SetSampleSpacing(1e-5);
    ExpectError(f, Cloud(good), "The grid is too large");
    // A modest grid over a small memory limit is refused too.
    auto g = Filter();
    g->SetSampleSpacing(0.01);
    g->SetMemoryLimit(1.0);
    ExpectError(g, Cloud(good), "The grid is too large");
  }
  {
    // SampleSpacing <= 0 derives the spacing: not an error.
    auto f = Filter();
    f->SetSampleSpacing(0.0);
    f->SetMaximumDimension(40);
    f->SetInputData(Cloud(good));
    f->Update();
    int dims[3];
    f->GetVolumeOutput()->GetDimensions(dims);
    NV_CHECK(std::max(dims[0], std::max(dims[1], dims[2])) == 41);
  }
  return nvtest::Result("TestFilterBadInput");
}
