// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvPieces.h"

#include "nvParallel.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <memory>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace nv
{
namespace
{
constexpr std::int64_t Grain = 1 << 15; ///< triangles or points per task

} // namespace

void JoinTriangles(const SurfaceArrays& surface, PointParts& parts)
{
  // The points that triangles share, joined on all threads.
  const VertexId* triangles = surface.Triangles;
  ParallelFor(0, surface.NumberOfTriangles, Grain, [&](std::int64_t first, std::int64_t last) {
    for (std::int64_t t = first; t < last; ++t)
    {
      parts.Join(triangles[3 * t], triangles[3 * t + 1]);
      parts.Join(triangles[3 * t], triangles[3 * t + 2]);
    }
  });
  parts.Flatten(surface.NumberOfPoints);
}

std::vector<std::int64_t> SurfaceParts(const SurfaceArrays& surface)
{
  PointParts parts(surface.NumberOfPoints);
  JoinTriangles(surface, parts);
  std::vector<std::int64_t> root(static_cast<std::size_t>(surface.NumberOfPoints));
  ParallelFor(0, surface.NumberOfPoints, Grain, [&](std::int64_t first, std::int64_t last) {
    for (std::int64_t p = first; p < last; ++p)
    {
      root[p] = parts.Parent[p].load(std::memory_order_relaxed);
    }
  });
  return root;
}

double SmallPieceVolume(double offset)
{
  const double radius = 2.0 * offset;
  return 4.0 / 3.0 * M_PI * radius * radius * radius;
}

double SmallVoidVolume(double offset)
{
  return 4.0 / 3.0 * M_PI * offset * offset * offset;
}

namespace
{
/// The nodes next to a surface vertex on the region's side: the vertex lies
/// on a grid edge (its other two coordinates are node coordinates), and one
/// end of that edge is in the region. A vertex on a node (phi = 0 there) has
/// the node and its six neighbours as candidates.
void AddSeeds(const Grid& grid, const float* phi, std::int64_t kBegin, std::int64_t layers, const double point[3],
  bool inside, std::vector<std::int64_t>& seeds)
{
  const std::int64_t extent[3] = { grid.Dims[0], grid.Dims[1], layers };
  double x[3];
  int axis = 0;
  double along = -1.0; // the largest distance from a node coordinate
  for (int a = 0; a < 3; ++a)
  {
    x[a] = (point[a] - grid.Origin[a]) / grid.Spacing - (a == 2 ? kBegin : 0);
    const double off = std::abs(x[a] - std::round(x[a]));
    if (off > along)
    {
      along = off;
      axis = a;
    }
  }
  std::int64_t node[3];
  for (int a = 0; a < 3; ++a)
  {
    node[a] = static_cast<std::int64_t>(a == axis && along > 1e-6 ? std::floor(x[a]) : std::round(x[a]));
  }
  auto add = [&](const std::int64_t ijk[3]) {
    for (int a = 0; a < 3; ++a)
    {
      if (ijk[a] < 0 || ijk[a] >= extent[a])
      {
        return;
      }
    }
    const std::int64_t n = ijk[0] + extent[0] * (ijk[1] + extent[1] * ijk[2]);
    if ((phi[n] > 0.0f) == inside)
    {
      seeds.push_back(n);
    }
  };
  add(node);
  for (int a = 0; a < 3; ++a)
  {
    for (int step : { -1, 1 })
    {
      if (along > 1e-6 && (a != axis || step < 0))
      {
        continue; // on an edge: only its other end
      }
      std::int64_t ijk[3] = { node[0], node[1], node[2] };
      ijk[a] += step;
      add(ijk);
    }
  }
}
} // namespace

bool FlipRegion(const Grid& grid, float* phi, std::int64_t kBegin, std::int64_t layers, const double* points,
  const std::vector<std::int64_t>& vertices, bool inside, double maximumVolume)
{
  const std::int64_t nx = grid.Dims[0], ny = grid.Dims[1];
  auto sideOf = [&](std::int64_t n) { return phi[n] > 0.0f; };
  // The seeds: each vertex's edge end in the region. Seeding from every
  // vertex, not one, matters: the region's nodes can be joined only across a
  // cell's diagonal (marching cubes joins them through an ambiguous face), so
  // one 6-connected flood need not reach them all.
  std::vector<std::int64_t> seeds;
  for (std::int64_t v : vertices)
  {
    AddSeeds(grid, phi, kBegin, layers, points + 3 * v, inside, seeds);
  }
  // Breadth-first search of the region, given up beyond maximumVolume.
  const std::int64_t limit =
    static_cast<std::int64_t>(maximumVolume / (grid.Spacing * grid.Spacing * grid.Spacing)) + 1;
  std::vector<std::int64_t> region;
  std::unordered_set<std::int64_t> visited;
  for (std::int64_t seed : seeds)
  {
    if (visited.insert(seed).second)
    {
      region.push_back(seed);
    }
  }
  if (region.empty())
  {
    return false;
  }
  for (std::size_t head = 0; head < region.size(); ++head)
  {
    if (static_cast<std::int64_t>(region.size()) > limit)
    {
      return false;
    }
    const std::int64_t n = region[head];
    const std::int64_t i = n % nx, j = (n / nx) % ny, k = n / (nx * ny);
    const std::int64_t neighbours[6] = { i > 0 ? n - 1 : -1, i < nx - 1 ? n + 1 : -1, j > 0 ? n - nx : -1,
      j < ny - 1 ? n + nx : -1, k > 0 ? n - nx * ny : -1, k < layers - 1 ? n + nx * ny : -1 };
    for (std::int64_t m : neighbours)
    {
      if (m >= 0 && sideOf(m) == inside && visited.insert(m).second)
      {
        region.push_back(m);
      }
    }
  }
  for (std::int64_t n : region)
  {
    // Outside values are negative or 0, inside values positive.
    phi[n] = inside ? -phi[n] : (phi[n] == 0.0f ? 1e-6f : -phi[n]);
  }
  return true;
}

//------------------------------------------------------------------------------
RemovedPieces RemoveSmallPieces(SurfaceArrays& surface, double offset, const Grid& grid, float* phi,
  std::int64_t kBegin, std::int64_t layers)
{
  PieceLimits limits;
  limits.Piece = SmallPieceVolume(offset);
  limits.Void = SmallVoidVolume(offset);
  return RemoveSmallPieces(surface, limits, grid, phi, kBegin, layers);
}

namespace
{
/// A connected part of a surface: its root point (its smallest point index),
/// its signed volume (> 0 a piece, < 0 a void or cavity), and whether it goes.
struct Part
{
  std::int64_t Root;
  double Volume;
  bool Drop;
  bool Supported = false; ///< a vertex where PieceLimits::Supported holds
};

/// Phase 1: the surface's connected parts (parts.Parent[p] is p's root once
/// it returns) with their signed volumes, by ascending root.
std::vector<Part> FindParts(const SurfaceArrays& surface, PointParts& parts)
{
  const std::int64_t m = surface.NumberOfTriangles;
  const VertexId* triangles = surface.Triangles;
  JoinTriangles(surface, parts);
  auto root = [&parts](std::int64_t p) { return parts.Parent[p].load(std::memory_order_relaxed); };
  // Signed volume of each part: the sum of p0 . (p1 x p2) / 6 over its
  // triangles. Each fixed chunk of triangles sums its runs of one part (a
  // chunk's triangles are near each other, so there are few), and the runs
  // are added in chunk order: the same volumes for any thread count.
  const std::int64_t chunks = (m + Grain - 1) / Grain;
  std::vector<std::vector<std::pair<std::int64_t, double>>> runs(static_cast<std::size_t>(chunks));
  ParallelFor(0, chunks, 1, [&](std::int64_t first, std::int64_t last) {
    for (std::int64_t chunk = first; chunk < last; ++chunk)
    {
      auto& sums = runs[chunk];
      for (std::int64_t t = chunk * Grain; t < std::min(m, (chunk + 1) * Grain); ++t)
      {
        const double* a = surface.Points + 3 * triangles[3 * t];
        const double* b = surface.Points + 3 * triangles[3 * t + 1];
        const double* c = surface.Points + 3 * triangles[3 * t + 2];
        const double v = (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                           a[2] * (b[0] * c[1] - b[1] * c[0])) / 6.0;
        const std::int64_t r = root(triangles[3 * t]);
        if (sums.empty() || sums.back().first != r)
        {
          sums.emplace_back(r, 0.0);
        }
        sums.back().second += v;
      }
    }
  });
  // Each part's volume: its runs in chunk order (a stable sort by root keeps
  // that order), the parts by ascending root.
  std::vector<std::pair<std::int64_t, double>> all;
  for (const auto& sums : runs)
  {
    all.insert(all.end(), sums.begin(), sums.end());
  }
  decltype(runs)().swap(runs);
  std::stable_sort(all.begin(), all.end(),
    [](const std::pair<std::int64_t, double>& x, const std::pair<std::int64_t, double>& y) { return x.first < y.first; });
  std::vector<Part> found;
  for (const auto& run : all)
  {
    if (found.empty() || found.back().Root != run.first)
    {
      found.push_back(Part{ run.first, 0.0, false });
    }
    found.back().Volume += run.second;
  }
  return found;
}

/// Phase 1, continued: the parts with a vertex where `supported` holds.
void MarkSupported(const SurfaceArrays& surface, PointParts& parts,
  const std::function<bool(const double* x)>& supported, std::vector<Part>& found)
{
  // Each chunk of points lists the parts (by their place in `found`) that
  // hold a supported vertex; the lists are then marked.
  const std::int64_t n = surface.NumberOfPoints;
  const std::int64_t chunks = (n + Grain - 1) / Grain;
  std::vector<std::vector<std::size_t>> marked(static_cast<std::size_t>(chunks));
  ParallelFor(0, chunks, 1, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t c = begin; c < end; ++c)
    {
      for (std::int64_t p = c * Grain; p < std::min(n, (c + 1) * Grain); ++p)
      {
        if (!supported(surface.Points + 3 * p))
        {
          continue;
        }
        const std::int64_t root = parts.Parent[p].load(std::memory_order_relaxed);
        const auto part = std::lower_bound(found.begin(), found.end(), root,
          [](const Part& u, std::int64_t r) { return u.Root < r; });
        const std::size_t index = static_cast<std::size_t>(part - found.begin());
        if (part != found.end() && part->Root == root && (marked[c].empty() || marked[c].back() != index))
        {
          marked[c].push_back(index);
        }
      }
    }
  });
  for (const auto& indices : marked)
  {
    for (std::size_t index : indices)
    {
      found[index].Supported = true;
    }
  }
}

