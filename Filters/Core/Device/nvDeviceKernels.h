// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The device back end's kernels: one source for the host and the GPU.
//
// Each kernel is a small struct whose call operator is the work of one band
// node s, written once over plain arrays (EvolutionArrays). Under nvcc the
// call operators are __host__ __device__ (NV_HD): the CUDA launcher
// (nvCudaLauncher.cu) runs them on the GPU, one thread a node, and the host
// launcher (nvHostLauncher.cxx) runs the very same functions over the
// thread pool (nvParallel.h), so the whole device algorithm runs and is
// tested on every machine. The loops around them (the sweeps, the
// over-relaxation's estimate, the stopping rule) are host code shared by
// both launchers (nvDeviceEvolution.cxx); a launcher only allocates, copies
// and launches.
//
// The formulas are those of the CPU core's solver (nvAllenCahnSolver.cxx),
// written the same way term for term, so that the host launcher gives the
// CPU core's phi bit for bit (the DeviceBackEnd test checks it). On a GPU,
// nvcc contracts a * b + c into fused multiply-adds and the reductions sum
// in another order: phi then differs in the last bits, not more.
//
// This header is plain C++ for the host compiler: it includes nothing of
// CUDA, and no STL beyond <cmath> and <cstdint>, whose math functions
// (::exp, ::sqrt, ::fabs, ::copysign, in double) CUDA provides on the device.
#ifndef nvDeviceKernels_h
#define nvDeviceKernels_h

#include <cmath>
#include <cstdint>

#if defined(__CUDACC__)
#define NV_HD __host__ __device__
#else
#define NV_HD
#endif

