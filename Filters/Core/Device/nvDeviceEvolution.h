// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The device back end's evolution: phi^0 (eq. 2), g (eq. 4 or 3) and the
// operator-split time steps (eq. 10-12) on the band, with the CPU core's
// sweeps, over-relaxation and stopping rule (nvAllenCahnSolver.h), run by a
// launcher (nvDeviceLauncher.h): on the GPU or, for the tests and machines
// without one, over the host's threads.
//
// Serial runs only (no halo exchange), and without PreserveOffset's drift
// correction: the run refuses those with the GPU (nvReconstruction.cxx).
#ifndef nvDeviceEvolution_h
#define nvDeviceEvolution_h

#include "nvAllenCahnSolver.h"
#include "nvDeviceLauncher.h"
#include "nvNarrowBand.h"
#include "nvParameters.h"

#include <vector>

namespace nv
{
class Monitor;

namespace device
{

/// The scheme's constants of nvDeviceKernels.h from the parameters.
EvolutionConstants ConstantsOf(const Parameters& parameters);

/**
 * Evolves phi on `band` (its distances and neighbour table, unchanged; or,
 * where the launcher built the band and `band` has no neighbour table, the
 * launcher's) with `launcher`: phi^0, then time steps until the relative change drops below
 * ConvergenceTolerance (if > 0) or MaximumNumberOfIterations steps are done,
 * or the monitor asks to stop. Returns one report a step. phi stays on the
 * device, for the dense volume and the surface there; launcher.Download
 * brings it to the host (L + 2 values, as AllenCahnSolver::GetPhi) only
 * where something on the host reads it (the device engine: Engine::Phi).
 * Throws DeviceError when the device fails.
 */
std::vector<StepReport> Evolve(
  const NarrowBand& band, const Parameters& parameters, EvolutionLauncher& launcher, Monitor* monitor);

} // namespace device
} // namespace nv

#endif
