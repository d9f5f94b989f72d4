// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvSurface.h"

#include "nvMarchingCubes.h"
#include "nvParallel.h"
#include "nvSurfaceField.h"
#include "nvSurfaceTerms.h"
#include "nvTruncatedDistance.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace nv
{
namespace
{
/// Bit i of row j + 9 k: the brick's node (i, j, k), 0 <= i, j, k <= 8, is
/// at or above the level (MarkAbove, nvSurfaceTerms.h).
using Rows = std::array<std::uint16_t, CornerRows>;
constexpr std::int64_t Grain = 8; ///< bricks per task

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
  const LayerValues& ValuesOf(std::int64_t layer) const
  {
    return this->ValueRing[static_cast<std::size_t>((layer + 3) % 3)];
  }
  LayerVertices& VerticesOf(std::int64_t layer) { return this->VertexRing[static_cast<std::size_t>((layer + 2) % 2)]; }
  const LayerVertices& VerticesOf(std::int64_t layer) const
  {
    return this->VertexRing[static_cast<std::size_t>((layer + 2) % 2)];
  }

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

  void BrickCoordinates(std::int64_t brick, std::int64_t b[3]) const { BrickAt(this->Bricks.data(), brick, b); }

  /// A brick's window (nvSurfaceTerms.h's FillWindow) from the ring of
  /// layers: a varying brick's values, another brick's one value.
  struct RingBricks
  {
    const Contourer* Self;
    std::int64_t B[3];            ///< the brick's coordinates in bricks
    const LayerValues* Layers[3]; ///< the layers before, of and after the brick
    const float* operator()(int ox, int oy, int oz, float& uniform) const
    {
      const Contourer& c = *this->Self;
      const LayerValues& values = *this->Layers[oz];
      const std::int64_t x = this->B[0] + ox - 1, y = this->B[1] + oy - 1;
      const bool inGrid = values.InGrid && x >= 0 && x < c.Bricks[0] && y >= 0 && y < c.Bricks[1];
      const std::int64_t inLayer = x + c.Bricks[0] * y;
      const std::int32_t slot = inGrid ? values.Slot[static_cast<std::size_t>(inLayer)] : -1;
      // Nodes beyond the grid are never read: any value will do.
      uniform = inGrid ? values.Uniform[static_cast<std::size_t>(inLayer)] : 0.0f;
      return slot < 0 ? nullptr : &values.Values[static_cast<std::size_t>(slot) * BrickNodes];
    }
  };

  void FillWindow(std::int64_t brick, SurfaceWindow& window) const
  {
    RingBricks bricks{ this, { 0, 0, 0 }, { nullptr, nullptr, nullptr } };
    this->BrickCoordinates(brick, bricks.B);
    for (int oz = 0; oz < 3; ++oz)
    {
      bricks.Layers[oz] = &this->ValuesOf(bricks.B[2] + oz - 1);
    }
    nv::FillWindow(window, bricks);
  }

  void FirstNode(std::int64_t brick, std::int64_t first[3]) const { FirstNodeOf(this->Bricks.data(), brick, first); }

  /// Marks the brick's cut edges (those of its first node plane along x and
  /// y only, if planeOnly): the edges whose two nodes lie on both sides.
  void MarkCutEdges(const Rows& above, std::int64_t brick, bool planeOnly, std::array<std::uint64_t, EdgeWords>& cut) const
  {
    std::int64_t first[3];
    this->FirstNode(brick, first);
    int nodes[3], edges[3]; // per axis: the brick's nodes on the grid, and the edges from them
    BrickNodesOnGrid(this->TheGrid.Dims.data(), first, nodes, edges);
    nv::MarkCutEdges(above.data(), nodes, edges, planeOnly, cut.data());
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
      SurfaceWindow window;
      for (std::int64_t r = begin; r < end; ++r)
      {
        this->FillWindow(vertices.Bricks[r], window);
        MarkAbove(window, vertices.Above[r].data());
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
      SurfaceWindow window;
      for (std::int64_t r = begin; r < end; ++r)
      {
        this->FillWindow(vertices.Bricks[r], window);
        std::int64_t first[3];
        this->FirstNode(vertices.Bricks[r], first);
        VertexId v = vertices.First[r] - layerFirst;
        auto vertex = [&](int bit) {
          VertexOn(window, first, bit, this->TheGrid.Dims.data(), this->TheGrid.Origin.data(), this->TheGrid.Spacing,
            xyz + 3 * v, normals + 3 * v);
          ++v;
        };
        ForEachCutEdge(vertices.Cut[r].data(), vertex);
      }
    });
  }

  /// The id of the vertex on edge `edge` of cell (i, j, k) of brick b.
  VertexId IdOf(const std::int64_t b[3], int i, int j, int k, int edge) const
  {
    int step[3];
    const int bit = CellEdgeBit(i, j, k, edge, step);
    const LayerVertices& vertices = this->VerticesOf(b[2] + step[2]);
    const std::int32_t r =
      vertices.Slot[static_cast<std::size_t>((b[0] + step[0]) + this->Bricks[0] * (b[1] + step[1]))];
    return vertices.First[r] + vertices.Before[r][bit / 64] + CutBefore(vertices.Cut[r].data(), bit);
  }

  /// The triangles of a layer's cut cells, to the sink in brick order.
  void MakeTriangles(std::int64_t layer)
  {
    const LayerVertices& vertices = this->VerticesOf(layer);
    const std::int64_t n = static_cast<std::int64_t>(vertices.Bricks.size());
    std::vector<std::int64_t> start(static_cast<std::size_t>(n + 1), 0);
    const CellCases& cases = MarchingCubesTable();
    ParallelFor(0, n, Grain, [&](std::int64_t begin, std::int64_t end) {
      for (std::int64_t r = begin; r < end; ++r)
      {
        std::int64_t first[3];
        this->FirstNode(vertices.Bricks[r], first);
        start[r + 1] = TrianglesIn(this->TheGrid.Dims.data(), first, vertices.Above[r].data(), cases);
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
        std::int64_t b[3], first[3];
        this->BrickCoordinates(vertices.Bricks[r], b);
        this->FirstNode(vertices.Bricks[r], first);
        VertexId* out = ids + 3 * start[r];
        auto cell = [&](int i, int j, int k, int signs) {
          auto idOf = [&](int e) { return this->IdOf(b, i, j, k, e); };
          out = CellTriangles(cases, signs, idOf, out);
        };
        ForEachCutCell(this->TheGrid.Dims.data(), first, vertices.Above[r].data(), cases, cell);
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

std::array<double, 6> BoundsOf(const SurfaceArrays& surface)
{
  std::array<double, 6> bounds{ { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 } };
  for (std::int64_t p = 0; p < surface.NumberOfPoints; ++p)
  {
    for (int a = 0; a < 3; ++a)
    {
      const double x = surface.Points[3 * p + a];
      bounds[2 * a] = p == 0 ? x : std::min(bounds[2 * a], x);
      bounds[2 * a + 1] = p == 0 ? x : std::max(bounds[2 * a + 1], x);
    }
  }
  return bounds;
}

} // namespace nv
