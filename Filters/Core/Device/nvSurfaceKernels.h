// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The device back end's surface kernels: the phi = 0 surface of the band
// (step 7), one source for the host and the GPU, as nvDeviceKernels.h.
//
// The CPU core makes the surface brick layer by brick layer
// (Output/nvSurface.cxx, from the implied distance of nvSurfaceField.h);
// these kernels do the same work brick by brick over the band's arrays,
// written the same way term for term, so that the host launcher gives the
// CPU core's vertices, normals and triangles bit for bit (TestCoreDevice):
//
//   PsiKernel         a band brick: the implied distance
//                       psi = sqrt(2) xi atanh(phi)   (the inverse of eq. 2)
//                     at its 512 nodes, clamped to +-eta/2, the band's
//                     nodes from phi and the others +-eta/2 by their side
//                     of the shell (NarrowBand::Inside), as BandField;
//   CutCellsKernel    a cut brick (a brick where psi changes sign, or just
//                     below one): the signs of its cells' corners, its cut
//                     edges (one vertex each) and its cut cells' triangles,
//                     counted;
//   VerticesKernel    a cut brick: its vertices (linear interpolation of psi
//                     along the cut edge, 1e-3 h away from the nodes) and
//                     their normals (central differences of psi,
//                     interpolated likewise, out of the shell), from its
//                     first vertex id on;
//   TrianglesKernel   a cut brick: its cut cells' triangles (the marching
//                     cubes case table, Output/nvMarchingCubes.h), as vertex
//                     ids: a vertex belongs to its edge, an edge to the brick
//                     of its first node, and a brick numbers its vertices in
//                     the order of its cut edges.
//
// Between the counts and the geometry the host adds up the counts (the
// first vertex and triangle of each cut brick, in brick order); it also
// lists the cut bricks (the bricks where psi varies and those just below
// them, sorted) before the kernels run. Both are compactions of a few bytes
// a brick; the per-node and per-cell work is in the kernels.
//
// The CUDA launcher runs them a brick a thread (the kernels' call operators
// take a brick); CutCellsKernel and VerticesKernel each hold the brick's
// window of psi (11^3 floats, 5.3 KB) in the thread's local memory. Simple,
// and not tuned: a block a brick with the window in shared memory is the
// next step once the GPU's timings are measured.
//
// Vertex ids and the triangles' order are those of the CPU core: bricks in
// ascending index, which is its layer by layer order. On a GPU, nvcc
// contracts a * b + c into fused multiply-adds: the vertices then differ in
// the last bits (and psi's logarithm may differ by an ulp), the triangles
// not, unless a vertex's psi is that close to 0.
#ifndef nvSurfaceKernels_h
#define nvSurfaceKernels_h

#include "nvDeviceKernels.h"

#include <cstdint>

