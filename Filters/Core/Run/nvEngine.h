// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The seam between the run (nvReconstruction.h) and what computes it: an
// engine builds the band (step 5), evolves phi on it (step 6), fills the
// dense arrays and makes the surface (step 7). Two engines, chosen once per
// run by MakeEngine:
//
//   the CPU engine     the core's own stages on the host's threads
//                      (Band, Scheme, Output), in a distributed run too;
//   the device engine  the device back end (Device/): the same equations
//                      (each written once, for both) in kernels that a
//                      launcher runs on a GPU, or on the host's threads
//                      for the tests (GpuKernels::OnHost).
//
// The one fallback rule: Device GPU does not fall back to the CPU. What the
// device cannot do (DeviceCannot), a device that fails, and a device with
// too little free memory for the band or the evolution (checked before
// each, nvDeviceEngine.cxx) stop the run with an error that says so and to
// choose Device CPU or Automatic (which runs on the CPU until the GPU has
// passed its tests on one, so it never meets these checks).
//
// This header is the interface only: the run, the VTK filter and the Python
// binding that include it compile no kernels.
#ifndef nvEngine_h
#define nvEngine_h

#include "nvDeviceMemory.h"
#include "nvDevices.h"
#include "nvNarrowBand.h"
#include "nvParameters.h"
#include "nvPartition.h"
#include "nvSettings.h"
#include "nvStageTimes.h"
#include "nvTimeLoop.h"
#include "nvVolume.h"

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace nv
{
namespace device
{
class Launcher;
}
class Halo;
class Monitor;
class SurfaceSink;

/// What an engine throws when its device fails: the message is the run's
/// error, whole.
class EngineError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/// The dense arrays a run fills (Reconstruction::RequestVolume), for the
/// node layers [Begin, End).
struct DenseVolume
{
  VolumeArrays Arrays;
  std::int64_t Begin = 0;
  std::int64_t End = 0;
};

/// What the engine's stages of a run share: where they report.
struct EngineContext
{
  Monitor* TheMonitor = nullptr; ///< progress and stop (may be null)
  bool StoppableSort = false;    ///< whether the points' sort may stop (a serial run)
  const Subdomain* Part = nullptr;
  StageTimes* Stages = nullptr;
};

class Engine
{
public:
  virtual ~Engine();
  virtual DeviceKind Kind() const = 0;
  /// "CPU", "GPU", or "GPU on the host" (GpuKernels::OnHost).
  virtual std::string Name() const = 0;

  /**
   * Step 5: the points (world coordinates, consumed) sorted into bricks,
   * the distances of eq. (6) and the band built from them (the paper's
   * band construction, nvNarrowBand.h); `dense`, unless null, gets every
   * reached node's distance and phi0 and the others' far values. The
   * band's RefusedSize is set where it would not fit; after a stop it is
   * empty (the caller asks the monitor). Adds the "distance" and the band's
   * stages.
   */
  virtual NarrowBand BuildBand(const Grid& grid, const Parameters& scheme, std::vector<double> xyz,
    const DenseVolume* dense, const EngineContext& context) = 0;
  /**
   * Step 6: phi^0 (eq. 2) and the time steps (10)-(12) on the band until
   * the stopping rule; one report a step. `halo`: the exchange with the
   * other processes, null when serial (the device engine runs serial runs
   * only: DeviceCannot).
   */
  virtual std::vector<StepReport> Evolve(
    NarrowBand& band, const Parameters& scheme, Halo* halo, const EngineContext& context) = 0;
  /// After a whole Evolve: the dense arrays' band nodes from phi (the
  /// "volume" stage), and what the outputs do not read freed (the
  /// distances, the neighbour table, the evolution's arrays).
  virtual void FinishEvolution(NarrowBand& band, const EngineContext& context) = 0;
  /// phi at the band's nodes and its two Dirichlet slots, after Evolve.
  virtual const BandValues& Phi() const = 0;
  /**
   * Step 7: the phi = 0 surface of the brick layers `owned` into `sink`.
   * Returns false if the monitor stopped it.
   */
  virtual bool Surface(const Grid& grid, const NarrowBand& band, const Parameters& scheme, const LayerRange& owned,
    SurfaceSink& sink, Monitor* monitor) = 0;
  /// The most bytes the device held at once (0 for the CPU).
  virtual double DeviceBytes() const { return 0.0; }
  /// The copies between the host and the device so far (none on the CPU).
  virtual CopyCounts DeviceCopies() const { return CopyCounts(); }
  /// Frees phi and everything else the engine holds.
  virtual void Release() = 0;
};

/**
 * What Device GPU cannot do in a run with these settings (distributed: a
 * run of several processes), as the error's words; empty when it can.
 */
std::string DeviceCannot(const Settings& settings, bool distributed);

/**
 * The engine for `settings.Device`: the CPU's for CPU and Automatic, the
 * device's for GPU with its kernels where `kernels` says. Null with `error`
 * set where Device GPU cannot run (DeviceCannot, or no CUDA device).
 */
std::unique_ptr<Engine> MakeEngine(
  const Settings& settings, bool distributed, GpuKernels kernels, std::string& error);

/// The device engine on a launcher of the caller's (tests: a launcher that
/// fails on purpose); `name` is its Name().
std::unique_ptr<Engine> MakeDeviceEngine(std::unique_ptr<device::Launcher> launcher, const std::string& name);

} // namespace nv

#endif
