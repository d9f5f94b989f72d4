// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// nv::Reconstruction, the run of the narrow volume method for one process
// or for each process of a distributed run: steps 1-6 of the steps that
// nvReconstruct.h lists (Run: the checks, the grid, the slab and the points,
// the memory budget, the distance and the band, the time steps) and step
// 7's surface from the band (ExtractSurface). nv::Reconstruct
// (nvReconstruct.h), the core's entry point, calls it and makes the
// outputs; the filters call nv::Reconstruct.
#ifndef nvReconstruction_h
#define nvReconstruction_h

#include "nvDeviceMemory.h"
#include "nvDevices.h"
#include "nvGapClosing.h"
#include "nvGrid.h"
#include "nvHalo.h"
#include "nvNarrowBand.h"
#include "nvParameters.h"
#include "nvPartition.h"
#include "nvPlan.h"
#include "nvSampling.h"
#include "nvSettings.h"
#include "nvStageTimes.h"
#include "nvVolume.h"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace nv
{
class Communicator;
class Engine;
struct EngineContext;
class Monitor;
class ShareMonitor;
class SurfaceSink;

/// The share of a run's progress that the measurement of the points'
/// spacing shows, when it is made for the run (the set-up's stage starts at
/// 0 as well, and shows once past it).
constexpr double SamplingStage = 0.1;

/// The share of the job's progress that the run (steps 1-6) takes, before
/// the outputs: its stages' own figures are of a shell's job. A part to
/// print (WallThickness > 0) takes about 80 % of the job's time (the bunny
/// at its defaults with a wall: 2.6 s of 3.2), so there the run takes the
/// first PrintRunShare of the progress (Reconstruction::OutputBegin).
constexpr double RunShare = 0.65;
constexpr double PrintRunShare = 0.2;
/// With the scan surface (Sheets Scan), the run's steps 1-6 take the first
/// ScanRunShare: the surface takes about twice their time.
constexpr double ScanRunShare = 0.35;

class Reconstruction
{
public:
  /// communicator: the other processes of a distributed run, or null.
  /// monitor: progress and abort, or null. kernels: where Device GPU's
  /// kernels run (nvEngine.h; OnHost for tests and benchmarks).
  Reconstruction(const Settings& settings, Communicator* communicator, Monitor* monitor,
    GpuKernels kernels = GpuKernels::OnGpu);
  /// The same on an engine of the caller's (tests: MakeDeviceEngine with a
  /// launcher that fails on purpose), which the run takes as it is.
  Reconstruction(const Settings& settings, Communicator* communicator, Monitor* monitor,
    std::unique_ptr<Engine> engine);
  ~Reconstruction();

  /// Returns the dense arrays to fill for the node layers [kBegin, kEnd).
  using VolumeAllocator = std::function<VolumeArrays(std::int64_t kBegin, std::int64_t kEnd)>;
  /**
   * Asks Run for the dense arrays of this process's piece and up to
   * `ghostLayers` node layers on each side (within the computed layers):
   * `allocate` is called once the piece is known, before the distances, and
   * the arrays are complete when Run returns true.
   */
  void RequestVolume(std::int64_t ghostLayers, VolumeAllocator allocate);

  /**
   * Steps 1-6 for this process's points (xyz triples). Returns false when the
   * run stops: Error() says why (the same on every process), or Aborted().
   * In a distributed run every process must call it. `measured`: the
   * sampling of these same points if known already (else it is measured).
   */
  bool Run(std::vector<double> xyz, std::shared_ptr<const Sampling> measured = nullptr);
  const std::string& Error() const { return this->Message; }
  bool Aborted() const { return this->Stopped; }

  /// The caller's monitor (may be null): the outputs report to it from
  /// OutputBegin(); the run's own stages go to it within [0, OutputBegin()).
  Monitor* GetMonitor() const { return this->Caller; }
  double OutputBegin() const;
  /// Whether this is the first process (or the only one): the one that
  /// speaks for the whole result.
  bool FirstProcess() const;

  /// Collective: whether `flag` is true on any process (itself when serial).
  bool Anywhere(bool flag);
  /// Collective: the sum over processes (itself when serial).
  double SumAll(double value);

  const Settings& GetSettings() const { return this->TheSettings; }
  const Grid& GetGrid() const { return this->ThePlan.TheGrid; }
  const Plan& GetPlan() const { return this->ThePlan; }
  const SamplingStatistics& GetSampling() const { return this->TheSampling->Statistics(); }
  /// The holes of the sampling left open (nvGapClosing.h).
  const GapReport& GetGaps() const { return this->Gaps; }
  /// The points the gap closing added (all processes).
  std::int64_t AddedPoints() const { return this->Added; }
  const Parameters& GetParameters() const { return this->ThePlan.Scheme; }
  /// The node layers along z of this process's output piece: its owned brick
  /// layers and the first node layer of the next piece, which both share.
  std::int64_t PieceBegin() const { return this->Piece[0]; }
  std::int64_t PieceEnd() const { return this->Piece[1]; }
  /// The node layers this process computes (its piece and ghost layers).
  std::int64_t ComputedBegin() const { return this->Computed[0]; }
  std::int64_t ComputedEnd() const { return this->Computed[1]; }
  bool EmptyPiece() const { return this->Piece[1] <= this->Piece[0]; }
  /// Band nodes of all processes.
  std::int64_t NumberOfBandNodes() const { return this->BandNodes; }
  const std::vector<double>& RelativeChanges() const { return this->Changes; }
  /// The seconds of the run's stages, in the order they ran (the outputs
  /// add theirs, nvReconstruct.h).
  const StageTimes& GetStageTimes() const { return this->Stages; }
  StageTimes& GetStageTimes() { return this->Stages; }
  double SetupSeconds() const { return this->SetupTime; }
  double EvolutionSeconds() const { return this->EvolutionTime; }

  /// The node layers of the dense arrays (RequestVolume).
  std::int64_t VolumeBegin() const { return this->Volume[0]; }
  std::int64_t VolumeEnd() const { return this->Volume[1]; }

  /// Step 7: the phi = 0 surface of this process's piece, from the band
  /// (nvSurfaceField.h, nvSurface.h). Returns false if the monitor stopped
  /// it, or if the device failed (Error() says so).
  bool ExtractSurface(SurfaceSink& sink);

  /// The band (after Run, its nodes only: the solver's other arrays are freed).
  const NarrowBand& GetBand() const { return this->Band; }
  const BandValues& GetPhi() const;

  /// The device that ran the job (the field data's DeviceUsed), and its
  /// name: "CPU", "GPU" (CUDA), or "GPU on the host" (GpuKernels::OnHost).
  /// CPU before the run has chosen.
  DeviceKind DeviceUsed() const;
  std::string DeviceName() const;
  /// The most bytes the GPU held at once (0 on the CPU): from the distance
  /// to the evolution's end (the dense volume's included), or while it made
  /// the surface (ExtractSurface), whichever held more.
  double DeviceBytes() const;
  /// The run's copies between the host and the GPU, bytes and seconds each
  /// way (none on the CPU or through the host launcher).
  CopyCounts DeviceCopies() const;

  /// Frees the band and phi once the outputs no longer need them (after the
  /// surface is extracted), so that the surface's last steps (small pieces,
  /// the output's arrays) do not hold them too. GetBand and GetPhi are then empty.
  void ReleaseBand();

private:
  bool RunSteps(std::vector<double> xyz, std::shared_ptr<const Sampling> measured);
  // The steps of Run, in order (nvReconstruct.h's list); each returns false when the run stops.
  bool CheckPoints(const std::vector<double>& xyz, double bounds[6]);
  /// Whether double precision resolves the cloud at its distance from the origin.
  bool CheckPrecision(const double bounds[6], std::int64_t points);
  bool PlanGrid(const std::vector<double>& xyz, const double bounds[6], std::shared_ptr<const Sampling> measured);
  bool GatherPoints(std::vector<double>& xyz);
  bool BuildBand(std::vector<double> xyz);
  bool ChooseEngine();
  bool Evolve();
  /// Where the engine's stages report (nvEngine.h).
  EngineContext Context();
  bool ProbeHoles();
  bool Fail(const std::string& message);
  bool CheckMemory(double gridNodes, double points);
  /// The error of a printing run whose grid, made fine for the wall
  /// (Plan::WallSpacing), is over the memory limit: the spacing the wall
  /// needs, the memory that takes, and the ways out with their figures.
  std::string WallGridTooLarge(
    double gridNodes, double bytes, double limit, double perNode, double points, bool withBand) const;
  void Partition(const std::vector<double>& xyz, std::int64_t layers);
  bool CloseGaps(std::vector<double>& xyz, GapClosing& closing);

  Settings TheSettings;
  GpuKernels Kernels;
  Communicator* Comm;
  Monitor* Caller;
  std::unique_ptr<ShareMonitor> RunStages; ///< the caller's, within [0, OutputBegin())
  Monitor* TheMonitor;                     ///< what the run's stages report to: RunStages, or null
  Plan ThePlan;
  std::shared_ptr<const Sampling> TheSampling;
  GapReport Gaps;
  std::int64_t Added = 0;
  std::vector<LayerRange> Owners;
  Subdomain Part;
  std::int64_t Piece[2] = { 0, 0 };
  std::int64_t Computed[2] = { 0, 0 };
  std::int64_t Volume[2] = { 0, 0 };
  std::int64_t VolumeGhosts = 0;
  VolumeAllocator AllocateVolume;
  double BytesBeforeBand = 0.0;
  double PointsBeforeBand = 0.0; ///< the points CheckMemory counted
  NarrowBand Band;
  std::unique_ptr<Halo> TheHalo;
  std::unique_ptr<Engine> TheEngine;   ///< chosen once, the run's first step
  std::unique_ptr<Engine> GivenEngine; ///< the caller's, for the next run
  std::int64_t BandNodes = 0;
  std::vector<double> Changes;
  double SetupTime = 0.0;
  double EvolutionTime = 0.0;
  StageTimes Stages;
  std::string Message;
  bool Stopped = false;
};

} // namespace nv

#endif
