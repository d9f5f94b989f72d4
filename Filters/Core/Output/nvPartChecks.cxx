// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The checks of the part (nvPartSteps.h): its thinnest wall (MinimumWall),
// and the scan points it lost (LostPoints) in regions (LostRegions).
#include "nvPartSteps.h"

#include "nvParallel.h"

#include <mutex>

namespace nv
{
namespace part
{
/// The least distance from a vertex of the inner surface (D > l + w / 2)
/// to a vertex of the outer surface; 0 without an inner surface. Stops
/// early when the monitor (may be null) asks (the caller asks it again).
double MinimumWall(const Grid& grid, const SurfaceArrays& part, const std::vector<float>& distance, double offset,
  double wall, std::array<double, 3>& where, Monitor* monitor)
{
  const std::int64_t n = part.NumberOfPoints;
  std::vector<char> inner(static_cast<std::size_t>(n), 0);
  const double split = offset + 0.5 * wall;
  ParallelFor(0, n, 1024, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t p = begin; p < end; ++p)
    {
      inner[p] = ValueAt(grid, distance.data(), part.Points + 3 * p) > split;
    }
  });
  std::vector<double> outerPoints, innerPoints;
  for (std::int64_t p = 0; p < n; ++p)
  {
    std::vector<double>& to = inner[p] ? innerPoints : outerPoints;
    to.insert(to.end(), part.Points + 3 * p, part.Points + 3 * p + 3);
  }
  if (innerPoints.empty() || outerPoints.empty())
  {
    return 0.0;
  }
  const NearestPoints outside(outerPoints.data(), static_cast<std::int64_t>(outerPoints.size() / 3));
  const double far = 2.0 * (offset + wall) + 4.0 * grid.Spacing;
  const std::int64_t count = static_cast<std::int64_t>(innerPoints.size() / 3);
  // The least, and the first inner vertex that has it (the same for any
  // number of threads).
  std::pair<double, std::int64_t> least{ std::numeric_limits<double>::infinity(), 0 };
  std::mutex lock;
  StoppableFor(0, count, 1024, monitor, [&](std::int64_t begin, std::int64_t end) {
    std::pair<double, std::int64_t> mine{ std::numeric_limits<double>::infinity(), 0 };
    for (std::int64_t p = begin; p < end; ++p)
    {
      mine = std::min(mine, std::make_pair(outside.Distance(&innerPoints[3 * p], far), p));
    }
    const std::lock_guard<std::mutex> guard(lock);
    least = std::min(least, mine);
  });
  std::copy(&innerPoints[3 * least.second], &innerPoints[3 * least.second] + 3, where.begin());
  return least.first;
}

/// The scan's lost points (PrintReport): those farther than
/// report.LostDistance outside the part beyond what the closing explains,
/// |D - l| for a point at D from the outer sheet (D = l on a surface smooth
/// at the offset's scale; a point in a concavity narrower than l is inside
/// the material, at D - l from its outer surface or less). The distance to
/// the part is to its nearest vertex. Points deeper than `cap` (D unknown),
/// and points where a drain hole was drilled, are not checked. Sets
/// report.FarthestLost; the points' indices, ascending.
std::vector<std::int64_t> LostPoints(const Grid& grid, const float* outer, const PartField& field,
  const SurfaceArrays& part, const std::vector<float>& distance, double offset, double cap, const PartRequest& request,
  const std::vector<Drill>& drills, PrintReport& report, Monitor* monitor)
{
  const std::int64_t n = request.Scan ? request.ScanPoints : 0;
  const NearestPoints vertices(part.Points, part.NumberOfPoints);
  const double bound = report.LostDistance, h = grid.Spacing;
  std::vector<float> beyond(static_cast<std::size_t>(n), 0.0f); // how far outside, beyond the bound
  StoppableFor(0, n, 1024, monitor, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t p = begin; p < end; ++p)
    {
      const double* x = request.Scan + 3 * p;
      const bool insideShell = ValueAt(grid, outer, x) > 0.0;
      // D, or none outside the outer sheet (the shell itself lost the point:
      // nothing explains a distance).
      const double d = insideShell ? ValueAt(grid, distance.data(), x) : offset;
      bool drilled = false;
      for (const Drill& drill : drills)
      {
        drilled = drilled || drill.Signed(x) < bound;
      }
      if (d >= cap - h || drilled)
      {
        continue;
      }
      // Inside f's material (restored material among it), a point is as
      // deep as f says, up to its clamp.
      const double explained = std::max(std::abs(d - offset), field.At(grid, x)) + bound;
      const double nearest = vertices.Distance(x, std::numeric_limits<double>::infinity());
      if (nearest > explained)
      {
        beyond[p] = static_cast<float>(nearest - std::abs(d - offset));
      }
    }
  });
  std::vector<std::int64_t> lost;
  report.FarthestLost = 0.0;
  for (std::int64_t p = 0; p < n; ++p)
  {
    if (beyond[p] > 0.0f)
    {
      lost.push_back(p);
      report.FarthestLost = std::max(report.FarthestLost, static_cast<double>(beyond[p]));
    }
  }
  return lost;
}