/// Phase 2: which parts go (Drop), and the counts and volumes of `removed`;
/// when every piece is small, the largest stays (limits.SpareLargest).
void ChooseParts(std::vector<Part>& found, const PieceLimits& limits, RemovedPieces& removed)
{
  const double smallPiece = limits.Piece;
  double smallVoid = limits.Void;
  const Part* spared = nullptr;
  bool largePiece = false;
  double largestVoid = 0.0;
  for (const Part& part : found)
  {
    if (part.Volume > 0.0)
    {
      largePiece = largePiece || part.Volume >= smallPiece;
      spared = (!spared || part.Volume > spared->Volume) ? &part : spared;
    }
    else
    {
      largestVoid = std::max(largestVoid, -part.Volume);
    }
  }
  if (limits.VoidShare > 0.0)
  {
    smallVoid = limits.VoidShare * largestVoid;
  }
  removed.VoidLimit = smallVoid;
  for (Part& part : found)
  {
    if (limits.SpareLargest && !largePiece && &part == spared)
    {
      continue;
    }
    if (part.Volume > 0.0 && part.Volume < smallPiece && !part.Supported)
    {
      part.Drop = true;
      ++removed.Pieces;
    }
    else if (part.Volume <= 0.0 && -part.Volume < smallVoid)
    {
      part.Drop = true;
      ++removed.Voids;
    }
    else if (part.Volume < 0.0)
    {
      ++removed.Cavities;
    }
    else
    {
      ++removed.KeptPieces;
    }
  }
  for (const Part& part : found)
  {
    if (!part.Drop)
    {
      removed.Volume += part.Volume;
      removed.CavityVolume += part.Volume < 0.0 ? -part.Volume : 0.0;
    }
  }
}

