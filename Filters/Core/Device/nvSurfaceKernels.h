// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The device back end's surface kernels: the phi = 0 surface of the band
// (step 7), one source for the host and the GPU, as nvDeviceKernels.h.
//
// The CPU core makes the surface brick layer by brick layer
// (Output/nvSurface.cxx, from the implied distance of nvSurfaceField.h);
// these kernels do the same work brick by brick over the band's arrays.
// Both call the same terms, written once (Output/nvSurfaceTerms.h: the
// implied distance, the window, the corners' signs, the cut edges, the
// vertex and its normal, the cut cells, their triangles and vertex ids), so
// that the host launcher gives the CPU core's vertices, normals and
// triangles bit for bit (TestCoreDevice). A kernel keeps which brick it
// works on, where it reads psi (the band's bricks, found by a binary
// search) and where it writes:
//
//   CutMarkKernel     a band brick where psi varies (not UniformBrick):
//                     itself and the bricks just below it on any axis,
//                     whose cells reach its first nodes, marked in a byte
//                     a grid brick; the marks are then listed in ascending
//                     order as the point sort's reached bricks
//                     (nvPointSort.h's ChunkSumKernel, ChunkStarts on the
//                     host, ReachListKernel): the cut bricks, CutBricksOf's
//                     list;
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
// first vertex and triangle of each cut brick, in brick order), and it adds
// up the chunks' counts of marked bricks while the cut bricks are listed:
// compactions of a few bytes a brick; the per-node and per-cell work is in
// the kernels.
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
#include "nvSurfaceTerms.h"

#include <cstdint>

namespace nv
{
namespace device
{

/// The marching cubes case table as plain bytes (nvSurfaceTerms.h), filled
/// on the host by MarchingCubesTable() (Output/nvMarchingCubes.h).
using CellCases = ::nv::CellCases;

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
  /// The outputs of one slab of cut bricks (SurfaceSlabs): Points and
  /// Normals hold the vertices from id PointsBase on, Triangles the
  /// triangles from TrianglesBase on (0, 0: the whole surface).
  double* Points = nullptr;
  float* Normals = nullptr;
  long long* Triangles = nullptr;
  std::int64_t PointsBase = 0;
  std::int64_t TrianglesBase = 0;
  const CellCases* Cases = nullptr;
};

constexpr int CutWords = EdgeWords;  ///< 3 axes x 512 edges / 64 bits
constexpr int AboveRows = CornerRows; ///< 9 x 9 rows of 9 corners

/// psi at the band brick a's nodes (index i + 8 (j + 8 k)), as BandField::Values.
struct PsiKernel
{
  ContourArrays A;
  ContourConstants C;
  NV_HD void operator()(std::int64_t a) const
  {
    BandBrickPsi(A.Inside + 8 * a, A.RedStart[a], A.RedStart[a + 1], A.BlackStart[a], A.BlackStart[a + 1], A.Offset,
      A.Phi, C.Scale, C.Cap, A.Psi + 512 * a);
  }
};


/// Band brick a, where psi varies: the cut bricks it makes marked (Marks, a
/// byte a grid brick, cleared before; marks of 1 from several threads at
/// once): itself and the bricks just below it on each axis within the grid,
/// as CutBricksOf (nvDeviceSurface.h).
struct CutMarkKernel
{
  ContourArrays A;
  ContourConstants C;
  std::uint8_t* Marks;
  NV_HD void operator()(std::int64_t a) const
  {
    bool inside;
    if (UniformBrick(A.Inside + 8 * a, A.RedStart[a], A.RedStart[a + 1], A.BlackStart[a], A.BlackStart[a + 1], inside))
    {
      return;
    }
    std::int64_t b[3];
    BrickAt(C.BrickDims, A.Bricks[a], b);
    for (int dz = 0; dz < 2 && b[2] - dz >= 0; ++dz)
    {
      for (int dy = 0; dy < 2 && b[1] - dy >= 0; ++dy)
      {
        for (int dx = 0; dx < 2 && b[0] - dx >= 0; ++dx)
        {
          Mark(Marks + (b[0] - dx) + C.BrickDims[0] * ((b[1] - dy) + C.BrickDims[1] * (b[2] - dz)));
        }
      }
    }
  }
};

/// The bricks around a brick for its window (nvSurfaceTerms.h's
/// FillWindow): a band brick's psi, -eta/2 on a brick no point reaches
/// (outside the shell), and 0 beyond the grid (never read there).
struct BandBricks
{
  const ContourArrays* A;
  const ContourConstants* C;
  std::int64_t B[3]; ///< the brick's coordinates in bricks
  NV_HD const float* operator()(int ox, int oy, int oz, float& uniform) const
  {
    const std::int64_t x = B[0] + ox - 1, y = B[1] + oy - 1, z = B[2] + oz - 1;
    const bool inGrid =
      x >= 0 && x < C->BrickDims[0] && y >= 0 && y < C->BrickDims[1] && z >= 0 && z < C->BrickDims[2];
    const std::int64_t a =
      inGrid ? IndexOf(A->Bricks, 0, A->NumberOfBricks, x + C->BrickDims[0] * (y + C->BrickDims[1] * z)) : -1;
    uniform = inGrid ? static_cast<float>(-C->Cap) : 0.0f;
    return a < 0 ? nullptr : A->Psi + 512 * a;
  }
};

/// The window of `brick`.
NV_HD inline void FillContourWindow(const ContourArrays& A, const ContourConstants& C, std::int64_t brick,
  SurfaceWindow& window)
{
  BandBricks bricks{ &A, &C, { 0, 0, 0 } };
  BrickAt(C.BrickDims, brick, bricks.B);
  FillWindow(window, bricks);
}


/// Cut brick r: the signs of its corners (Above), its cut edges (Cut) and
/// the counts of its vertices and triangles (nvSurfaceTerms.h's MarkAbove,
/// MarkCutEdges and TrianglesIn, as nvSurface.cxx's MakeVertices and
/// MakeTriangles).
struct CutCellsKernel
{
  ContourArrays A;
  ContourConstants C;
  NV_HD void operator()(std::int64_t r) const
  {
    SurfaceWindow window;
    const std::int64_t brick = A.CutBricks[r];
    FillContourWindow(A, C, brick, window);
    std::uint16_t* above = A.Above + AboveRows * r;
    MarkAbove(window, above);
    std::int64_t first[3];
    FirstNodeOf(C.BrickDims, brick, first);
    int nodes[3], edges[3];
    BrickNodesOnGrid(C.GridDims, first, nodes, edges);
    std::uint64_t* cut = A.Cut + CutWords * r;
    MarkCutEdges(above, nodes, edges, false, cut);
    std::int32_t vertices = 0;
    for (int w = 0; w < CutWords; ++w)
    {
      vertices += Popcount(cut[w]);
    }
    A.VertexCount[r] = vertices;
    A.TriangleCount[r] = TrianglesIn(C.GridDims, first, above, *A.Cases);
  }
};

/// Cut brick r's vertices and normals, ids FirstVertex[r] on in the order of
/// its cut edges (nvSurfaceTerms.h's VertexOn, as nvSurface.cxx's
/// MakeVertices).
struct VerticesKernel
{
  ContourArrays A;
  ContourConstants C;

