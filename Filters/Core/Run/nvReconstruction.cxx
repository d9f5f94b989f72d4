// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvReconstruction.h"

#include "nvCommunicator.h"
#include "nvEngine.h"
#include "nvHoleProbe.h"
#include "nvMemory.h"
#include "nvParallel.h"
#include "nvSurface.h"
#include "nvSurfaceField.h"
#include "nvTruncatedDistance.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

namespace nv
{
namespace
{
/// Bytes a band node takes at most, during the evolution: its place in the
/// brick (2) and six neighbour indices (24), and the solver's four vectors
/// (8 + 8 + 8 + 4); its distance (8) is freed before those are made. (The
/// band's construction holds less: 16 bytes of transient lists, then 34.)
constexpr double BytesPerBandNode = 2.0 + 24.0 + 28.0;
/// The per-brick tables: 24 bytes for a brick of 512 nodes.
constexpr double BytesPerGridNode = 24.0 / 512.0;
/// A point: its coordinates here and in the distance's buckets.
constexpr double BytesPerPoint = 48.0;

double Seconds(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The brick layers along z of a grid (nvPartition.h splits them).
std::int64_t BrickLayers(const Grid& grid)
{
  return (grid.Dims[2] + BrickSize - 1) >> BrickShift;
}

/// The brick layer of a point at height z (the first or the last for one
/// beyond them).
std::int64_t BrickLayerOf(const Grid& grid, double z, std::int64_t layers)
{
  const std::int64_t k = static_cast<std::int64_t>((z - grid.Origin[2]) / grid.Spacing);
  return std::min(layers - 1, std::max<std::int64_t>(0, k >> BrickShift));
}

/// Bytes per node of the dense arrays a run on one process holds: the
/// output's (Settings::OutputBytesPerNode), and when printing the dense phi
/// whatever OutputVolume says and the part's own arrays (nvPrintPart.h).
double DenseBytesPerNode(const Settings& settings)
{
  const double output = settings.OutputBytesPerNode();
  return settings.WallThickness > 0.0
    ? std::max(output, 4.0 + 2.0) + PartBytesPerNode + (settings.CavityClosingDistance > 0.0 ? ClosingBytesPerNode : 0.0)
    : output;
}

/// The ways to a smaller run that the too-large messages give: the grid,
/// the limit, and OutputVolume off where that saves memory (not where the
/// dense phi is needed anyway: a part to print, one sheet kept); for a part,
/// the spacing its wall needs where the grid is finer than that.
std::string SmallerRunAdvice(const Settings& settings, double spacing)
{
  Settings without = settings;
  without.OutputVolume = false;
  std::ostringstream text;
  if (settings.WallThickness > 0.0 && spacing < settings.WallThickness / LeastCellsPerWall)
  {
    text << "A part's wall of " << settings.WallThickness << " needs a spacing of "
         << settings.WallThickness / LeastCellsPerWall << " (SampleSpacing 0 chooses it). ";
  }
  text << "Increase SampleSpacing, lower MaximumDimension, raise MemoryLimit"
       << (DenseBytesPerNode(without) < DenseBytesPerNode(settings) ? " or turn OutputVolume off." : ".");
  return text.str();
}

std::string MiB(double bytes)
{
  std::ostringstream text;
  text << bytes / 1048576.0 << " MiB";
  return text.str();
}
} // namespace

//------------------------------------------------------------------------------
Reconstruction::Reconstruction(
  const Settings& settings, Communicator* communicator, Monitor* monitor, GpuKernels kernels)
  : TheSettings(settings)
  , Kernels(kernels)
  , Comm(communicator)
  , Caller(monitor)
  , RunStages(monitor ? new ShareMonitor(*monitor, 0.0, this->OutputBegin() / RunShare) : nullptr)
  , TheMonitor(RunStages.get())
{
}

Reconstruction::Reconstruction(
  const Settings& settings, Communicator* communicator, Monitor* monitor, std::unique_ptr<Engine> engine)
  : Reconstruction(settings, communicator, monitor)
{
  this->GivenEngine = std::move(engine);
}

double Reconstruction::OutputBegin() const
{
  return this->TheSettings.WallThickness > 0.0 ? PrintRunShare
    : this->TheSettings.Sheets == Sheets::Scan ? ScanRunShare
                                               : RunShare;
}

Reconstruction::~Reconstruction() = default;

bool Reconstruction::Anywhere(bool flag)
{
  return this->Comm ? this->Comm->MaxAll(flag ? 1.0 : 0.0) > 0.0 : flag;
}

double Reconstruction::SumAll(double value)
{
  if (this->Comm)
  {
    this->Comm->SumAll(&value, 1);
  }
  return value;
}

bool Reconstruction::Fail(const std::string& message)
{
  this->Message = message;
  return false;
}

//------------------------------------------------------------------------------
bool Reconstruction::FirstProcess() const
{
  return !this->Comm || this->Comm->Rank() == 0;
}

bool Reconstruction::Run(std::vector<double> xyz, std::shared_ptr<const Sampling> measured)
{
  bool ok = false;
  WithThreads(this->TheSettings.NumberOfThreads,
    [&]() { ok = this->RunSteps(std::move(xyz), std::move(measured)); });
  return ok;
}

bool Reconstruction::RunSteps(std::vector<double> xyz, std::shared_ptr<const Sampling> measured)
{
  // Steps 1-6 of nvReconstruct.h's list, each false when the run stops.
  double bounds[6];
  try
  {
    return this->ChooseEngine() && this->CheckPoints(xyz, bounds) &&
      this->PlanGrid(xyz, bounds, std::move(measured)) && this->GatherPoints(xyz) &&
      this->BuildBand(std::move(xyz)) && this->Evolve() &&
      this->Stages.Time("hole probe", [&]() { return this->ProbeHoles(); });
  }
  catch (const EngineError& error) // the device failed (nvEngine.h's one rule)
  {
    this->TheEngine->Release();
    return this->Fail(error.what());
  }
}

bool Reconstruction::ChooseEngine()
{
  // 1, continued: where the run computes, the CPU or the device (nvEngine.h),
  // unless the caller gave the engine (for this run only).
  if (this->GivenEngine)
  {
    this->TheEngine = std::move(this->GivenEngine);
    return true;
  }
  std::string error;
  this->TheEngine = MakeEngine(this->TheSettings, this->Comm != nullptr, this->Kernels, error);
  return this->TheEngine ? true : this->Fail(error);
}

DeviceKind Reconstruction::DeviceUsed() const
{
  return this->TheEngine ? this->TheEngine->Kind() : DeviceKind::CPU;
}

std::string Reconstruction::DeviceName() const
{
  return this->TheEngine ? this->TheEngine->Name() : std::string("CPU");
}

double Reconstruction::DeviceBytes() const
{
  return this->TheEngine ? this->TheEngine->DeviceBytes() : 0.0;
}

CopyCounts Reconstruction::DeviceCopies() const
{
  return this->TheEngine ? this->TheEngine->DeviceCopies() : CopyCounts();
}

const BandValues& Reconstruction::GetPhi() const
{
  static const BandValues none;
  return this->TheEngine ? this->TheEngine->Phi() : none;
}

bool Reconstruction::CheckPoints(const std::vector<double>& xyz, double bounds[6])
{
  // 1. The points: counted and checked on every process, errors agreed by all.
  const std::int64_t bad = PointBounds(xyz, bounds);
  double totals[2] = { static_cast<double>(xyz.size() / 3), bad >= 0 ? 1.0 : 0.0 };
  if (this->Comm)
  {
    this->Comm->SumAll(totals, 2);
    GlobalBounds(*this->Comm, bounds);
  }
  if (totals[0] < 1.0)
  {
    return this->Fail("The input has no points: nothing to reconstruct.");
  }
  if (totals[1] > 0.0)
  {
    std::ostringstream error;
    if (bad >= 0)
    {
      error << "Input point " << bad << " has a non-finite coordinate (NaN or infinity); ";
    }
    else
    {
      error << "A point of another process's piece has a non-finite coordinate (NaN or infinity); ";
    }
    error << "remove such points before reconstructing.";
    return this->Fail(error.str());
  }
  return this->CheckPrecision(bounds, static_cast<std::int64_t>(totals[0]));
}

namespace
{
/// The largest absolute coordinate of the bounds.
double Farthest(const double bounds[6])
{
  double farthest = 0.0;
  for (int i = 0; i < 6; ++i)
  {
    farthest = std::max(farthest, std::abs(bounds[i]));
  }
  return farthest;
}

/// How far apart two doubles near the cloud's largest coordinate can be at
/// least: the precision of every coordinate and distance the run computes.
double CoordinateStep(const double bounds[6])
{
  const double farthest = Farthest(bounds);
  return std::nextafter(farthest, std::numeric_limits<double>::infinity()) - farthest;
}

/// A grid cell must span this many coordinate steps, so that rounding moves
/// a distance by 1 % of a cell at most (PlanGrid); a cloud that spans fewer
/// cannot have such a cell (CheckPrecision).
constexpr double LeastCellSteps = 100.0;

std::string FarFromOriginAdvice()
{
  return "Move the cloud near the origin (subtract its centre, e.g. with ParaView's Transform filter or "
         "vtkTransformFilter) and move the results back.";
}
} // namespace

bool Reconstruction::CheckPrecision(const double bounds[6], std::int64_t points)
{
  // Coordinates far from the origin that double precision cannot resolve
  // (a cloud of a metre at 1e16 becomes a few points, or one).
  const double step = CoordinateStep(bounds);
  const double extent = std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] });
  std::ostringstream error;
  if (extent == 0.0)
  {
    // One point: with an offset set, its shell is a ball (PlanGrid checks
    // that the grid is resolved there); the automatic offset needs two.
    if (points < 2 || this->TheSettings.OffsetDistance > 0.0)
    {
      return true;
    }
    error << "An automatic OffsetDistance needs at least two distinct points, and all " << points
          << " points coincide, at (" << bounds[0] << ", " << bounds[2] << ", " << bounds[4] << ").\n"
          << "Set OffsetDistance for the ball around them";
    if (step >= LeastCellSteps * std::numeric_limits<double>::min())
    {
      error << "; or, if the cloud is larger than " << step
            << " (the step of double precision at its distance from the origin), its points merged: "
            << "move it near the origin (subtract its centre) and move the results back";
    }
    error << ".";
    return this->Fail(error.str());
  }
  if (extent >= LeastCellSteps * step)
  {
    return true;
  }
  error << "The coordinates cannot resolve the cloud: it spans " << extent << " at up to " << Farthest(bounds)
        << " from the origin, where double precision steps by " << step << ".\n"
        << FarFromOriginAdvice();
  return this->Fail(error.str());
}

