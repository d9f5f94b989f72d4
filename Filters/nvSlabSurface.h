// The phi = 0 surface without a dense volume: the grid is cut into slabs of
// z layers; each slab is filled (phi only) and contoured by vtkFlyingEdges3D
// in the grid's own coordinates, and the vertices that neighbouring slabs
// both make on their shared plane are merged. Peak memory is one slab, not
// the box. The vertices and triangles are those of contouring the whole
// volume; only the normals on the shared planes differ slightly (one-sided
// gradients there).
#ifndef nvSlabSurface_h
#define nvSlabSurface_h

#include "vtkSmartPointer.h"

#include <vector>

class vtkPolyData;

namespace nv
{
class Monitor;
struct NarrowBand;
struct Parameters;
class TruncatedDistance;

/// Slab thickness in cells (a multiple of the brick size).
constexpr int SlabCells = 16;

vtkSmartPointer<vtkPolyData> ExtractSurfaceBySlabs(const TruncatedDistance& distance,
  const NarrowBand& band, const std::vector<double>& phi, const Parameters& parameters, Monitor* monitor);

} // namespace nv

#endif
