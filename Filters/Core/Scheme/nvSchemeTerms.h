// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The scheme's terms at one band node, written once: the CPU's solver
// (nvAllenCahnSolver.cxx) and the device back end's kernels
// (Device/nvDeviceKernels.h) both call these functions, so the two cannot
// drift apart. Under nvcc they are __host__ __device__ (NV_HD); they use
// only the double-precision math that CUDA provides on the device (::exp,
// ::sqrt, ::fabs, ::copysign).
//
// The loops around them (which nodes, in which order, on which threads)
// stay with each side; the sweeps' and the steps' loops, shared too, are in
// nvTimeLoop.h.
#ifndef nvSchemeTerms_h
#define nvSchemeTerms_h

#include "nvHostDevice.h"

#include <cmath>
#include <cstdint>

namespace nv
{

/// phi0 = tanh((l - d) / (sqrt(2) xi)), eq. (2). tanh z = (1 - e^(-2|z|)) /
/// (1 + e^(-2|z|)), signed as z: one exp, which costs a third of a tanh
/// (the solver's start-up takes one per band node); within 1e-16 of tanh,
/// and -1 at d = infinity.
NV_HD inline double InitialPhi(double distance, double offset, double xi)
{
  const double z = (offset - distance) / (::sqrt(2.0) * xi);
  const double e = ::exp(-2.0 * ::fabs(z));
  return ::copysign((1.0 - e) / (1.0 + e), z);
}

/// g of eq. (4) (eq4 true) or of eq. (3), for a given phi0.
NV_HD inline double EdgeStop(double phi0, bool eq4)
{
  const double a = ::fabs(phi0);
  return eq4 ? (1.0 - a) * a : 1.0 - phi0 * phi0;
}

/// The weight of the implicit step (10)-(11) at a node: w = c / (1 + 6 c),
/// c = dt g / h^2.
NV_HD inline double CouplingWeight(double g, double timeStep, double spacing)
{
  const double c = timeStep * g / (spacing * spacing);
  return c / (1.0 + 6.0 * c);
}

/// The decay of eq. (12) over one step, exp(-2 g dt / eps^2), in single
/// precision: read once a step, where its rounding (relative 6e-8) moves phi
/// by at most 3e-8 a step, less than the rounding of the volume output's
/// float phi; 4 bytes a node saved.
NV_HD inline float ReactionDecay(double g, double timeStep, double epsilon)
{
  return static_cast<float>(::exp(-2.0 * g * timeStep / (epsilon * epsilon)));
}

/// The closed-form solution of (9) over one step, eq. (12), decay =
/// ReactionDecay. A decay that underflows to 0 (huge dt) sends phi to
/// sign(phi), and 0 stays 0.
NV_HD inline double ReactionStep(double phi, double decay)
{
  const double q = decay + phi * phi * (1.0 - decay);
  return q > 0.0 ? phi / ::sqrt(q) : phi;
}

/**
 * One node's over-relaxed Gauss-Seidel change in the implicit step
 * (10)-(11), its six neighbours `n` (indices into phi) held fixed:
 * (1 + 6 c) phi_s - c sum(neighbours) = phi^n_s, c = dt g_s / h^2, so
 * phi_s = phi^n_s + w (sum - 6 phi^n_s) with w = CouplingWeight; the change
 * is omega times the distance to that value. The caller adds it to phi[s].
 */
NV_HD inline double RelaxationChange(
  const double* phi, const std::uint32_t* n, std::int64_t s, double previous, double coupling, double omega)
{
  const double sum = phi[n[0]] + phi[n[1]] + phi[n[2]] + phi[n[3]] + phi[n[4]] + phi[n[5]];
  const double solved = previous + coupling * (sum - 6.0 * previous);
  return omega * (solved - phi[s]);
}

/// A node's term of the stopping rule's norms (section 4):
/// (phi^{n+1} - phi^n)^2; the other is (phi^n)^2.
NV_HD inline double SquaredChange(double phi, double previous)
{
  return (phi - previous) * (phi - previous);
}

} // namespace nv

#endif
