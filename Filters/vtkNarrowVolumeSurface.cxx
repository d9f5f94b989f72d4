// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNarrowVolumeSurface.h"

#include "nvNarrowBand.h"
#include "nvOutputs.h"
#include "nvParallel.h"
#include "nvTruncatedDistance.h"
#include "nvVolume.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFlyingEdges3D.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <map>

namespace nv
{
namespace
{
using Key = std::array<float, 2>; // (x, y) of a vertex on a shared plane

/// The isosurfacer's progress to the monitor, and the monitor's abort to it.
void ForwardProgress(vtkObject* caller, unsigned long, void* clientData, void* callData)
{
  Monitor* monitor = static_cast<Monitor*>(clientData);
  monitor->Progress(*static_cast<double*>(callData));
  if (monitor->Aborted())
  {
    vtkAlgorithm::SafeDownCast(caller)->SetAbortExecute(1);
  }
}

/// Contours phi (nodes of z layers [kBegin, kEnd)) in the grid's own frame.
vtkSmartPointer<vtkPolyData> ContourLocal(
  const Grid& grid, vtkDataArray* phi, std::int64_t kBegin, std::int64_t kEnd, Monitor* monitor = nullptr)
{
  vtkNew<vtkImageData> image;
  image->SetOrigin(0.0, 0.0, 0.0);
  image->SetSpacing(grid.Spacing, grid.Spacing, grid.Spacing);
  image->SetExtent(0, static_cast<int>(grid.Dims[0] - 1), 0, static_cast<int>(grid.Dims[1] - 1),
    static_cast<int>(kBegin), static_cast<int>(kEnd - 1));
  image->GetPointData()->SetScalars(phi);
  vtkNew<vtkFlyingEdges3D> contour;
  contour->SetInputData(image);
  contour->SetValue(0, 0.0);
  contour->ComputeNormalsOn();
  contour->ComputeGradientsOff();
  contour->ComputeScalarsOff();
  if (monitor)
  {
    vtkNew<vtkCallbackCommand> forward;
    forward->SetCallback(ForwardProgress);
    forward->SetClientData(monitor);
    contour->AddObserver(vtkCommand::ProgressEvent, forward);
  }
  contour->Update();
  return contour->GetOutput();
}

/// Replaces the surface's float grid-frame points by double world points.
void MoveToWorld(vtkPolyData* surface, const Grid& grid)
{
  vtkPoints* local = surface->GetPoints();
  if (!local)
  {
    return;
  }
  vtkNew<vtkPoints> world;
  world->SetDataTypeToDouble();
  world->SetNumberOfPoints(local->GetNumberOfPoints());
  for (vtkIdType p = 0; p < local->GetNumberOfPoints(); ++p)
  {
    double x[3];
    local->GetPoint(p, x);
    world->SetPoint(p, grid.Origin[0] + x[0], grid.Origin[1] + x[1], grid.Origin[2] + x[2]);
  }
  surface->SetPoints(world);
}
} // namespace

vtkSmartPointer<vtkPolyData> ExtractSurface(
  const Grid& grid, vtkDataArray* phi, std::int64_t kBegin, std::int64_t kEnd, Monitor* monitor)
{
  auto surface = ContourLocal(grid, phi, kBegin, kEnd < 0 ? grid.Dims[2] : kEnd, monitor);
  MoveToWorld(surface, grid);
  return surface;
}

vtkSmartPointer<vtkPolyData> ExtractSurfaceBySlabs(const TruncatedDistance& distance,
  const NarrowBand& band, const std::vector<double>& phi, const Parameters& parameters, Monitor* monitor,
  std::int64_t kFirst, std::int64_t kLast)
{
  const Grid& grid = distance.GetGrid();
  const std::int64_t nx = grid.Dims[0], ny = grid.Dims[1];
  const std::int64_t nz = kLast < 0 ? grid.Dims[2] : kLast;
  const std::vector<std::int64_t> reached = distance.ReachedBricks();

  vtkNew<vtkPoints> points; // float, as vtkFlyingEdges3D makes them
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  vtkNew<vtkCellArray> triangles;

  // Only the slabs that hold band nodes (nvOutputs.h).
  std::map<Key, vtkIdType> sharedBelow; // vertices the previous slab made on this slab's first plane
  std::vector<float> slab;
  std::int64_t previousEnd = -1;
  for (const Slab& next : SurfaceSlabs(distance, band, kFirst, nz))
  {
    const std::int64_t kBegin = next.Begin, kEnd = next.End;
    std::map<Key, vtkIdType> sharedAbove;
    if (kBegin != previousEnd - 1)
    {
      sharedBelow.clear(); // the slab below was skipped
    }
    previousEnd = kEnd;
    if (monitor)
    {
      monitor->Progress(static_cast<double>(kBegin - kFirst) / (nz - kFirst));
      if (monitor->Aborted())
      {
        break;
      }
    }

    slab.resize(static_cast<std::size_t>(nx * ny * (kEnd - kBegin)));
    VolumeArrays arrays;
    arrays.Phi = slab.data();
    FillVolume(distance, band, phi, parameters, reached, arrays, kBegin, kEnd);

    vtkNew<vtkFloatArray> scalars;
    scalars->SetName("phi");
    scalars->SetArray(slab.data(), static_cast<vtkIdType>(slab.size()), 1); // borrowed, not copied
    vtkSmartPointer<vtkPolyData> piece = ContourLocal(grid, scalars, kBegin, kEnd);

    // Append, merging the vertices on the plane shared with the slab below.
    const float zBelow = static_cast<float>(kBegin * grid.Spacing);
    const float zAbove = static_cast<float>((kEnd - 1) * grid.Spacing);
    vtkDataArray* pieceNormals = piece->GetPointData()->GetNormals();
    std::vector<vtkIdType> id(static_cast<std::size_t>(piece->GetNumberOfPoints()));
    for (vtkIdType p = 0; p < piece->GetNumberOfPoints(); ++p)
    {
      double x[3];
      piece->GetPoint(p, x);
      const float z = static_cast<float>(x[2]);
      const Key key{ { static_cast<float>(x[0]), static_cast<float>(x[1]) } };
      if (z == zBelow && !sharedBelow.empty())
      {
        const auto it = sharedBelow.find(key);
        if (it != sharedBelow.end())
        {
          id[p] = it->second;
          continue;
        }
      }
      id[p] = points->InsertNextPoint(x);
      normals->InsertNextTuple(pieceNormals->GetTuple(p));
      if (z == zAbove)
      {
        sharedAbove[key] = id[p];
      }
    }
    vtkCellArray* polys = piece->GetPolys();
    vtkIdType count;
    const vtkIdType* cell;
    for (polys->InitTraversal(); polys->GetNextCell(count, cell);)
    {
      vtkIdType mapped[3] = { id[cell[0]], id[cell[1]], id[cell[2]] };
      triangles->InsertNextCell(3, mapped);
    }
    sharedBelow.swap(sharedAbove);
  }

  auto surface = vtkSmartPointer<vtkPolyData>::New();
  surface->SetPoints(points);
  surface->SetPolys(triangles);
  surface->GetPointData()->SetNormals(normals);
  MoveToWorld(surface, grid);
  return surface;
}

} // namespace nv
