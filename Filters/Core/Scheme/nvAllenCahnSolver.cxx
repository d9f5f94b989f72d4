// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvAllenCahnSolver.h"

#include "nvCommunicator.h"
#include "nvDriftCorrection.h"
#include "nvHalo.h"
#include "nvNarrowBand.h"
#include "nvParallel.h"

#include <algorithm>
#include <cmath>

namespace nv
{
namespace
{
constexpr std::int64_t Grain = 4096;
/// Plain Gauss-Seidel sweeps before the over-relaxation factor is estimated
/// (at the ninth, the ratio of successive changes has settled: estimated at
/// the fifth, it comes out lower, and the sweeps of 7 cases add up to 15 %
/// more).
constexpr int EstimationSweeps = 8;
}

double AllenCahnSolver::InitialPhi(double distance, double offset, double xi)
{
  // tanh z = (1 - e^(-2|z|)) / (1 + e^(-2|z|)), signed as z: one exp, which
  // costs a third of a tanh (the solver's start-up takes one per band node);
  // within 1e-16 of tanh, and -1 at d = infinity.
  const double z = (offset - distance) / (std::sqrt(2.0) * xi);
  const double e = std::exp(-2.0 * std::fabs(z));
  return std::copysign((1.0 - e) / (1.0 + e), z);
}

double AllenCahnSolver::EdgeStop(double phi0, EdgeStopping function)
{
  const double a = std::fabs(phi0);
  return function == EdgeStopping::Eq4 ? (1.0 - a) * a : 1.0 - phi0 * phi0;
}

BandValues AllenCahnSolver::InitialField(const NarrowBand& band, const Parameters& parameters)
{
  const std::int64_t size = band.Size();
  BandValues phi(static_cast<std::size_t>(size + 2));
  // Dirichlet values of eq. (5).
  phi[band.InsideSlot()] = 1.0 - parameters.Delta;
  phi[band.OutsideSlot()] = -1.0 + parameters.Delta;
  const double xi = parameters.Xi();
  const double l = parameters.OffsetDistance;
  ParallelFor(0, size, Grain, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t s = begin; s < end; ++s)
    {
      phi[s] = InitialPhi(band.Distance[s], l, xi); // eq. (2); d = inf gives -1
    }
  });
  return phi;
}

AllenCahnSolver::AllenCahnSolver(const NarrowBand& band, const Parameters& parameters, Halo* halo)
  : AllenCahnSolver(band, parameters, InitialField(band, parameters), halo)
{
}

AllenCahnSolver::AllenCahnSolver(
  const NarrowBand& band, const Parameters& parameters, BandValues phi0, Halo* halo)
  : Band(band)
  , Exchange(halo)
  , Params(parameters)
  , Phi(std::move(phi0))
{
  const std::int64_t size = band.Size();
  this->Previous.resize(static_cast<std::size_t>(size));
  this->Coupling.resize(static_cast<std::size_t>(size));
  this->Decay.resize(static_cast<std::size_t>(size));

  const double h = parameters.Spacing;
  const double dt = parameters.EffectiveTimeStep();
  const double eps = parameters.Epsilon();
  const EdgeStopping function = parameters.EdgeStoppingFunction;
  // Over-relaxation: a fixed factor if given, else estimated during the
  // first sweeps (see Diffuse).
  this->Omega = parameters.Relaxation > 0.0 ? parameters.Relaxation : 1.0;
  this->EstimateOmega = !(parameters.Relaxation > 0.0);

  ParallelFor(0, size, Grain, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t s = begin; s < end; ++s)
    {
      const double phi0 = this->Phi[s];
      const double g = EdgeStop(phi0, function); // eq. (4) or (3)
      const double c = dt * g / (h * h);
      this->Coupling[s] = c / (1.0 + 6.0 * c);
      this->Decay[s] = static_cast<float>(std::exp(-2.0 * g * dt / (eps * eps)));
      this->Previous[s] = phi0; // first touch here; each step sets it again
    }
  });
  if (parameters.PreserveOffset)
  {
    this->Correction.reset(new DriftCorrection(band, halo));
  }
}

AllenCahnSolver::~AllenCahnSolver() = default;

double AllenCahnSolver::HalfSweep(std::int64_t begin, std::int64_t end)
{
  double* phi = this->Phi.data();
  const double* previous = this->Previous.data();
  const double* coupling = this->Coupling.data();
  const std::uint32_t* neighbor = this->Band.Neighbor.data();
  const double omega = this->Omega;
  return ParallelMax(end - begin, [&](std::int64_t first, std::int64_t last) {
    double change = 0.0;
    for (std::int64_t s = begin + first; s < begin + last; ++s)
    {
      // (10)-(11) at node s with its neighbours held fixed:
      // (1 + 6 c) phi_s - c sum(neighbours) = phi^n_s, c = dt g_s / h^2, so
      // phi_s = phi^n_s + w (sum - 6 phi^n_s) with w = c / (1 + 6 c).
      const std::uint32_t* n = neighbor + 6 * s;
      const double sum = phi[n[0]] + phi[n[1]] + phi[n[2]] + phi[n[3]] + phi[n[4]] + phi[n[5]];
      const double rhs = previous[s];
      const double solved = rhs + coupling[s] * (sum - 6.0 * rhs);
      const double step = omega * (solved - phi[s]);
      change = std::max(change, std::fabs(step));
      phi[s] += step;
    }
    return change;
  });
}

