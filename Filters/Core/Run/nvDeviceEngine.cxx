// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The device engine (nvEngine.h): the band, the evolution, the dense volume
// and the surface by the device back end's kernels (Device/), on a GPU or
// through the host launcher. One process, no PreserveOffset (DeviceCannot).
// The points go up once; the band's distances and neighbour table are built
// and stay there for the evolution; phi stays there for the dense volume and
// the surface, and comes back only if the host reads it (Phi: the hole
// probe, a caller's GetPhi), once.
//
// Before the band is built, and again before the evolution, the engine
// compares what the stage will need on the device (nvDeviceMemory.h's
// counts of the CUDA launcher's arrays) with the device's free memory
// (Launcher::FreeBytes) and refuses a stage that does not fit, with the
// bytes needed and free and what to change (CheckFreeMemory); the band's
// batches shrink first, where smaller ones fit. The surface checks its
// tables and then its outputs likewise (ContourOnDevice). Device GPU
// does not fall back to the CPU (nvEngine.h's one rule); Automatic runs on
// the CPU and never comes here.
#include "nvEngine.h"

#include "nvDeviceDistance.h"
#include "nvDeviceEvolution.h"
#include "nvDeviceLauncher.h"
#include "nvDeviceSurface.h"
#include "nvMemory.h"
#include "nvSurface.h"
#include "nvSurfaceField.h"
#include "nvTruncatedDistance.h"

#include <algorithm>
#include <array>

namespace nv
{
namespace
{
/// The dense kernels' constants, by VolumeWriter's expressions, for the
/// node layers [kBegin, kEnd).
device::DenseConstants DenseConstantsOf(const Grid& grid, const Parameters& scheme, std::int64_t kBegin, std::int64_t kEnd)
{
  device::DenseConstants constants;
  const std::array<std::int64_t, 3> bricks = BrickDimensions(grid);
  for (int a = 0; a < 3; ++a)
  {
    constants.GridDims[a] = grid.Dims[a];
    constants.BrickDims[a] = bricks[a];
  }
  constants.Begin = kBegin;
  constants.End = kEnd;
  constants.Offset = scheme.OffsetDistance;
  constants.Xi = scheme.Xi();
  constants.Far = static_cast<float>(grid.FarDistance());
  return constants;
}

class DeviceEngine : public Engine
{
public:
  DeviceEngine(std::unique_ptr<device::Launcher> launcher, const std::string& name)
    : Launcher(std::move(launcher))
    , TheName(name)
  {
  }

  DeviceKind Kind() const override { return DeviceKind::GPU; }
  std::string Name() const override { return this->TheName; }

  NarrowBand BuildBand(const Grid& grid, const Parameters& scheme, std::vector<double> xyz, const DenseVolume* dense,
    const EngineContext& context) override
  {
    // The points sorted into bricks, the distances of eq. (6) and the band
    // built from them by the kernels, the CPU's bit for bit
    // (nvDeviceDistance.h); the dense arrays, if asked for, from each
    // batch's distances there (nvVolumeKernels.h).
    return Guard([&]() {
      // What the points' sort and the band's batches need, with the dense
      // arrays, against the device's free memory (the band's own arrays
      // come after: their size is known once the distances are). The
      // batches are as large as DefaultBatch, halved while they would not
      // fit, down to MinimumBatch.
      const std::array<std::int64_t, 3> brickDims = BrickDimensions(grid);
      const std::int64_t bricks = brickDims[0] * brickDims[1] * brickDims[2];
      const std::int64_t points = static_cast<std::int64_t>(xyz.size() / 3);
      double denseBytes = 0.0;
      if (dense)
      {
        const VolumeArrays& a = dense->Arrays;
        denseBytes = device::DenseBytes((dense->End - dense->Begin) * grid.Dims[0] * grid.Dims[1],
          (a.Phi ? 1 : 0) + (a.InitialPhi ? 1 : 0) + (a.Distance ? 1 : 0), a.Band != nullptr);
      }
      const auto needed = [&](std::int64_t batch) {
        return device::BandBuildBytes(points, bricks, batch, denseBytes);
      };
      const double free = this->Launcher->FreeBytes();
      std::int64_t batch = std::min(device::LauncherDistance::DefaultBatch, bricks);
      while (batch > device::LauncherDistance::MinimumBatch && needed(batch) > free)
      {
        batch = std::max(device::LauncherDistance::MinimumBatch, batch / 2);
      }
      this->CheckFreeMemory(needed(batch), "to build the narrow band");
      const auto sorting = StageTimes::Clock::now();
      const TruncatedDistance gridOnly(grid, scheme.Reach()); // the points are the device's
      device::LauncherDistance onDevice(gridOnly, xyz.data(), points, *this->Launcher, batch);
      std::vector<double>().swap(xyz);
      context.Stages->Add("distance", sorting);
      if (dense)
      {
        this->Launcher->DenseBegin(dense->Arrays, DenseConstantsOf(grid, scheme, dense->Begin, dense->End));
        this->Dense = true;
        onDevice.FillDense();
      }
      return BuildNarrowBand(gridOnly, scheme, context.TheMonitor, context.Part, nullptr, context.Stages, &onDevice);
    });
  }