/// The lost points in regions: points in cells of side `reach` that touch
/// (26 neighbours) are one region; the regions, the most points first.
std::vector<LostRegion> LostRegions(const double* scan, const std::vector<std::int64_t>& lost, double reach)
{
  const std::int64_t n = static_cast<std::int64_t>(lost.size());
  if (n == 0)
  {
    return {};
  }
  using Cell = std::array<std::int64_t, 3>;
  std::vector<std::pair<Cell, std::int64_t>> cells(static_cast<std::size_t>(n)); // (cell, index into lost)
  for (std::int64_t i = 0; i < n; ++i)
  {
    const double* x = scan + 3 * lost[i];
    cells[i] = { { static_cast<std::int64_t>(std::floor(x[0] / reach)),
                   static_cast<std::int64_t>(std::floor(x[1] / reach)),
                   static_cast<std::int64_t>(std::floor(x[2] / reach)) },
      i };
  }
  std::sort(cells.begin(), cells.end());
  std::vector<std::int64_t> parent(static_cast<std::size_t>(n));
  for (std::int64_t i = 0; i < n; ++i)
  {
    parent[i] = i;
  }
  const auto root = [&](std::int64_t i) {
    while (parent[i] != i)
    {
      i = parent[i] = parent[parent[i]];
    }
    return i;
  };
  for (std::int64_t i = 0; i < n; ++i)
  {
    const Cell& c = cells[i].first;
    for (std::int64_t dz = -1; dz <= 1; ++dz)
    {
      for (std::int64_t dy = -1; dy <= 1; ++dy)
      {
        for (std::int64_t dx = -1; dx <= 1; ++dx)
        {
          const Cell other{ { c[0] + dx, c[1] + dy, c[2] + dz } };
          const auto found = std::lower_bound(cells.begin(), cells.end(), std::make_pair(other, std::int64_t(0)));
          if (found != cells.end() && found->first == other)
          {
            parent[root(i)] = root(found - cells.begin());
          }
        }
      }
    }
  }
  std::vector<std::int64_t> regionOf(static_cast<std::size_t>(n), -1);
  std::vector<LostRegion> regions;
  std::vector<std::array<double, 6>> boxes;
  for (std::int64_t i = 0; i < n; ++i)
  {
    const std::int64_t r = root(i);
    if (regionOf[r] < 0)
    {
      regionOf[r] = static_cast<std::int64_t>(regions.size());
      regions.emplace_back();
      boxes.push_back({ { std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
        std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
        std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity() } });
    }
    LostRegion& region = regions[regionOf[r]];
    std::array<double, 6>& box = boxes[regionOf[r]];
    const double* x = scan + 3 * lost[cells[i].second];
    ++region.Points;
    for (int a = 0; a < 3; ++a)
    {
      region.Center[a] += x[a];
      box[2 * a] = std::min(box[2 * a], x[a]);
      box[2 * a + 1] = std::max(box[2 * a + 1], x[a]);
    }
  }
  for (std::size_t r = 0; r < regions.size(); ++r)
  {
    for (int a = 0; a < 3; ++a)
    {
      regions[r].Center[a] /= static_cast<double>(regions[r].Points);
      regions[r].Size[a] = boxes[r][2 * a + 1] - boxes[r][2 * a];
    }
  }
  std::stable_sort(regions.begin(), regions.end(),
    [](const LostRegion& u, const LostRegion& v) { return u.Points > v.Points; });
  return regions;
}
} // namespace part
} // namespace nv