  /// Writes the vertex of each cut edge, from id V on.
  struct Writer
  {
    const VerticesKernel* Kernel;
    const SurfaceWindow* Window;
    const std::int64_t* First;
    std::int64_t V;
    NV_HD void operator()(int bit)
    {
      const ContourArrays& A = Kernel->A;
      const ContourConstants& C = Kernel->C;
      const std::int64_t at = V - A.PointsBase;
      VertexOn(*Window, First, bit, C.GridDims, C.Origin, C.Spacing, A.Points + 3 * at, A.Normals + 3 * at);
      ++V;
    }
  };

  NV_HD void operator()(std::int64_t r) const
  {
    SurfaceWindow window;
    const std::int64_t brick = A.CutBricks[r];
    FillContourWindow(A, C, brick, window);
    std::int64_t first[3];
    FirstNodeOf(C.BrickDims, brick, first);
    Writer writer{ this, &window, first, A.FirstVertex[r] };
    ForEachCutEdge(A.Cut + CutWords * r, writer);
  }
};

/// Cut brick r's triangles, from FirstTriangle[r] on, cell after cell
/// (nvSurfaceTerms.h's CellTriangles, as nvSurface.cxx's MakeTriangles;
/// the ids by CellEdgeBit and CutBefore, as its IdOf).
struct TrianglesKernel
{
  ContourArrays A;
  ContourConstants C;

  /// The id of the vertex on edge `edge` of cell (i, j, k) of the brick at
  /// brick coordinates b: its edge's brick is found among the cut bricks,
  /// and the vertex counted among that brick's cut edges.
  NV_HD long long IdOf(const std::int64_t b[3], int i, int j, int k, int edge) const
  {
    int step[3];
    const int bit = CellEdgeBit(i, j, k, edge, step);
    const std::int64_t brick =
      (b[0] + step[0]) + C.BrickDims[0] * ((b[1] + step[1]) + C.BrickDims[1] * (b[2] + step[2]));
    const std::int64_t r = IndexOf(A.CutBricks, 0, A.NumberOfCutBricks, brick);
    if (r < 0)
    {
      return -1; // not reached: a cut edge's brick is a cut brick
    }
    const std::uint64_t* cut = A.Cut + CutWords * r;
    long long id = A.FirstVertex[r];
    for (int w = 0; w < bit / 64; ++w) // the cut edges of the brick's earlier words
    {
      id += Popcount(cut[w]);
    }
    return id + CutBefore(cut, bit);
  }

  /// A cell's vertex ids.
  struct Ids
  {
    const TrianglesKernel* Kernel;
    const std::int64_t* B;
    int I, J, K;
    NV_HD long long operator()(int edge) const { return Kernel->IdOf(B, I, J, K, edge); }
  };

  /// Writes a cut cell's triangles.
  struct Writer
  {
    const TrianglesKernel* Kernel;
    const std::int64_t* B;
    long long* Out;
    NV_HD void operator()(int i, int j, int k, int signs)
    {
      Ids ids{ Kernel, B, i, j, k };
      Out = CellTriangles(*Kernel->A.Cases, signs, ids, Out);
    }
  };

  NV_HD void operator()(std::int64_t r) const
  {
    std::int64_t b[3], first[3];
    BrickAt(C.BrickDims, A.CutBricks[r], b);
    FirstNodeOf(C.BrickDims, A.CutBricks[r], first);
    Writer writer{ this, b, A.Triangles + 3 * (A.FirstTriangle[r] - A.TrianglesBase) };
    ForEachCutCell(C.GridDims, first, A.Above + AboveRows * r, *A.Cases, writer);
  }
};

} // namespace device
} // namespace nv

#endif