int AllenCahnSolver::Diffuse(double* lastChange)
{
  const std::int64_t size = this->Band.Size();
  double* previous = this->Previous.data();
  const double* phi = this->Phi.data();
  ParallelFor(0, size, Grain, [&](std::int64_t begin, std::int64_t end) {
    std::copy(phi + begin, phi + end, previous + begin);
  });
  // Red nodes only read black neighbours and vice versa, so each half sweep
  // is order-independent and runs in parallel with identical results. In a
  // distributed run each process sweeps its owned nodes and then refreshes
  // its ghost nodes of the colour just swept (nvHalo.h).
  std::int64_t redBegin, redEnd, blackBegin, blackEnd;
  this->Band.OwnedNodes(true, redBegin, redEnd);
  this->Band.OwnedNodes(false, blackBegin, blackEnd);
  int sweeps = 0;
  double change = 0.0;
  double previousChange = 0.0;
  do
  {
    const double red = this->HalfSweep(redBegin, redEnd);
    if (this->Exchange)
    {
      this->Exchange->Exchange(this->Phi.data(), true);
    }
    const double black = this->HalfSweep(blackBegin, blackEnd);
    if (this->Exchange)
    {
      this->Exchange->Exchange(this->Phi.data(), false);
    }
    change = std::max(red, black);
    if (this->Exchange)
    {
      change = this->Exchange->GetCommunicator().MaxAll(change);
    }
    if (this->EstimateOmega && sweeps == EstimationSweeps && previousChange > 0.0)
    {
      // Plain Gauss-Seidel sweeps of a consistently ordered (red-black)
      // system contract by rho^2, rho the spectral radius of the Jacobi
      // iteration; the optimal over-relaxation is then 2 / (1 + sqrt(1 - rho^2)).
      // rho depends on the band's thickness and on g across it, so it is
      // measured here, once, from the ratio of two successive changes (the
      // bound from the largest coupling, 6 c / (1 + 6 c), over-relaxes the
      // thin band: 78 sweeps instead of 57 on the teacup's 7 steps). Every
      // process and thread count sees the same changes, so the same factor.
      const double contraction = std::min(change / previousChange, 0.99);
      this->Omega = 2.0 / (1.0 + std::sqrt(1.0 - contraction));
      this->EstimateOmega = false;
    }
    previousChange = change;
    ++sweeps;
  } while (change >= this->Params.GaussSeidelTolerance && sweeps < this->Params.MaximumNumberOfSweeps);
  if (lastChange)
  {
    *lastChange = change;
  }
  return sweeps;
}

void AllenCahnSolver::React()
{
  ParallelFor(0, this->Band.Size(), Grain, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t s = begin; s < end; ++s)
    {
      this->Phi[s] = React(this->Phi[s], this->Decay[s]); // eq. (12)
    }
  });
}

void AllenCahnSolver::ReleaseWorkspace()
{
  SolverValues().swap(this->Previous);
  SolverValues().swap(this->Coupling);
  SolverFloats().swap(this->Decay);
}

template <typename Fn>
double AllenCahnSolver::OwnedSum(Fn&& fn)
{
  double total = 0.0;
  for (bool red : { true, false })
  {
    std::int64_t begin, end;
    this->Band.OwnedNodes(red, begin, end);
    total += ParallelSum(end - begin, [&](std::int64_t first, std::int64_t last) {
      double sum = 0.0;
      for (std::int64_t s = begin + first; s < begin + last; ++s)
      {
        sum += fn(s);
      }
      return sum;
    });
  }
  return total;
}

StepReport AllenCahnSolver::Step(bool last)
{
  StepReport report;
  if (this->Correction)
  {
    // PreserveOffset: the multiplier term of (1'), measured on the last step
    // (nvDriftCorrection.cxx).
    this->Correction->Correct(this->Phi.data(), this->Coupling.data());
  }
  report.Sweeps = this->Diffuse(&report.SweepChange);
  this->React();
  if (this->Correction && !last)
  {
    this->Correction->Measure(this->Phi.data(), this->Previous.data(), this->Coupling.data());
  }
  // Relative change of section 4; Previous still holds phi^n.
  const double* phi = this->Phi.data();
  const double* previous = this->Previous.data();
  double norms[2] = {
    this->OwnedSum([&](std::int64_t s) { return (phi[s] - previous[s]) * (phi[s] - previous[s]); }),
    this->OwnedSum([&](std::int64_t s) { return previous[s] * previous[s]; }) };
  if (this->Exchange)
  {
    this->Exchange->GetCommunicator().SumAll(norms, 2);
  }
  const double change2 = norms[0], norm2 = norms[1];
  report.RelativeChange = norm2 > 0.0 ? std::sqrt(change2 / norm2) : 0.0;
  return report;
}

std::vector<StepReport> AllenCahnSolver::Run(Monitor* monitor)
{
  std::vector<StepReport> reports;
  const int steps = std::max(0, this->Params.MaximumNumberOfIterations);
  for (int n = 0; n < steps; ++n)
  {
    if (monitor)
    {
      monitor->Progress(static_cast<double>(n) / steps);
      bool stop = monitor->Aborted();
      if (this->Exchange) // every process stops, or none
      {
        stop = this->Exchange->GetCommunicator().MaxAll(stop ? 1.0 : 0.0) > 0.0;
      }
      if (stop)
      {
        break;
      }
    }
    reports.push_back(this->Step(n + 1 == steps));
    if (this->Params.ConvergenceTolerance > 0.0 &&
      reports.back().RelativeChange < this->Params.ConvergenceTolerance)
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
