// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// PreserveOffset: the scheme (10)-(12) with Lagrange multipliers that
// cancel the drift of the phi = 0 sheets by mean-curvature motion and keep
// the smoothing. The derivation is in nvDriftCorrection.cxx, beside the code.
#ifndef nvDriftCorrection_h
#define nvDriftCorrection_h

#include "nvPartition.h"

#include <array>
#include <cstdint>
#include <vector>

namespace nv
{
class Halo;
struct NarrowBand;

class DriftCorrection
{
public:
  /**
   * band: with its brick tables (BuildNarrowBand; a band without them gets
   * no correction). halo: the exchange with the neighbouring processes of a
   * distributed run, or null.
   */
  DriftCorrection(const NarrowBand& band, Halo* halo);

  /**
   * After a step (10)-(12): measures how the step moved the sheets, from
   * phi = phi^{n+1} and previous = phi^n (the right-hand side of (10)).
   * coupling: the solver's w = c / (1 + 6 c) per node, c = dt g / h^2.
   */
  void Measure(const double* phi, const double* previous, const double* coupling);

  /**
   * Before the next step's (10): moves the sheets back by what the measured
   * step moved them (in place; owned nodes, then the ghost nodes are
   * refreshed). Does nothing before the first measurement.
   */
  void Correct(double* phi, const double* coupling);

private:
  bool Applies() const;
  /// The band's bricks in the owned layers: band.Bricks[first, last).
  void OwnedBricks(std::int64_t& first, std::int64_t& last) const;

  const NarrowBand& Band;
  Halo* Exchange;
  std::array<std::int64_t, 3> BrickDims{ { 0, 0, 0 } };
  LayerRange Layers;             ///< brick layers with sums: the owned ones and their ghosts
  std::vector<double> BrickSums; ///< per brick of Layers: the sums of (C') (see the .cxx)
  std::vector<double> Mu;        ///< per owned band brick: mu (3) and lambda of (C')
  bool Measured = false;
};

} // namespace nv

#endif
