// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvAllenCahnSolver.h"

#include "nvCommunicator.h"
#include "nvDriftCorrection.h"
#include "nvHalo.h"
#include "nvNarrowBand.h"
#include "nvParallel.h"
#include "nvSchemeTerms.h"

#include <algorithm>
#include <cmath>

namespace nv
{
namespace
{
constexpr std::int64_t Grain = 4096;
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
  const bool eq4 = parameters.EdgeStoppingFunction == EdgeStopping::Eq4;

  ParallelFor(0, size, Grain, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t s = begin; s < end; ++s)
    {
      const double phi0 = this->Phi[s];
      const double g = EdgeStop(phi0, eq4); // eq. (4) or (3)
      this->Coupling[s] = CouplingWeight(g, dt, h); // (10)-(11)
      this->Decay[s] = ReactionDecay(g, dt, eps);   // (12)
      this->Previous[s] = phi0; // first touch here; each step sets it again
    }
  });
  if (parameters.PreserveOffset)
  {
    this->Correction.reset(new DriftCorrection(band, halo));
  }
}

AllenCahnSolver::~AllenCahnSolver() = default;

double AllenCahnSolver::HalfSweep(std::int64_t begin, std::int64_t end, double omega)
{
  double* phi = this->Phi.data();
  const double* previous = this->Previous.data();
  const double* coupling = this->Coupling.data();
  const std::uint32_t* neighbor = this->Band.Neighbor.data();
  return ParallelMax(end - begin, [&](std::int64_t first, std::int64_t last) {
    double change = 0.0;
    for (std::int64_t s = begin + first; s < begin + last; ++s)
    {
      // (10)-(11) at node s with its neighbours held fixed.
      const double step = RelaxationChange(phi, neighbor + 6 * s, s, previous[s], coupling[s], omega);
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
  double change = 0.0;
  const int sweeps = SweepUntilSettled(
    [&](double omega) {
      const double red = this->HalfSweep(redBegin, redEnd, omega);
      if (this->Exchange)
      {
        this->Exchange->Exchange(this->Phi.data(), true);
      }
      const double black = this->HalfSweep(blackBegin, blackEnd, omega);
      if (this->Exchange)
      {
        this->Exchange->Exchange(this->Phi.data(), false);
      }
      const double both = std::max(red, black);
      return this->Exchange ? this->Exchange->GetCommunicator().MaxAll(both) : both;
    },
    this->Params, this->Relaxation, change);
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
      this->Phi[s] = ReactionStep(this->Phi[s], this->Decay[s]); // eq. (12)
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
    this->OwnedSum([&](std::int64_t s) { return SquaredChange(phi[s], previous[s]); }),
    this->OwnedSum([&](std::int64_t s) { return previous[s] * previous[s]; }) };
  if (this->Exchange)
  {
    this->Exchange->GetCommunicator().SumAll(norms, 2);
  }
  report.RelativeChange = RelativeChange(norms[0], norms[1]);
  return report;
}

std::vector<StepReport> AllenCahnSolver::Run(Monitor* monitor)
{
  return RunTimeSteps(
    this->Params, monitor, [&](bool last) { return this->Step(last); },
    [&](bool stop) { // every process stops, or none
      return this->Exchange ? this->Exchange->GetCommunicator().MaxAll(stop ? 1.0 : 0.0) > 0.0 : stop;
    });
}

} // namespace nv
