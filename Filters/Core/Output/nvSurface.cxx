// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvSurface.h"

#include "nvMarchingCubes.h"
#include "nvParallel.h"
#include "nvSurfaceField.h"
#include "nvTruncatedDistance.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace nv
{
namespace
{
constexpr int WindowSize = BrickSize + 3;      ///< nodes -1 .. 9 of a brick along each axis
constexpr int EdgeWords = 3 * BrickNodes / 64; ///< bit 512 axis + n: the edge from node n along the axis
constexpr int CornerSize = BrickSize + 1;      ///< the corners of a brick's cells along an axis, 0 .. 8
/// Bit i of row j + 9 k: the brick's node (i, j, k), 0 <= i, j, k <= 8, is
/// at or above the level. Cut edges and cells' cases are read from these bits.
using Rows = std::array<std::uint16_t, CornerSize * CornerSize>;
constexpr std::int64_t Grain = 8;              ///< bricks per task
/// No vertex closer to a node than this fraction of h. A node on the level
/// itself (phi = 0 there, or so close that the vertex rounds onto it) would
/// put the vertices of all its cut edges on one point, and give zero-area
/// triangles. Three points inside three different edges of a cube are never
/// on one line, so every triangle then has an area.
constexpr double Margin = 1e-3;

/// The field on the nodes -1 .. 9 of a brick along each axis: its own, the
/// far corners of its cells (node 8), and one more on each side for the
/// central differences.
struct Window
{
  std::array<float, WindowSize * WindowSize * WindowSize> Values;
  float& At(int i, int j, int k) { return this->Values[(i + 1) + WindowSize * ((j + 1) + WindowSize * (k + 1))]; }
  float At(int i, int j, int k) const
  {
    return this->Values[(i + 1) + WindowSize * ((j + 1) + WindowSize * (k + 1))];
  }
};

/// The field on one brick layer: the values of the bricks where it varies,
/// one value for each other brick.
struct LayerValues
{
  bool InGrid = false;
  std::vector<float> Uniform;        ///< per brick of the layer
  std::vector<std::int64_t> Varying; ///< ascending
  std::vector<std::int32_t> Slot;    ///< per brick of the layer: index into Varying, or -1
  std::vector<float> Values;         ///< BrickNodes per varying brick
};

/// The vertices of the cut bricks of one brick layer. Edge 512 axis + n of a
/// brick runs from its node n along the axis; its vertex's id is the brick's
/// first id plus the number of cut edges before it.
struct LayerVertices
{
  std::vector<std::int64_t> Bricks; ///< ascending
  std::vector<std::int32_t> Slot;   ///< per brick of the layer: index into Bricks, or -1
  std::vector<std::array<std::uint64_t, EdgeWords>> Cut;
  std::vector<std::array<std::uint16_t, EdgeWords>> Before; ///< cut edges in the brick's earlier words
  std::vector<VertexId> First;
  std::vector<Rows> Above;
};

class Contourer
{
public:
  Contourer(const Grid& grid, const BrickField& field, SurfaceSink& sink)
    : TheGrid(grid)
    , Field(field)
    , Sink(sink)
    , Bricks(BrickDimensions(grid))
    , PerLayer(Bricks[0] * Bricks[1])
  {
  }

  bool Run(std::int64_t begin, std::int64_t end, Monitor* monitor)
  {
    end = end < 0 ? this->Bricks[2] : std::min(end, this->Bricks[2]);
    if (begin >= end)
    {
      return true;
    }
    this->Load(begin - 1);
    this->Load(begin);
    for (std::int64_t z = begin; z <= end; ++z)
    {
      if (z < this->Bricks[2])
      {
        this->Load(z + 1);
        this->MakeVertices(z, z == end); // of the last layer, only the plane shared with the next piece
      }
      if (z > begin)
      {
        this->MakeTriangles(z - 1);
      }
      if (monitor)
      {
        monitor->Progress(static_cast<double>(z - begin + 1) / static_cast<double>(end - begin + 1));
        if (monitor->Aborted())
        {
          return false;
        }
      }
    }
    return true;
  }

private:
  // The vertices of layer z read the values of layers z - 1 .. z + 1, and
  // the triangles of layer z - 1 the vertices of layers z - 1 and z.
  LayerValues& ValuesOf(std::int64_t layer) { return this->ValueRing[static_cast<std::size_t>((layer + 3) % 3)]; }
  LayerVertices& VerticesOf(std::int64_t layer) { return this->VertexRing[static_cast<std::size_t>((layer + 2) % 2)]; }

  void Load(std::int64_t layer)
  {
    LayerValues& values = this->ValuesOf(layer);
    values.InGrid = layer >= 0 && layer < this->Bricks[2];
    values.Varying.clear();
    if (!values.InGrid)
    {
      return;
    }
    this->Field.Layer(layer, values.Uniform, values.Varying);
    values.Slot.assign(static_cast<std::size_t>(this->PerLayer), -1);
    const std::int64_t n = static_cast<std::int64_t>(values.Varying.size());
    for (std::int64_t r = 0; r < n; ++r)
    {
      values.Slot[static_cast<std::size_t>(values.Varying[r] - layer * this->PerLayer)] = static_cast<std::int32_t>(r);
    }
    values.Values.resize(static_cast<std::size_t>(n * BrickNodes));
    ParallelFor(0, n, Grain, [&](std::int64_t first, std::int64_t last) {
      for (std::int64_t r = first; r < last; ++r)
      {
        this->Field.Values(values.Varying[r], &values.Values[static_cast<std::size_t>(r * BrickNodes)]);
      }
    });
  }

  /// The bricks of a layer whose cells or edges may be cut: those where the
  /// field varies and those just below them (on any axis), whose cells reach
  /// their first nodes. Any other cell has its eight corners in bricks of one
  /// uniform value.
  std::vector<std::int64_t> CutBricks(std::int64_t layer)
  {
    std::vector<std::int64_t> cut;
    for (int dz = 0; dz < 2; ++dz)
    {
      const LayerValues& values = this->ValuesOf(layer + dz);
      for (std::int64_t b : values.Varying)
      {
        const std::int64_t bx = b % this->Bricks[0], by = (b / this->Bricks[0]) % this->Bricks[1];
        for (int dy = 0; dy < 2 && by - dy >= 0; ++dy)
        {
          for (int dx = 0; dx < 2 && bx - dx >= 0; ++dx)
          {
            cut.push_back(layer * this->PerLayer + (bx - dx) + this->Bricks[0] * (by - dy));
          }
        }
      }
    }
    std::sort(cut.begin(), cut.end());
    cut.erase(std::unique(cut.begin(), cut.end()), cut.end());
    return cut;
  }

  void BrickCoordinates(std::int64_t brick, std::int64_t b[3]) const
  {
    b[0] = brick % this->Bricks[0];
    b[1] = (brick / this->Bricks[0]) % this->Bricks[1];
    b[2] = brick / this->PerLayer;
  }

  void FillWindow(std::int64_t brick, Window& window)
  {
    // Along each axis, the part of the window that the brick before, the
    // brick itself and the brick after provide: {first window node, first
    // node in that brick, count}.
    static const int parts[3][3] = { { -1, BrickSize - 1, 1 }, { 0, 0, BrickSize }, { BrickSize, 0, 2 } };
    std::int64_t b[3];
    this->BrickCoordinates(brick, b);
    for (int oz = 0; oz < 3; ++oz)
    {
      const LayerValues& values = this->ValuesOf(b[2] + oz - 1);
      for (int oy = 0; oy < 3; ++oy)
      {
        for (int ox = 0; ox < 3; ++ox)
        {
          const std::int64_t x = b[0] + ox - 1, y = b[1] + oy - 1;
          const bool inGrid = values.InGrid && x >= 0 && x < this->Bricks[0] && y >= 0 && y < this->Bricks[1];
          const std::int64_t inLayer = x + this->Bricks[0] * y;
          const std::int32_t slot = inGrid ? values.Slot[static_cast<std::size_t>(inLayer)] : -1;
          // Nodes beyond the grid are never read: any value will do.
          const float uniform = inGrid ? values.Uniform[static_cast<std::size_t>(inLayer)] : 0.0f;
          for (int k = 0; k < parts[oz][2]; ++k)
          {
            for (int j = 0; j < parts[oy][2]; ++j)
            {
              float* row = &window.At(parts[ox][0], parts[oy][0] + j, parts[oz][0] + k);
              const float* source = slot < 0 ? nullptr
                                             : &values.Values[static_cast<std::size_t>(slot) * BrickNodes +
                                                 static_cast<std::size_t>(parts[ox][1] +
                                                   BrickSize * ((parts[oy][1] + j) + BrickSize * (parts[oz][1] + k)))];
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

  /// The gradient of the field at window node (i, j, k), grid node g:
  /// central differences, one-sided on the grid's faces.
  void Gradient(const Window& window, const int local[3], const std::int64_t g[3], double gradient[3]) const
  {
    for (int a = 0; a < 3; ++a)
    {
      const int before = g[a] > 0 ? -1 : 0;
      const int after = g[a] < this->TheGrid.Dims[a] - 1 ? 1 : 0;
      int p[3] = { local[0], local[1], local[2] }, q[3] = { local[0], local[1], local[2] };
      p[a] += after;
      q[a] += before;
      gradient[a] = after == before
        ? 0.0
        : (static_cast<double>(window.At(p[0], p[1], p[2])) - window.At(q[0], q[1], q[2])) /
          ((after - before) * this->TheGrid.Spacing);
    }
  }

  /// The vertex on cut edge `bit` of a brick whose first node is `first`.
  void Vertex(const Window& window, const std::int64_t first[3], int bit, double xyz[3], float normal[3]) const
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
    // Linear interpolation to the level 0 (v0 and v1 have opposite signs).
    const double t = std::min(1.0 - Margin, std::max(Margin, v0 / (v0 - v1)));
    double d0[3], d1[3], n[3];
    this->Gradient(window, p0, g0, d0);
    this->Gradient(window, p1, g1, d1);
    for (int a = 0; a < 3; ++a)
    {
      xyz[a] = this->TheGrid.Origin[a] + this->TheGrid.Spacing * (static_cast<double>(g0[a]) + (a == axis ? t : 0.0));
      n[a] = d0[a] + t * (d1[a] - d0[a]);
    }
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int a = 0; a < 3; ++a)
    {
      normal[a] = length > 0.0 ? static_cast<float>(-n[a] / length) : 0.0f; // down the field: out of the shell
    }
  }

  void FirstNode(std::int64_t brick, std::int64_t first[3]) const
  {
    this->BrickCoordinates(brick, first);
    for (int a = 0; a < 3; ++a)
    {
      first[a] <<= BrickShift;
    }
  }

  /// Marks the brick's cut edges (those of its first node plane along x and
  /// y only, if planeOnly): the edges whose two nodes lie on both sides.
  void MarkCutEdges(const Rows& above, std::int64_t brick, bool planeOnly, std::array<std::uint64_t, EdgeWords>& cut) const
  {
    std::int64_t first[3];
    this->FirstNode(brick, first);
    int nodes[3], edges[3]; // per axis: the brick's nodes on the grid, and the edges from them
    for (int a = 0; a < 3; ++a)
    {
      nodes[a] = static_cast<int>(std::min<std::int64_t>(BrickSize, this->TheGrid.Dims[a] - first[a]));
      edges[a] = static_cast<int>(std::min<std::int64_t>(BrickSize, this->TheGrid.Dims[a] - 1 - first[a]));
    }
    cut.fill(0);
    const unsigned present = (1u << nodes[0]) - 1u;
    for (int k = 0; k < (planeOnly ? 1 : nodes[2]); ++k)
    {
      for (int j = 0; j < nodes[1]; ++j)
      {
        const unsigned row = above[static_cast<std::size_t>(j + CornerSize * k)];
        const unsigned along[3] = { (row ^ (row >> 1)) & ((1u << edges[0]) - 1u),
          j < edges[1] ? (row ^ above[static_cast<std::size_t>(j + 1 + CornerSize * k)]) & present : 0u,
          k < edges[2] && !planeOnly ? (row ^ above[static_cast<std::size_t>(j + CornerSize * (k + 1))]) & present : 0u };
        const int byte = j + BrickSize * k; // the row's 8 nodes are bits 8 byte .. 8 byte + 7 of an axis
        for (int axis = 0; axis < (planeOnly ? 2 : 3); ++axis)
        {
          cut[static_cast<std::size_t>(axis * (BrickNodes / 64) + byte / 8)] |= std::uint64_t(along[axis]) << (8 * (byte % 8));
        }
      }
    }
  }

  /// The vertices of a layer's cut bricks: their ids (in brick order, then
  /// edge order), their coordinates and normals to the sink.
  void MakeVertices(std::int64_t layer, bool planeOnly)
  {
    LayerVertices& vertices = this->VerticesOf(layer);
    vertices.Bricks = this->CutBricks(layer);
    const std::int64_t n = static_cast<std::int64_t>(vertices.Bricks.size());
    vertices.Slot.assign(static_cast<std::size_t>(this->PerLayer), -1);
    for (std::int64_t r = 0; r < n; ++r)
    {
      vertices.Slot[static_cast<std::size_t>(vertices.Bricks[r] - layer * this->PerLayer)] = static_cast<std::int32_t>(r);
    }
    vertices.Cut.resize(static_cast<std::size_t>(n));
    vertices.Before.resize(static_cast<std::size_t>(n));
    vertices.First.resize(static_cast<std::size_t>(n));
    vertices.Above.resize(static_cast<std::size_t>(n));
    // The cut edges, then room for their vertices, then the vertices.
    ParallelFor(0, n, Grain, [&](std::int64_t begin, std::int64_t end) {
      Window window;
      for (std::int64_t r = begin; r < end; ++r)
      {
        this->FillWindow(vertices.Bricks[r], window);
        MarkAbove(window, vertices.Above[r]);
        this->MarkCutEdges(vertices.Above[r], vertices.Bricks[r], planeOnly, vertices.Cut[r]);
      }
    });
    const VertexId layerFirst = this->NextId;
    for (std::int64_t r = 0; r < n; ++r)
    {
      vertices.First[r] = this->NextId;
      for (int w = 0; w < EdgeWords; ++w)
      {
        vertices.Before[r][w] = static_cast<std::uint16_t>(this->NextId - vertices.First[r]);
        this->NextId += Popcount(vertices.Cut[r][w]);
      }
    }
    double* xyz = nullptr;
    float* normals = nullptr;
    this->Sink.AddPoints(this->NextId - layerFirst, xyz, normals);
    ParallelFor(0, n, Grain, [&](std::int64_t begin, std::int64_t end) {
      Window window;
      for (std::int64_t r = begin; r < end; ++r)
      {
        this->FillWindow(vertices.Bricks[r], window);
        std::int64_t first[3];
        this->FirstNode(vertices.Bricks[r], first);
        VertexId v = vertices.First[r] - layerFirst;
        for (int w = 0; w < EdgeWords; ++w)
        {
          for (std::uint64_t bits = vertices.Cut[r][w]; bits; bits &= bits - 1, ++v)
          {
            const int bit = 64 * w + Popcount((bits & (~bits + 1)) - 1); // the lowest set bit
            this->Vertex(window, first, bit, xyz + 3 * v, normals + 3 * v);
          }
        }
      }
    });
  }

  static void MarkAbove(const Window& window, Rows& above)
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
        above[static_cast<std::size_t>(j + CornerSize * k)] = static_cast<std::uint16_t>(row);
      }
    }
  }

  /// The id of the vertex on edge `edge` of cell (i, j, k) of brick b.
  VertexId IdOf(const std::int64_t b[3], int i, int j, int k, int edge)
  {
    const int corner = EdgeCorner(edge);
    const int node[3] = { i + (corner & 1), j + ((corner >> 1) & 1), k + ((corner >> 2) & 1) };
    const LayerVertices& vertices = this->VerticesOf(b[2] + (node[2] >> BrickShift));
    const std::int32_t r = vertices.Slot[static_cast<std::size_t>(
      (b[0] + (node[0] >> BrickShift)) + this->Bricks[0] * (b[1] + (node[1] >> BrickShift)))];
    const int bit = BrickNodes * EdgeAxis(edge) + (node[0] & (BrickSize - 1)) +
      BrickSize * ((node[1] & (BrickSize - 1)) + BrickSize * (node[2] & (BrickSize - 1)));
    const std::uint64_t below = vertices.Cut[r][bit / 64] & ((std::uint64_t(1) << (bit % 64)) - 1);
    return vertices.First[r] + vertices.Before[r][bit / 64] + Popcount(below);
  }

  /// Visits the cut cells of a brick: fn(i, j, k, case).
  template <typename Fn>
  void ForEachCutCell(const LayerVertices& vertices, std::int64_t r, Fn&& fn) const
  {
    std::int64_t first[3];
    this->FirstNode(vertices.Bricks[r], first);
    const Rows& above = vertices.Above[r];
    const std::array<CellCase, 256>& cases = MarchingCubesCases();
    for (int k = 0; k < BrickSize && first[2] + k + 1 < this->TheGrid.Dims[2]; ++k)
    {
      for (int j = 0; j < BrickSize && first[1] + j + 1 < this->TheGrid.Dims[1]; ++j)
      {
        // The four rows of corners of a row of cells; corner c = x + 2 y + 4 z.
        const unsigned r00 = above[static_cast<std::size_t>(j + CornerSize * k)];
        const unsigned r10 = above[static_cast<std::size_t>(j + 1 + CornerSize * k)];
        const unsigned r01 = above[static_cast<std::size_t>(j + CornerSize * (k + 1))];
        const unsigned r11 = above[static_cast<std::size_t>(j + 1 + CornerSize * (k + 1))];
        if (r00 == r10 && r00 == r01 && r00 == r11 && (r00 == 0u || r00 == (1u << CornerSize) - 1u))
        {
          continue; // all corners on one side
        }
        for (int i = 0; i < BrickSize && first[0] + i + 1 < this->TheGrid.Dims[0]; ++i)
        {
          const int signs = static_cast<int>(
            ((r00 >> i) & 3u) | (((r10 >> i) & 3u) << 2) | (((r01 >> i) & 3u) << 4) | (((r11 >> i) & 3u) << 6));
          if (cases[signs].Count > 0)
          {
            fn(i, j, k, cases[signs]);
          }
        }
      }
    }
  }

  /// The triangles of a layer's cut cells, to the sink in brick order.
  void MakeTriangles(std::int64_t layer)
  {
    const LayerVertices& vertices = this->VerticesOf(layer);
    const std::int64_t n = static_cast<std::int64_t>(vertices.Bricks.size());
    std::vector<std::int64_t> start(static_cast<std::size_t>(n + 1), 0);
    ParallelFor(0, n, Grain, [&](std::int64_t begin, std::int64_t end) {
      for (std::int64_t r = begin; r < end; ++r)
      {
        this->ForEachCutCell(vertices, r, [&](int, int, int, const CellCase& cell) { start[r + 1] += cell.Count; });
      }
    });
    for (std::int64_t r = 0; r < n; ++r)
    {
      start[r + 1] += start[r];
    }
    VertexId* ids = this->Sink.AddTriangles(start[n]);
    ParallelFor(0, n, Grain, [&](std::int64_t begin, std::int64_t end) {
      for (std::int64_t r = begin; r < end; ++r)
      {
        std::int64_t b[3];
        this->BrickCoordinates(vertices.Bricks[r], b);
        VertexId* out = ids + 3 * start[r];
        this->ForEachCutCell(vertices, r, [&](int i, int j, int k, const CellCase& cell) {
          VertexId id[CellEdges];
          int known = 0; // the edges whose id is in id[]
          for (int t = 0; t < cell.Count; ++t)
          {
            for (int v = 0; v < 3; ++v)
            {
              const int e = cell.Triangles[t][v];
              if (!((known >> e) & 1))
              {
                id[e] = this->IdOf(b, i, j, k, e);
                known |= 1 << e;
              }
              *out++ = id[e];
            }
          }
        });
      }
    });
  }

  const Grid& TheGrid;
  const BrickField& Field;
  SurfaceSink& Sink;
  std::array<std::int64_t, 3> Bricks;
  std::int64_t PerLayer;
  std::array<LayerValues, 3> ValueRing;
  std::array<LayerVertices, 2> VertexRing;
  VertexId NextId = 0;
};
} // namespace

SurfaceSink::~SurfaceSink() = default;

void SurfaceMesh::AddPoints(std::int64_t n, double*& xyz, float*& normals)
{
  this->Points.resize(this->Points.size() + static_cast<std::size_t>(3 * n));
  this->Normals.resize(this->Normals.size() + static_cast<std::size_t>(3 * n));
  xyz = this->Points.data() + this->Points.size() - 3 * n;
  normals = this->Normals.data() + this->Normals.size() - 3 * n;
}

VertexId* SurfaceMesh::AddTriangles(std::int64_t n)
{
  this->Triangles.resize(this->Triangles.size() + static_cast<std::size_t>(3 * n));
  return this->Triangles.data() + this->Triangles.size() - 3 * n;
}

SurfaceArrays SurfaceMesh::View()
{
  SurfaceArrays arrays;
  arrays.Points = this->Points.data();
  arrays.Normals = this->Normals.data();
  arrays.Triangles = this->Triangles.data();
  arrays.NumberOfPoints = static_cast<std::int64_t>(this->Points.size() / 3);
  arrays.NumberOfTriangles = static_cast<std::int64_t>(this->Triangles.size() / 3);
  return arrays;
}

void SurfaceMesh::Truncate(const SurfaceArrays& kept)
{
  this->Points.resize(static_cast<std::size_t>(3 * kept.NumberOfPoints));
  this->Normals.resize(static_cast<std::size_t>(3 * kept.NumberOfPoints));
  this->Triangles.resize(static_cast<std::size_t>(3 * kept.NumberOfTriangles));
}

bool ContourBricks(const Grid& grid, const BrickField& field, SurfaceSink& sink, std::int64_t layerBegin,
  std::int64_t layerEnd, Monitor* monitor)
{
  Contourer contourer(grid, field, sink);
  return contourer.Run(layerBegin, layerEnd, monitor);
}

} // namespace nv