namespace nv
{
namespace device
{

/**
 * The band as both sides hold it: a structure of arrays indexed by the band
 * node s = 0 .. Size - 1, red nodes first, then black ones (nvNarrowBand.h),
 * and the neighbour table. On the GPU these pointers are device memory, on
 * the host the band's own arrays or host copies. Precision, array by array:
 *
 * - Neighbor: uint32, 6 a node (-x, +x, -y, +y, -z, +z), the band's own
 *   table, unchanged: indices into Phi, Size and Size + 1 being the two
 *   Dirichlet slots of eq. (5). 32 bits address bands of up to 4.29e9 nodes
 *   (nvNarrowBand.h's MaximumBandSize), half the bytes of 64-bit indices.
 * - Distance: double, d of eq. (6), read once by InitialPhiKernel. Double as
 *   the CPU core's, so that phi0 is the same bits (float would move the
 *   sheets by up to 6e-8 of the box, but it would break the host launcher's
 *   bit-for-bit check against the CPU core).
 * - Phi: double, Size + 2 values. The Gauss-Seidel sweeps stop on changes of
 *   1e-6 (GaussSeidelTolerance) of values near 1, a tenth of float's
 *   resolution there (6e-8) only: in float the stopping test would measure
 *   rounding. Double also keeps the norms of the stopping rule exact enough
 *   for ConvergenceTolerance down to 1e-5 and below.
 * - Previous: double, phi^n (the right-hand side of eq. 10 and the stopping
 *   rule's reference): the same reasons as Phi.
 * - Coupling: double, w = c / (1 + 6 c), c = dt g / h^2 (eq. 10-11), read
 *   every sweep; double as the CPU core's, for the bit-for-bit check. (A
 *   float w would save 4 bytes of the 46 a node that a sweep reads; it is
 *   a candidate once the GPU's timings are measured.)
 * - Decay: float, exp(-2 g dt / eps^2) of eq. (12), read once a step, as
 *   the CPU core's (its rounding moves phi by at most 3e-8 a step).
 */
struct EvolutionArrays
{
  std::int64_t Size = 0;
  const std::uint32_t* Neighbor = nullptr;
  const double* Distance = nullptr;
  double* Phi = nullptr;
  double* Previous = nullptr;
  double* Coupling = nullptr;
  float* Decay = nullptr;
};

/// The scheme's constants (nvParameters.h), computed once on the host.
struct EvolutionConstants
{
  double Offset = 0.0;        ///< l
  double Xi = 0.0;            ///< xi of eq. (2)
  double TimeStep = 0.0;      ///< dt
  double Spacing = 0.0;       ///< h
  double Epsilon = 0.0;       ///< eps of eq. (12)
  bool EdgeStopEq4 = true;    ///< g of eq. (4), else of eq. (3)
};

/// phi0 = tanh((l - d) / (sqrt(2) xi)), eq. (2), as AllenCahnSolver::InitialPhi.
NV_HD inline double InitialPhi(double distance, double offset, double xi)
{
  const double z = (offset - distance) / (::sqrt(2.0) * xi);
  const double e = ::exp(-2.0 * ::fabs(z));
  return ::copysign((1.0 - e) / (1.0 + e), z);
}

/// g of eq. (4) or eq. (3), as AllenCahnSolver::EdgeStop.
NV_HD inline double EdgeStop(double phi0, bool eq4)
{
  const double a = ::fabs(phi0);
  return eq4 ? (1.0 - a) * a : 1.0 - phi0 * phi0;
}

/// Eq. (12) over one step, as AllenCahnSolver::React.
NV_HD inline double React(double phi, double decay)
{
  const double q = decay + phi * phi * (1.0 - decay);
  return q > 0.0 ? phi / ::sqrt(q) : phi;
}

/// phi^0 of eq. (2) at node s (d = +inf gives -1).
struct InitialPhiKernel
{
  EvolutionArrays A;
  EvolutionConstants C;
  NV_HD void operator()(std::int64_t s) const { A.Phi[s] = InitialPhi(A.Distance[s], C.Offset, C.Xi); }
};

/// The per-node coefficients of (10) and (12) from phi^0, and phi^n = phi^0.
struct CoefficientsKernel
{
  EvolutionArrays A;
  EvolutionConstants C;
  NV_HD void operator()(std::int64_t s) const
  {
    const double phi0 = A.Phi[s];
    const double g = EdgeStop(phi0, C.EdgeStopEq4); // eq. (4) or (3)
    const double c = C.TimeStep * g / (C.Spacing * C.Spacing);
    A.Coupling[s] = c / (1.0 + 6.0 * c);
    A.Decay[s] = static_cast<float>(::exp(-2.0 * g * C.TimeStep / (C.Epsilon * C.Epsilon)));
    A.Previous[s] = phi0;
  }
};

/// phi^n = phi at the start of a step.
struct KeepPreviousKernel
{
  EvolutionArrays A;
  NV_HD void operator()(std::int64_t s) const { A.Previous[s] = A.Phi[s]; }
};

/// One node of a red or black half sweep of (10)-(11), over-relaxed by
/// Omega; returns |change| (the sweeps' stopping test takes the max).
/// A red node reads only black neighbours and the reverse, so the nodes of
/// one colour are independent: any order, any number of threads, the same
/// result.
struct RelaxKernel
{
  EvolutionArrays A;
  double Omega = 1.0;
  NV_HD double operator()(std::int64_t s) const
  {
    // (1 + 6 c) phi_s - c sum(neighbours) = phi^n_s, c = dt g_s / h^2, so
    // phi_s = phi^n_s + w (sum - 6 phi^n_s) with w = c / (1 + 6 c).
    const std::uint32_t* n = A.Neighbor + 6 * s;
    const double* phi = A.Phi;
    const double sum = phi[n[0]] + phi[n[1]] + phi[n[2]] + phi[n[3]] + phi[n[4]] + phi[n[5]];
    const double rhs = A.Previous[s];
    const double solved = rhs + A.Coupling[s] * (sum - 6.0 * rhs);
    const double step = Omega * (solved - phi[s]);
    A.Phi[s] += step;
    return ::fabs(step);
  }
};

/// The reaction step (12) at node s, in place.
struct ReactKernel
{
  EvolutionArrays A;
  NV_HD void operator()(std::int64_t s) const { A.Phi[s] = React(A.Phi[s], A.Decay[s]); }
};

/// The terms of the stopping rule's norms (section 4) at node s.
struct ChangeSquaredKernel
{
  EvolutionArrays A;
  NV_HD double operator()(std::int64_t s) const
  {
    return (A.Phi[s] - A.Previous[s]) * (A.Phi[s] - A.Previous[s]);
  }
};
struct NormSquaredKernel
{
  EvolutionArrays A;
  NV_HD double operator()(std::int64_t s) const { return A.Previous[s] * A.Previous[s]; }
};

} // namespace device
} // namespace nv

#endif
