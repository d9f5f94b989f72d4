// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The time step of the scheme: one implicit diffusion step (10)-(11) against
// the exact solution of its linear system, and the reaction step (12) against
// its fixed points and a fine numerical integration of (9).
#include "nvAllenCahnSolver.h"
#include "nvSchemeTerms.h"
#include "nvNarrowBand.h"
#include "nvParameters.h"
#include "nvTestUtilities.h"

#include <cmath>

namespace
{

/// Two band nodes side by side along x: s = 0 (red, d = 0.8 < l) and s = 1
/// (black, d = 1.3 > l). Every other neighbour is off the band and reads the
/// Dirichlet value of eq. (5) chosen by the node's own phi0 sign.
nv::NarrowBand TwoNodeBand()
{
  nv::NarrowBand band;
  band.GridNodes.Dims = { { 4, 3, 3 } };
  band.GridNodes.Spacing = 1.0;
  band.Offset = { 1 + 8 + 64, 2 + 8 + 64 }; // (1, 1, 1) and (2, 1, 1) in brick 0
  band.Distance = { 0.8, 1.3 };
  band.RedCount = 1; // node 0 is swept first, then node 1
  const std::uint32_t in = band.InsideSlot(), out = band.OutsideSlot();
  band.Neighbor = { in, 1, in, in, in, in, 0, out, out, out, out, out };
  return band;
}

nv::Parameters SchemeParameters()
{
  nv::Parameters p;
  p.OffsetDistance = 1.0;
  p.Spacing = 1.0;
  p.XiCells = 1.0;
  p.EpsilonCells = 2.0;
  p.GaussSeidelTolerance = 1e-15;
  return p;
}

void TestImplicitStep()
{
  const nv::NarrowBand band = TwoNodeBand();
  const nv::Parameters p = SchemeParameters();
  nv::AllenCahnSolver solver(band, p);

  // By hand: phi0 = tanh((l - d) / (sqrt(2) xi)), g = (1 - |phi0|) |phi0| (eq. 4),
  // c = dt g / h^2 with dt = eps^2.
  const double xi = 1.0 / (std::sqrt(2.0) * std::atanh(0.99));
  const double eps = 2.0 / (std::sqrt(2.0) * std::atanh(0.99));
  const double a0 = std::tanh((1.0 - 0.8) / (std::sqrt(2.0) * xi));
  const double a1 = std::tanh((1.0 - 1.3) / (std::sqrt(2.0) * xi));
  NV_CHECK_NEAR(solver.GetPhi()[0], a0, 1e-15);
  NV_CHECK_NEAR(solver.GetPhi()[1], a1, 1e-15);
  NV_CHECK_NEAR(solver.GetPhi()[2], 0.99, 0.0);
  NV_CHECK_NEAR(solver.GetPhi()[3], -0.99, 0.0);
  const double c0 = eps * eps * (1 - std::fabs(a0)) * std::fabs(a0);
  const double c1 = eps * eps * (1 - std::fabs(a1)) * std::fabs(a1);

  // (10)-(11): (1 + 6 c0) x0 - c0 (x1 + 5 * 0.99) = a0
  //            (1 + 6 c1) x1 - c1 (x0 - 5 * 0.99) = a1
  const double m00 = 1 + 6 * c0, m01 = -c0, r0 = a0 + 5 * 0.99 * c0;
  const double m10 = -c1, m11 = 1 + 6 * c1, r1 = a1 - 5 * 0.99 * c1;
  const double det = m00 * m11 - m01 * m10;
  const double x0 = (r0 * m11 - m01 * r1) / det;
  const double x1 = (m00 * r1 - m10 * r0) / det;

  double lastChange = 1.0;
  const int sweeps = solver.Diffuse(&lastChange);
  NV_CHECK(sweeps > 1 && sweeps < 100);
  NV_CHECK(lastChange < 1e-15);
  NV_CHECK_NEAR(solver.GetPhi()[0], x0, 1e-14);
  NV_CHECK_NEAR(solver.GetPhi()[1], x1, 1e-14);
  // The Dirichlet slots never change.
  NV_CHECK_NEAR(solver.GetPhi()[2], 0.99, 0.0);
  NV_CHECK_NEAR(solver.GetPhi()[3], -0.99, 0.0);
}

void TestReactionClosedForm()
{
  // Fixed points of F'(phi) = phi^3 - phi: -1, 0, 1.
  for (double decay : { 0.0, 0.3, 1.0 })
  {
    NV_CHECK_NEAR(nv::ReactionStep(1.0, decay), 1.0, 1e-15);
    NV_CHECK_NEAR(nv::ReactionStep(-1.0, decay), -1.0, 1e-15);
    NV_CHECK_NEAR(nv::ReactionStep(0.0, decay), 0.0, 0.0);
  }
  // g = 0 (decay = 1): no change.
  NV_CHECK_NEAR(nv::ReactionStep(0.37, 1.0), 0.37, 1e-15);

  // (9): dphi/dt = -g (phi^3 - phi) / eps^2, integrated by RK4 with small steps,
  // must match (12) with decay = exp(-2 g dt / eps^2).
  const double g = 0.21, eps = 0.8, dt = 0.64;
  for (double phi0 : { -0.9, -0.3, 0.05, 0.5, 0.97 })
  {
    auto rate = [&](double phi) { return -g * (phi * phi * phi - phi) / (eps * eps); };
    double phi = phi0;
    const int n = 20000;
    const double tau = dt / n;
    for (int i = 0; i < n; ++i)
    {
      const double k1 = rate(phi), k2 = rate(phi + 0.5 * tau * k1), k3 = rate(phi + 0.5 * tau * k2),
                   k4 = rate(phi + tau * k3);
      phi += tau * (k1 + 2 * k2 + 2 * k3 + k4) / 6;
    }
    NV_CHECK_NEAR(nv::ReactionStep(phi0, std::exp(-2 * g * dt / (eps * eps))), phi, 1e-12);
  }
}

void TestEdgeStopping()
{
  NV_CHECK_NEAR(nv::EdgeStop(0.5, true), 0.25, 0.0);
  NV_CHECK_NEAR(nv::EdgeStop(-0.2, true), 0.16, 1e-16);
  NV_CHECK_NEAR(nv::EdgeStop(-0.2, false), 0.96, 1e-16);
  NV_CHECK_NEAR(nv::EdgeStop(0.0, true), 0.0, 0.0);
}

void TestStepAndStoppingRule()
{
  const nv::NarrowBand band = TwoNodeBand();
  nv::Parameters p = SchemeParameters();
  p.MaximumNumberOfIterations = 50;
  p.ConvergenceTolerance = 0.0;
  nv::AllenCahnSolver fixed(band, p);
  NV_CHECK(fixed.Run().size() == 50); // tolerance 0: exactly the maximum

  p.ConvergenceTolerance = 1e-3;
  nv::AllenCahnSolver stopping(band, p);
  const std::vector<nv::StepReport> reports = stopping.Run();
  NV_CHECK(reports.size() < 50);
  NV_CHECK(reports.back().RelativeChange < 1e-3);
  for (std::size_t n = 0; n + 1 < reports.size(); ++n)
  {
    NV_CHECK(reports[n].RelativeChange >= 1e-3);
  }
}

} // namespace

int main()
{
  TestImplicitStep();
  TestReactionClosedForm();
  TestEdgeStopping();
  TestStepAndStoppingRule();
  return nvtest::Result("TestCoreScheme");
}
