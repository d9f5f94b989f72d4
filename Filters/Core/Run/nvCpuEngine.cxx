// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The CPU engine (nvEngine.h): the core's stages on the host's threads.
#include "nvEngine.h"

#include "nvAllenCahnSolver.h"
#include "nvMemory.h"
#include "nvSurface.h"
#include "nvSurfaceField.h"
#include "nvTruncatedDistance.h"

namespace nv
{
namespace
{
class CpuEngine : public Engine
{
public:
  DeviceKind Kind() const override { return DeviceKind::CPU; }
  std::string Name() const override { return "CPU"; }

  NarrowBand BuildBand(const Grid& grid, const Parameters& scheme, std::vector<double> xyz, const DenseVolume* dense,
    const EngineContext& context) override
  {
    // The dense arrays take each brick's distances as the band's
    // construction computes them, and the band's phi after the evolution.
    BrickVisitor writeBrick;
    if (dense)
    {
      this->Writer.reset(new VolumeWriter(grid, scheme, dense->Arrays, dense->Begin, dense->End));
      this->Writer->Clear();
      VolumeWriter* writer = this->Writer.get();
      writeBrick = [writer](std::int64_t brick, const double* d) { writer->WriteBrick(brick, d); };
    }
    // The points sorted into bricks, for the band only: gone once it is built.
    const auto sorting = StageTimes::Clock::now();
    Monitor* stoppable = context.StoppableSort ? context.TheMonitor : nullptr;
    const TruncatedDistance distance(
      grid, xyz.data(), static_cast<std::int64_t>(xyz.size() / 3), scheme.Reach(), stoppable);
    std::vector<double>().swap(xyz);
    context.Stages->Add("distance", sorting);
    if (StopAsked(stoppable))
    {
      return NarrowBand{};
    }
    return BuildNarrowBand(distance, scheme, context.TheMonitor, context.Part, writeBrick, context.Stages);
  }

  std::vector<StepReport> Evolve(
    NarrowBand& band, const Parameters& scheme, Halo* halo, const EngineContext& context) override
  {
    {
      // The distances serve phi^0 only: freed before the solver's other
      // arrays are made, so that the two never hold memory together.
      BandValues phi0 = AllenCahnSolver::InitialField(band, scheme);
      Free(band.Distance);
      ReleaseFreedMemory();
      this->Solver.reset(new AllenCahnSolver(band, scheme, std::move(phi0), halo));
    }
    return this->Solver->Run(context.TheMonitor);
  }

  void FinishEvolution(NarrowBand& band, const EngineContext& context) override
  {
    // The outputs need the band's nodes and phi only.
    this->Solver->ReleaseWorkspace();
    Free(band.Neighbor);
    ReleaseFreedMemory();
    if (this->Writer)
    {
      const auto writing = StageTimes::Clock::now();
      this->Writer->WriteBand(band, this->Solver->GetPhi());
      this->Writer.reset();
      context.Stages->Add("volume", writing);
    }
  }

  const BandValues& Phi() const override { return this->Solver ? this->Solver->GetPhi() : this->None; }

  bool Surface(const Grid& grid, const NarrowBand& band, const Parameters& scheme, const LayerRange& owned,
    SurfaceSink& sink, Monitor* monitor) override
  {
    const BandField field(band, this->Phi(), scheme);
    return ContourBricks(grid, field, sink, owned.Begin, owned.End, monitor);
  }

  void Release() override
  {
    this->Solver.reset();
    this->Writer.reset();
  }

private:
  std::unique_ptr<VolumeWriter> Writer; ///< fills the dense arrays (steps 5 and 6)
  std::unique_ptr<AllenCahnSolver> Solver;
  BandValues None;
};
} // namespace

std::unique_ptr<Engine> MakeCpuEngine()
{
  return std::unique_ptr<Engine>(new CpuEngine);
}

} // namespace nv