bool Reconstruction::PlanGrid(
  const std::vector<double>& xyz, const double bounds[6], std::shared_ptr<const Sampling> measured)
{
  // 2. The points' spacing, and the grid.
  if (!measured)
  {
    auto sampling = std::make_shared<Sampling>();
    if (this->TheMonitor)
    {
      this->TheMonitor->Stage(0.0, SamplingStage);
    }
    if (!sampling->Measure(xyz, this->Comm, this->TheMonitor))
    {
      this->Stopped = true;
      return false;
    }
    measured = sampling;
  }
  this->TheSampling = measured;
  this->Stages.Add("sampling", measured->Seconds());
  this->ThePlan = MakePlan(this->TheSettings, bounds, this->TheSampling->Statistics());
  if (!this->ThePlan.Valid())
  {
    return this->Fail(this->ThePlan.Error);
  }
  const double step = CoordinateStep(bounds);
  if (this->ThePlan.TheGrid.Spacing < LeastCellSteps * step)
  {
    std::ostringstream error;
    error << "The coordinates cannot resolve the grid: its spacing " << this->ThePlan.TheGrid.Spacing
          << " is below " << LeastCellSteps << " steps of double precision (" << step
          << ") at the cloud's distance from the origin.\n"
          << FarFromOriginAdvice();
    return this->Fail(error.str());
  }
  return true;
}

