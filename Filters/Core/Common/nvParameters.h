// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The parameters of the phase-field narrow volume method, in the paper's terms.
// Paper: Li et al., "Fast and efficient narrow volume reconstruction from
// scattered data", Pattern Recognition 48 (2015). Section numbers and equation
// numbers below refer to it.
#ifndef nvParameters_h
#define nvParameters_h

#include <cmath>
#include <cstdint>

namespace nv
{

/// Which nodes the scheme updates: the narrow band only (the paper's "N"
/// columns) or every node of the grid (the "W" columns, for comparison).
enum class Domain
{
  NarrowBand = 0,
  WholeDomain = 1
};

/// The edge-stopping function g(x) that multiplies both terms of eq. (1),
/// numbered by its equation in the paper.
enum class EdgeStopping
{
  Eq3 = 3, ///< g = 1 - phi0^2, the earlier paper's choice
  Eq4 = 4  ///< g = (1 - |phi0|) |phi0|, the paper's choice for narrow band runs
};

/// Where the distance and the evolution run (the property Device): Automatic is the CPU
/// until the GPU back end has passed its tests on a GPU (nvReconstruction.cxx).
enum class ComputeDevice
{
  Automatic = 0,
  CPU = 1,
  GPU = 2
};

/// atanh(0.99): the tanh profile goes from -0.99 to 0.99 over 2 sqrt(2) eps atanh(0.99).
inline double Atanh099()
{
  return std::atanh(0.99);
}

/// eps_m = m h / (sqrt(2) atanh(0.99)) (section 3): the interface width that
/// spans 2m cells between phi = -0.99 and phi = 0.99.
inline double EpsilonFromCells(double m, double h)
{
  return m * h / (std::sqrt(2.0) * Atanh099());
}

struct Parameters
{
  double OffsetDistance = 0.1; ///< l, world units
  double Spacing = 0.01;       ///< h, world units
  double XiCells = 2.0;        ///< xi = eps_m with m = XiCells (eq. 2)
  double EpsilonCells = 6.0;   ///< eps = eps_m with m = EpsilonCells (eq. 1, 12)
  double TimeStep = 0.0;       ///< dt; <= 0 means eps^2 (section 4)
  int MaximumNumberOfIterations = 10;
  double ConvergenceTolerance = 0.0; ///< relative l2 change per step; 0: run all steps
  double GaussSeidelTolerance = 1e-6; ///< max-norm change of one red-black sweep
  int MaximumNumberOfSweeps = 1000;   ///< safety cap on Gauss-Seidel sweeps per step
  /// Over-relaxation factor of the red-black Gauss-Seidel sweeps: 1 is plain
  /// Gauss-Seidel; 0 (default) measures the optimal factor during the first
  /// sweeps (see AllenCahnSolver::Diffuse). The converged step (10) is the same.
  double Relaxation = 0.0;
  double Delta = 0.01;                ///< delta of eq. (5): band is |phi0| < 1 - delta
  std::int64_t MaximumBandNodes = -1; ///< refuse a larger band (memory budget); < 0: no limit
  nv::Domain Domain = nv::Domain::NarrowBand;
  EdgeStopping EdgeStoppingFunction = EdgeStopping::Eq4;
  /// After each step, cancel the local mean translation of the sheets
  /// (nvDriftCorrection.h); false: exactly the paper's scheme.
  bool PreserveOffset = false;

  double Xi() const { return EpsilonFromCells(this->XiCells, this->Spacing); }
  double Epsilon() const { return EpsilonFromCells(this->EpsilonCells, this->Spacing); }
  double EffectiveTimeStep() const
  {
    const double eps = this->Epsilon();
    return this->TimeStep > 0.0 ? this->TimeStep : eps * eps;
  }
  /// eta/2 = sqrt(2) xi atanh(1 - delta): half the width of the band (= m h for delta = 0.01).
  double HalfBandWidth() const
  {
    return std::sqrt(2.0) * this->Xi() * std::atanh(1.0 - this->Delta);
  }
  /// Distances are needed only below l + eta/2 (eq. 6).
  double Reach() const { return this->OffsetDistance + this->HalfBandWidth(); }
};

} // namespace nv

#endif