namespace nv
{
namespace device
{

/// Set bits of x (the portable form of nvTruncatedDistance.h's Popcount on
/// the host, the GPU's instruction on the device: the same count).
NV_HD inline int PopCount(std::uint64_t x)
{
#if defined(__CUDA_ARCH__)
  return __popcll(x);
#else
  x = x - ((x >> 1) & 0x5555555555555555ULL);
  x = (x & 0x3333333333333333ULL) + ((x >> 2) & 0x3333333333333333ULL);
  x = (x + (x >> 4)) & 0x0F0F0F0F0F0F0F0FULL;
  return static_cast<int>((x * 0x0101010101010101ULL) >> 56);
#endif
}

/// The marching cubes case table as plain bytes, both sides: for each of the
/// 256 sign patterns of a cell's corners (bit c: corner c at or above the
/// level), Count triangles of three cell edges each. Filled on the host from
/// MarchingCubesCases() (Output/nvDeviceSurface.cxx).
struct CellCases
{
  std::uint8_t Count[256];
  std::uint8_t Edges[256][15];
};

/// Corner c of a cell is at (c & 1, (c >> 1) & 1, (c >> 2) & 1); edge e runs
/// from corner EdgeCornerOf(e) along axis e / 4 (nvMarchingCubes.cxx's EdgeCorner).
NV_HD inline int EdgeCornerOf(int edge)
{
  const int axis = edge / 4, m = edge % 4;
  return (m & ((1 << axis) - 1)) | ((m >> axis) << (axis + 1));
}

/// The grid and psi's constants, computed once on the host.
struct ContourConstants
{
  std::int64_t GridDims[3] = { 0, 0, 0 };
  std::int64_t BrickDims[3] = { 0, 0, 0 };
  double Origin[3] = { 0.0, 0.0, 0.0 };
  double Spacing = 0.0; ///< h
  double Scale = 0.0;   ///< sqrt(2) xi (ImpliedDistance's)
  double Cap = 0.0;     ///< eta/2: psi's clamp, and its value off the band
};

/**
 * The band and the surface as both sides hold them. Precision, array by
 * array:
 *
 * - Bricks, RedStart, BlackStart, Offset, Inside: the band's own arrays
 *   (nvNarrowBand.h), unchanged: int64, int64, int64, uint16, uint64.
 * - Phi: double, the band's phi (L + 2 values), as the evolution leaves it.
 * - Psi: float, 512 a band brick: the implied distance at its nodes. Float
 *   as the CPU core's surface field (BrickField): psi serves the signs, the
 *   interpolation along an edge and the normals, for which float's 24 bits
 *   (6e-8 of eta/2) are plenty, and it halves the window each thread reads.
 * - CutBricks: int64, ascending grid brick indices (the host's list).
 * - Cut: uint64, 24 words a cut brick: bit 512 axis + n is the edge from
 *   node n along the axis, cut by the level.
 * - Above: uint16, 81 rows a cut brick: bit i of row j + 9 k is whether psi
 *   >= 0 at node (i, j, k) of the brick, 0 <= i, j, k <= 8.
 * - VertexCount, TriangleCount: int32, a cut brick (at most 3 512 and 5 512).
 * - FirstVertex, FirstTriangle: int64, a cut brick (the host's sums).
 * - Points: double, 3 a vertex, world coordinates (as the surface sink's).
 * - Normals: float, 3 a vertex, unit (as the sink's).
 * - Triangles: long long (VertexId), 3 a triangle.
 */
struct ContourArrays
{
  std::int64_t NumberOfBricks = 0;
  const std::int64_t* Bricks = nullptr;
  const std::int64_t* RedStart = nullptr;
  const std::int64_t* BlackStart = nullptr;
  const std::uint16_t* Offset = nullptr;
  const std::uint64_t* Inside = nullptr;
  const double* Phi = nullptr;
  float* Psi = nullptr;
  std::int64_t NumberOfCutBricks = 0;
  const std::int64_t* CutBricks = nullptr;
  std::uint64_t* Cut = nullptr;
  std::uint16_t* Above = nullptr;
  std::int32_t* VertexCount = nullptr;
  std::int32_t* TriangleCount = nullptr;
  const std::int64_t* FirstVertex = nullptr;
  const std::int64_t* FirstTriangle = nullptr;
  double* Points = nullptr;
  float* Normals = nullptr;
  long long* Triangles = nullptr;
  const CellCases* Cases = nullptr;
};

constexpr int CutWords = 24;  ///< 3 axes x 512 edges / 64 bits
constexpr int AboveRows = 81; ///< 9 x 9 rows of 9 corners
constexpr int WindowSide = 11; ///< nodes -1 .. 9 of a brick along an axis
/// No vertex closer to a node than this fraction of h (nvSurface.cxx's Margin).
constexpr double VertexMargin = 1e-3;

/// psi of phi, clamped to [-eta/2, eta/2] (ImpliedDistance::operator(),
/// written the same way): psi = sqrt(2) xi atanh(phi), atanh(phi) =
/// log((1 + phi) / (1 - phi)) / 2, the inverse of eq. (2).
NV_HD inline float ImpliedDistanceOf(double phi, double scale, double cap)
{
  const double psi = ::fabs(phi) < 1.0 ? 0.5 * scale * ::log((1.0 + phi) / (1.0 - phi)) : ::copysign(cap, phi);
  const double low = -cap < psi ? psi : -cap;   // std::max(-cap, psi)
  return static_cast<float>(low < cap ? low : cap); // std::min(cap, low)
}

/// The index of `brick` in the ascending `sorted` (n values), or -1.
NV_HD inline std::int64_t FindBrick(const std::int64_t* sorted, std::int64_t n, std::int64_t brick)
{
  std::int64_t lo = 0, hi = n;
  while (lo < hi)
  {
    const std::int64_t mid = lo + (hi - lo) / 2;
    if (sorted[mid] < brick)
    {
      lo = mid + 1;
    }
    else
    {
      hi = mid;
    }
  }
  return lo < n && sorted[lo] == brick ? lo : -1;
}

/// psi at the band brick a's nodes (index i + 8 (j + 8 k)), as BandField::Values.
struct PsiKernel
{
  ContourArrays A;
  ContourConstants C;
  NV_HD void operator()(std::int64_t a) const
  {
    float* values = A.Psi + 512 * a;
    const std::uint64_t* inside = A.Inside + 8 * a;
    const float in = static_cast<float>(C.Cap), out = static_cast<float>(-C.Cap);
    for (int n = 0; n < 512; ++n) // nodes off the band: their side of the shell
    {
      values[n] = ((inside[n / 64] >> (n % 64)) & 1) ? in : out;
    }
    for (std::int64_t s = A.RedStart[a]; s < A.RedStart[a + 1]; ++s) // band nodes: each at its place
    {
      values[A.Offset[s]] = ImpliedDistanceOf(A.Phi[s], C.Scale, C.Cap);
    }
    for (std::int64_t s = A.BlackStart[a]; s < A.BlackStart[a + 1]; ++s)
    {
      values[A.Offset[s]] = ImpliedDistanceOf(A.Phi[s], C.Scale, C.Cap);
    }
  }
};

/// psi on the nodes -1 .. 9 of a brick along each axis (nvSurface.cxx's
/// Window): the brick's own nodes, the far corners of its cells (node 8)
/// and one more on each side for the central differences.
struct ContourWindow
{
  float Values[WindowSide * WindowSide * WindowSide];
  NV_HD float& At(int i, int j, int k) { return Values[(i + 1) + WindowSide * ((j + 1) + WindowSide * (k + 1))]; }
  NV_HD float At(int i, int j, int k) const
  {
    return Values[(i + 1) + WindowSide * ((j + 1) + WindowSide * (k + 1))];
  }
};

/// The brick's coordinates (bx, by, bz) in bricks.
NV_HD inline void BrickCoordinatesOf(const ContourConstants& c, std::int64_t brick, std::int64_t b[3])
{
  b[0] = brick % c.BrickDims[0];
  b[1] = (brick / c.BrickDims[0]) % c.BrickDims[1];
  b[2] = brick / (c.BrickDims[0] * c.BrickDims[1]);
}

/// Fills the window of `brick` from the 27 bricks around it (nvSurface.cxx's
/// FillWindow): a band brick's psi, -eta/2 on a brick no point reaches
/// (outside the shell), and 0 beyond the grid (never read there).
NV_HD inline void FillContourWindow(const ContourArrays& A, const ContourConstants& C, std::int64_t brick,
  ContourWindow& window)
{
  // Along each axis, the part of the window that the brick before, the
  // brick itself and the brick after provide: {first window node, first
  // node in that brick, count}.
  const int parts[3][3] = { { -1, 7, 1 }, { 0, 0, 8 }, { 8, 0, 2 } };
  std::int64_t b[3];
  BrickCoordinatesOf(C, brick, b);
  for (int oz = 0; oz < 3; ++oz)
  {
    for (int oy = 0; oy < 3; ++oy)
    {
      for (int ox = 0; ox < 3; ++ox)
      {
        const std::int64_t x = b[0] + ox - 1, y = b[1] + oy - 1, z = b[2] + oz - 1;
        const bool inGrid =
          x >= 0 && x < C.BrickDims[0] && y >= 0 && y < C.BrickDims[1] && z >= 0 && z < C.BrickDims[2];
        const std::int64_t a =
          inGrid ? FindBrick(A.Bricks, A.NumberOfBricks, x + C.BrickDims[0] * (y + C.BrickDims[1] * z)) : -1;
        const float uniform = inGrid ? static_cast<float>(-C.Cap) : 0.0f;
        for (int k = 0; k < parts[oz][2]; ++k)
        {
          for (int j = 0; j < parts[oy][2]; ++j)
          {
            float* row = &window.At(parts[ox][0], parts[oy][0] + j, parts[oz][0] + k);
            const float* source = a < 0 ? nullptr
                                        : A.Psi + 512 * a + parts[ox][1] +
                                          8 * ((parts[oy][1] + j) + 8 * (parts[oz][1] + k));
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

/// Visits the cut cells of a cut brick whose first node is `first`, from its
/// corner rows (nvSurface.cxx's ForEachCutCell): fn(i, j, k, case).
template <typename Fn>
NV_HD void ForEachCutCellOf(
  const ContourConstants& C, const CellCases& cases, const std::uint16_t* above, const std::int64_t first[3], Fn& fn)
{
  for (int k = 0; k < 8 && first[2] + k + 1 < C.GridDims[2]; ++k)
  {
    for (int j = 0; j < 8 && first[1] + j + 1 < C.GridDims[1]; ++j)
    {
      // The four rows of corners of a row of cells; corner c = x + 2 y + 4 z.
      const unsigned r00 = above[j + 9 * k];
      const unsigned r10 = above[j + 1 + 9 * k];
      const unsigned r01 = above[j + 9 * (k + 1)];
      const unsigned r11 = above[j + 1 + 9 * (k + 1)];
      if (r00 == r10 && r00 == r01 && r00 == r11 && (r00 == 0u || r00 == (1u << 9) - 1u))
      {
        continue; // all corners on one side
      }
      for (int i = 0; i < 8 && first[0] + i + 1 < C.GridDims[0]; ++i)
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

/// The first node of a brick.
NV_HD inline void FirstNodeOf(const ContourConstants& c, std::int64_t brick, std::int64_t first[3])
{
  BrickCoordinatesOf(c, brick, first);
  for (int a = 0; a < 3; ++a)
  {
    first[a] *= 8;
  }
}

/// Cut brick r: the signs of its corners (Above), its cut edges (Cut) and
/// the counts of its vertices and triangles (nvSurface.cxx's MarkAbove,
/// MarkCutEdges and the count of MakeTriangles).
struct CutCellsKernel
{
  ContourArrays A;
  ContourConstants C;
  NV_HD void operator()(std::int64_t r) const
  {
    ContourWindow window;
    const std::int64_t brick = A.CutBricks[r];
    FillContourWindow(A, C, brick, window);
    std::uint16_t* above = A.Above + AboveRows * r;
    for (int k = 0; k < 9; ++k) // a node at 0 counts as above the level
    {
      for (int j = 0; j < 9; ++j)
      {
        unsigned row = 0;
        for (int i = 0; i < 9; ++i)
        {
          row |= static_cast<unsigned>(window.At(i, j, k) >= 0.0f) << i;
        }
        above[j + 9 * k] = static_cast<std::uint16_t>(row);
      }
    }
    // The cut edges: those whose two nodes lie on both sides, of the
    // brick's nodes on the grid.
    std::int64_t first[3];
    FirstNodeOf(C, brick, first);
    int nodes[3], edges[3];
    for (int a = 0; a < 3; ++a)
    {
      const std::int64_t left = C.GridDims[a] - first[a];
      nodes[a] = static_cast<int>(left < 8 ? left : 8);
      edges[a] = static_cast<int>(left - 1 < 8 ? left - 1 : 8);
    }
    std::uint64_t* cut = A.Cut + CutWords * r;
    for (int w = 0; w < CutWords; ++w)
    {
      cut[w] = 0;
    }
    const unsigned present = (1u << nodes[0]) - 1u;
    for (int k = 0; k < nodes[2]; ++k)
    {
      for (int j = 0; j < nodes[1]; ++j)
      {
        const unsigned row = above[j + 9 * k];
        const unsigned along[3] = { (row ^ (row >> 1)) & ((1u << edges[0]) - 1u),
          j < edges[1] ? (row ^ above[j + 1 + 9 * k]) & present : 0u,
          k < edges[2] ? (row ^ above[j + 9 * (k + 1)]) & present : 0u };
        const int byte = j + 8 * k; // the row's 8 nodes are bits 8 byte .. 8 byte + 7 of an axis
        for (int axis = 0; axis < 3; ++axis)
        {
          cut[axis * 8 + byte / 8] |= static_cast<std::uint64_t>(along[axis]) << (8 * (byte % 8));
        }
      }
    }
    std::int32_t vertices = 0;
    for (int w = 0; w < CutWords; ++w)
    {
      vertices += PopCount(cut[w]);
    }
    A.VertexCount[r] = vertices;
    Counter counter{ A.Cases, 0 };
    ForEachCutCellOf(C, *A.Cases, above, first, counter);
    A.TriangleCount[r] = counter.Triangles;
  }

  struct Counter
  {
    const CellCases* Cases;
    std::int32_t Triangles;
    NV_HD void operator()(int, int, int, int signs) { Triangles += Cases->Count[signs]; }
  };
};

/// Cut brick r's vertices and normals, ids FirstVertex[r] on in the order of
/// its cut edges (nvSurface.cxx's Vertex and Gradient).
struct VerticesKernel
{
  ContourArrays A;
  ContourConstants C;

  /// The gradient of psi at window node `local`, grid node g: central
  /// differences, one-sided on the grid's faces.
  NV_HD void Gradient(const ContourWindow& window, const int local[3], const std::int64_t g[3], double gradient[3]) const
  {
    for (int a = 0; a < 3; ++a)
    {
      const int before = g[a] > 0 ? -1 : 0;
      const int after = g[a] < C.GridDims[a] - 1 ? 1 : 0;
      int p[3] = { local[0], local[1], local[2] }, q[3] = { local[0], local[1], local[2] };
      p[a] += after;
      q[a] += before;
      gradient[a] = after == before
        ? 0.0
        : (static_cast<double>(window.At(p[0], p[1], p[2])) - window.At(q[0], q[1], q[2])) /
          ((after - before) * C.Spacing);
    }
  }

  NV_HD void operator()(std::int64_t r) const
  {
    ContourWindow window;
    const std::int64_t brick = A.CutBricks[r];
    FillContourWindow(A, C, brick, window);
    std::int64_t first[3];
    FirstNodeOf(C, brick, first);
    std::int64_t v = A.FirstVertex[r];
    const std::uint64_t* cut = A.Cut + CutWords * r;
    for (int w = 0; w < CutWords; ++w)
    {
      for (std::uint64_t bits = cut[w]; bits; bits &= bits - 1, ++v)
      {
        const int bit = 64 * w + PopCount((bits & (~bits + 1)) - 1); // the lowest set bit
        const int node = bit % 512, axis = bit / 512;
        int p0[3] = { node & 7, (node >> 3) & 7, node >> 6 };
        int p1[3] = { p0[0], p0[1], p0[2] };
        ++p1[axis];
        std::int64_t g0[3], g1[3];
        for (int a = 0; a < 3; ++a)
        {
          g0[a] = first[a] + p0[a];
          g1[a] = first[a] + p1[a];
        }
        const double v0 = window.At(p0[0], p0[1], p0[2]), v1 = window.At(p1[0], p1[1], p1[2]);
        // Linear interpolation to the level 0 (v0 and v1 have opposite
        // signs), kept VertexMargin h from the nodes:
        // t = std::min(1 - margin, std::max(margin, v0 / (v0 - v1))).
        const double ratio = v0 / (v0 - v1);
        const double low = VertexMargin < ratio ? ratio : VertexMargin;
        const double t = low < 1.0 - VertexMargin ? low : 1.0 - VertexMargin;
        double d0[3], d1[3], n[3];
        this->Gradient(window, p0, g0, d0);
        this->Gradient(window, p1, g1, d1);
        double* xyz = A.Points + 3 * v;
        for (int a = 0; a < 3; ++a)
        {
          xyz[a] = C.Origin[a] + C.Spacing * (static_cast<double>(g0[a]) + (a == axis ? t : 0.0));
          n[a] = d0[a] + t * (d1[a] - d0[a]);
        }
        const double length = ::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        float* normal = A.Normals + 3 * v;
        for (int a = 0; a < 3; ++a)
        {
          normal[a] = length > 0.0 ? static_cast<float>(-n[a] / length) : 0.0f; // down psi: out of the shell
        }
      }
    }
  }
};

/// Cut brick r's triangles, from FirstTriangle[r] on, cell after cell
/// (nvSurface.cxx's MakeTriangles and IdOf).
struct TrianglesKernel
{
  ContourArrays A;
  ContourConstants C;

  /// The id of the vertex on edge `edge` of cell (i, j, k) of the brick at
  /// brick coordinates b: its edge's brick is found among the cut bricks,
  /// and the vertex counted among that brick's cut edges.
  NV_HD long long IdOf(const std::int64_t b[3], int i, int j, int k, int edge) const
  {
    const int corner = EdgeCornerOf(edge);
    const int node[3] = { i + (corner & 1), j + ((corner >> 1) & 1), k + ((corner >> 2) & 1) };
    const std::int64_t brick =
      (b[0] + (node[0] >> 3)) + C.BrickDims[0] * ((b[1] + (node[1] >> 3)) + C.BrickDims[1] * (b[2] + (node[2] >> 3)));
    const std::int64_t r = FindBrick(A.CutBricks, A.NumberOfCutBricks, brick);
    if (r < 0)
    {
      return -1; // not reached: a cut edge's brick is a cut brick
    }
    const int bit = 512 * (edge / 4) + (node[0] & 7) + 8 * ((node[1] & 7) + 8 * (node[2] & 7));
    const std::uint64_t* cut = A.Cut + CutWords * r;
    long long id = A.FirstVertex[r];
    for (int w = 0; w < bit / 64; ++w)
    {
      id += PopCount(cut[w]);
    }
    return id + PopCount(cut[bit / 64] & ((std::uint64_t(1) << (bit % 64)) - 1));
  }

  struct Writer
  {
    const TrianglesKernel* Kernel;
    const std::int64_t* B;
    long long* Out;
    NV_HD void operator()(int i, int j, int k, int signs)
    {
      const CellCases& cases = *Kernel->A.Cases;
      long long id[12];
      int known = 0; // the edges whose id is in id[]
      for (int t = 0; t < cases.Count[signs]; ++t)
      {
        for (int v = 0; v < 3; ++v)
        {
          const int e = cases.Edges[signs][3 * t + v];
          if (!((known >> e) & 1))
          {
            id[e] = Kernel->IdOf(B, i, j, k, e);
            known |= 1 << e;
          }
          *Out++ = id[e];
        }
      }
    }
  };

  NV_HD void operator()(std::int64_t r) const
  {
    std::int64_t b[3], first[3];
    BrickCoordinatesOf(C, A.CutBricks[r], b);
    FirstNodeOf(C, A.CutBricks[r], first);
    Writer writer{ this, b, A.Triangles + 3 * A.FirstTriangle[r] };
    ForEachCutCellOf(C, *A.Cases, A.Above + AboveRows * r, first, writer);
  }
};

} // namespace device
} // namespace nv

#endif