bool Reconstruction::GatherPoints(std::vector<double>& xyz)
{
  // 3. This process's slab, and the points within its reach: the band's,
  // and the gap closing's around it.
  const Grid& grid = this->ThePlan.TheGrid;
  const std::int64_t layers = BrickLayers(grid);
  this->Partition(xyz, layers);
  GapClosing closing(grid, this->ThePlan.Scheme.OffsetDistance, this->ThePlan.ClosingRadius);

  // 4. Memory before any allocation that grows with the grid.
  if (!this->CheckMemory(static_cast<double>(grid.NumberOfNodes()), static_cast<double>(xyz.size() / 3)))
  {
    return false;
  }
  if (this->Comm)
  {
    // Each process's slab, widened by the reach of the distance and of the gap closing.
    std::vector<std::array<double, 2>> zRanges(this->Owners.size());
    const double margin = this->ThePlan.Scheme.Reach() + grid.Spacing + closing.Reach();
    for (std::size_t q = 0; q < this->Owners.size(); ++q)
    {
      const Subdomain other = Subdomain::Around(this->Owners[q], layers);
      zRanges[q] = { grid.Origin[2] + other.Computed.Begin * BrickSize * grid.Spacing - margin,
        grid.Origin[2] + (std::min(other.Computed.End * BrickSize, grid.Dims[2]) - 1) * grid.Spacing + margin };
      if (other.Computed.Empty())
      {
        zRanges[q] = { 1.0, 0.0 }; // nothing
      }
    }
    xyz = ExchangePoints(*this->Comm, xyz, zRanges);
  }
  // (3, continued) The points that bridge the holes of the sampling.
  return this->Stages.Time("gap closing", [&]() { return this->CloseGaps(xyz, closing); });
}

