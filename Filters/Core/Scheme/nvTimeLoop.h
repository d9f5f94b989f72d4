// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The loops of the scheme, written once for the CPU's solver
// (nvAllenCahnSolver.cxx) and the device back end (Device/
// nvDeviceEvolution.cxx): the Gauss-Seidel sweeps of the implicit step
// (10)-(11) until they settle, with the over-relaxation factor estimated
// once, and the time steps until the stopping rule of section 4 holds. Each
// side passes what one sweep and one step are on its arrays.
#ifndef nvTimeLoop_h
#define nvTimeLoop_h

#include "nvParallel.h" // Monitor
#include "nvParameters.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace nv
{

/// What happened in one time step.
struct StepReport
{
  int Sweeps = 0;              ///< Gauss-Seidel sweeps of the diffusion step
  double SweepChange = 0.0;    ///< max |change| of the last sweep
  double RelativeChange = 0.0; ///< ||phi^{n+1} - phi^n||_2 / ||phi^n||_2 (section 4)
};

/**
 * The over-relaxation factor of the sweeps: Relaxation if it is set (> 0),
 * else 1 until it is estimated, once, after EstimationSweeps plain sweeps.
 * Plain Gauss-Seidel sweeps of a consistently ordered (red-black) system
 * contract by rho^2, rho the spectral radius of the Jacobi iteration; the
 * optimal over-relaxation is then 2 / (1 + sqrt(1 - rho^2)). rho depends
 * on the band's thickness and on g across it, so it is measured, from the
 * ratio of two successive changes (the bound from the largest coupling,
 * 6 c / (1 + 6 c), over-relaxes the thin band: 78 sweeps instead of 57 on
 * the teacup's 7 steps). Every process and thread count sees the same
 * changes, so the same factor.
 */
struct OverRelaxation
{
  /// Plain sweeps before the estimate: at the ninth, the ratio of
  /// successive changes has settled (estimated at the fifth, it comes out
  /// lower, and the sweeps of 7 cases add up to 15 % more).
  static constexpr int EstimationSweeps = 8;

  double Omega = 1.0;
  bool Estimate = false;

  explicit OverRelaxation(double relaxation)
    : Omega(relaxation > 0.0 ? relaxation : 1.0)
    , Estimate(!(relaxation > 0.0))
  {
  }

  /// After sweep number `sweeps` (from 0) with max change `change`, the
  /// previous sweep's being `previousChange`.
  void AfterSweep(int sweeps, double change, double previousChange)
  {
    if (this->Estimate && sweeps == EstimationSweeps && previousChange > 0.0)
    {
      const double contraction = std::min(change / previousChange, 0.99);
      this->Omega = 2.0 / (1.0 + std::sqrt(1.0 - contraction));
      this->Estimate = false;
    }
  }
};

/**
 * The implicit step (10)-(11): sweeps until the max change of a sweep drops
 * below GaussSeidelTolerance or MaximumNumberOfSweeps are done.
 * `sweep(omega)` runs one red and one black half sweep and returns the max
 * |change| of the whole sweep (over all processes in a distributed run).
 * Returns the sweeps; `lastChange` gets the last one's change.
 */
template <typename Sweep>
int SweepUntilSettled(Sweep&& sweep, const Parameters& parameters, OverRelaxation& relaxation, double& lastChange)
{
  int sweeps = 0;
  double change = 0.0;
  double previousChange = 0.0;
  do
  {
    change = sweep(relaxation.Omega);
    relaxation.AfterSweep(sweeps, change, previousChange);
    previousChange = change;
    ++sweeps;
  } while (change >= parameters.GaussSeidelTolerance && sweeps < parameters.MaximumNumberOfSweeps);
  lastChange = change;
  return sweeps;
}

/// The relative change of section 4 from its two sums of squares.
inline double RelativeChange(double change2, double norm2)
{
  return norm2 > 0.0 ? std::sqrt(change2 / norm2) : 0.0;
}

/**
 * The time steps: `step(last)` runs one (last: no step follows) and returns
 * its report, until the relative change drops below ConvergenceTolerance
 * (if > 0) or MaximumNumberOfIterations steps are done, or the monitor asks
 * to stop: `agree(stop)` makes every process of a distributed run stop, or
 * none (it returns stop in a serial run). Progress goes to the monitor.
 */
template <typename Step, typename Agree>
std::vector<StepReport> RunTimeSteps(const Parameters& parameters, Monitor* monitor, Step&& step, Agree&& agree)
{
  std::vector<StepReport> reports;
  const int steps = std::max(0, parameters.MaximumNumberOfIterations);
  for (int n = 0; n < steps; ++n)
  {
    if (monitor)
    {
      monitor->Progress(static_cast<double>(n) / steps);
      if (agree(monitor->Aborted()))
      {
        break;
      }
    }
    reports.push_back(step(n + 1 == steps));
    if (parameters.ConvergenceTolerance > 0.0 && reports.back().RelativeChange < parameters.ConvergenceTolerance)
    {
      break;
    }
  }
  if (monitor)
  {
    monitor->Progress(1.0);
  }
  return reports;
}

} // namespace nv

#endif
