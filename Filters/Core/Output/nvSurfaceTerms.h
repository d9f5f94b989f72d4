// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The surface's terms, written once for the CPU core and the device's
// kernels (NV_HD, as Band/nvPointSort.h): the CPU core's contouring
// (nvSurface.cxx, nvSurfaceField.h) and the surface kernels
// (Device/nvSurfaceKernels.h) both call them, so that the host launcher
// gives the CPU core's vertices, normals and triangles bit for bit
// (TestCoreDevice). What stays with each caller is which brick it works on
// and where its values come from and go: the CPU core reads its bricks from
// a ring of three brick layers, the kernels from the band's arrays.
//
//   ImpliedDistanceOf  psi = sqrt(2) xi atanh(phi), the inverse of eq. (2),
//                      clamped to +-eta/2 (nvSurfaceField.h says why);
//   BandBrickPsi       psi at a band brick's 512 nodes: its band nodes'
//                      from phi, the others +-eta/2 by their side of the
//                      shell (IndexOf, nvBandTerms.h: a brick among the band's);
//   SurfaceWindow      psi on the nodes -1 .. 9 of a brick along each axis
//     FillWindow       (11^3), filled from the 27 bricks around it;
//   MarkAbove          the signs of a brick's cells' corners (a node at 0
//                      counts as above the level);
//   MarkCutEdges       the edges whose two nodes lie on both sides;
//   ForEachCutEdge     a brick's cut edges in order, one vertex each;
//   VertexOn           the vertex on a cut edge (linear interpolation of
//     WindowGradient   psi, 1e-3 h from the nodes) and its normal (central
//                      differences of psi, interpolated likewise, out of
//                      the shell);
//   ForEachCutCell     a brick's cut cells and their marching cubes cases;
//   TrianglesIn        the number of their triangles;
//   CellTriangles      a cut cell's triangles as vertex ids;
//   EdgeCorner,        a cell edge's first corner and axis, and the brick
//     EdgeAxis,        and bit of a cell's edge: a vertex belongs to its
//     CellEdgeBit,     edge, an edge to the brick of its first node, and a
//     CutBefore        brick numbers its vertices in the order of its cut
//                      edges (vertex ids by popcount, Common/nvBits.h).
//
// Still written on each side, each for its own data flow: the list of cut
// bricks (the CPU core's a brick layer at a time from its ring, the
// device's for the whole band at once, CutMarkKernel; the test of a brick
// where psi varies is one, UniformBrick), where a window's bricks are
// read from (RingBricks, BandBricks), the numbering of the vertices (the
// CPU core counts them serially as it goes and keeps each word's count
// before it; the host adds up the kernels' counts, and a kernel counts a
// brick's earlier words again). A brick's coordinates and first node are
// Band's terms (nvBandTerms.h's BrickAt, FirstNodeOf), for both.
//
// On a GPU, nvcc contracts a * b + c into fused multiply-adds: the vertices
// then differ in the last bits, the triangles not, unless a vertex's psi is
// that close to 0.
#ifndef nvSurfaceTerms_h
#define nvSurfaceTerms_h

#include "nvBandTerms.h"
#include "nvBits.h"
#include "nvHostDevice.h"
#include "nvTruncatedDistance.h"

#include <cmath>
#include <cstdint>

