// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvPrintPart.h"

#include "nvParallel.h"
#include "nvPartSteps.h"
#include "nvPieces.h"
#include "nvSurfaceField.h"
#include "nvTruncatedDistance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

namespace nv
{
namespace
{
/// The share of the largest cavity below which a cavity is merged into the
/// wall when MinimumCavityVolume is 0.
constexpr double AutomaticCavityShare = 0.01;
/// The bound of the scan's check, in cells (PrintReport::LostDistance): the
/// part's vertices lie within a cell of one another, and its outer surface
/// within about half a cell of the closing; twice a cell covers both.
constexpr double LostDistanceCells = 2.0;
/// The radius of the material put back around a lost point and the rods
/// that join it to its neighbours (Restoration), in cells: a limb two cells
/// thick at least, which the grid holds.
constexpr double LostRadiusCells = 2.0;
/// Lost points nearer than this many cells are one region (LostRegions).
constexpr double LostRegionReach = 4.0;

} // namespace

using namespace part; // the steps (nvPartSteps.h)

bool MakePart(const Grid& grid, const Parameters& parameters, const float* outer, const PartRequest& request,
  SurfaceSink& sink, Monitor* monitor, PrintReport& report)
{
  const double l = parameters.OffsetDistance, h = grid.Spacing, wall = request.Wall;
  // The progress of the steps, as shares of the request's stage, about as
  // their time goes (the distance D is the longest).
  const auto step = [&](double from, double to) {
    if (monitor)
    {
      monitor->Stage(request.Progress[0] + from * request.Progress[1], (to - from) * request.Progress[1]);
    }
  };
  step(0.0, 0.1);
  // The outer sheet: phi = 0 with the cavities filled.
  SurfaceMesh sheet;
  const DenseField field(grid, outer, 0, grid.Dims[2], parameters);
  if (!ContourBricks(grid, field, sheet, 0, -1, monitor))
  {
    return false;
  }
  // The part's surfaces, f = 0.
  const double closing = request.CavityClosing;
  const double cap = l + wall + closing + 4.0 * h;
  step(0.1, 0.5);
  const std::vector<float> distance = SheetDistance(grid, outer, sheet.Points, cap, monitor);
  if (monitor && monitor->Aborted())
  {
    return false;
  }
  // With a closing distance c: G, the distance to the surface of the cavity
  // eroded by c (E, D > l + w + c), from E's surface's vertices.
  std::vector<float> grown;
  if (closing > 0.0)
  {
    SurfaceMesh eroded;
    {
      std::vector<float> depth(distance.size());
      const float deepest = static_cast<float>(l + wall + closing);
      ParallelFor(0, grid.NumberOfNodes(), 1 << 16, [&](std::int64_t begin, std::int64_t end) {
        for (std::int64_t n = begin; n < end; ++n)
        {
          depth[n] = outer[n] > 0.0f ? distance[n] - deepest : -deepest;
        }
      });
      if (!ContourBricks(grid, NodeField(grid, depth, -deepest), eroded, 0, -1, nullptr))
      {
        return false;
      }
    }
    grown = SheetDistance(grid, outer, eroded.Points, closing + 4.0 * h, monitor);
    if (StopAsked(monitor))
    {
      return false;
    }
  }
  const InnerField inner{ distance, closing > 0.0 ? &grown : nullptr, l + wall, closing };
  step(0.5, 0.7);
  std::vector<Drill> drills;
  // Contours f (with the holes drilled and the lost points' material put
  // back, as asked) into the sink, and removes its loose pieces and small
  // cavities: the cavities below `minimumCavity` (0: a share of the
  // largest), the pieces below a ball of 2 l unless `supported` keeps them.
  PieceLimits limits;
  limits.Piece = SmallPieceVolume(l);
  limits.SpareLargest = false; // slivers of an open scan's closing are no part
  std::unique_ptr<PartField> part;
  const auto contour = [&](const Restoration* restored, double minimumCavity) {
    part.reset(); // one at a time
    part.reset(new PartField(grid, outer, distance, l, inner, drills, restored));
    SurfaceArrays none = sink.View();
    none.NumberOfPoints = none.NumberOfTriangles = 0;
    sink.Truncate(none);
    if (!ContourBricks(grid, *part, sink, 0, -1, monitor))
    {
      return false;
    }
    limits.Void = minimumCavity;
    limits.VoidShare = minimumCavity > 0.0 ? 0.0 : AutomaticCavityShare;
    const RemovedPieces removed = RemoveSmallPieces(sink, limits, grid, nullptr, 0, 0);
    report.MaterialVolume = removed.Volume;
    report.CavityVolume = removed.CavityVolume;
    report.MinimumCavityVolume = removed.VoidLimit;
    report.KeptCavities = removed.Cavities;
    report.RemovedCavities = removed.Voids;
    report.RemovedPieces = removed.Pieces;
    report.Pieces = removed.KeptPieces;
    return true;
  };
  if (!contour(nullptr, request.MinimumCavity))
  {
    return false;
  }
  // The wall as made, before the holes cut through it.
  report.MinimumWallThickness =
    report.KeptCavities > 0 ? MinimumWall(grid, sink.View(), distance, l, wall, report.ThinnestWallAt, monitor) : 0.0;
  if (StopAsked(monitor))
  {
    return false;
  }
  step(0.7, 0.85);
  if ((request.DrainHoles > 0 || !request.DrainPositions.empty()) && report.KeptCavities > 0)
  {
    // Again with the holes: the kept cavities now open to the outside, the
    // merged ones go as before (by the same volume).
    const double radius =
      0.5 * (request.DrainDiameter > 0.0 ? request.DrainDiameter : std::max(2.0 * wall, 4.0 * h));
    drills = DrainHoles(grid, outer, inner, l, wall, report.MinimumCavityVolume, radius, request, report);
    const double cavity = report.MinimumCavityVolume, cavityVolume = report.CavityVolume;
    const std::int64_t kept = report.KeptCavities;
    if (!contour(nullptr, cavity))
    {
      return false;
    }
    report.CavityVolume = cavityVolume; // the cavities are open now: the volumes before
    report.KeptCavities = kept;
    report.DrainHoles = static_cast<std::int64_t>(drills.size());
  }
  // The scan against the part: material around the points it lost, where
  // they are a limb or a piece and not the scan (RestorableShare), then
  // what is still lost.
  step(0.85, 1.0);
  report.LostDistance = LostDistanceCells * h;
  report.ScanPoints = request.Scan ? request.ScanPoints : 0;
  std::vector<std::int64_t> lost =
    LostPoints(grid, outer, *part, sink.View(), distance, l, cap, request, drills, report, monitor);
  if (StopAsked(monitor))
  {
    return false;
  }
  if (!lost.empty() && static_cast<double>(lost.size()) <= RestorableShare * static_cast<double>(request.ScanPoints))
  {
    const Restoration restored(grid, request.Scan, request.ScanPoints, lost, LostRadiusCells * h, 2.0 * l);
    const double reach = (LostRadiusCells + 1.0) * h;
    limits.Supported = [&](const double* x) { return restored.NearLost(x, reach); };
    const double cavityVolume = report.CavityVolume;
    const std::int64_t kept = report.KeptCavities;
    if (!contour(&restored, report.MinimumCavityVolume))
    {
      return false;
    }
    if (!drills.empty())
    {
      report.CavityVolume = cavityVolume;
      report.KeptCavities = kept;
    }
    const std::vector<std::int64_t> left =
      LostPoints(grid, outer, *part, sink.View(), distance, l, cap, request, drills, report, monitor);
    if (StopAsked(monitor))
    {
      return false;
    }
    std::vector<std::int64_t> back; // the lost points held now
    std::set_difference(lost.begin(), lost.end(), left.begin(), left.end(), std::back_inserter(back));
    report.RestoredPoints = static_cast<std::int64_t>(back.size());
    report.RestoredRegions = LostRegions(request.Scan, back, LostRegionReach * h);
    lost = left;
  }
  report.LostPoints = static_cast<std::int64_t>(lost.size());
  report.LostRegions = LostRegions(request.Scan, lost, LostRegionReach * h);
  report.Bounds = BoundsOf(sink.View());
  return !(monitor && monitor->Aborted());
}

} // namespace nv
