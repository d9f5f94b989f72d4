// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// Surfaces in the filter's tests: vertices by the grid edge they lie on (to
// compare two contourings of one grid), and the checks a printable mesh
// passes (closed, manifold, no zero-area triangle).
#ifndef nvTestSurfaces_h
#define nvTestSurfaces_h

#include "nvTestUtilities.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkFeatureEdges.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <array>
#include <cmath>
#include <map>

namespace nvtest
{

using EdgeKey = std::array<long long, 4>; ///< i, j, k of the edge's first node, axis
using NodeKey = std::array<long long, 3>;

/// Where a vertex sits on its grid edge, and its normal.
struct EdgeVertex
{
  double T = 0.0; ///< fraction of h along the edge
  double Normal[3] = { 0.0, 0.0, 0.0 };
};

/// The vertices of a surface by the grid edge they lie on; a vertex within
/// 1e-4 h of a node cannot tell its edge, and counts at that node.
struct SurfaceVertices
{
  std::map<EdgeKey, EdgeVertex> Edges;
  std::map<NodeKey, int> AtNodes;
  int Stray = 0; ///< vertices off the grid's edges
};

inline SurfaceVertices VerticesByEdge(vtkPolyData* surface, const double origin[3], double h)
{
  SurfaceVertices result;
  vtkDataArray* normals = surface->GetPointData()->GetNormals();
  for (vtkIdType p = 0; p < surface->GetNumberOfPoints(); ++p)
  {
    double x[3], u[3], off[3];
    surface->GetPoint(p, x);
    int axis = 0, fractional = 0;
    for (int a = 0; a < 3; ++a)
    {
      u[a] = (x[a] - origin[a]) / h;
      off[a] = std::fabs(u[a] - std::round(u[a]));
      axis = off[a] > off[axis] ? a : axis;
      fractional += off[a] > 1e-4;
    }
    if (fractional == 0)
    {
      ++result.AtNodes[NodeKey{ { std::llround(u[0]), std::llround(u[1]), std::llround(u[2]) } }];
      continue;
    }
    result.Stray += fractional > 1;
    EdgeKey key;
    for (int a = 0; a < 3; ++a)
    {
      key[a] = a == axis ? static_cast<long long>(std::floor(u[a])) : std::llround(u[a]);
    }
    key[3] = axis;
    EdgeVertex& vertex = result.Edges[key];
    vertex.T = u[axis] - std::floor(u[axis]);
    for (int a = 0; a < 3 && normals; ++a)
    {
      vertex.Normal[a] = normals->GetComponent(p, a);
    }
  }
  return result;
}

/**
 * Whether surface a has its vertices on the cut edges of reference b, the
 * vertices of b first moved at least `margin` h away from the nodes; then the
 * largest difference of position (in h) and of normal (b's vertices at a node
 * have no edge to compare along, and are matched by count).
 */
inline bool SameEdges(const SurfaceVertices& a, SurfaceVertices b, double& shift, double& turn, double margin = 0.0)
{
  shift = turn = 0.0;
  std::size_t matched = 0;
  for (const auto& edge : a.Edges)
  {
    const auto other = b.Edges.find(edge.first);
    if (other != b.Edges.end())
    {
      ++matched;
      const double t = std::min(1.0 - margin, std::max(margin, other->second.T));
      shift = std::max(shift, std::fabs(edge.second.T - t));
      for (int c = 0; c < 3; ++c)
      {
        turn = std::max(turn, std::fabs(edge.second.Normal[c] - other->second.Normal[c]));
      }
      continue;
    }
    // A vertex of b at the edge's first or last node, moved off it by the margin.
    const bool first = std::fabs(edge.second.T - margin) < 1e-6, last = std::fabs(edge.second.T - 1.0 + margin) < 1e-6;
    NodeKey node{ { edge.first[0], edge.first[1], edge.first[2] } };
    node[edge.first[3]] += last ? 1 : 0;
    auto at = b.AtNodes.find(node);
    if (!(first || last) || at == b.AtNodes.end() || at->second == 0)
    {
      return false;
    }
    --at->second;
  }
  for (const auto& node : b.AtNodes)
  {
    if (node.second != 0)
    {
      return false;
    }
  }
  return matched == b.Edges.size();
}

inline vtkIdType BadEdges(vtkPolyData* surface, bool boundary, bool nonManifold)
{
  vtkNew<vtkFeatureEdges> edges;
  edges->SetInputData(surface);
  edges->SetBoundaryEdges(boundary);
  edges->SetNonManifoldEdges(nonManifold);
  edges->FeatureEdgesOff();
  edges->ManifoldEdgesOff();
  edges->Update();
  return edges->GetOutput()->GetNumberOfCells();
}

/// Triangles of zero area, with the points in double precision and rounded
/// to float (as an STL file holds them).
inline vtkIdType ZeroAreaTriangles(vtkPolyData* surface, bool asFloat)
{
  vtkIdType count = 0;
  vtkIdType n;
  const vtkIdType* ids;
  vtkCellArray* polys = surface->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    double x[3][3];
    for (int v = 0; v < 3; ++v)
    {
      surface->GetPoint(ids[v], x[v]);
      for (int a = 0; a < 3 && asFloat; ++a)
      {
        x[v][a] = static_cast<float>(x[v][a]);
      }
    }
    double e[2][3], c[3];
    for (int a = 0; a < 3; ++a)
    {
      e[0][a] = x[1][a] - x[0][a];
      e[1][a] = x[2][a] - x[0][a];
    }
    for (int a = 0; a < 3; ++a)
    {
      c[a] = e[0][(a + 1) % 3] * e[1][(a + 2) % 3] - e[0][(a + 2) % 3] * e[1][(a + 1) % 3];
    }
    count += c[0] == 0.0 && c[1] == 0.0 && c[2] == 0.0;
  }
  return count;
}

/// Triangles whose winding (right-hand rule) disagrees with their vertices' normals.
inline vtkIdType MisorientedTriangles(vtkPolyData* surface)
{
  vtkDataArray* normals = surface->GetPointData()->GetNormals();
  vtkIdType count = 0;
  vtkIdType n;
  const vtkIdType* ids;
  vtkCellArray* polys = surface->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    double x[3][3], sum[3] = { 0, 0, 0 };
    for (int v = 0; v < 3; ++v)
    {
      surface->GetPoint(ids[v], x[v]);
      for (int a = 0; a < 3; ++a)
      {
        sum[a] += normals->GetComponent(ids[v], a);
      }
    }
    double c = 0.0;
    for (int a = 0; a < 3; ++a)
    {
      const int b = (a + 1) % 3, d = (a + 2) % 3;
      c += sum[a] * ((x[1][b] - x[0][b]) * (x[2][d] - x[0][d]) - (x[1][d] - x[0][d]) * (x[2][b] - x[0][b]));
    }
    count += c <= 0.0;
  }
  return count;
}

} // namespace nvtest

#endif