namespace nv
{

constexpr int WindowSize = BrickSize + 3;      ///< nodes -1 .. 9 of a brick along each axis
constexpr int CornerSize = BrickSize + 1;      ///< the corners of a brick's cells along an axis, 0 .. 8
constexpr int CornerRows = CornerSize * CornerSize; ///< rows of corners of a brick: 81
constexpr int EdgeWords = 3 * BrickNodes / 64; ///< bit 512 axis + n: the edge from node n along the axis
constexpr int CellEdges = 12;
/// No vertex closer to a node than this fraction of h. A node on the level
/// itself (phi = 0 there, or so close that the vertex rounds onto it) would
/// put the vertices of all its cut edges on one point, and give zero-area
/// triangles. Three points inside three different edges of a cube are never
/// on one line, so every triangle then has an area.
constexpr double VertexMargin = 1e-3;

/// Whether a band brick has one value of psi: none of its nodes in the
/// band ([redBegin, redEnd) and [blackBegin, blackEnd) empty) and all of
/// them on one side of the shell (its 8 words of inside bits all ones,
/// `inside`, or all zeros). The CPU core's layers skip such a brick
/// (BandField, UniformBandBrick) and the device's cut bricks leave it out
/// (CutMarkKernel).
NV_HD inline bool UniformBrick(const std::uint64_t* words, std::int64_t redBegin, std::int64_t redEnd,
  std::int64_t blackBegin, std::int64_t blackEnd, bool& inside)
{
  bool all = true, none = true;
  for (int w = 0; w < 8; ++w)
  {
    all = all && words[w] == ~std::uint64_t(0);
    none = none && words[w] == 0;
  }
  inside = all;
  const bool banded = redEnd > redBegin || blackEnd > blackBegin;
  return !banded && (all || none);
}

/// psi of phi, clamped to [-cap, cap] (cap = eta/2); its sign is phi's.
/// scale = sqrt(2) xi; atanh(phi) = log((1 + phi) / (1 - phi)) / 2, the
/// faster form.
NV_HD inline float ImpliedDistanceOf(double phi, double scale, double cap)
{
  const double psi = ::fabs(phi) < 1.0 ? 0.5 * scale * ::log((1.0 + phi) / (1.0 - phi)) : ::copysign(cap, phi);
  const double low = -cap < psi ? psi : -cap;       // std::max(-cap, psi)
  return static_cast<float>(low < cap ? low : cap); // std::min(cap, low)
}

/**
 * psi at the nodes of band brick a (index i + 8 (j + 8 k)): off the band
 * their side of the shell (bit n of inside[]: +cap inside, -cap outside),
 * the band nodes s of [redBegin, redEnd) and [blackBegin, blackEnd) at
 * their place offset[s] from phi[s].
 */
NV_HD inline void BandBrickPsi(const std::uint64_t* inside, std::int64_t redBegin, std::int64_t redEnd,
  std::int64_t blackBegin, std::int64_t blackEnd, const std::uint16_t* offset, const double* phi, double scale,
  double cap, float* values)
{
  const float in = static_cast<float>(cap), out = static_cast<float>(-cap);
  for (int n = 0; n < BrickNodes; ++n)
  {
    values[n] = ((inside[n / 64] >> (n % 64)) & 1) ? in : out;
  }
  for (std::int64_t s = redBegin; s < redEnd; ++s)
  {
    values[offset[s]] = ImpliedDistanceOf(phi[s], scale, cap);
  }
  for (std::int64_t s = blackBegin; s < blackEnd; ++s)
  {
    values[offset[s]] = ImpliedDistanceOf(phi[s], scale, cap);
  }
}

/// The field on the nodes -1 .. 9 of a brick along each axis: its own, the
/// far corners of its cells (node 8), and one more on each side for the
/// central differences.
struct SurfaceWindow
{
  float Values[WindowSize * WindowSize * WindowSize];
  NV_HD float& At(int i, int j, int k) { return this->Values[(i + 1) + WindowSize * ((j + 1) + WindowSize * (k + 1))]; }
  NV_HD float At(int i, int j, int k) const
  {
    return this->Values[(i + 1) + WindowSize * ((j + 1) + WindowSize * (k + 1))];
  }
};

/**
 * Fills the window of a brick from the 27 bricks around it. bricks(ox, oy,
 * oz, uniform), 0 <= o < 3 for the brick before, the brick itself and the
 * brick after along each axis: that brick's BrickNodes values, or null and
 * its one value in `uniform` (any value for a brick beyond the grid: its
 * nodes are never read).
 */
template <typename Bricks>
NV_HD void FillWindow(SurfaceWindow& window, const Bricks& bricks)
{
  // Along each axis, the part of the window that the brick before, the
  // brick itself and the brick after provide: {first window node, first
  // node in that brick, count}.
  const int parts[3][3] = { { -1, BrickSize - 1, 1 }, { 0, 0, BrickSize }, { BrickSize, 0, 2 } };
  for (int oz = 0; oz < 3; ++oz)
  {
    for (int oy = 0; oy < 3; ++oy)
    {
      for (int ox = 0; ox < 3; ++ox)
      {
        float uniform = 0.0f;
        const float* values = bricks(ox, oy, oz, uniform);
        for (int k = 0; k < parts[oz][2]; ++k)
        {
          for (int j = 0; j < parts[oy][2]; ++j)
          {
            float* row = &window.At(parts[ox][0], parts[oy][0] + j, parts[oz][0] + k);
            const float* source = values ? values + parts[ox][1] +
                BrickSize * ((parts[oy][1] + j) + BrickSize * (parts[oz][1] + k))
                                         : nullptr;
            // Rows of 1, 8 or 2 values; a constant count for the 8 lets the
            // compiler copy them inline rather than call memmove.
            if (ox == 1)
            {
              for (int i = 0; i < BrickSize; ++i)
              {
                row[i] = source ? source[i] : uniform;
              }
            }
            else
            {
              for (int i = 0; i < parts[ox][2]; ++i)
              {
                row[i] = source ? source[i] : uniform;
              }
            }
          }
        }
      }
    }
  }
}

/// Bit i of row j + 9 k of `above` (CornerRows rows): the brick's node (i,
/// j, k), 0 <= i, j, k <= 8, is at or above the level. Cut edges and cells'
/// cases are read from these bits.
NV_HD inline void MarkAbove(const SurfaceWindow& window, std::uint16_t* above)
{
  for (int k = 0; k < CornerSize; ++k)
  {
    for (int j = 0; j < CornerSize; ++j)
    {
      unsigned row = 0;
      for (int i = 0; i < CornerSize; ++i)
      {
        row |= static_cast<unsigned>(window.At(i, j, k) >= 0.0f) << i;
      }
      above[j + CornerSize * k] = static_cast<std::uint16_t>(row);
    }
  }
}

/// Per axis, the nodes of the brick whose first node is `first` that are on
/// the grid, and the edges from them.
NV_HD inline void BrickNodesOnGrid(const std::int64_t gridDims[3], const std::int64_t first[3], int nodes[3], int edges[3])
{
  for (int a = 0; a < 3; ++a)
  {
    const std::int64_t left = gridDims[a] - first[a];
    nodes[a] = static_cast<int>(left < BrickSize ? left : BrickSize);            // std::min(BrickSize, left)
    edges[a] = static_cast<int>(left - 1 < BrickSize ? left - 1 : BrickSize); // std::min(BrickSize, left - 1)
  }
}

/// Marks a brick's cut edges in cut[EdgeWords] (those of its first node
/// plane along x and y only, if planeOnly): the edges whose two nodes lie
/// on both sides. nodes, edges: BrickNodesOnGrid's.
NV_HD inline void MarkCutEdges(
  const std::uint16_t* above, const int nodes[3], const int edges[3], bool planeOnly, std::uint64_t* cut)
{
  for (int w = 0; w < EdgeWords; ++w)
  {
    cut[w] = 0;
  }
  const unsigned present = (1u << nodes[0]) - 1u;
  for (int k = 0; k < (planeOnly ? 1 : nodes[2]); ++k)
  {
    for (int j = 0; j < nodes[1]; ++j)
    {
      const unsigned row = above[j + CornerSize * k];
      const unsigned along[3] = { (row ^ (row >> 1)) & ((1u << edges[0]) - 1u),
        j < edges[1] ? (row ^ above[j + 1 + CornerSize * k]) & present : 0u,
        k < edges[2] && !planeOnly ? (row ^ above[j + CornerSize * (k + 1)]) & present : 0u };
      const int byte = j + BrickSize * k; // the row's 8 nodes are bits 8 byte .. 8 byte + 7 of an axis
      for (int axis = 0; axis < (planeOnly ? 2 : 3); ++axis)
      {
        cut[axis * (BrickNodes / 64) + byte / 8] |= std::uint64_t(along[axis]) << (8 * (byte % 8));
      }
    }
  }
}

/// Visits a brick's cut edges in order: fn(bit), bit 512 axis + n.
template <typename Fn>
NV_HD void ForEachCutEdge(const std::uint64_t* cut, Fn& fn)
{
  for (int w = 0; w < EdgeWords; ++w)
  {
    for (std::uint64_t bits = cut[w]; bits; bits &= bits - 1)
    {
      fn(64 * w + Popcount((bits & (~bits + 1)) - 1)); // the lowest set bit
    }
  }
}

/// The gradient of the field at window node `local`, grid node g: central
/// differences, one-sided on the grid's faces (h: spacing).
NV_HD inline void WindowGradient(const SurfaceWindow& window, const int local[3], const std::int64_t g[3],
  const std::int64_t gridDims[3], double spacing, double gradient[3])
{
  for (int a = 0; a < 3; ++a)
  {
    const int before = g[a] > 0 ? -1 : 0;
    const int after = g[a] < gridDims[a] - 1 ? 1 : 0;
    int p[3] = { local[0], local[1], local[2] }, q[3] = { local[0], local[1], local[2] };
    p[a] += after;
    q[a] += before;
    gradient[a] = after == before
      ? 0.0
      : (static_cast<double>(window.At(p[0], p[1], p[2])) - window.At(q[0], q[1], q[2])) / ((after - before) * spacing);
  }
}

/// The vertex on cut edge `bit` of a brick whose first node is `first`:
/// its world coordinates xyz and unit normal (down the field: out of the
/// shell).
NV_HD inline void VertexOn(const SurfaceWindow& window, const std::int64_t first[3], int bit,
  const std::int64_t gridDims[3], const double origin[3], double spacing, double xyz[3], float normal[3])
{
  const int node = bit % BrickNodes, axis = bit / BrickNodes;
  int p0[3] = { node & (BrickSize - 1), (node >> BrickShift) & (BrickSize - 1), node >> (2 * BrickShift) };
  int p1[3] = { p0[0], p0[1], p0[2] };
  ++p1[axis];
  std::int64_t g0[3], g1[3];
  for (int a = 0; a < 3; ++a)
  {
    g0[a] = first[a] + p0[a];
    g1[a] = first[a] + p1[a];
  }
  const double v0 = window.At(p0[0], p0[1], p0[2]), v1 = window.At(p1[0], p1[1], p1[2]);
  // Linear interpolation to the level 0 (v0 and v1 have opposite signs),
  // kept VertexMargin h from the nodes:
  // t = std::min(1 - margin, std::max(margin, v0 / (v0 - v1))).
  const double ratio = v0 / (v0 - v1);
  const double low = VertexMargin < ratio ? ratio : VertexMargin;
  const double t = low < 1.0 - VertexMargin ? low : 1.0 - VertexMargin;
  double d0[3], d1[3], n[3];
  WindowGradient(window, p0, g0, gridDims, spacing, d0);
  WindowGradient(window, p1, g1, gridDims, spacing, d1);
  for (int a = 0; a < 3; ++a)
  {
    xyz[a] = origin[a] + spacing * (static_cast<double>(g0[a]) + (a == axis ? t : 0.0));
    n[a] = d0[a] + t * (d1[a] - d0[a]);
  }
  const double length = ::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (int a = 0; a < 3; ++a)
  {
    normal[a] = length > 0.0 ? static_cast<float>(-n[a] / length) : 0.0f;
  }
}

/// Corner c of a cell is at offset (c & 1, (c >> 1) & 1, (c >> 2) & 1)
/// from the cell's first node. Edge e runs from corner EdgeCorner(e) along
/// axis EdgeAxis(e) = e / 4.
NV_HD inline int EdgeAxis(int edge)
{
  return edge / 4;
}
NV_HD inline int EdgeCorner(int edge)
{
  // The edges along an axis start at the four corners whose bit for that axis is 0.
  const int axis = EdgeAxis(edge), m = edge % 4;
  return (m & ((1 << axis) - 1)) | ((m >> axis) << (axis + 1));
}

/// The marching cubes case table as plain bytes (nvMarchingCubes.h's
/// MarchingCubesTable): for each of the 256 sign patterns of a cell's
/// corners (bit c: corner c at or above the level), Count triangles of
/// three cell edges each.
struct CellCases
{
  std::uint8_t Count[256];
  std::uint8_t Edges[256][15];
};

/// Visits the cut cells of a brick whose first node is `first`, from its
/// corner rows `above` (MarkAbove's): fn(i, j, k, signs), signs the cell's
/// case.
template <typename Fn>
NV_HD void ForEachCutCell(const std::int64_t gridDims[3], const std::int64_t first[3], const std::uint16_t* above,
  const CellCases& cases, Fn& fn)
{
  for (int k = 0; k < BrickSize && first[2] + k + 1 < gridDims[2]; ++k)
  {
    for (int j = 0; j < BrickSize && first[1] + j + 1 < gridDims[1]; ++j)
    {
      // The four rows of corners of a row of cells; corner c = x + 2 y + 4 z.
      const unsigned r00 = above[j + CornerSize * k];
      const unsigned r10 = above[j + 1 + CornerSize * k];
      const unsigned r01 = above[j + CornerSize * (k + 1)];
      const unsigned r11 = above[j + 1 + CornerSize * (k + 1)];
      if (r00 == r10 && r00 == r01 && r00 == r11 && (r00 == 0u || r00 == (1u << CornerSize) - 1u))
      {
        continue; // all corners on one side
      }
      for (int i = 0; i < BrickSize && first[0] + i + 1 < gridDims[0]; ++i)
      {
        const int signs = static_cast<int>(
          ((r00 >> i) & 3u) | (((r10 >> i) & 3u) << 2) | (((r01 >> i) & 3u) << 4) | (((r11 >> i) & 3u) << 6));
        if (cases.Count[signs] > 0)
        {
          fn(i, j, k, signs);
        }
      }
    }
  }
}

/// The number of triangles of a brick's cut cells (ForEachCutCell's arguments).
struct TriangleCounter
{
  const CellCases* Cases;
  std::int32_t Triangles;
  NV_HD void operator()(int, int, int, int signs) { this->Triangles += this->Cases->Count[signs]; }
};
NV_HD inline std::int32_t TrianglesIn(
  const std::int64_t gridDims[3], const std::int64_t first[3], const std::uint16_t* above, const CellCases& cases)
{
  TriangleCounter counter{ &cases, 0 };
  ForEachCutCell(gridDims, first, above, cases, counter);
  return counter.Triangles;
}

/// Edge `edge` of cell (i, j, k) of a brick: the brick its vertex belongs
/// to (that of the edge's first node), as steps of 0 or 1 from this one
/// along each axis, and the edge's bit there.
NV_HD inline int CellEdgeBit(int i, int j, int k, int edge, int step[3])
{
  const int corner = EdgeCorner(edge);
  const int node[3] = { i + (corner & 1), j + ((corner >> 1) & 1), k + ((corner >> 2) & 1) };
  for (int a = 0; a < 3; ++a)
  {
    step[a] = node[a] >> BrickShift;
  }
  return BrickNodes * EdgeAxis(edge) + (node[0] & (BrickSize - 1)) +
    BrickSize * ((node[1] & (BrickSize - 1)) + BrickSize * (node[2] & (BrickSize - 1)));
}

/// The cut edges of a brick before edge `bit` in its word: added to the
/// brick's first id and the cut edges of its earlier words, the id of the
/// edge's vertex.
NV_HD inline int CutBefore(const std::uint64_t* cut, int bit)
{
  return Popcount(cut[bit / 64] & ((std::uint64_t(1) << (bit % 64)) - 1));
}

/**
 * The triangles of a cut cell of case `signs` to out (3 ids each), from
 * idOf(edge), the id of the vertex on a cell edge, asked once an edge.
 * Returns the end of what it wrote.
 */
template <typename IdOf>
NV_HD long long* CellTriangles(const CellCases& cases, int signs, IdOf& idOf, long long* out)
{
  long long id[CellEdges];
  int known = 0; // the edges whose id is in id[]
  for (int t = 0; t < cases.Count[signs]; ++t)
  {
    for (int v = 0; v < 3; ++v)
    {
      const int e = cases.Edges[signs][3 * t + v];
      if (!((known >> e) & 1))
      {
        id[e] = idOf(e);
        known |= 1 << e;
      }
      *out++ = id[e];
    }
  }
  return out;
}

} // namespace nv

#endif
