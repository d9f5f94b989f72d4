// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The surface on an open scan (MakeOpenSurface, nvScanSteps.h), and the
// pieces of the solid it is made on.
#include "nvScanSteps.h"

#include "nvNearestPoints.h"
#include "nvParallel.h"
#include "nvPartSteps.h"
#include "nvPieces.h"
#include "nvSurfaceField.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

namespace nv
{
namespace scan
{
namespace
{
/// A ray's way across the shell is at most this many times the deepest D
/// on it: across a sheet of thickness 2 D it is 2 D, along one far more.
constexpr double AcrossShare = 2.6;
/// The points a triangle of the open surface looks at to tell whether it
/// is on the scan or beyond its rim, and the share of their mean distance
/// by which their centroid may lie off the triangle: about 0.2 among the
/// points around (where random sampling puts it), 0.64 on a rim's line
/// (half a disc: 4 / (3 pi) over 2 / 3), more beyond it.
constexpr int RimNeighbours = 24;
constexpr double RimShare = 0.55;
/// A bend of the sheet sharper than RimBend / l is around a rim (a
/// half-pipe of radius l bends by 1 / l); edges shorter than ShortestEdge
/// cells are too short to tell a bend from the contouring's noise.
constexpr double RimBend = 0.6;
constexpr double ShortestEdge = 0.3;
/// Rounds of the normals' smoothing before the bend is measured: about two
/// cells of the sheet, less than a rim's half-pipe (pi l), more than a
/// noisy envelope's bumps.
constexpr int SmoothingRounds = 10;
/// A ray's end is on the other face when the nearest vertex there faces
/// away from the ray's start: normals at more than about 135 degrees.
constexpr double OppositeNormals = -0.7;

/// Whether x lies inside the grid's box.
bool InGrid(const Grid& grid, const double x[3])
{
  for (int a = 0; a < 3; ++a)
  {
    const double u = (x[a] - grid.Origin[a]) / grid.Spacing;
    if (!(u >= 0.0 && u <= static_cast<double>(grid.Dims[a] - 1)))
    {
      return false;
    }
  }
  return true;
}
} // namespace

std::int32_t PieceAt(const Grid& grid, const float* outer, const std::vector<std::int32_t>& pieces, const double* x)
{
  std::int64_t cell[3];
  for (int a = 0; a < 3; ++a)
  {
    cell[a] = std::min(grid.Dims[a] - 2,
      std::max<std::int64_t>(0, static_cast<std::int64_t>(std::floor((x[a] - grid.Origin[a]) / grid.Spacing))));
  }
  for (int corner = 0; corner < 8; ++corner)
  {
    const std::int64_t n =
      grid.Index(cell[0] + (corner & 1), cell[1] + ((corner >> 1) & 1), cell[2] + ((corner >> 2) & 1));
    if (outer[n] > 0.0f)
    {
      return pieces[n];
    }
  }
  return -1;
}

double Trilinear(const Grid& grid, const float* values, const double x[3])
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

std::vector<std::int32_t> SolidPieces(const Grid& grid, const float* outer, std::int32_t& pieces)
{
  const std::int64_t nx = grid.Dims[0], ny = grid.Dims[1], nodes = grid.NumberOfNodes();
  std::vector<std::int32_t> piece(static_cast<std::size_t>(nodes), -1);
  std::vector<std::int64_t> queue;
  pieces = 0;
  for (std::int64_t start = 0; start < nodes; ++start)
  {
    if (outer[start] <= 0.0f || piece[start] >= 0)
    {
      continue;
    }
    piece[start] = pieces;
    queue.assign(1, start);
    for (std::size_t head = 0; head < queue.size(); ++head)
    {
      const std::int64_t n = queue[head];
      const std::int64_t i = n % nx, j = (n / nx) % ny, k = n / (nx * ny);
      const std::int64_t next[6] = { i > 0 ? n - 1 : -1, i < nx - 1 ? n + 1 : -1, j > 0 ? n - nx : -1,
        j < ny - 1 ? n + nx : -1, k > 0 ? n - nx * ny : -1, k < grid.Dims[2] - 1 ? n + nx * ny : -1 };
      for (std::int64_t m : next)
      {
        if (m >= 0 && piece[m] < 0 && outer[m] > 0.0f)
        {
          piece[m] = pieces;
          queue.push_back(m);
        }
      }
    }
    ++pieces;
  }
  return piece;
}

bool MakeOpenSurface(const Grid& grid, const OpenScanInput& input, SurfaceMesh& open, Monitor* monitor)
{
  const auto step = [&](double from, double to) {
    if (input.Step)
    {
      input.Step(from, to);
    }
  };
  step(0.0, 0.15);
  const double h = grid.Spacing;
  const float* outer = input.Outer;
  const std::vector<float>& distance = *input.Distance;
  const std::vector<std::int32_t>& pieces = *input.Pieces;
  const SurfaceMesh& sheet = *input.Sheet;
  const std::int64_t vertices = static_cast<std::int64_t>(sheet.Points.size() / 3);
  const std::int64_t triangles = static_cast<std::int64_t>(sheet.Triangles.size() / 3);
  // The sheet's vertices around open pieces.
  std::vector<std::int32_t> vertexPiece(static_cast<std::size_t>(vertices));
  ParallelFor(0, vertices, 4096, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t v = begin; v < end; ++v)
    {
      const std::int32_t p = PieceAt(grid, outer, pieces, &sheet.Points[3 * v]);
      vertexPiece[v] = p >= 0 && (*input.Open)[p] ? p : -1;
    }
  });
  // Each vertex's ray across the shell, and the vertex at its end.
  const NearestPoints near(sheet.Points.data(), vertices, true);
  std::vector<std::int64_t> partner(static_cast<std::size_t>(vertices), -1);
  const double longest = 8.0 * input.Offset + 8.0 * h;
  ParallelFor(0, vertices, 1024, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t v = begin; v < end; ++v)
    {
      if (vertexPiece[v] < 0)
      {
        continue;
      }
      const double* y = &sheet.Points[3 * v];
      const float* n = &sheet.Normals[3 * v];
      double deepest = 0.0, x[3];
      bool left = false;
      double t = 0.5 * h;
      for (; t < longest; t += 0.5 * h)
      {
        for (int a = 0; a < 3; ++a)
        {
          x[a] = y[a] - t * n[a];
        }
        if (!InGrid(grid, x))
        {
          break;
        }
        if (t > h && Trilinear(grid, outer, x) <= 0.0)
        {
          left = true;
          break;
        }
        deepest = std::max(deepest, Trilinear(grid, distance.data(), x));
      }
      if (!left || t > AcrossShare * deepest + h)
      {
        continue;
      }
      double away = 0.0;
      const std::int64_t w = near.Nearest(x, 2.0 * h, away);
      if (w < 0 || vertexPiece[w] != vertexPiece[v])
      {
        continue;
      }
      const float* m = &sheet.Normals[3 * w];
      if (n[0] * m[0] + n[1] * m[1] + n[2] * m[2] < OppositeNormals)
      {
        partner[v] = w;
      }
    }
  });
  if (StopAsked(monitor))
  {
    return false;
  }
  // The sheet's neighbours of each vertex (twice each, one per triangle).
  std::vector<std::int64_t> first(static_cast<std::size_t>(vertices) + 1, 0), ring;
  for (std::int64_t t = 0; t < 3 * triangles; ++t)
  {
    first[sheet.Triangles[t] + 1] += 2;
  }
  std::partial_sum(first.begin(), first.end(), first.begin());
  ring.resize(static_cast<std::size_t>(first.back()));
  {
    std::vector<std::int64_t> next(first.begin(), first.end() - 1);
    for (std::int64_t t = 0; t < triangles; ++t)
    {
      for (int c = 0; c < 3; ++c)
      {
        const std::int64_t a = sheet.Triangles[3 * t + c];
        ring[next[a]++] = sheet.Triangles[3 * t + (c + 1) % 3];
        ring[next[a]++] = sheet.Triangles[3 * t + (c + 2) % 3];
      }
    }
  }
  // The normals smoothed along the sheet (SmoothingRounds of the mean over
  // each vertex and its neighbours), so that the bumps of a noisy scan's
  // envelope do not read as bends.
  std::vector<float> smooth(sheet.Normals);
  {
    std::vector<float> next(smooth.size());
    for (int round = 0; round < SmoothingRounds; ++round)
    {
      ParallelFor(0, vertices, 4096, [&](std::int64_t begin, std::int64_t end) {
        for (std::int64_t v = begin; v < end; ++v)
        {
          double sum[3] = { smooth[3 * v], smooth[3 * v + 1], smooth[3 * v + 2] };
          for (std::int64_t r = first[v]; r < first[v + 1]; ++r)
          {
            for (int a = 0; a < 3; ++a)
            {
              sum[a] += smooth[3 * ring[r] + a];
            }
          }
          const double norm = std::sqrt(sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2]);
          for (int a = 0; a < 3; ++a)
          {
            next[3 * v + a] = static_cast<float>(norm > 0.0 ? sum[a] / norm : 0.0);
          }
        }
      });
      smooth.swap(next);
    }
  }
  // Where the sheet bends as a half-pipe of radius l does (around a rim, or
  // all around a strip of scan narrower than the shell), its two faces
  // meet: no vertex there is on a face, whatever its ray says. The bend:
  // the angle between the normals of an edge's ends over its length.
  const double sharpest = RimBend / input.Offset;
  for (std::int64_t t = 0; t < triangles; ++t)
  {
    for (int c = 0; c < 3; ++c)
    {
      const std::int64_t a = sheet.Triangles[3 * t + c], b = sheet.Triangles[3 * t + (c + 1) % 3];
      const double* x = &sheet.Points[3 * a];
      const double* y = &sheet.Points[3 * b];
      const double length = std::sqrt(std::pow(x[0] - y[0], 2) + std::pow(x[1] - y[1], 2) + std::pow(x[2] - y[2], 2));
      if (length < ShortestEdge * h)
      {
        continue; // too short to measure a bend on
      }
      const float* m = &smooth[3 * a];
      const float* n = &smooth[3 * b];
      const double cosine = std::max(-1.0, std::min(1.0, static_cast<double>(m[0] * n[0] + m[1] * n[1] + m[2] * n[2])));
      if (std::acos(cosine) > sharpest * length)
      {
        partner[a] = partner[b] = -1;
      }
    }
  }
  // Patches: the vertices on a face, joined by the sheet's edges.
  PointParts patches(vertices);
  for (std::int64_t t = 0; t < triangles; ++t)
  {
    for (int c = 0; c < 3; ++c)
    {
      const std::int64_t a = sheet.Triangles[3 * t + c], b = sheet.Triangles[3 * t + (c + 1) % 3];
      if (partner[a] >= 0 && partner[b] >= 0)
      {
        patches.Join(a, b);
      }
    }
  }
  // Opposite patches, from the rays; two colours by breadth-first search,
  // the patches with the most rays first.
  std::vector<std::pair<std::int64_t, std::int64_t>> across;
  for (std::int64_t v = 0; v < vertices; ++v)
  {
    if (partner[v] >= 0 && partner[partner[v]] >= 0)
    {
      const std::int64_t a = patches.Root(v), b = patches.Root(partner[v]);
      if (a != b)
      {
        across.emplace_back(a, b);
        across.emplace_back(b, a);
      }
    }
  }
  std::sort(across.begin(), across.end());
  std::vector<signed char> colour(static_cast<std::size_t>(vertices), 0); // per patch root
  {
    std::vector<std::pair<std::int64_t, std::int64_t>> byRays; // (-rays, patch)
    for (std::size_t i = 0; i < across.size();)
    {
      std::size_t j = i;
      while (j < across.size() && across[j].first == across[i].first)
      {
        ++j;
      }
      byRays.emplace_back(-static_cast<std::int64_t>(j - i), across[i].first);
      i = j;
    }
    std::sort(byRays.begin(), byRays.end());
    std::vector<std::int64_t> queue;
    for (const auto& start : byRays)
    {
      if (colour[start.second] != 0)
      {
        continue;
      }
      colour[start.second] = 1;
      queue.assign(1, start.second);
      for (std::size_t head = 0; head < queue.size(); ++head)
      {
        const std::int64_t a = queue[head];
        auto at = std::lower_bound(across.begin(), across.end(), std::make_pair(a, std::int64_t(-1)));
        for (; at != across.end() && at->first == a; ++at)
        {
          if (colour[at->second] == 0)
          {
            colour[at->second] = static_cast<signed char>(-colour[a]);
            queue.push_back(at->second);
          }
        }
      }
    }
  }
  // Every vertex's face: its patch's colour, or the nearest coloured
  // vertex's along the sheet's edges.
  std::vector<signed char> face(static_cast<std::size_t>(vertices), 0);
  std::vector<std::int64_t> queue;
  for (std::int64_t v = 0; v < vertices; ++v)
  {
    if (vertexPiece[v] >= 0 && partner[v] >= 0 && colour[patches.Root(v)] != 0)
    {
      face[v] = colour[patches.Root(v)];
      queue.push_back(v);
    }
  }
  for (std::size_t head = 0; head < queue.size(); ++head)
  {
    const std::int64_t v = queue[head];
    for (std::int64_t r = first[v]; r < first[v + 1]; ++r)
    {
      const std::int64_t w = ring[r];
      if (face[w] == 0 && vertexPiece[w] >= 0)
      {
        face[w] = face[v];
        queue.push_back(w);
      }
    }
  }
  // D_A and D_B, and psi = (D_B - D_A) / 2 on the open pieces.
  std::vector<double> sideA, sideB;
  for (std::int64_t v = 0; v < vertices; ++v)
  {
    std::vector<double>& side = face[v] > 0 ? sideA : sideB;
    if (face[v] != 0)
    {
      side.insert(side.end(), &sheet.Points[3 * v], &sheet.Points[3 * v] + 3);
    }
  }
  if (sideA.empty() || sideB.empty())
  {
    return true; // no two faces: nothing to put between them
  }
  const std::int64_t nodes = grid.NumberOfNodes();
  double deepest = 0.0;
  for (std::int64_t n = 0; n < nodes; ++n)
  {
    if (outer[n] > 0.0f && (*input.Open)[pieces[n]])
    {
      deepest = std::max(deepest, static_cast<double>(distance[n]));
    }
  }
  const double cap = 2.0 * deepest + 4.0 * h, clamp = 3.0 * h;
  step(0.15, 0.4);
  std::vector<float> psi = part::SheetDistance(grid, outer, sideB, cap, monitor);
  if (StopAsked(monitor))
  {
    return false;
  }
  {
    step(0.4, 0.65);
    const std::vector<float> toA = part::SheetDistance(grid, outer, sideA, cap, monitor);
    if (StopAsked(monitor))
    {
      return false;
    }
    ParallelFor(0, nodes, 1 << 16, [&](std::int64_t begin, std::int64_t end) {
      for (std::int64_t n = begin; n < end; ++n)
      {
        const bool onOpen = outer[n] > 0.0f && (*input.Open)[pieces[n]];
        const double value = onOpen ? 0.5 * (static_cast<double>(psi[n]) - toA[n]) : -clamp;
        psi[n] = static_cast<float>(std::max(-clamp, std::min(clamp, value)));
      }
    });
  }
  step(0.65, 0.8);
  SurfaceMesh raw;
  if (!ContourBricks(grid, NodeField(grid, psi, static_cast<float>(-clamp)), raw, 0, -1, monitor))
  {
    return false;
  }
  step(0.8, 1.0);
  // Kept: the triangles in cells wholly inside the open pieces (not across
  // the outer sheet), with points all around (not beyond the scan's rim,
  // where the middle between the faces goes on to the rim's half-pipe).
  const NearestPoints points(input.Scan, input.ScanPoints);
  const std::int64_t rawTriangles = static_cast<std::int64_t>(raw.Triangles.size() / 3);
  std::vector<char> keep(static_cast<std::size_t>(rawTriangles), 0);
  ParallelFor(0, rawTriangles, 1024, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t t = begin; t < end; ++t)
    {
      double c[3] = { 0.0, 0.0, 0.0 };
      for (int k = 0; k < 3; ++k)
      {
        for (int a = 0; a < 3; ++a)
        {
          c[a] += raw.Points[3 * raw.Triangles[3 * t + k] + a] / 3.0;
        }
      }
      std::int64_t cell[3];
      for (int a = 0; a < 3; ++a)
      {
        cell[a] = std::min(grid.Dims[a] - 2,
          std::max<std::int64_t>(0, static_cast<std::int64_t>(std::floor((c[a] - grid.Origin[a]) / h))));
      }
      bool inside = true;
      for (int corner = 0; corner < 8 && inside; ++corner)
      {
        const std::int64_t n =
          grid.Index(cell[0] + (corner & 1), cell[1] + ((corner >> 1) & 1), cell[2] + ((corner >> 2) & 1));
        inside = outer[n] > 0.0f && (*input.Open)[pieces[n]];
      }
      if (!inside)
      {
        continue;
      }
      keep[t] = 2; // inside; kept below if it has points all around
      std::vector<std::array<double, 3>> around;
      points.Nearest(c, RimNeighbours, input.Reach, around);
      if (static_cast<int>(around.size()) < RimNeighbours / 2)
      {
        continue;
      }
      double centroid[3] = { 0.0, 0.0, 0.0 }, mean = 0.0;
      for (const std::array<double, 3>& y : around)
      {
        double d2 = 0.0;
        for (int a = 0; a < 3; ++a)
        {
          centroid[a] += y[a] / static_cast<double>(around.size());
          d2 += (y[a] - c[a]) * (y[a] - c[a]);
        }
        mean += std::sqrt(d2) / static_cast<double>(around.size());
      }
      const double off = std::sqrt(std::pow(centroid[0] - c[0], 2) + std::pow(centroid[1] - c[1], 2) +
        std::pow(centroid[2] - c[2], 2));
      keep[t] = off <= RimShare * mean ? 1 : 2;
    }
  });
  // The holes the test left among the kept (a sampling's chance gaps) are
  // filled, then the loose shreds and ribbons go.
  std::vector<std::array<std::int64_t, 3>> edges; // (a, b, triangle), a < b
  edges.reserve(3 * static_cast<std::size_t>(rawTriangles));
  for (std::int64_t t = 0; t < rawTriangles; ++t)
  {
    for (int c = 0; c < 3; ++c)
    {
      const std::int64_t a = raw.Triangles[3 * t + c], b = raw.Triangles[3 * t + (c + 1) % 3];
      edges.push_back({ std::min(a, b), std::max(a, b), t });
    }
  }
  std::sort(edges.begin(), edges.end());
  std::vector<std::pair<std::int64_t, std::int64_t>> neighbours; // triangles sharing an edge
  std::vector<char> edged(static_cast<std::size_t>(rawTriangles), 0); // with an edge of its own (the mesh's end)
  for (std::size_t e = 0; e < edges.size();)
  {
    std::size_t f = e + 1;
    while (f < edges.size() && edges[f][0] == edges[e][0] && edges[f][1] == edges[e][1])
    {
      neighbours.emplace_back(edges[e][2], edges[f][2]);
      ++f;
    }
    edged[edges[e][2]] = edged[edges[e][2]] || f == e + 1;
    e = f;
  }
  edges.clear();
  edges.shrink_to_fit();
  // The dropped regions (joined across edges) that kept triangles enclose
  // wholly are put back: gaps of the sampling. Beyond the rim the middle
  // goes on to the outer sheet, where it meets triangles across the sheet
  // (dropped before the test) or ends.
  std::vector<double> area(static_cast<std::size_t>(rawTriangles), 0.0);
  for (std::int64_t t = 0; t < rawTriangles; ++t)
  {
    const double* a = &raw.Points[3 * raw.Triangles[3 * t]];
    const double* b = &raw.Points[3 * raw.Triangles[3 * t + 1]];
    const double* c = &raw.Points[3 * raw.Triangles[3 * t + 2]];
    const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] }, v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
    area[t] = 0.5 * std::sqrt(std::pow(u[1] * v[2] - u[2] * v[1], 2) + std::pow(u[2] * v[0] - u[0] * v[2], 2) +
      std::pow(u[0] * v[1] - u[1] * v[0], 2));
  }
  const double least = M_PI * input.Offset * input.Offset;
  const auto regionAreas = [&](char state, PointParts& regions) {
    for (const auto& pair : neighbours)
    {
      if (keep[pair.first] == state && keep[pair.second] == state)
      {
        regions.Join(pair.first, pair.second);
      }
    }
    std::vector<double> total(static_cast<std::size_t>(rawTriangles), 0.0);
    for (std::int64_t t = 0; t < rawTriangles; ++t)
    {
      total[regions.Root(t)] += keep[t] == state ? area[t] : 0.0;
    }
    return total;
  };
  {
    PointParts holes(rawTriangles);
    regionAreas(2, holes);
    std::vector<char> reaches(static_cast<std::size_t>(rawTriangles), 0); // per region: reaches the mesh's end or the sheet
    for (std::int64_t t = 0; t < rawTriangles; ++t)
    {
      if (keep[t] == 2 && edged[t])
      {
        reaches[holes.Root(t)] = 1;
      }
    }
    for (const auto& pair : neighbours)
    {
      if (keep[pair.first] == 2 && keep[pair.second] == 0)
      {
        reaches[holes.Root(pair.first)] = 1;
      }
      if (keep[pair.second] == 2 && keep[pair.first] == 0)
      {
        reaches[holes.Root(pair.second)] = 1;
      }
    }
    for (std::int64_t t = 0; t < rawTriangles; ++t)
    {
      keep[t] = keep[t] == 2 && !reaches[holes.Root(t)] ? 1 : keep[t];
    }
  }
  {
    // Each region's boundary, its triangles' edges that no kept triangle
    // shares (each a third of its triangle's perimeter, near enough).
    PointParts shreds(rawTriangles);
    const std::vector<double> total = regionAreas(1, shreds);
    std::vector<int> shared(static_cast<std::size_t>(rawTriangles), 0);
    for (const auto& pair : neighbours)
    {
      if (keep[pair.first] == 1 && keep[pair.second] == 1)
      {
        ++shared[pair.first];
        ++shared[pair.second];
      }
    }
    std::vector<double> boundary(static_cast<std::size_t>(rawTriangles), 0.0);
    for (std::int64_t t = 0; t < rawTriangles; ++t)
    {
      if (keep[t] == 1 && shared[t] < 3)
      {
        double perimeter = 0.0;
        for (int c = 0; c < 3; ++c)
        {
          const double* x = &raw.Points[3 * raw.Triangles[3 * t + c]];
          const double* y = &raw.Points[3 * raw.Triangles[3 * t + (c + 1) % 3]];
          perimeter += std::sqrt(std::pow(x[0] - y[0], 2) + std::pow(x[1] - y[1], 2) + std::pow(x[2] - y[2], 2));
        }
        boundary[shreds.Root(t)] += (3 - shared[t]) * perimeter / 3.0;
      }
    }
    // Gone: shreds smaller than a disc of radius l, and ribbons narrower than
    // l (twice the area over the boundary: a strip's width), which a tube
    // of points along a curve leaves.
    for (std::int64_t t = 0; t < rawTriangles; ++t)
    {
      const std::int64_t region = shreds.Root(t);
      keep[t] = keep[t] == 1 && total[region] >= least && 2.0 * total[region] >= input.Offset * boundary[region] ? 1 : 0;
    }
  }
  std::vector<VertexId> index(raw.Points.size() / 3, -1);
  for (std::int64_t t = 0; t < rawTriangles; ++t)
  {
    if (!keep[t])
    {
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      VertexId& at = index[raw.Triangles[3 * t + k]];
      if (at < 0)
      {
        at = static_cast<VertexId>(open.Points.size() / 3);
        const std::size_t from = 3 * static_cast<std::size_t>(raw.Triangles[3 * t + k]);
        open.Points.insert(open.Points.end(), raw.Points.begin() + from, raw.Points.begin() + from + 3);
        open.Normals.insert(open.Normals.end(), raw.Normals.begin() + from, raw.Normals.begin() + from + 3);
      }
      open.Triangles.push_back(at);
    }
  }
  return !StopAsked(monitor);
}
} // namespace scan
} // namespace nv