  std::vector<StepReport> Evolve(NarrowBand& band, const Parameters& scheme, Halo*, const EngineContext& context) override
  {
    std::vector<StepReport> reports;
    Guard([&]() {
      // The evolution's arrays, on top of the band's, against the device's
      // free memory.
      this->CheckFreeMemory(device::EvolutionBytes(band.Size()),
        "for the evolution on the band's " + std::to_string(band.Size()) + " nodes");
      reports = device::Evolve(band, scheme, *this->Launcher, context.TheMonitor);
      this->Evolved = true;
    });
    return reports;
  }

  void FinishEvolution(NarrowBand& band, const EngineContext& context) override
  {
    if (this->Dense)
    {
      // The band's phi into the dense arrays on the device (DenseBandKernel,
      // the evolution's phi still there), then the arrays to the host, once.
      const auto writing = StageTimes::Clock::now();
      Guard([&]() {
        device::DenseBandArrays arrays;
        arrays.Bricks = band.Bricks.data();
        arrays.RedStart = band.RedStart.data();
        arrays.BlackStart = band.BlackStart.data();
        arrays.Offset = band.Offset.data();
        arrays.Phi = nullptr; // the launcher's own
        this->Launcher->DenseBand(arrays, static_cast<std::int64_t>(band.Bricks.size()), band.Size());
        this->Launcher->DenseDownload();
      });
      context.Stages->Add("volume", writing);
    }
    this->PeakBytes = this->Launcher->DeviceBytes();
    // The device's memory freed but phi's, which the surface takes there.
    this->Launcher->ReleaseEvolution();
    Free(band.Distance);
    Free(band.Neighbor);
    ReleaseFreedMemory();
  }

  const BandValues& Phi() const override
  {
    // Brought to the host the first time it is read there (the surface and
    // the dense volume take it on the device).
    if (this->Evolved && this->HostPhi.empty() && this->Launcher)
    {
      Guard([&]() { this->Launcher->Download(this->HostPhi); });
    }
    return this->HostPhi;
  }

  bool Surface(const Grid& grid, const NarrowBand& band, const Parameters& scheme, const LayerRange&,
    SurfaceSink& sink, Monitor* monitor) override
  {
    // The band's tables go to the device (phi is there), the vertices and
    // triangles come back (nvDeviceSurface.h).
    if (monitor)
    {
      monitor->Progress(0.0);
    }
    Guard([&]() {
      ContourOnDevice(grid, band, this->HostPhi, scheme, *this->Launcher, sink,
        [this](double bytes, const std::string& stage) { this->CheckFreeMemory(bytes, stage); });
    });
    this->PeakBytes = std::max(this->PeakBytes, this->Launcher->DeviceBytes());
    if (monitor)
    {
      monitor->Progress(1.0);
    }
    return !(monitor && monitor->Aborted());
  }

  double DeviceBytes() const override { return this->PeakBytes; }
  CopyCounts DeviceCopies() const override { return this->Launcher ? this->Launcher->Copies() : this->Copied; }

  void Release() override
  {
    if (this->Launcher)
    {
      this->Copied = this->Launcher->Copies();
    }
    BandValues().swap(this->HostPhi);
    this->Evolved = false;
    this->Launcher.reset(); // and phi on the device
  }

private:
  /// Refuses a stage that needs more than the device's free memory: an
  /// EngineError with the bytes needed and free and what to change.
  void CheckFreeMemory(double needed, const std::string& stage) const
  {
    const double free = this->Launcher->FreeBytes();
    if (needed > free)
    {
      throw EngineError("The GPU has too little free memory " + stage + ": it needs about " +
        device::ByteWords(needed) + ", and " + device::ByteWords(free) +
        " is free. Choose a coarser grid (increase SampleSpacing or lower MaximumDimension), or choose "
        "Device CPU or Automatic.");
    }
  }

  /// fn(), its device's failure the run's error (EngineError).
  template <typename Fn>
  static auto Guard(Fn&& fn) -> decltype(fn())
  {
    try
    {
      return fn();
    }
    catch (const device::DeviceError& error)
    {
      throw EngineError(std::string(error.what()) + "\nChoose Device CPU or Automatic.");
    }
  }

  std::unique_ptr<device::Launcher> Launcher;
  std::string TheName;
  bool Dense = false; ///< the device fills the dense arrays
  bool Evolved = false;            ///< the launcher holds the evolved phi
  mutable BandValues HostPhi;       ///< its copy on the host, once Phi is asked for
  double PeakBytes = 0.0;
  CopyCounts Copied; ///< the launcher's, once it is gone
};
} // namespace

std::unique_ptr<Engine> MakeDeviceEngine(GpuKernels kernels, std::string& error)
{
  std::unique_ptr<device::Launcher> launcher;
  if (kernels == GpuKernels::OnHost)
  {
    launcher = device::MakeHostLauncher();
  }
  else
  {
    std::string why;
    try
    {
      launcher = device::MakeCudaLauncher(why);
    }
    catch (const device::DeviceError& failure)
    {
      why = failure.what();
    }
    if (!launcher)
    {
      error = "Device is GPU, but " + why + ". Choose Device CPU or Automatic.";
      return nullptr;
    }
  }
  return MakeDeviceEngine(std::move(launcher), kernels == GpuKernels::OnHost ? "GPU on the host" : "GPU");
}

std::unique_ptr<Engine> MakeDeviceEngine(std::unique_ptr<device::Launcher> launcher, const std::string& name)
{
  return std::unique_ptr<Engine>(new DeviceEngine(std::move(launcher), name));
}

} // namespace nv