bool Reconstruction::BuildBand(std::vector<double> xyz)
{
  // 5. Distance (eq. 6, 7) and band (collect, store, connect); the dense arrays, if
  // asked for, take each brick's distances as the band's construction
  // computes them.
  const auto start = std::chrono::steady_clock::now();
  const Grid& grid = this->ThePlan.TheGrid;
  if (this->TheMonitor)
  {
    this->TheMonitor->Stage(0.0, 0.3);
  }
  DenseVolume dense;
  const bool filled = this->AllocateVolume && !this->EmptyPiece();
  if (filled)
  {
    this->Volume[0] = std::max(this->Computed[0], this->Piece[0] - this->VolumeGhosts);
    this->Volume[1] = std::min(this->Computed[1], this->Piece[1] + this->VolumeGhosts);
    dense.Arrays = this->AllocateVolume(this->Volume[0], this->Volume[1]);
    dense.Begin = this->Volume[0];
    dense.End = this->Volume[1];
  }
  this->Band = this->TheEngine->BuildBand(grid, this->ThePlan.Scheme, std::move(xyz), filled ? &dense : nullptr,
    this->Context());
  ReleaseFreedMemory();
  this->SetupTime = Seconds(start);
  double failed[2] = { static_cast<double>(this->Band.RefusedSize),
    this->TheMonitor && this->TheMonitor->Aborted() ? 1.0 : 0.0 };
  if (this->Comm)
  {
    this->Comm->MaxAll(failed, 2);
  }
  if (failed[0] > 0.0 && this->ThePlan.WallSpacing > 0.0)
  {
    // Printing on a grid made fine for the wall: the wall's message, with
    // the band's bytes counted.
    const Grid& grid = this->ThePlan.TheGrid;
    return this->Fail(this->WallGridTooLarge(static_cast<double>(grid.NumberOfNodes()),
      this->BytesBeforeBand + failed[0] * BytesPerBandNode, this->TheSettings.MemoryLimitBytes(),
      DenseBytesPerNode(this->TheSettings), this->PointsBeforeBand, true));
  }
  if (failed[0] > 0.0)
  {
    std::ostringstream error;
    error << "The narrow band is too large: " << failed[0] << " nodes" << (this->Comm ? " on one process" : "")
          << " need about " << MiB(failed[0] * BytesPerBandNode) << ", more than the "
          << MiB(this->TheSettings.MemoryLimitBytes() - this->BytesBeforeBand) << " left under the limit of "
          << MiB(this->TheSettings.MemoryLimitBytes())
          << ". " << SmallerRunAdvice(this->TheSettings, this->ThePlan.TheGrid.Spacing);
    return this->Fail(error.str());
  }
  if (failed[1] > 0.0)
  {
    this->Stopped = true;
    return false;
  }
  std::int64_t red[2], black[2];
  this->Band.OwnedNodes(true, red[0], red[1]);
  this->Band.OwnedNodes(false, black[0], black[1]);
  this->BandNodes = static_cast<std::int64_t>(this->SumAll(static_cast<double>(red[1] - red[0] + black[1] - black[0])));
  return true;
}

