// Writes the solution on the whole grid (dense arrays) for output and for
// isosurfacing. Band nodes take the evolved phi; every other node keeps its
// initial value phi0 of eq. (2), which the scheme never changes there.
#ifndef nvVolume_h
#define nvVolume_h

#include "NarrowVolumeFiltersModule.h"
#include "nvParameters.h"

#include <vector>

namespace nv
{
struct NarrowBand;
class TruncatedDistance;

/// Dense arrays to fill, each of grid.NumberOfNodes() values; null ones are skipped.
struct VolumeArrays
{
  float* Phi = nullptr;
  float* InitialPhi = nullptr;
  float* Distance = nullptr;     ///< eq. (6): beyond reach, h sqrt(Nx^2 + Ny^2 + Nz^2)
  unsigned char* Band = nullptr; ///< 1 on band nodes
};

/// phi: the solver's values at band nodes (at least band.Size() of them).
NARROWVOLUMEFILTERS_EXPORT void FillVolume(const TruncatedDistance& distance, const NarrowBand& band,
  const std::vector<double>& phi, const Parameters& parameters, const VolumeArrays& arrays);

} // namespace nv

#endif
