// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The operator-split Allen-Cahn scheme of section 3 on the band nodes:
// implicit diffusion (10)-(11) by red-black Gauss-Seidel, then the closed-form
// reaction step (12).
#ifndef nvAllenCahnSolver_h
#define nvAllenCahnSolver_h

#include "nvMemory.h"
#include "nvNarrowBand.h"
#include "nvParameters.h"
#include "nvTimeLoop.h"

#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

namespace nv
{
class DriftCorrection;
class Halo;
class Monitor;

using SolverValues = UninitializedVector<double>;
using SolverFloats = UninitializedVector<float>;

class AllenCahnSolver
{
public:
  /**
   * Sets phi^0 by eq. (2) and the per-node coefficients of (10) and (12).
   * halo: in a distributed run, the exchange with the neighbouring processes
   * (the sweeps then update the owned nodes only, and the stopping tests use
   * global norms); null in a serial run.
   */
  AllenCahnSolver(const NarrowBand& band, const Parameters& parameters, Halo* halo = nullptr);
  /**
   * The same from phi^0 as InitialField returns it: the band's distances are
   * not read, so a caller short of memory frees them first (the solver's
   * three other arrays then take their place).
   */
  AllenCahnSolver(const NarrowBand& band, const Parameters& parameters, BandValues phi0, Halo* halo = nullptr);
  ~AllenCahnSolver();

  /// phi^0 of eq. (2) at the band nodes and the Dirichlet values of eq. (5)
  /// in slots L and L + 1: the only use of the band's distances.
  static BandValues InitialField(const NarrowBand& band, const Parameters& parameters);

  /// One time step: diffusion (10) then reaction (12). With PreserveOffset,
  /// the multiplier of the last step first, and a measurement after (unless
  /// last is true: no step follows to use it).
  StepReport Step(bool last = false);

  /**
   * Runs steps until the relative change drops below the convergence
   * tolerance (if > 0) or MaximumNumberOfIterations steps are done, or the
   * monitor asks to stop. Returns the reports of the steps taken.
   */
  std::vector<StepReport> Run(Monitor* monitor = nullptr);

  /// Implicit step (10)-(11): solves phi* - dt g Lap_h phi* = phi^n in place.
  /// Returns the number of sweeps and sets the last sweep's max change.
  int Diffuse(double* lastChange = nullptr);
  /// Reaction step (12), in place.
  void React();

  /// Frees the arrays only the time steps need; phi stays.
  void ReleaseWorkspace();

  /// phi at band node s (s < L); slots L and L + 1 hold the Dirichlet values.
  const BandValues& GetPhi() const { return this->Phi; }
  BandValues& GetPhi() { return this->Phi; }

private:
  /// One red or black half sweep over [begin, end), over-relaxed by omega;
  /// returns the max |change|.
  double HalfSweep(std::int64_t begin, std::int64_t end, double omega);

  /// Sum over the owned nodes of fn(s), over all processes in a distributed run.
  template <typename Fn>
  double OwnedSum(Fn&& fn);

  const NarrowBand& Band;
  Halo* Exchange = nullptr;
  Parameters Params;
  OverRelaxation Relaxation{ Params.Relaxation }; ///< the sweeps' factor, estimated once (nvTimeLoop.h)
  BandValues Phi;              ///< L + 2 values
  SolverValues Previous; ///< phi^n, the right-hand side of (10)
  SolverValues Coupling; ///< w_s = c_s / (1 + 6 c_s), c_s = dt g_s / h^2
  SolverFloats Decay;    ///< exp(-2 g_s dt / eps^2), in float (ReactionDecay)
  std::unique_ptr<DriftCorrection> Correction; ///< with PreserveOffset only
};

} // namespace nv

#endif
