// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvMarchingCubes.h"

#include <algorithm>
#include <vector>

namespace nv
{
namespace
{
int OtherCorner(int edge)
{
  return EdgeCorner(edge) | (1 << EdgeAxis(edge));
}

/// Whether the edge lies in face (axis, side) of the cell.
bool InFace(int edge, int axis, int side)
{
  return EdgeAxis(edge) != axis && ((EdgeCorner(edge) >> axis) & 1) == side;
}

bool ShareFace(int e, int f)
{
  for (int axis = 0; axis < 3; ++axis)
  {
    for (int side = 0; side < 2; ++side)
    {
      if (InFace(e, axis, side) && InFace(f, axis, side))
      {
        return true;
      }
    }
  }
  return false;
}

/// Cuts one face: links the cut edges that the surface joins within it.
void CutFace(int signs, int axis, int side, std::array<std::vector<int>, CellEdges>& links)
{
  auto above = [signs](int corner) { return (signs >> corner) & 1; };
  std::vector<int> cut;
  for (int e = 0; e < CellEdges; ++e)
  {
    if (InFace(e, axis, side) && above(EdgeCorner(e)) != above(OtherCorner(e)))
    {
      cut.push_back(e);
    }
  }
  auto link = [&links](int e, int f) {
    links[e].push_back(f);
    links[f].push_back(e);
  };
  if (cut.size() == 2)
  {
    link(cut[0], cut[1]);
  }
  else if (cut.size() == 4)
  {
    // Diagonal corners of the same sign: a segment around each corner at or
    // above the level, so the corners below are joined.
    for (int corner = 0; corner < 8; ++corner)
    {
      if (((corner >> axis) & 1) != side || !above(corner))
      {
        continue;
      }
      std::vector<int> around;
      for (int e : cut)
      {
        if (EdgeCorner(e) == corner || OtherCorner(e) == corner)
        {
          around.push_back(e);
        }
      }
      link(around[0], around[1]);
    }
  }
}

/// Puts the loop in the order whose normal (right-hand rule) points towards
/// the corners below the level.
void Orient(int signs, std::vector<int>& loop)
{
  double normal[3] = { 0, 0, 0 }; // Newell's normal of the polygon through the edges' midpoints
  double towardsBelow[3] = { 0, 0, 0 };
  const std::size_t n = loop.size();
  for (std::size_t v = 0; v < n; ++v)
  {
    double p[2][3];
    for (int q = 0; q < 2; ++q)
    {
      const int e = loop[(v + q) % n];
      for (int a = 0; a < 3; ++a)
      {
        p[q][a] = ((EdgeCorner(e) >> a) & 1) + (a == EdgeAxis(e) ? 0.5 : 0.0);
      }
    }
    for (int a = 0; a < 3; ++a)
    {
      normal[a] += p[0][(a + 1) % 3] * p[1][(a + 2) % 3] - p[0][(a + 2) % 3] * p[1][(a + 1) % 3];
    }
    const int e = loop[v];
    towardsBelow[EdgeAxis(e)] += ((signs >> EdgeCorner(e)) & 1) ? 1.0 : -1.0;
  }
  if (normal[0] * towardsBelow[0] + normal[1] * towardsBelow[1] + normal[2] * towardsBelow[2] < 0.0)
  {
    std::reverse(loop.begin(), loop.end());
  }
}

/// Triangles of one polygon, as a fan from the first vertex whose diagonals
/// all cross the cell's inside: a diagonal lying in a face could be made by
/// the neighbouring cell too, and the surface would not be manifold there.
void Triangulate(const std::vector<int>& loop, CellCase& result)
{
  const int n = static_cast<int>(loop.size());
  for (int apex = 0; apex < n; ++apex)
  {
    bool inside = true;
    for (int m = 2; m < n - 1; ++m)
    {
      inside = inside && !ShareFace(loop[apex], loop[(apex + m) % n]);
    }
    if (!inside)
    {
      continue;
    }
    for (int m = 1; m < n - 1; ++m)
    {
      result.Triangles[result.Count++] = { { static_cast<std::uint8_t>(loop[apex]),
        static_cast<std::uint8_t>(loop[(apex + m) % n]), static_cast<std::uint8_t>(loop[(apex + m + 1) % n]) } };
    }
    return;
  }
}

CellCase BuildCase(int signs)
{
  std::array<std::vector<int>, CellEdges> links;
  for (int axis = 0; axis < 3; ++axis)
  {
    for (int side = 0; side < 2; ++side)
    {
      CutFace(signs, axis, side, links);
    }
  }
  // Each cut edge lies in two faces, one link in each: the links form loops.
  CellCase result;
  std::vector<bool> done(CellEdges, false);
  for (int first = 0; first < CellEdges; ++first)
  {
    if (links[first].empty() || done[first])
    {
      continue;
    }
    std::vector<int> loop;
    int previous = -1;
    for (int e = first; loop.empty() || e != first;)
    {
      loop.push_back(e);
      done[e] = true;
      const int next = links[e][0] == previous ? links[e][1] : links[e][0];
      previous = e;
      e = next;
    }
    Orient(signs, loop);
    Triangulate(loop, result);
  }
  return result;
}
} // namespace

const std::array<CellCase, 256>& MarchingCubesCases()
{
  static const std::array<CellCase, 256> table = [] {
    std::array<CellCase, 256> cases;
    for (int signs = 0; signs < 256; ++signs)
    {
      cases[signs] = BuildCase(signs);
    }
    return cases;
  }();
  return table;
}

const CellCases& MarchingCubesTable()
{
  static const CellCases table = [] {
    CellCases cases{};
    const std::array<CellCase, 256>& source = MarchingCubesCases();
    for (int signs = 0; signs < 256; ++signs)
    {
      cases.Count[signs] = static_cast<std::uint8_t>(source[signs].Count);
      for (int t = 0; t < source[signs].Count; ++t)
      {
        for (int v = 0; v < 3; ++v)
        {
          cases.Edges[signs][3 * t + v] = source[signs].Triangles[t][v];
        }
      }
    }
    return cases;
  }();
  return table;
}

} // namespace nv