bool Reconstruction::Evolve()
{
  // 6. Evolution: (10)-(12) per time step.
  const auto start = std::chrono::steady_clock::now();
  if (this->TheMonitor)
  {
    this->TheMonitor->Stage(0.3, 0.35);
  }
  if (this->Comm)
  {
    this->TheHalo.reset(new Halo(this->Band, this->Part, this->Owners, *this->Comm));
    if (!this->TheHalo->Agree())
    {
      return this->Fail("Internal error: neighbouring processes disagree on their shared band layers.");
    }
  }
  for (const StepReport& step : this->TheEngine->Evolve(this->Band, this->ThePlan.Scheme, this->TheHalo.get(),
         this->Context()))
  {
    this->Changes.push_back(step.RelativeChange);
  }
  this->EvolutionTime = Seconds(start);
  this->Stages.Add("evolution", this->EvolutionTime);
  if (this->Anywhere(this->TheMonitor && this->TheMonitor->Aborted()))
  {
    this->TheEngine->Release();
    this->Stopped = true;
    return false;
  }
  this->TheEngine->FinishEvolution(this->Band, this->Context());
  return true;
}

EngineContext Reconstruction::Context()
{
  EngineContext context;
  context.TheMonitor = this->TheMonitor;
  // Stoppable in the sort only when serial: one process alone cannot stop a distributed run.
  context.StoppableSort = !this->Comm;
  context.Part = &this->Part;
  context.Stages = &this->Stages;
  return context;
}

bool Reconstruction::ProbeHoles()
{
  // 6, continued: whether each hole left open pierces the evolved shell
  // (nvHoleProbe.h). Each process probes the discs in its own brick layers.
  std::vector<OpenHole>& holes = this->Gaps.Holes;
  if (holes.empty())
  {
    return true;
  }
  const Grid& grid = this->ThePlan.TheGrid;
  const std::int64_t layers = BrickLayers(grid);
  const LayerRange owned = this->Part.Owned;
  const BandField field(this->Band, this->GetPhi(), this->ThePlan.Scheme);
  std::vector<double> pierced(holes.size(), 0.0);
  ParallelFor(0, static_cast<std::int64_t>(holes.size()), 1, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t i = begin; i < end; ++i)
    {
      pierced[i] = Pierces(field, grid, holes[i], this->ThePlan.Scheme.OffsetDistance,
                     [&](const Hole& disc) { return owned.Contains(BrickLayerOf(grid, disc.Center[2], layers)); })
        ? 1.0
        : 0.0;
    }
  });
  if (this->Comm)
  {
    this->Comm->SumAll(pierced.data(), static_cast<int>(pierced.size()));
  }
  for (std::size_t i = 0; i < holes.size(); ++i)
  {
    holes[i].Pierced = pierced[i] > 0.0;
  }
  return true;
}

void Reconstruction::ReleaseBand()
{
  this->TheHalo.reset();
  if (this->TheEngine)
  {
    this->TheEngine->Release();
  }
  this->Band = NarrowBand{};
  ReleaseFreedMemory();
}

void Reconstruction::RequestVolume(std::int64_t ghostLayers, VolumeAllocator allocate)
{
  this->VolumeGhosts = std::max<std::int64_t>(0, ghostLayers);
  this->AllocateVolume = std::move(allocate);
}

bool Reconstruction::ExtractSurface(SurfaceSink& sink)
{
  if (this->EmptyPiece())
  {
    return true;
  }
  bool done = false;
  WithThreads(this->TheSettings.NumberOfThreads, [&]() {
    try
    {
      done = this->TheEngine->Surface(
        this->ThePlan.TheGrid, this->Band, this->ThePlan.Scheme, this->Part.Owned, sink, this->TheMonitor);
    }
    catch (const EngineError& error) // the device failed (nvEngine.h's one rule)
    {
      this->Fail(error.what());
    }
  });
  return done;
}