/// Phase 3 (with phi): each dropped region of phi flipped from its
/// vertices, before the points move.
void FlipDroppedRegions(const std::vector<Part>& found, const std::vector<char>& drop, PointParts& parts,
  const SurfaceArrays& surface, const PieceLimits& limits, const RemovedPieces& removed, const Grid& grid,
  float* phi, std::int64_t kBegin, std::int64_t layers)
{
  // The dropped parts' vertices (few), found on all threads chunk by
  // chunk, then grouped by root in ascending order.
  const std::int64_t n = surface.NumberOfPoints;
  const std::int64_t chunks = (n + Grain - 1) / Grain;
  std::vector<std::vector<std::int64_t>> dropped(static_cast<std::size_t>(chunks));
  ParallelFor(0, chunks, 1, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t c = begin; c < end; ++c)
    {
      for (std::int64_t p = c * Grain; p < std::min(n, (c + 1) * Grain); ++p)
      {
        if (drop[parts.Parent[p].load(std::memory_order_relaxed)])
        {
          dropped[c].push_back(p);
        }
      }
    }
  });
  std::unordered_map<std::int64_t, std::vector<std::int64_t>> vertices; // by root
  for (const auto& points : dropped)
  {
    for (std::int64_t p : points)
    {
      vertices[parts.Parent[p].load(std::memory_order_relaxed)].push_back(p);
    }
  }
  for (const Part& part : found)
  {
    if (part.Drop)
    {
      const bool piece = part.Volume > 0.0;
      FlipRegion(grid, phi, kBegin, layers, surface.Points, vertices[part.Root], piece,
        2.0 * (piece ? limits.Piece : removed.VoidLimit));
    }
  }
}

