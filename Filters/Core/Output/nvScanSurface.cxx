// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvScanSurface.h"

#include "nvNearestPoints.h"
#include "nvParallel.h"
#include "nvPartSteps.h"
#include "nvPieces.h"
#include "nvScanSteps.h"
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
/// A piece of S holds an open scan when most of its points, this many at
/// least, lie farther than the offset from the closed surface.
constexpr std::int64_t LeastOpenPoints = 10;


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
/// Each point's distance to the surface, in cells: to the nearest of the
/// triangles around its nearest vertex (none: an empty vector); `nearest`
/// (may be null): that vertex.
std::vector<double> PointDistances(const SurfaceArrays& surface, const double* scan, std::int64_t scanPoints, double h,
  std::vector<std::int64_t>* nearest = nullptr)
{
  if (surface.NumberOfPoints == 0 || scanPoints == 0)
  {
    return {};
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
  if (nearest)
  {
    nearest->assign(static_cast<std::size_t>(scanPoints), -1);
  }
  const double far = std::numeric_limits<double>::max();
  ParallelFor(0, scanPoints, 1024, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t p = begin; p < end; ++p)
    {
      const double* x = scan + 3 * p;
      double d = far;
      const std::int64_t v = vertices.Nearest(x, far, d);
      if (nearest)
      {
        (*nearest)[p] = v;
      }
      for (std::int64_t a = first[v]; a < first[v + 1]; ++a)
      {
        const VertexId* corner = surface.Triangles + 3 * around[a];
        d = std::min(d, TriangleDistance(x, surface.Points + 3 * corner[0], surface.Points + 3 * corner[1],
          surface.Points + 3 * corner[2]));
      }
      away[p] = d / h;
    }
  });
  return away;
}

/// The closed surface's parts that are slabs: each part (vertices joined by
/// triangles) whose thickness, twice its volume over its area, is less than
/// twice the 95th percentile of its points' distances to it (a point is the
/// part's whose nearest vertex is, if nearer than `reach`; `away` in
/// cells): one vertex of each.
std::vector<std::int64_t> SlabVertices(const SurfaceArrays& surface, const std::vector<std::int64_t>& nearest,
  const std::vector<double>& away, double h, double reach)
{
  const std::int64_t points = surface.NumberOfPoints;
  const std::vector<std::int64_t> part = SurfaceParts(surface);
  std::vector<double> volume(static_cast<std::size_t>(points), 0.0), area(static_cast<std::size_t>(points), 0.0);
  for (std::int64_t t = 0; t < surface.NumberOfTriangles; ++t)
  {
    const double* a = surface.Points + 3 * surface.Triangles[3 * t];
    const double* b = surface.Points + 3 * surface.Triangles[3 * t + 1];
    const double* c = surface.Points + 3 * surface.Triangles[3 * t + 2];
    const double cross[3] = { (b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]),
      (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]),
      (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) };
    const std::int64_t root = part[surface.Triangles[3 * t]];
    area[root] += 0.5 * std::sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]);
    volume[root] += (a[0] * cross[0] + a[1] * cross[1] + a[2] * cross[2]) / 6.0;
  }
  std::vector<std::vector<double>> spread(static_cast<std::size_t>(points));
  for (std::size_t p = 0; p < nearest.size(); ++p)
  {
    if (nearest[p] >= 0 && away[p] * h < reach) // not the points of another piece, far
    {
      spread[part[nearest[p]]].push_back(away[p] * h);
    }
  }
  std::vector<std::int64_t> slabs;
  for (std::int64_t v = 0; v < points; ++v)
  {
    if (part[v] == v && !spread[v].empty() && area[v] > 0.0 &&
      2.0 * std::fabs(volume[v]) / area[v] < 2.0 * Quantile(spread[v], 0.95))
    {
      slabs.push_back(v);
    }
  }
  return slabs;
}

/// The grid node nearest to x (-1: x outside the grid's box by more than half a cell).
std::int64_t NodeNear(const Grid& grid, const double* x)
{
  std::int64_t ijk[3];
  for (int a = 0; a < 3; ++a)
  {
    ijk[a] = static_cast<std::int64_t>(std::floor((x[a] - grid.Origin[a]) / grid.Spacing + 0.5));
    if (ijk[a] < 0 || ijk[a] >= grid.Dims[a])
    {
      return -1;
    }
  }
  return grid.Index(ijk[0], ijk[1], ijk[2]);
}