//------------------------------------------------------------------------------
bool Reconstruction::CloseGaps(std::vector<double>& xyz, GapClosing& closing)
{
  // Every process bridges the holes among the points it holds (those far
  // from its slab may come out otherwise, and matter nowhere), and reports
  // the holes left open seen from the points of its own brick layers.
  if (this->TheMonitor)
  {
    this->TheMonitor->Stage(0.0, 0.15);
  }
  const Grid& grid = this->ThePlan.TheGrid;
  const LayerRange owned = this->Part.Owned;
  const std::int64_t layers = BrickLayers(grid);
  std::function<bool(const double*)> owns;
  if (this->Comm)
  {
    owns = [&grid, owned, layers](const double* x) { return owned.Contains(BrickLayerOf(grid, x[2], layers)); };
  }
  const std::size_t given = xyz.size();
  const bool stopped = !closing.Run(xyz, owns, this->TheMonitor);
  if (this->Anywhere(stopped))
  {
    this->Stopped = true;
    return false;
  }
  std::vector<Hole> holes = closing.OpenHoles();
  double added = 0.0;
  for (std::size_t p = given; p < xyz.size(); p += 3)
  {
    added += !owns || owns(&xyz[p]) ? 1.0 : 0.0;
  }
  if (this->Comm)
  {
    std::vector<double> mine;
    for (const Hole& hole : holes)
    {
      mine.insert(mine.end(), { hole.Center[0], hole.Center[1], hole.Center[2], hole.Radius, hole.Normal[0],
                                hole.Normal[1], hole.Normal[2] });
    }
    const std::vector<double> all =
      this->Comm->Exchange(std::vector<std::vector<double>>(static_cast<std::size_t>(this->Comm->Size()), mine));
    holes.clear();
    for (std::size_t i = 0; i + 6 < all.size(); i += 7)
    {
      holes.push_back(
        Hole{ { { all[i], all[i + 1], all[i + 2] } }, all[i + 3], { { all[i + 4], all[i + 5], all[i + 6] } } });
    }
    added = this->SumAll(added);
  }
  this->Gaps = SummarizeHoles(std::move(holes), this->ThePlan.Scheme.OffsetDistance);
  this->Added = static_cast<std::int64_t>(added);
  return true;
}

void Reconstruction::Partition(const std::vector<double>& xyz, std::int64_t layers)
{
  // The whole grid, or a slab of brick layers balanced by the number of
  // points per layer (nvPartition.h).
  const Grid& grid = this->ThePlan.TheGrid;
  this->Part = Subdomain::Whole(layers);
  this->Owners.assign(1, this->Part.Owned);
  if (this->Comm)
  {
    std::vector<double> weights(static_cast<std::size_t>(layers), 0.0);
    for (std::size_t p = 0; p + 2 < xyz.size(); p += 3)
    {
      weights[static_cast<std::size_t>(BrickLayerOf(grid, xyz[p + 2], layers))] += 1.0;
    }
    this->Comm->SumAll(weights.data(), static_cast<int>(layers));
    this->Owners = SplitLayers(weights, this->Comm->Size());
    this->Part = Subdomain::Around(this->Owners[this->Comm->Rank()], layers);
  }
  this->Computed[0] = this->Part.Computed.Begin * BrickSize;
  this->Computed[1] = std::min(this->Part.Computed.End * BrickSize, grid.Dims[2]);
  this->Piece[0] = this->Part.Owned.Begin * BrickSize;
  this->Piece[1] = this->Part.Owned.Empty() ? this->Piece[0]
                                            : std::min(this->Part.Owned.End * BrickSize + 1, grid.Dims[2]);
}