/// Phase 4: the kept points to the front, in their order (new id <= old
/// id), then the kept triangles, renumbered.
void KeepParts(SurfaceArrays& surface, const std::vector<char>& drop, PointParts& parts)
{
  const std::int64_t n = surface.NumberOfPoints, m = surface.NumberOfTriangles;
  auto root = [&parts](std::int64_t p) { return parts.Parent[p].load(std::memory_order_relaxed); };
  std::vector<std::int64_t> newId(static_cast<std::size_t>(n), -1);
  std::int64_t kept = 0;
  for (std::int64_t p = 0; p < n; ++p)
  {
    if (!drop[root(p)])
    {
      newId[p] = kept;
      std::copy(surface.Points + 3 * p, surface.Points + 3 * p + 3, surface.Points + 3 * kept);
      std::copy(surface.Normals + 3 * p, surface.Normals + 3 * p + 3, surface.Normals + 3 * kept);
      ++kept;
    }
  }
  std::int64_t keptTriangles = 0;
  for (std::int64_t t = 0; t < m; ++t)
  {
    if (!drop[root(surface.Triangles[3 * t])])
    {
      for (int c = 0; c < 3; ++c)
      {
        surface.Triangles[3 * keptTriangles + c] = newId[surface.Triangles[3 * t + c]];
      }
      ++keptTriangles;
    }
  }
  surface.NumberOfPoints = kept;
  surface.NumberOfTriangles = keptTriangles;
}
} // namespace

RemovedPieces RemoveSmallPieces(SurfaceArrays& surface, const PieceLimits& limits, const Grid& grid, float* phi,
  std::int64_t kBegin, std::int64_t layers)
{
  RemovedPieces removed;
  if (surface.NumberOfTriangles == 0)
  {
    return removed;
  }
  PointParts parts(surface.NumberOfPoints);
  std::vector<Part> found = FindParts(surface, parts);
  if (limits.Supported)
  {
    MarkSupported(surface, parts, limits.Supported, found);
  }
  ChooseParts(found, limits, removed);
  if (removed.Pieces + removed.Voids == 0)
  {
    return removed;
  }
  std::vector<char> drop(static_cast<std::size_t>(surface.NumberOfPoints), 0); // by root
  for (const Part& part : found)
  {
    drop[part.Root] = part.Drop;
  }
  if (phi)
  {
    FlipDroppedRegions(found, drop, parts, surface, limits, removed, grid, phi, kBegin, layers);
  }
  KeepParts(surface, drop, parts);
  return removed;
}

RemovedPieces RemoveSmallPieces(SurfaceSink& sink, double offset, const Grid& grid, float* phi,
  std::int64_t kBegin, std::int64_t layers)
{
  PieceLimits limits;
  limits.Piece = SmallPieceVolume(offset);
  limits.Void = SmallVoidVolume(offset);
  return RemoveSmallPieces(sink, limits, grid, phi, kBegin, layers);
}

RemovedPieces RemoveSmallPieces(SurfaceSink& sink, const PieceLimits& limits, const Grid& grid, float* phi,
  std::int64_t kBegin, std::int64_t layers)
{
  SurfaceArrays arrays = sink.View();
  const RemovedPieces removed = RemoveSmallPieces(arrays, limits, grid, phi, kBegin, layers);
  sink.Truncate(arrays);
  return removed;
}

} // namespace nv
