// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The output surface: the zero level of a field (nvSurfaceField.h) by
// marching cubes (nvMarchingCubes.h), made only in the bricks where the
// field changes sign, so that its cost follows the band and not the box.
//
// The paper takes "the isosurface phi = 0" (section 3) from the whole grid.
// Outside the band phi is constant up to the side of the shell, so no cell
// there is cut: every cut edge has a band node at one end. This code visits
// the bricks of the band and the bricks just below them (whose cells reach
// into the band), one brick layer at a time, and makes exactly what a
// contouring of the whole grid (vtkFlyingEdges3D) makes from the same
// values: the same vertices (linear interpolation along the cut edges, a node
// at 0 counting as above the level), the same number of triangles, and
// normals from central differences of the field interpolated along the edge,
// pointing towards its negative side (out of the shell). One difference: no
// vertex lies within 1e-3 h of a node, so that no triangle has zero area.
//
// A vertex belongs to its edge, and an edge to the brick of its first node;
// a brick numbers its vertices in the order of its cut edges (a bit mask,
// counted by popcount), so vertices are shared between cells and bricks
// without any search tree, and the output is the same for any number of
// threads. Per brick layer: the vertices of layer z + 1, then the triangles
// of layer z, which use them.
//
// The device back end does this work brick by brick over the band's arrays
// (Device/nvSurfaceKernels.h, Device/nvDeviceSurface.h), with the same
// terms (nvSurfaceTerms.h: the window, the cut edges, the vertices and
// normals, the cut cells, their triangles and vertex ids);
// TestCoreDevice checks that they give the same surface.
#ifndef nvSurface_h
#define nvSurface_h

#include "nvGrid.h"

#include <array>
#include <cstdint>
#include <vector>

namespace nv
{
class BrickField;
class Monitor;

/// A vertex's number in the output: long long, as VTK's 64-bit ids
/// (vtkIdType), so that a sink can hand out a VTK array's own memory.
using VertexId = long long;

/// A triangle surface in a sink's arrays: NumberOfPoints points (3 doubles
/// each) with their normals (3 floats each), NumberOfTriangles triangles (3
/// vertex ids each).
struct SurfaceArrays
{
  double* Points = nullptr;
  float* Normals = nullptr;
  VertexId* Triangles = nullptr;
  std::int64_t NumberOfPoints = 0;
  std::int64_t NumberOfTriangles = 0;
};

/// Receives the surface as it is made, brick layer by brick layer, into
/// arrays of its own (a VTK array's, a numpy array's), which later steps
/// edit in place (nvPieces.h).
class SurfaceSink
{
public:
  virtual ~SurfaceSink();
  /// Room for n more vertices, filled after the call (possibly by several
  /// threads): 3 n world coordinates (xyz) and 3 n unit normals.
  virtual void AddPoints(std::int64_t n, double*& xyz, float*& normals) = 0;
  /// Room for n more triangles, filled likewise: three vertex ids each
  /// (vertices numbered from 0 in the order of their room).
  virtual VertexId* AddTriangles(std::int64_t n) = 0;
  /// The surface received so far, in the sink's arrays.
  virtual SurfaceArrays View() = 0;
  /// Keeps the first kept.NumberOfPoints points and kept.NumberOfTriangles triangles.
  virtual void Truncate(const SurfaceArrays& kept) = 0;
};

/// A sink that keeps the surface in plain arrays.
/// The box of a surface's points: xmin, xmax, ymin, ... (all 0 when it has none).
std::array<double, 6> BoundsOf(const SurfaceArrays& surface);

class SurfaceMesh : public SurfaceSink
{
public:
  void AddPoints(std::int64_t n, double*& xyz, float*& normals) override;
  VertexId* AddTriangles(std::int64_t n) override;
  SurfaceArrays View() override;
  void Truncate(const SurfaceArrays& kept) override;
  std::vector<double> Points;
  std::vector<float> Normals;
  std::vector<VertexId> Triangles;
};

/**
 * The field = 0 surface of the cells in brick layers [layerBegin, layerEnd)
 * (layerEnd < 0: to the grid's end). The vertices on the top plane of the
 * last layer, which the next piece of a distributed run shares, are made with
 * the values of the layer above. The field must be readable on the layers
 * around: layerBegin - 1 to layerEnd. Returns false if the monitor stopped it.
 */
bool ContourBricks(const Grid& grid, const BrickField& field, SurfaceSink& sink, std::int64_t layerBegin = 0,
  std::int64_t layerEnd = -1, Monitor* monitor = nullptr);

} // namespace nv

#endif
