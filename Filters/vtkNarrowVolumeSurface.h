// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The phi = 0 surface, by vtkFlyingEdges3D, from the dense volume or slab by
// slab without it.
//
// Contouring runs in the grid's own frame (origin 0) and the vertices are
// moved to world coordinates in double precision afterwards, so that a cloud
// far from the origin (1e8, say) keeps the precision of its own size.
//
// Without a dense volume, the grid is cut into slabs of z layers; each slab is
// filled (phi only) and contoured, and the vertices that neighbouring slabs
// both make on their shared plane are merged. Peak memory is one slab, not
// the box. The vertices and triangles are those of contouring the whole
// volume; only the normals on the shared planes differ slightly (one-sided
// gradients there).
#ifndef vtkNarrowVolumeSurface_h
#define vtkNarrowVolumeSurface_h

#include "vtkSmartPointer.h"

#include <cstdint>
#include <vector>

class vtkDataArray;
class vtkPolyData;

namespace nv
{
class Monitor;
struct NarrowBand;
struct Grid;
struct Parameters;
class TruncatedDistance;

/// The phi = 0 surface of a dense phi array, one value per node of the z
/// layers [kBegin, kEnd) (kEnd < 0: to the grid's end). monitor: the
/// isosurfacer's progress, and a request to stop it (which VTK 9.2's
/// vtkFlyingEdges3D sees only when it is done).
vtkSmartPointer<vtkPolyData> ExtractSurface(const Grid& grid, vtkDataArray* phi, std::int64_t kBegin = 0,
  std::int64_t kEnd = -1, Monitor* monitor = nullptr);

/// The same surface without the dense array.
vtkSmartPointer<vtkPolyData> ExtractSurfaceBySlabs(const TruncatedDistance& distance,
  const NarrowBand& band, const std::vector<double>& phi, const Parameters& parameters, Monitor* monitor,
  std::int64_t kBegin = 0, std::int64_t kEnd = -1);

} // namespace nv

#endif
