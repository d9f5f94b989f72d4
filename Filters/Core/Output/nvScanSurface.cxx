// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvScanSurface.h"

#include "nvNearestPoints.h"
#include "nvParallel.h"
#include "nvPartSteps.h"
#include "nvPieces.h"
#include "nvSurfaceField.h"
#include "nvTruncatedDistance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace nv
{
namespace
{
/// f is kept within +-ClampCells cells, where the contouring reads it.
constexpr double ClampCells = 3.0;

/// A field on the grid's nodes read at any place inside the grid: trilinear.
double Trilinear(const Grid& grid, const std::vector<float>& values, const double x[3])
{
  std::int64_t cell[3];
  double t[3];
  for (int a = 0; a < 3; ++a)
  {
    const double u = (x[a] - grid.Origin[a]) / grid.Spacing;
    const std::int64_t last = std::max<std::int64_t>(0, grid.Dims[a] - 2);
    cell[a] = std::min(last, std::max<std::int64_t>(0, static_cast<std::int64_t>(std::floor(u))));
    t[a] = std::min(1.0, std::max(0.0, u - static_cast<double>(cell[a])));
  }
  double sum = 0.0;
  for (int corner = 0; corner < 8; ++corner)
  {
    const int di = corner & 1, dj = (corner >> 1) & 1, dk = (corner >> 2) & 1;
    const std::int64_t i = std::min(cell[0] + di, grid.Dims[0] - 1), j = std::min(cell[1] + dj, grid.Dims[1] - 1),
                       k = std::min(cell[2] + dk, grid.Dims[2] - 1);
    const double w = (di ? t[0] : 1.0 - t[0]) * (dj ? t[1] : 1.0 - t[1]) * (dk ? t[2] : 1.0 - t[2]);
    sum += w * values[grid.Index(i, j, k)];
  }
  return sum;
}

/// The local depth s: the points' median depth per cell of a coarse grid,
/// averaged over the 27 cells around each (weighted by their points), read
/// at a place by interpolating between the cells' centres (those with points
/// near; 0 where none is).
class LocalDepth
{
public:
  LocalDepth(const Grid& grid, double side, const double* points, const std::vector<float>& depth)
    : Side(side)
  {
    for (int a = 0; a < 3; ++a)
    {
      this->Origin[a] = grid.Origin[a];
      this->Dims[a] = static_cast<std::int64_t>(std::floor((grid.Dims[a] - 1) * grid.Spacing / side)) + 1;
    }
    // The points' cells, and each cell's median depth and count.
    const std::int64_t n = static_cast<std::int64_t>(depth.size());
    std::vector<std::pair<std::int64_t, float>> byCell(static_cast<std::size_t>(n));
    for (std::int64_t p = 0; p < n; ++p)
    {
      byCell[p] = { this->CellOf(points + 3 * p), depth[p] };
    }
    std::sort(byCell.begin(), byCell.end());
    std::vector<std::int64_t> cells;
    std::vector<double> median, count;
    for (std::size_t begin = 0; begin < byCell.size();)
    {
      std::size_t end = begin;
      while (end < byCell.size() && byCell[end].first == byCell[begin].first)
      {
        ++end;
      }
      const std::size_t middle = begin + (end - begin) / 2; // sorted by depth within the cell
      cells.push_back(byCell[begin].first);
      median.push_back(byCell[middle].second);
      count.push_back(static_cast<double>(end - begin));
      begin = end;
    }
    // The average over the 27 cells around each cell that has points near.
    std::vector<std::int64_t> near;
    for (std::int64_t c : cells)
    {
      this->ForAround(c, [&](std::int64_t d) { near.push_back(d); });
    }
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    this->Cells = near;
    this->Values.resize(near.size());
    ParallelFor(0, static_cast<std::int64_t>(near.size()), 256, [&](std::int64_t begin, std::int64_t end) {
      for (std::int64_t m = begin; m < end; ++m)
      {
        double sum = 0.0, weight = 0.0;
        this->ForAround(near[m], [&](std::int64_t d) {
          const auto at = std::lower_bound(cells.begin(), cells.end(), d);
          if (at != cells.end() && *at == d)
          {
            const std::size_t q = static_cast<std::size_t>(at - cells.begin());
            sum += count[q] * median[q];
            weight += count[q];
          }
        });
        this->Values[m] = static_cast<float>(sum / weight);
      }
    });
  }

  /// s at x: between the centres of the 8 cells around it, those that have a value.
  double At(const double x[3]) const
  {
    std::int64_t low[3];
    double t[3];
    for (int a = 0; a < 3; ++a)
    {
      const double u = (x[a] - this->Origin[a]) / this->Side - 0.5;
      low[a] = static_cast<std::int64_t>(std::floor(u));
      t[a] = u - static_cast<double>(low[a]);
    }
    double sum = 0.0, weight = 0.0;
    for (int corner = 0; corner < 8; ++corner)
    {
      const int di = corner & 1, dj = (corner >> 1) & 1, dk = (corner >> 2) & 1;
      const std::int64_t i = low[0] + di, j = low[1] + dj, k = low[2] + dk;
      if (i < 0 || j < 0 || k < 0 || i >= this->Dims[0] || j >= this->Dims[1] || k >= this->Dims[2])
      {
        continue;
      }
      const std::int64_t c = i + this->Dims[0] * (j + this->Dims[1] * k);
      const auto at = std::lower_bound(this->Cells.begin(), this->Cells.end(), c);
      if (at == this->Cells.end() || *at != c)
      {
        continue;
      }
      const double w = (di ? t[0] : 1.0 - t[0]) * (dj ? t[1] : 1.0 - t[1]) * (dk ? t[2] : 1.0 - t[2]);
      sum += w * this->Values[static_cast<std::size_t>(at - this->Cells.begin())];
      weight += w;
    }
    return weight > 0.0 ? sum / weight : 0.0;
  }

private:
  std::int64_t CellOf(const double x[3]) const
  {
    std::int64_t c[3];
    for (int a = 0; a < 3; ++a)
    {
      c[a] = std::min(this->Dims[a] - 1,
        std::max<std::int64_t>(0, static_cast<std::int64_t>(std::floor((x[a] - this->Origin[a]) / this->Side))));
    }
    return c[0] + this->Dims[0] * (c[1] + this->Dims[1] * c[2]);
  }

  template <class Visit>
  void ForAround(std::int64_t c, Visit visit) const
  {
    const std::int64_t i = c % this->Dims[0], j = (c / this->Dims[0]) % this->Dims[1],
                       k = c / (this->Dims[0] * this->Dims[1]);
    for (std::int64_t dk = -1; dk <= 1; ++dk)
      for (std::int64_t dj = -1; dj <= 1; ++dj)
        for (std::int64_t di = -1; di <= 1; ++di)
        {
          const std::int64_t a = i + di, b = j + dj, e = k + dk;
          if (a >= 0 && b >= 0 && e >= 0 && a < this->Dims[0] && b < this->Dims[1] && e < this->Dims[2])
          {
            visit(a + this->Dims[0] * (b + this->Dims[1] * e));
          }
        }
  }

  double Side;
  double Origin[3];
  std::int64_t Dims[3];
  std::vector<std::int64_t> Cells; ///< the cells with a value, ascending
  std::vector<float> Values;
};

/// The distance from x to the triangle abc (the nearest of its points:
/// inside, on an edge, or a corner; Ericson, Real-Time Collision Detection 5.1.5).
double TriangleDistance(const double x[3], const double* a, const double* b, const double* c)
{
  double ab[3], ac[3], ax[3];
  for (int i = 0; i < 3; ++i)
  {
    ab[i] = b[i] - a[i];
    ac[i] = c[i] - a[i];
    ax[i] = x[i] - a[i];
  }
  const auto dot = [](const double* u, const double* v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; };
  const double d1 = dot(ab, ax), d2 = dot(ac, ax);
  double v = 0.0, w = 0.0; // the nearest point: a + v ab + w ac
  const double abab = dot(ab, ab), abac = dot(ab, ac), acac = dot(ac, ac);
  const double d3 = d1 - abab, d4 = d2 - abac; // with x - b
  const double d5 = d1 - abac, d6 = d2 - acac; // with x - c
  const double vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
  if (d1 <= 0.0 && d2 <= 0.0)
  {
    v = w = 0.0; // corner a
  }
  else if (d3 >= 0.0 && d4 <= d3)
  {
    v = 1.0; // corner b
  }
  else if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
  {
    v = d1 / (d1 - d3); // edge ab
  }
  else if (d6 >= 0.0 && d5 <= d6)
  {
    w = 1.0; // corner c
  }
  else if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
  {
    w = d2 / (d2 - d6); // edge ac
  }
  else if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
  {
    w = (d4 - d3) / ((d4 - d3) + (d5 - d6)); // edge bc
    v = 1.0 - w;
  }
  else
  {
    const double denominator = 1.0 / (va + vb + vc); // inside
    v = vb * denominator;
    w = vc * denominator;
  }
  double d = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    const double r = ax[i] - v * ab[i] - w * ac[i];
    d += r * r;
  }
  return std::sqrt(d);
}

/// Sorts a vector's values and gives the one at share q (0..1) of the way.
double Quantile(std::vector<double>& values, double q)
{
  if (values.empty())
  {
    return std::numeric_limits<double>::quiet_NaN();
  }
  const std::size_t at = std::min(values.size() - 1, static_cast<std::size_t>(q * static_cast<double>(values.size())));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(at), values.end());
  return values[at];
}
} // namespace

