// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The uniform grid of the method (section 3): nodes x_ijk = origin + (i, j, k) h.
#ifndef nvGrid_h
#define nvGrid_h

#include <array>
#include <cstdint>

namespace nv
{

struct Grid
{
  std::array<double, 3> Origin{ { 0.0, 0.0, 0.0 } };
  double Spacing = 1.0;
  std::array<std::int64_t, 3> Dims{ { 0, 0, 0 } }; ///< number of nodes per axis

  std::int64_t NumberOfNodes() const { return this->Dims[0] * this->Dims[1] * this->Dims[2]; }
  std::int64_t Index(std::int64_t i, std::int64_t j, std::int64_t k) const
  {
    return i + this->Dims[0] * (j + this->Dims[1] * k);
  }
  void Ijk(std::int64_t index, std::int64_t ijk[3]) const
  {
    ijk[0] = index % this->Dims[0];
    index /= this->Dims[0];
    ijk[1] = index % this->Dims[1];
    ijk[2] = index / this->Dims[1];
  }
  /// The truncated value of eq. (6) for nodes beyond reach: h sqrt(Nx^2 + Ny^2 + Nz^2).
  double FarDistance() const;
};

/**
 * The grid for points with bounding box `bounds` (xmin, xmax, ymin, ...):
 * spacing h, and the box padded by `padding` on every side so that the band
 * and one spare layer of nodes fit inside.
 */
Grid MakeGrid(const double bounds[6], double spacing, double padding);

/**
 * The padding around the points' box: the band reaches l + eta/2 from the
 * points, and two spare cells keep every band node's neighbours on the grid.
 */
double GridPadding(double reach, double spacing);

/**
 * The spacing h that puts `maximumDimension` cells along the longest side of
 * the padded box, for offset l and xi = eps_m (so that reach = l + m h).
 * Returns 0 when maximumDimension is too small to hold the padding.
 */
double SpacingForMaximumDimension(
  const double bounds[6], double offset, double xiCells, int maximumDimension);

} // namespace nv

#endif