/// Adds `part` to the sink's surface; returns its connected pieces.
std::int64_t Append(SurfaceMesh& part, SurfaceSink& sink)
{
  const std::int64_t points = static_cast<std::int64_t>(part.Points.size() / 3);
  const std::int64_t triangles = static_cast<std::int64_t>(part.Triangles.size() / 3);
  if (triangles == 0)
  {
    return 0;
  }
  const VertexId offset = static_cast<VertexId>(sink.View().NumberOfPoints);
  double* xyz = nullptr;
  float* normals = nullptr;
  sink.AddPoints(points, xyz, normals);
  std::copy(part.Points.begin(), part.Points.end(), xyz);
  std::copy(part.Normals.begin(), part.Normals.end(), normals);
  VertexId* ids = sink.AddTriangles(triangles);
  for (std::size_t i = 0; i < part.Triangles.size(); ++i)
  {
    ids[i] = part.Triangles[i] + offset;
  }
  // Its pieces: the parts named by themselves.
  const std::vector<std::int64_t> root = SurfaceParts(part.View());
  std::int64_t pieces = 0;
  for (std::int64_t v = 0; v < points; ++v)
  {
    pieces += root[v] == v ? 1 : 0;
  }
  return pieces;
}
} // namespace

bool MakeScanSurface(const Grid& grid, const Parameters& parameters, const float* outer, const double* scan,
  std::int64_t scanPoints, bool removeSmallPieces, SurfaceSink& sink, Monitor* monitor, ScanReport& report,
  const double progress[2])
{
  using scan::Trilinear;
  // The progress of the steps, as shares of the run's, about as their time
  // goes (an open scan's surface takes the second half).
  const auto step = [&](double from, double to) {
    if (monitor)
    {
      monitor->Stage(progress[0] + from * progress[1], (to - from) * progress[1]);
    }
  };
  step(0.0, 0.05);
  const double l = parameters.OffsetDistance, h = grid.Spacing;
  const double clamp = ClampCells * h;
  const std::int64_t nodes = grid.NumberOfNodes();
  // The outer sheet, and D, the distance to it.
  SurfaceMesh sheet;
  if (!ContourBricks(grid, DenseField(grid, outer, 0, grid.Dims[2], parameters), sheet, 0, -1, monitor))
  {
    return false;
  }
  step(0.05, 0.3);
  const std::vector<float> distance = part::SheetDistance(grid, outer, sheet.Points, 2.0 * l + 2.0 * clamp, monitor);
  if (StopAsked(monitor))
  {
    return false;
  }
  // Each point's depth below C's surface, D(p) - l (D signed: negative
  // outside S), and the local depth s.
  std::vector<float> field(static_cast<std::size_t>(nodes));
  ParallelFor(0, nodes, 1 << 16, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t n = begin; n < end; ++n)
    {
      field[n] = outer[n] > 0.0f ? distance[n] : -distance[n];
    }
  });
  std::vector<float> depth(static_cast<std::size_t>(scanPoints));
  ParallelFor(0, scanPoints, 4096, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t p = begin; p < end; ++p)
    {
      depth[p] = static_cast<float>(Trilinear(grid, field.data(), scan + 3 * p) - l);
    }
  });
  const LocalDepth local(grid, std::max(l, 2.0 * h), scan, depth);
  {
    std::vector<double> middles(depth.begin(), depth.end());
    report.MedianDepth = Quantile(middles, 0.5) / h;
  }
  // f on every node (in place of the signed D), within +-clamp.
  const double shallowest = -(l - h), deepest = l;
  ParallelFor(0, grid.Dims[2], 1, [&](std::int64_t kBegin, std::int64_t kEnd) {
    for (std::int64_t k = kBegin; k < kEnd; ++k)
    {
      for (std::int64_t j = 0; j < grid.Dims[1]; ++j)
      {
        for (std::int64_t i = 0; i < grid.Dims[0]; ++i)
        {
          const std::int64_t n = grid.Index(i, j, k);
          const double d = field[n] - l;
          double f = d > 0.0 ? clamp : -clamp;
          if (d > shallowest - clamp && d < deepest + clamp) // where s can bring f within the clamp
          {
            const double x[3] = { grid.Origin[0] + static_cast<double>(i) * h,
              grid.Origin[1] + static_cast<double>(j) * h, grid.Origin[2] + static_cast<double>(k) * h };
            const double s = std::min(deepest, std::max(shallowest, local.At(x)));
            f = std::min(clamp, std::max(-clamp, d - s));
          }
          field[n] = static_cast<float>(f);
        }
      }
    }
  });
  if (StopAsked(monitor))
  {
    return false;
  }
  // The closed surface, f = 0, its loose pieces removed.
  PieceLimits limits; // 0: none removed, only counted and measured
  limits.SpareLargest = false; // the shreds of an open scan's closing are no surface on it
  limits.Piece = removeSmallPieces ? SmallPieceVolume(l) : 0.0;
  limits.Void = removeSmallPieces ? SmallVoidVolume(l) : 0.0;
  const auto contourClosed = [&]() {
    SurfaceArrays none = sink.View();
    none.NumberOfPoints = none.NumberOfTriangles = 0;
    sink.Truncate(none);
    if (!ContourBricks(grid, NodeField(grid, field, static_cast<float>(-clamp)), sink, 0, -1, monitor))
    {
      return false;
    }
    const RemovedPieces removed = RemoveSmallPieces(sink, limits, grid, nullptr, 0, 0);
    report.Volume = removed.Volume;
    report.Pieces = removed.KeptPieces;
    report.RemovedPieces = removed.Pieces;
    report.RemovedVoids = removed.Voids;
    return true;
  };
  step(0.3, 0.5);
  if (!contourClosed())
  {
    return false;
  }
  std::vector<std::int64_t> nearest;
  std::vector<double> away = PointDistances(sink.View(), scan, scanPoints, h, &nearest);
  // The pieces of S that hold an open scan, whose surface is the open one
  // (nvScanSteps.h): those whose points the closed surface mostly missed (a
  // clean open scan's closing is empty or in shreds), and those around a
  // closed part thinner than its points' spread (a noisy open scan's
  // closing is a thin slab through the points' middle, both of its sides
  // among them: SlabParts).
  std::int32_t count = 0;
  const std::vector<std::int32_t> pieces = scan::SolidPieces(grid, outer, count);
  std::vector<char> open(static_cast<std::size_t>(count), 0);
  for (std::int64_t v : SlabVertices(sink.View(), nearest, away, h, 2.0 * l))
  {
    const std::int32_t piece = scan::PieceAt(grid, outer, pieces, sink.View().Points + 3 * v);
    if (piece >= 0)
    {
      open[piece] = 1;
    }
  }
  std::vector<std::int64_t> held(static_cast<std::size_t>(count), 0), missed(static_cast<std::size_t>(count), 0);
  for (std::int64_t p = 0; p < scanPoints; ++p)
  {
    const std::int64_t n = NodeNear(grid, scan + 3 * p);
    if (n >= 0 && pieces[n] >= 0)
    {
      (!away.empty() && away[p] * h < l ? held : missed)[pieces[n]] += 1;
    }
  }
  bool anyOpen = false;
  for (std::int32_t piece = 0; piece < count; ++piece)
  {
    open[piece] = open[piece] || (missed[piece] > held[piece] && missed[piece] >= LeastOpenPoints);
    anyOpen = anyOpen || open[piece];
  }
  if (anyOpen)
  {
    step(0.5, 0.55);
    ParallelFor(0, nodes, 1 << 16, [&](std::int64_t begin, std::int64_t end) {
      for (std::int64_t n = begin; n < end; ++n)
      {
        if (pieces[n] >= 0 && open[pieces[n]])
        {
          field[n] = static_cast<float>(-clamp);
        }
      }
    });
    if (!contourClosed())
    {
      return false;
    }
    scan::OpenScanInput input;
    input.Outer = outer;
    input.Distance = &distance;
    input.Sheet = &sheet;
    input.Pieces = &pieces;
    input.Open = &open;
    input.Scan = scan;
    input.ScanPoints = scanPoints;
    input.Offset = l;
    input.Reach = std::numeric_limits<double>::max();
    input.Step = [&](double from, double to) { step(0.55 + 0.45 * from, 0.55 + 0.45 * to); };
    SurfaceMesh openSurface;
    if (!scan::MakeOpenSurface(grid, input, openSurface, monitor))
    {
      return false;
    }
    report.OpenPieces = Append(openSurface, sink);
    away = PointDistances(sink.View(), scan, scanPoints, h);
  }
  report.Bounds = BoundsOf(sink.View());
  report.Points = scanPoints;
  double sum = 0.0;
  for (double d : away)
  {
    sum += d;
  }
  report.MeanDistance = away.empty() ? std::numeric_limits<double>::quiet_NaN() : sum / static_cast<double>(away.size());
  report.MedianDistance = Quantile(away, 0.5);
  report.Distance95 = Quantile(away, 0.95);
  return !StopAsked(monitor);
}

} // namespace nv