bool MakeScanSurface(const Grid& grid, const Parameters& parameters, const float* outer, const double* scan,
  std::int64_t scanPoints, bool removeSmallPieces, SurfaceSink& sink, Monitor* monitor, ScanReport& report)
{
  const double l = parameters.OffsetDistance, h = grid.Spacing;
  const double clamp = ClampCells * h;
  // The outer sheet, and D, the distance to it, signed: positive inside S.
  SurfaceMesh sheet;
  if (!ContourBricks(grid, DenseField(grid, outer, 0, grid.Dims[2], parameters), sheet, 0, -1, monitor))
  {
    return false;
  }
  std::vector<float> distance = part::SheetDistance(grid, outer, sheet.Points, 2.0 * l + 2.0 * clamp, monitor);
  if (StopAsked(monitor))
  {
    return false;
  }
  sheet = SurfaceMesh();
  const std::int64_t nodes = grid.NumberOfNodes();
  ParallelFor(0, nodes, 1 << 16, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t n = begin; n < end; ++n)
    {
      distance[n] = outer[n] > 0.0f ? distance[n] : -distance[n];
    }
  });
  // Each point's depth below C's surface, D(p) - l, and the local depth s.
  std::vector<float> depth(static_cast<std::size_t>(scanPoints));
  ParallelFor(0, scanPoints, 4096, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t p = begin; p < end; ++p)
    {
      depth[p] = static_cast<float>(Trilinear(grid, distance, scan + 3 * p) - l);
    }
  });
  const LocalDepth local(grid, std::max(l, 2.0 * h), scan, depth);
  {
    std::vector<double> middles(depth.begin(), depth.end());
    report.MedianDepth = Quantile(middles, 0.5) / h;
  }
  // f on every node (in place of D), within +-clamp.
  const double shallowest = -(l - h), deepest = l;
  ParallelFor(0, grid.Dims[2], 1, [&](std::int64_t kBegin, std::int64_t kEnd) {
    for (std::int64_t k = kBegin; k < kEnd; ++k)
    {
      for (std::int64_t j = 0; j < grid.Dims[1]; ++j)
      {
        for (std::int64_t i = 0; i < grid.Dims[0]; ++i)
        {
          const std::int64_t n = grid.Index(i, j, k);
          const double d = distance[n] - l;
          double f = d > 0.0 ? clamp : -clamp;
          if (d > shallowest - clamp && d < deepest + clamp) // where s can bring f within the clamp
          {
            const double x[3] = { grid.Origin[0] + static_cast<double>(i) * h,
              grid.Origin[1] + static_cast<double>(j) * h, grid.Origin[2] + static_cast<double>(k) * h };
            const double s = std::min(deepest, std::max(shallowest, local.At(x)));
            f = std::min(clamp, std::max(-clamp, d - s));
          }
          distance[n] = static_cast<float>(f);
        }
      }
    }
  });
  if (StopAsked(monitor))
  {
    return false;
  }
  const std::vector<float>& field = distance;
  if (!ContourBricks(grid, NodeField(grid, field, static_cast<float>(-clamp)), sink, 0, -1, monitor))
  {
    return false;
  }
  PieceLimits limits; // 0: none removed, only counted and measured
  limits.SpareLargest = false; // the shreds of an open scan's closing are no surface on it
  limits.Piece = removeSmallPieces ? SmallPieceVolume(l) : 0.0;
  limits.Void = removeSmallPieces ? SmallVoidVolume(l) : 0.0;
  const RemovedPieces removed = RemoveSmallPieces(sink, limits, grid, nullptr, 0, 0);
  report.Volume = removed.Volume;
  report.Pieces = removed.KeptPieces;
  report.RemovedPieces = removed.Pieces;
  report.RemovedVoids = removed.Voids;
  // The points' distances to it: to the nearest of the triangles around
  // the nearest vertex.
  const SurfaceArrays surface = sink.View();
  for (std::int64_t p = 0; p < surface.NumberOfPoints; ++p)
  {
    for (int a = 0; a < 3; ++a)
    {
      const double x = surface.Points[3 * p + a];
      report.Bounds[2 * a] = p == 0 ? x : std::min(report.Bounds[2 * a], x);
      report.Bounds[2 * a + 1] = p == 0 ? x : std::max(report.Bounds[2 * a + 1], x);
    }
  }
  report.Points = scanPoints;
  if (surface.NumberOfPoints == 0 || scanPoints == 0)
  {
    report.MeanDistance = report.Distance95 = report.MedianDistance = std::numeric_limits<double>::quiet_NaN();
    return !StopAsked(monitor);
  }
  const NearestPoints vertices(surface.Points, surface.NumberOfPoints, true);
  std::vector<std::int64_t> first(static_cast<std::size_t>(surface.NumberOfPoints) + 1, 0), around;
  for (std::int64_t t = 0; t < 3 * surface.NumberOfTriangles; ++t)
  {
    ++first[surface.Triangles[t] + 1];
  }
  for (std::int64_t v = 0; v < surface.NumberOfPoints; ++v)
  {
    first[v + 1] += first[v];
  }
  around.resize(static_cast<std::size_t>(first.back()));
  {
    std::vector<std::int64_t> next(first.begin(), first.end() - 1);
    for (std::int64_t t = 0; t < surface.NumberOfTriangles; ++t)
    {
      for (int c = 0; c < 3; ++c)
      {
        around[next[surface.Triangles[3 * t + c]]++] = t;
      }
    }
  }
  std::vector<double> away(static_cast<std::size_t>(scanPoints));
  const double far = std::numeric_limits<double>::max();
  ParallelFor(0, scanPoints, 1024, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t p = begin; p < end; ++p)
    {
      const double* x = scan + 3 * p;
      double d = far;
      const std::int64_t v = vertices.Nearest(x, far, d);
      for (std::int64_t a = first[v]; a < first[v + 1]; ++a)
      {
        const VertexId* corner = surface.Triangles + 3 * around[a];
        d = std::min(d, TriangleDistance(x, surface.Points + 3 * corner[0], surface.Points + 3 * corner[1],
          surface.Points + 3 * corner[2]));
      }
      away[p] = d / h;
    }
  });
  double sum = 0.0;
  for (double d : away)
  {
    sum += d;
  }
  report.MeanDistance = sum / static_cast<double>(scanPoints);
  report.MedianDistance = Quantile(away, 0.5);
  report.Distance95 = Quantile(away, 0.95);
  return !StopAsked(monitor);
}

} // namespace nv
