// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The field whose zero level is the output surface, read brick by brick.
//
// phi = 0 is the surface, but phi itself is a poor field to contour: the
// tanh profile of eq. (2) is saturated (|phi| > 0.99 on most nodes near the
// surface), so gradients, hence normals, and the linear interpolation of
// vertices along edges follow the grid rather than the surface. The profile's
// inverse, the signed distance it implies,
//
//     psi = sqrt(2) xi atanh(phi)      (phi = tanh(psi / (sqrt(2) xi)), eq. 2),
//
// has the same sign, hence the same zero set and the same cut cells, and is
// close to a distance: smooth surfaces come out smooth. psi is clamped to
// +-eta/2, the psi of the Dirichlet values +-(1 - delta) of eq. (5): off the
// band |phi0| >= 1 - delta, so there psi is +-eta/2 and only the side of the
// shell a node is on is needed, not its distance. (With xi >= eps_1 the band
// is at least 2 h wide, so a cut edge always has a band node at one end.)
#ifndef nvSurfaceField_h
#define nvSurfaceField_h

#include "nvGrid.h"
#include "nvNarrowBand.h"
#include "nvParameters.h"
#include "nvSurfaceTerms.h"
#include "nvTruncatedDistance.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace nv
{

/// psi of phi, clamped to [-eta/2, eta/2]; its sign is phi's: the
/// parameters' ImpliedDistanceOf (nvSurfaceTerms.h, which the device's
/// kernels call too).
class ImpliedDistance
{
public:
  explicit ImpliedDistance(const Parameters& parameters);
  float operator()(double phi) const { return ImpliedDistanceOf(phi, this->Scale, this->Cap); }
  /// The value at nodes outside the band: inside the shell +eta/2, outside -eta/2.
  float Inside() const { return static_cast<float>(this->Cap); }
  float Outside() const { return static_cast<float>(-this->Cap); }
  double GetScale() const { return this->Scale; }
  double GetCap() const { return this->Cap; }

private:
  double Scale; ///< sqrt(2) xi
  double Cap;   ///< eta/2
};

/// A field on the grid's nodes, read by bricks (nvTruncatedDistance.h).
class BrickField
{
public:
  virtual ~BrickField();
  /**
   * Brick layer `layer` (0 <= layer < number of brick layers): `varying`,
   * the bricks (ascending) where the field takes more than one value, and
   * `uniform[bx + BrickDims[0] by]`, the value on each other brick (sized here).
   */
  virtual void Layer(std::int64_t layer, std::vector<float>& uniform, std::vector<std::int64_t>& varying) const = 0;
  /// The values at a brick's nodes, index i + 8 (j + 8 k); nodes past the grid's end: any value.
  virtual void Values(std::int64_t brick, float values[BrickNodes]) const = 0;
};

/**
 * psi from the band: its nodes' phi, and +-eta/2 elsewhere by the side of
 * the shell the node is on (NarrowBand::Inside). The band's ghost layers
 * count: a distributed run contours its piece with the serial values.
 */
class BandField : public BrickField
{
public:
  BandField(const NarrowBand& band, const BandValues& phi, const Parameters& parameters);
  void Layer(std::int64_t layer, std::vector<float>& uniform, std::vector<std::int64_t>& varying) const override;
  void Values(std::int64_t brick, float values[BrickNodes]) const override;

private:
  const NarrowBand& Band;
  const BandValues& Phi;
  ImpliedDistance Psi;
  std::array<std::int64_t, 3> BrickDims;
};

/// psi from a dense phi on the node layers [kBegin, kEnd) (any value elsewhere).
class DenseField : public BrickField
{
public:
  DenseField(const Grid& grid, const float* phi, std::int64_t kBegin, std::int64_t kEnd, const Parameters& parameters);
  void Layer(std::int64_t layer, std::vector<float>& uniform, std::vector<std::int64_t>& varying) const override;
  void Values(std::int64_t brick, float values[BrickNodes]) const override;

private:
  Grid TheGrid;
  const float* Phi;
  std::int64_t Begin, End;
  ImpliedDistance Psi;
  std::array<std::int64_t, 3> BrickDims;
};

/// A field given on every node of the grid, as it is (the part's f, the
/// scan surface's; every brick varies); beyond the grid, `outside`.
class NodeField : public BrickField
{
public:
  NodeField(const Grid& grid, const std::vector<float>& values, float outside);
  void Layer(std::int64_t layer, std::vector<float>& uniform, std::vector<std::int64_t>& varying) const override;
  void Values(std::int64_t brick, float values[BrickNodes]) const override;

private:
  const Grid& TheGrid;
  const std::vector<float>& Nodes;
  float Outside;
  std::array<std::int64_t, 3> BrickDims;
};

/**
 * Whether psi takes one value on band brick a: no band nodes, and all its
 * nodes on one side of the shell (`inside`: which). The bricks where it
 * varies are those BandField::Layer lists and the device's surface contours
 * (CutMarkKernel, Device/nvSurfaceKernels.h). UniformBrick's test
 * (nvSurfaceTerms.h), on the band's arrays.
 */
inline bool UniformBandBrick(const NarrowBand& band, std::int64_t a, bool& inside)
{
  return UniformBrick(&band.Inside[8 * a], band.RedStart[a], band.RedStart[a + 1], band.BlackStart[a],
    band.BlackStart[a + 1], inside);
}

/// Bricks per axis of a grid.
std::array<std::int64_t, 3> BrickDimensions(const Grid& grid);

} // namespace nv

#endif