std::string Reconstruction::WallGridTooLarge(
  double gridNodes, double bytes, double limit, double perNode, double points, bool withBand) const
{
  // The ways out, each with a figure that fits: the dense arrays in half
  // the limit at most (the narrow band needs the rest), by bisection over
  // the grids MakeGrid makes (a grid's size falls as its spacing grows or
  // its box shrinks).
  const Plan& plan = this->ThePlan;
  const double* bounds = plan.PointsBounds.data();
  const double room = 0.5 * limit, offsetSpacing = plan.Scheme.OffsetDistance / 4.0; // l = 4 h
  // The bytes for the model scaled by s about its centre with this wall: an
  // automatic offset scales with it (the sampling does), and the spacing is
  // the finer of the offset's and the wall's.
  const auto bytesAt = [&](double s, double wallSpacing) {
    double box[6];
    for (int a = 0; a < 3; ++a)
    {
      const double middle = 0.5 * (bounds[2 * a] + bounds[2 * a + 1]), half = 0.5 * (bounds[2 * a + 1] - bounds[2 * a]);
      box[2 * a] = middle - s * half;
      box[2 * a + 1] = middle + s * half;
    }
    const double scaled = plan.AutomaticOffset ? s : 1.0;
    const double spacing = std::min(scaled * offsetSpacing, wallSpacing);
    const Grid grid = MakeGrid(box, spacing, GridPadding(scaled * plan.Scheme.Reach(), spacing));
    return static_cast<double>(grid.NumberOfNodes()) * (perNode + BytesPerGridNode) + points * BytesPerPoint;
  };
  const auto bisect = [](double fits, double fails, const std::function<bool(double)>& ok) {
    for (int round = 0; round < 60; ++round)
    {
      const double middle = 0.5 * (fits + fails);
      (ok(middle) ? fits : fails) = middle;
    }
    return fits;
  };
  const double scale = bytesAt(1e-3, plan.WallSpacing) <= room
    ? bisect(1e-3, 1.0, [&](double s) { return bytesAt(s, plan.WallSpacing) <= room; })
    : 0.0;
  // A thicker wall helps while the offset's own grid fits.
  const bool thickerHelps = bytesAt(1.0, offsetSpacing) <= room;
  const double coarse = thickerHelps
    ? bisect(offsetSpacing, plan.WallSpacing, [&](double h) { return bytesAt(1.0, h) <= room; })
    : 0.0;
  std::ostringstream error;
  error << "The wall is too thin for this model's size within the memory limit: WallThickness "
        << this->TheSettings.WallThickness << " needs a grid spacing of " << plan.WallSpacing << " or less ("
        << LeastCellsPerWall << " cells across the wall), about " << gridNodes << " nodes over the cloud's box ("
        << bounds[1] - bounds[0] << " x " << bounds[3] - bounds[2] << " x " << bounds[5] - bounds[4]
        << "), which need about " << MiB(bytes) << (withBand ? " with the narrow band" : " before the narrow band")
        << ", over the limit of " << MiB(limit) << ".\n"
        << "Scale the model to its print size first (a model in millimetres at 1:1 is life-size";
  if (scale > 0.0)
  {
    error << ": scaled by " << ThreeDigits(scale, false)
          << " or less, this wall's grid takes half the limit at most, the band the rest";
  }
  error << ")";
  if (thickerHelps)
  {
    error << ", or set WallThickness to " << ThreeDigits(LeastCellsPerWall * coarse, true) << " or more";
  }
  error << ", or raise MemoryLimit.";
  return error.str();
}

bool Reconstruction::CheckMemory(double gridNodes, double points)
{
  // Checked in two stages. Here, before any allocation that grows with the
  // grid: the dense output, the per-brick tables, the points, and in Whole
  // Domain mode the band arrays on every computed node. The narrow band's own
  // size is known only once its distances are computed: BuildNarrowBand
  // refuses it then, before allocating its arrays, if it would not fit in
  // what is left.
  const Grid& grid = this->ThePlan.TheGrid;
  const double layerNodes = static_cast<double>(grid.Dims[0] * grid.Dims[1]);
  const double computedNodes = layerNodes * static_cast<double>(this->Computed[1] - this->Computed[0]);
  const double pieceNodes = layerNodes * static_cast<double>(this->Piece[1] - this->Piece[0]);
  const bool whole = this->ThePlan.Scheme.Domain == Domain::WholeDomain;
  const double perNode = DenseBytesPerNode(this->TheSettings);
  const double bytes = pieceNodes * perNode + gridNodes * BytesPerGridNode +
    (whole ? computedNodes * BytesPerBandNode : 0.0) + points * BytesPerPoint;
  const double limit = this->TheSettings.MemoryLimitBytes();
  this->BytesBeforeBand = bytes;
  this->PointsBeforeBand = points;
  if (this->Anywhere(bytes > limit || (whole && computedNodes > static_cast<double>(MaximumBandSize))))
  {
    if (this->ThePlan.WallSpacing > 0.0 && bytes > limit)
    {
      return this->Fail(this->WallGridTooLarge(gridNodes, bytes, limit, perNode, points, false));
    }
    std::ostringstream error;
    error << "The grid is too large: about " << gridNodes << " nodes (spacing " << grid.Spacing << ") need about "
          << MiB(bytes) << (this->Comm ? " on some process" : "") << ", over the limit of " << MiB(limit)
          << ". " << SmallerRunAdvice(this->TheSettings, this->ThePlan.TheGrid.Spacing);
    return this->Fail(error.str());
  }
  if (!whole)
  {
    this->ThePlan.Scheme.MaximumBandNodes = static_cast<std::int64_t>((limit - bytes) / BytesPerBandNode);
  }
  return true;
}

} // namespace nv
