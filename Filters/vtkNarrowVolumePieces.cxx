// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNarrowVolumePieces.h"

#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <numeric>
#include <vector>

namespace nv
{

RemovedPieces RemoveSmallSurfacePieces(vtkPolyData* surface, double offset, std::vector<DroppedPart>* dropped)
{
  RemovedPieces removed;
  vtkPoints* points = surface ? surface->GetPoints() : nullptr;
  vtkCellArray* polys = surface ? surface->GetPolys() : nullptr;
  if (!points || !polys || polys->GetNumberOfCells() == 0)
  {
    return removed;
  }
  // Connected parts: union-find over the points that triangles share.
  const vtkIdType numberOfPoints = points->GetNumberOfPoints();
  std::vector<vtkIdType> parent(static_cast<std::size_t>(numberOfPoints));
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](vtkIdType a) {
    while (parent[a] != a)
    {
      a = parent[a] = parent[parent[a]];
    }
    return a;
  };
  vtkIdType npts;
  const vtkIdType* ids;
  for (polys->InitTraversal(); polys->GetNextCell(npts, ids);)
  {
    for (vtkIdType t = 1; t < npts; ++t)
    {
      parent[root(ids[t])] = root(ids[0]);
    }
  }
  // Signed volume of each part: the sum of p0 . (p1 x p2) / 6 over its triangles.
  std::vector<double> volume(static_cast<std::size_t>(numberOfPoints), 0.0); // by root
  for (polys->InitTraversal(); polys->GetNextCell(npts, ids);)
  {
    for (vtkIdType t = 1; t + 1 < npts; ++t)
    {
      double a[3], b[3], c[3];
      points->GetPoint(ids[0], a);
      points->GetPoint(ids[t], b);
      points->GetPoint(ids[t + 1], c);
      volume[root(ids[0])] += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                                a[2] * (b[0] * c[1] - b[1] * c[0])) / 6.0;
    }
  }
  std::vector<char> used(static_cast<std::size_t>(numberOfPoints), 0);
  for (polys->InitTraversal(); polys->GetNextCell(npts, ids);)
  {
    used[root(ids[0])] = 1;
  }
  // Which parts go; when every piece is small, the largest stays (a tiny
  // cloud's shell is all there is).
  const double smallPiece = SmallPieceVolume(offset), smallVoid = SmallVoidVolume(offset);
  vtkIdType spared = -1;
  bool largePiece = false;
  for (vtkIdType r = 0; r < numberOfPoints; ++r)
  {
    if (used[r] && volume[r] > 0.0)
    {
      largePiece = largePiece || volume[r] >= smallPiece;
      spared = (spared < 0 || volume[r] > volume[spared]) ? r : spared;
    }
  }
  std::vector<char> drop(static_cast<std::size_t>(numberOfPoints), 0);
  for (vtkIdType r = 0; r < numberOfPoints; ++r)
  {
    if (!used[r] || (!largePiece && r == spared))
    {
      continue;
    }
    if (volume[r] > 0.0 && volume[r] < smallPiece)
    {
      drop[r] = 1;
      ++removed.Pieces;
    }
    else if (volume[r] <= 0.0 && -volume[r] < smallVoid)
    {
      drop[r] = 1;
      ++removed.Voids;
    }
  }
  if (removed.Pieces + removed.Voids == 0)
  {
    return removed;
  }
  if (dropped)
  {
    for (vtkIdType r = 0; r < numberOfPoints; ++r)
    {
      if (drop[r])
      {
        DroppedPart part;
        points->GetPoint(r, part.Vertex.data()); // the root is one of the part's vertices
        part.Piece = volume[r] > 0.0;
        dropped->push_back(part);
      }
    }
  }

  // The kept triangles, and only the points they use.
  std::vector<vtkIdType> newId(static_cast<std::size_t>(numberOfPoints), -1);
  vtkNew<vtkPoints> keptPoints;
  keptPoints->SetDataType(points->GetDataType());
  vtkNew<vtkPointData> keptData;
  keptData->CopyAllocate(surface->GetPointData());
  vtkNew<vtkCellArray> keptPolys;
  std::vector<vtkIdType> cell;
  for (polys->InitTraversal(); polys->GetNextCell(npts, ids);)
  {
    if (drop[root(ids[0])])
    {
      continue;
    }
    cell.assign(ids, ids + npts);
    for (vtkIdType& id : cell)
    {
      if (newId[id] < 0)
      {
        newId[id] = keptPoints->InsertNextPoint(points->GetPoint(id));
        keptData->CopyData(surface->GetPointData(), id, newId[id]);
      }
      id = newId[id];
    }
    keptPolys->InsertNextCell(npts, cell.data());
  }
  vtkNew<vtkPolyData> kept;
  kept->SetPoints(keptPoints);
  kept->SetPolys(keptPolys);
  kept->GetPointData()->ShallowCopy(keptData);
  surface->ShallowCopy(kept);
  return removed;
}

} // namespace nv
