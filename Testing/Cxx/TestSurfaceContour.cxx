// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The surface of output port 1 (nvSurface.h), made in the band's bricks,
// against vtkFlyingEdges3D on the whole grid of the same values: the same cut
// edges, vertices and normals to float round-off, the same number of
// triangles; for each of the 256 cases of a cell, on a random field (with
// nodes exactly on the level), on the implied distance of a run's band, and
// on port 0's phi. Its surface is closed, manifold, free of zero-area
// triangles, its triangles wound like its normals, and the same for any
// number of threads.
#include "nvMarchingCubes.h"
#include "nvReconstruction.h"
#include "nvSurface.h"
#include "nvSurfaceField.h"
#include "vtkNarrowVolumeReconstruction.h"

#include "nvTestClouds.h"
#include "nvTestSurfaces.h"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFlyingEdges3D.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkPoints.h>

#include <cstring>
#include <random>

namespace
{
/// The core's surface as a vtkPolyData.
vtkSmartPointer<vtkPolyData> ToPolyData(const nv::SurfaceMesh& mesh)
{
  vtkNew<vtkDoubleArray> xyz;
  xyz->SetNumberOfComponents(3);
  xyz->SetNumberOfTuples(static_cast<vtkIdType>(mesh.Points.size() / 3));
  std::copy(mesh.Points.begin(), mesh.Points.end(), xyz->GetPointer(0));
  vtkNew<vtkFloatArray> normals;
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(xyz->GetNumberOfTuples());
  std::copy(mesh.Normals.begin(), mesh.Normals.end(), normals->GetPointer(0));
  vtkNew<vtkCellArray> triangles;
  for (std::size_t t = 0; t < mesh.Triangles.size(); t += 3)
  {
    const vtkIdType ids[3] = { mesh.Triangles[t], mesh.Triangles[t + 1], mesh.Triangles[t + 2] };
    triangles->InsertNextCell(3, ids);
  }
  vtkNew<vtkPoints> points;
  points->SetData(xyz);
  auto surface = vtkSmartPointer<vtkPolyData>::New();
  surface->SetPoints(points);
  surface->SetPolys(triangles);
  surface->GetPointData()->SetNormals(normals);
  return surface;
}

/// The field on every node of the grid (x fastest), read as the contouring reads it.
std::vector<float> DenseValues(const nv::Grid& grid, const nv::BrickField& field)
{
  const auto bricks = nv::BrickDimensions(grid);
  std::vector<float> dense(static_cast<std::size_t>(grid.NumberOfNodes()));
  std::vector<float> uniform;
  std::vector<std::int64_t> varying;
  float values[nv::BrickNodes];
  for (std::int64_t layer = 0; layer < bricks[2]; ++layer)
  {
    field.Layer(layer, uniform, varying);
    for (std::int64_t b = layer * bricks[0] * bricks[1]; b < (layer + 1) * bricks[0] * bricks[1]; ++b)
    {
      const bool varies = std::binary_search(varying.begin(), varying.end(), b);
      if (varies)
      {
        field.Values(b, values);
      }
      const std::int64_t first[3] = { (b % bricks[0]) * nv::BrickSize, ((b / bricks[0]) % bricks[1]) * nv::BrickSize,
        layer * nv::BrickSize };
      for (int n = 0; n < nv::BrickNodes; ++n)
      {
        const std::int64_t i = first[0] + n % 8, j = first[1] + (n / 8) % 8, k = first[2] + n / 64;
        if (i < grid.Dims[0] && j < grid.Dims[1] && k < grid.Dims[2])
        {
          dense[static_cast<std::size_t>(grid.Index(i, j, k))] =
            varies ? values[n] : uniform[static_cast<std::size_t>(b - layer * bricks[0] * bricks[1])];
        }
      }
    }
  }
  return dense;
}

/// vtkFlyingEdges3D at 0 on dense values of the grid.
vtkSmartPointer<vtkPolyData> FlyingEdges(const nv::Grid& grid, const std::vector<float>& values)
{
  vtkNew<vtkImageData> image;
  image->SetOrigin(grid.Origin.data());
  image->SetSpacing(grid.Spacing, grid.Spacing, grid.Spacing);
  image->SetDimensions(static_cast<int>(grid.Dims[0]), static_cast<int>(grid.Dims[1]), static_cast<int>(grid.Dims[2]));
  vtkNew<vtkFloatArray> scalars;
  scalars->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
  std::copy(values.begin(), values.end(), scalars->GetPointer(0));
  image->GetPointData()->SetScalars(scalars);
  vtkNew<vtkFlyingEdges3D> contour;
  contour->SetInputData(image);
  contour->SetValue(0, 0.0);
  contour->ComputeNormalsOn();
  contour->Update();
  return contour->GetOutput();
}

/// Same triangle count, same cut edges, vertices (moved 1e-3 h away from the
/// nodes, nvSurface.h) and normals to float round-off.
bool SameAsFlyingEdges(vtkPolyData* ours, vtkPolyData* reference, const nv::Grid& grid, const char* what)
{
  const auto a = nvtest::VerticesByEdge(ours, grid.Origin.data(), grid.Spacing);
  const auto b = nvtest::VerticesByEdge(reference, grid.Origin.data(), grid.Spacing);
  double shift = 0.0, turn = 0.0;
  const bool sameEdges = nvtest::SameEdges(a, b, shift, turn, 1e-3);
  const bool same = ours->GetNumberOfPolys() == reference->GetNumberOfPolys() &&
    ours->GetNumberOfPoints() == reference->GetNumberOfPoints() && sameEdges && a.AtNodes.empty() &&
    a.Stray == 0 && b.Stray == 0 && shift < 1e-5 && turn < 1e-4;
  if (!same)
  {
    std::printf("FAILED %s: %lld triangles and %lld points against vtkFlyingEdges3D's %lld and %lld; same cut "
                "edges %d; vertices apart by %.3g h at most, normals by %.3g\n",
      what, static_cast<long long>(ours->GetNumberOfPolys()), static_cast<long long>(ours->GetNumberOfPoints()),
      static_cast<long long>(reference->GetNumberOfPolys()), static_cast<long long>(reference->GetNumberOfPoints()),
      sameEdges, shift, turn);
  }
  return same;
}

nv::Parameters UnitParameters()
{
  nv::Parameters parameters;
  parameters.Spacing = 1.0;
  parameters.XiCells = 2.0;
  return parameters;
}

/// Every case of one cell: VTK's triangle count and vertices.
void TestCases()
{
  nv::Grid grid;
  grid.Dims = { { 2, 2, 2 } };
  const nv::Parameters parameters = UnitParameters();
  int different = 0;
  for (int signs = 0; signs < 256; ++signs)
  {
    std::vector<float> phi(8);
    for (int c = 0; c < 8; ++c)
    {
      phi[static_cast<std::size_t>(c)] = ((signs >> c) & 1) ? 0.2f + 0.07f * c : -0.25f - 0.05f * c;
    }
    const nv::DenseField field(grid, phi.data(), 0, 2, parameters);
    nv::SurfaceMesh mesh;
    nv::ContourBricks(grid, field, mesh);
    const auto reference = FlyingEdges(grid, DenseValues(grid, field));
    const auto ours = ToPolyData(mesh);
    different += !SameAsFlyingEdges(ours, reference, grid, "one cell");
    different += nv::MarchingCubesCases()[signs].Count != reference->GetNumberOfPolys();
    NV_CHECK(nvtest::MisorientedTriangles(ours) == 0);
  }
  std::printf("256 cases of a cell: %d differ from vtkFlyingEdges3D\n", different);
  NV_CHECK(different == 0);
}

/// A random field over several bricks, some of them cut off by the grid's
/// end, with nodes exactly on the level and at +-1.
void TestRandomField()
{
  nv::Grid grid;
  grid.Origin = { { -1.5, 2.0, 0.25 } };
  grid.Spacing = 0.1;
  grid.Dims = { { 21, 19, 18 } };
  nv::Parameters parameters = UnitParameters();
  parameters.Spacing = grid.Spacing;
  std::mt19937 random(5);
  std::uniform_real_distribution<float> uniform(-1.0f, 1.0f);
  std::vector<float> phi(static_cast<std::size_t>(grid.NumberOfNodes()));
  for (float& value : phi)
  {
    value = uniform(random);
    value = std::fabs(value) < 0.05f ? 0.0f : std::fabs(value) > 0.95f ? std::copysign(1.0f, value) : value;
  }
  const nv::DenseField field(grid, phi.data(), 0, grid.Dims[2], parameters);
  nv::SurfaceMesh mesh;
  nv::ContourBricks(grid, field, mesh);
  const auto ours = ToPolyData(mesh);
  NV_CHECK(SameAsFlyingEdges(ours, FlyingEdges(grid, DenseValues(grid, field)), grid, "random field"));
  // phi itself has nodes on the level: vtkFlyingEdges3D makes zero-area triangles there.
  const auto onPhi = FlyingEdges(grid, phi);
  std::printf("random field: %lld triangles; zero-area: %lld (vtkFlyingEdges3D on phi: %lld); non-manifold edges %lld\n",
    static_cast<long long>(ours->GetNumberOfPolys()), static_cast<long long>(nvtest::ZeroAreaTriangles(ours, false)),
    static_cast<long long>(nvtest::ZeroAreaTriangles(onPhi, false)),
    static_cast<long long>(nvtest::BadEdges(ours, false, true)));
  NV_CHECK(nvtest::ZeroAreaTriangles(onPhi, false) > 0);
  NV_CHECK(nvtest::ZeroAreaTriangles(ours, false) == 0);
  NV_CHECK(nvtest::ZeroAreaTriangles(ours, true) == 0);
  NV_CHECK(nvtest::BadEdges(ours, false, true) == 0);
}

const double Center[3] = { 0.3, -0.2, 0.1 };

/// A run's band: the contouring in its bricks against the whole grid's.
void TestBand()
{
  nv::Settings settings;
  settings.OffsetDistance = 0.1;
  settings.SampleSpacing = 0.02;
  settings.MemoryLimitBytes = 1e9;
  nv::Reconstruction run(settings, nullptr, nullptr);
  NV_CHECK(run.Run(nvtest::SpherePoints(6000, 0.5, Center)));
  nv::SurfaceMesh mesh;
  NV_CHECK(run.ExtractSurface(mesh));
  const auto ours = ToPolyData(mesh);
  const nv::BandField field(run.GetBand(), run.GetPhi(), run.GetParameters());
  NV_CHECK(SameAsFlyingEdges(ours, FlyingEdges(run.GetGrid(), DenseValues(run.GetGrid(), field)), run.GetGrid(), "band"));
  std::printf("band: %lld triangles; open edges %lld, non-manifold %lld, zero-area %lld (as float %lld), "
              "wound against their normals %lld\n",
    static_cast<long long>(ours->GetNumberOfPolys()), static_cast<long long>(nvtest::BadEdges(ours, true, false)),
    static_cast<long long>(nvtest::BadEdges(ours, false, true)), static_cast<long long>(nvtest::ZeroAreaTriangles(ours, false)),
    static_cast<long long>(nvtest::ZeroAreaTriangles(ours, true)), static_cast<long long>(nvtest::MisorientedTriangles(ours)));
  NV_CHECK(ours->GetNumberOfPolys() > 10000);
  NV_CHECK(nvtest::BadEdges(ours, true, false) == 0);
  NV_CHECK(nvtest::BadEdges(ours, false, true) == 0);
  NV_CHECK(nvtest::ZeroAreaTriangles(ours, false) == 0);
  NV_CHECK(nvtest::ZeroAreaTriangles(ours, true) == 0);
  NV_CHECK(nvtest::MisorientedTriangles(ours) == 0);
}

/// The filter: port 1 is the contour of the implied distance of port 0's phi;
/// the same surface for one thread and two.
void TestFilter()
{
  const auto cloud = nvtest::SphereCloud<vtkPolyData>(6000, 0.5, Center);
  vtkSmartPointer<vtkPolyData> surfaces[2];
  for (int threads = 1; threads <= 2; ++threads)
  {
    vtkNew<vtkNarrowVolumeReconstruction> filter;
    filter->SetInputData(cloud);
    filter->SetOffsetDistance(0.1);
    filter->SetSampleSpacing(0.02);
    filter->SetNumberOfThreads(threads);
    filter->Update();
    surfaces[threads - 1] = filter->GetSurfaceOutput();
    if (threads == 2)
    {
      vtkImageData* volume = filter->GetVolumeOutput();
      nv::Grid grid;
      volume->GetOrigin(grid.Origin.data());
      grid.Spacing = volume->GetSpacing()[0];
      for (int a = 0; a < 3; ++a)
      {
        grid.Dims[a] = volume->GetDimensions()[a];
      }
      nv::Parameters parameters;
      parameters.Spacing = grid.Spacing;
      const nv::ImpliedDistance psi(parameters);
      vtkFloatArray* phi = vtkFloatArray::SafeDownCast(volume->GetPointData()->GetArray("phi"));
      std::vector<float> values(static_cast<std::size_t>(phi->GetNumberOfValues()));
      for (std::size_t n = 0; n < values.size(); ++n)
      {
        values[n] = psi(phi->GetValue(static_cast<vtkIdType>(n)));
      }
      NV_CHECK(SameAsFlyingEdges(surfaces[1], FlyingEdges(grid, values), grid, "port 0's phi"));
    }
  }
  auto same = [](vtkDataArray* a, vtkDataArray* b) {
    return a && b && a->GetDataType() == b->GetDataType() && a->GetNumberOfValues() == b->GetNumberOfValues() &&
      std::memcmp(a->GetVoidPointer(0), b->GetVoidPointer(0), a->GetNumberOfValues() * a->GetDataTypeSize()) == 0;
  };
  NV_CHECK(same(surfaces[0]->GetPoints()->GetData(), surfaces[1]->GetPoints()->GetData()));
  NV_CHECK(same(surfaces[0]->GetPointData()->GetNormals(), surfaces[1]->GetPointData()->GetNormals()));
  NV_CHECK(same(surfaces[0]->GetPolys()->GetConnectivityArray(), surfaces[1]->GetPolys()->GetConnectivityArray()));
}
} // namespace

int main()
{
  TestCases();
  TestRandomField();
  TestBand();
  TestFilter();
  return nvtest::Result("TestSurfaceContour");
}
