// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvReconstruct.h"

#include "nvCommunicator.h"
#include "nvParallel.h"
#include "nvPrintPart.h"
#include "nvRunWarnings.h"
#include "nvScanSurface.h"
#include "nvSheets.h"
#include "nvSurface.h"
#include "nvSurfaceField.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstring>
#include <iomanip>
#include <limits>
#include <sstream>
#include <utility>

namespace nv
{

VolumeContents DenseArraysAsked(const Settings& settings)
{
  VolumeContents contents;
  contents.InitialPhi = settings.OutputVolume && settings.OutputInitialPhi;
  contents.Distance = settings.OutputVolume && settings.OutputDistance;
  contents.Band = settings.OutputVolume && settings.OutputNarrowBand;
  return contents;
}

namespace
{
using namespace warnings; // the messages (nvRunWarnings.h)

/// Whether the surface is the part to print (nvPrintPart.h) rather than the shell.
bool Printing(const Settings& settings)
{
  return settings.WallThickness > 0.0;
}

/// Whether the surface is the scan surface (nvScanSurface.h) rather than
/// sheets of the shell; the part to print comes first. A distributed run
/// keeps both sheets (it has no whole grid).
bool ScanSurface(const Settings& settings, bool distributed)
{
  return settings.Sheets == Sheets::Scan && !Printing(settings) && !distributed;
}

/// Whether the run fills dense arrays (RequestVolume): for output 0, or to
/// keep one sheet (KeepSheets needs the whole grid, which a distributed run
/// does not have: there both sheets are kept).
bool NeedsDenseVolume(const Settings& settings, bool distributed)
{
  return settings.OutputVolume || (settings.Sheets != Sheets::Both && !distributed) || Printing(settings);
}

/// Whether the surface comes from a copy of the dense phi (one sheet kept)
/// rather than from the band; the part to print comes from one always.
bool SurfaceFromDenseCopy(const Settings& settings, bool distributed)
{
  return settings.Sheets != Sheets::Both && !distributed;
}

/// The surface of the sheets the settings keep, from `phi`, a copy of the
/// dense phi on the whole grid, which KeepSheets rewrites. Returns false if
/// the monitor stopped it; `cavities`: KeepSheets' count (NoInnerSheet).
bool ContourDense(
  const Reconstruction& run, float* phi, SurfaceSink& sink, Monitor* monitor, std::int64_t& cavities)
{
  const Grid& grid = run.GetGrid();
  cavities = KeepSheets(grid, phi, run.GetSettings().Sheets, monitor);
  if (StopAsked(monitor))
  {
    return false;
  }
  const DenseField field(grid, phi, 0, grid.Dims[2], run.GetParameters());
  return ContourBricks(grid, field, sink, 0, -1, monitor);
}

/// Whether the chosen sheets left nothing because the shell encloses no
/// cavity: an open input has no inner sheet.
bool NoInnerSheet(const Settings& settings, std::int64_t cavities)
{
  return settings.Sheets == Sheets::Inner && cavities == 0;
}

/// The seconds of the run's stages on this process: one tuple, a component
/// per stage, named after it.
SummaryArray StageSeconds(const StageTimes& times)
{
  SummaryArray array{ "StageSeconds", SummaryArray::Double, static_cast<int>(times.Get().size()), {}, {} };
  for (const auto& stage : times.Get())
  {
    array.ComponentNames.push_back(stage.first);
    array.Values.push_back(stage.second);
  }
  return array;
}

/// The run's figures, as the field data of output 0.
std::vector<SummaryArray> RunSummary(const Reconstruction& run, const RemovedPieces& removed)
{
  const GapReport& gaps = run.GetGaps();
  return {
    { "NumberOfIterations", SummaryArray::Int, 1, { static_cast<double>(run.RelativeChanges().size()) } },
    { "NarrowBandNodes", SummaryArray::Id, 1, { static_cast<double>(run.NumberOfBandNodes()) } },
    { "RelativeChange", SummaryArray::Double, 1, run.RelativeChanges() },
    { "OffsetDistance", SummaryArray::Double, 1, { run.GetParameters().OffsetDistance } },
    { "SampleSpacing", SummaryArray::Double, 1, { run.GetGrid().Spacing } },
    { "MedianPointSpacing", SummaryArray::Double, 1, { run.GetSampling().MedianSpacing } },
    { "ClosingRadius", SummaryArray::Double, 1, { run.GetPlan().ClosingRadius } },
    { "AddedPoints", SummaryArray::Id, 1, { static_cast<double>(run.AddedPoints()) } },
    { "NumberOfGaps", SummaryArray::Double, 1, { static_cast<double>(gaps.Gaps) } },
    { "PiercedGaps", SummaryArray::Double, 1, { static_cast<double>(gaps.PiercedGaps()) } },
    { "LargestGap", SummaryArray::Double, 1, { gaps.LargestGap } },
    { "LargestGapCenter", SummaryArray::Double, 3,
      { gaps.LargestGapCenter[0], gaps.LargestGapCenter[1], gaps.LargestGapCenter[2] } },
    { "RemovedPieces", SummaryArray::Double, 1, { static_cast<double>(removed.Pieces) } },
    { "RemovedVoids", SummaryArray::Double, 1, { static_cast<double>(removed.Voids) } },
    // The Device property's value that ran: 1 (CPU) or 2 (GPU, also its kernels on the host in tests).
    { "DeviceUsed", SummaryArray::Int, 1, { static_cast<double>(run.DeviceUsed()) } },
    StageSeconds(run.GetStageTimes()),
  };
}

/// The run's results (the property table's RESULTS): one line per result.
Results ResultsOf(const Reconstruction& run)
{
  const Grid& grid = run.GetGrid();
  Results chosen;
  chosen.OffsetDistanceUsed = run.GetParameters().OffsetDistance;
  chosen.ClosingRadiusUsed = run.GetPlan().ClosingRadius;
  chosen.SampleSpacingUsed = grid.Spacing;
  chosen.GridUsed = std::to_string(grid.Dims[0]) + " x " + std::to_string(grid.Dims[1]) + " x " +
    std::to_string(grid.Dims[2]);
  chosen.GridDimensionsUsed = { static_cast<int>(grid.Dims[0]), static_cast<int>(grid.Dims[1]),
    static_cast<int>(grid.Dims[2]) };
  return chosen;
}

/// The part's size against the cloud's: "0.836 x 0.996 x 0.749 (the cloud
/// 0.838 x 0.998 x 0.753)", 4 significant digits.
std::string PartSize(const double part[6], const double cloud[6])
{
  auto size = [](const double bounds[6]) {
    std::ostringstream text;
    text << std::setprecision(4) << bounds[1] - bounds[0] << " x " << bounds[3] - bounds[2] << " x "
         << bounds[5] - bounds[4];
    return text.str();
  };
  return size(part) + " (the cloud " + size(cloud) + ")";
}

/// A copy of the dense phi, for the part to print or the scan surface to
/// fill its cavities in (FillCavities). A node where phi is exactly 0 (a
/// sheet through a plane of nodes, as a cloud whose faces lie on the grid's
/// planes gives) counts as the shell's: KeepSheets fills only phi < 0, and a
/// plane of zeros inside the outer sheet would stop the distance D there and
/// open a cavity in the wall.
std::vector<float> OuterOf(const Grid& grid, const VolumeArrays& dense)
{
  std::vector<float> outer(dense.Phi, dense.Phi + grid.NumberOfNodes());
  std::replace(outer.begin(), outer.end(), 0.0f, std::numeric_limits<float>::min());
  return outer;
}

/// phi > 0 inside the outer sheet: its cavities filled (KeepSheets, Outer).
/// Returns false if the monitor stopped it.
bool FillCavities(const Grid& grid, std::vector<float>& outer, Monitor* monitor)
{
  KeepSheets(grid, outer.data(), Sheets::Outer, monitor);
  return !StopAsked(monitor);
}

/// Step 7, the scan surface (nvScanSurface.h), from a copy of the dense phi
/// whose cavities are filled. Returns false if the monitor stopped it.
bool MakeScan(Reconstruction& run, SurfaceSink& sink, const VolumeArrays& dense, const std::vector<double>& scan,
  Outcome& outcome)
{
  const Grid& grid = run.GetGrid();
  if (!run.GetSettings().OutputVolume)
  {
    outcome.Warnings.push_back(OneSheetNeedsGridWarning(true));
  }
  std::vector<float> outer = OuterOf(grid, dense);
  const double progress[2] = { run.OutputBegin(), 1.0 - run.OutputBegin() };
  const bool done = run.GetStageTimes().Time("scan surface", [&]() {
    return FillCavities(grid, outer, run.GetMonitor()) &&
      MakeScanSurface(grid, run.GetParameters(), outer.data(), scan.data(), static_cast<std::int64_t>(scan.size() / 3),
        run.GetSettings().RemoveSmallPieces, sink, run.GetMonitor(), outcome.Scan, progress);
  });
  outcome.Scanned = done;
  outcome.Removed.Pieces = outcome.Scan.RemovedPieces;
  outcome.Removed.Voids = outcome.Scan.RemovedVoids;
  return done;
}

/// Step 7, printing: the part (nvPrintPart.h), from a copy of the dense phi
/// whose cavities KeepSheets fills. Returns false if the monitor stopped it.
bool MakePrintPart(Reconstruction& run, SurfaceSink& sink, const VolumeArrays& dense,
  const std::vector<double>& scan, Outcome& outcome)
{
  const Settings& settings = run.GetSettings();
  const Grid& grid = run.GetGrid();
  std::vector<float> outer = OuterOf(grid, dense);
  const std::int64_t shellNodes = std::count_if(outer.begin(), outer.end(), [](float phi) { return phi > 0.0f; });
  outcome.Print.ShellVolume = static_cast<double>(shellNodes) * std::pow(grid.Spacing, 3);
  PartRequest request;
  request.Wall = settings.WallThickness;
  request.MinimumCavity = settings.MinimumCavityVolume;
  request.CavityClosing = settings.CavityClosingDistance;
  request.DrainHoles = settings.NumberOfDrainHoles;
  request.DrainDiameter = settings.DrainHoleDiameter;
  request.Down = settings.DrainHoleAxis;
  request.DrainAngle = settings.DrainHoleAngle;
  request.DrainPositions = settings.DrainHolePositions;
  request.Scan = scan.data();
  request.ScanPoints = static_cast<std::int64_t>(scan.size() / 3);
  request.Progress[0] = run.OutputBegin();
  request.Progress[1] = 1.0 - run.OutputBegin();
  const bool done = run.GetStageTimes().Time("part", [&]() {
    return FillCavities(grid, outer, run.GetMonitor()) &&
      MakePart(grid, run.GetParameters(), outer.data(), request, sink, run.GetMonitor(), outcome.Print);
  });
  outcome.Printed = done;
  outcome.Chosen.PartSizeUsed = PartSize(outcome.Print.Bounds.data(), run.GetPlan().PointsBounds.data());
  outcome.Removed.Pieces = outcome.Print.RemovedPieces;
  outcome.Removed.Voids = outcome.Print.RemovedCavities;
  outcome.Removed.Cavities = outcome.Print.KeptCavities;
  return done;
}

/// Step 7, the shell: the sheets the settings keep, from the band or from a
/// copy of the dense phi. Returns false if the monitor stopped it.
/// noInnerSheet: a warning said why the surface is empty.
bool MakeShell(Reconstruction& run, SurfaceSink& sink, const VolumeArrays& dense, bool distributed,
  Outcome& outcome, bool& noInnerSheet)
{
  const Settings& settings = run.GetSettings();
  if (!SurfaceFromDenseCopy(settings, distributed))
  {
    if (settings.Sheets != Sheets::Both)
    {
      outcome.Warnings.push_back(OneSheetDistributedWarning());
    }
    return run.GetStageTimes().Time("surface", [&]() { return run.ExtractSurface(sink); });
  }
  // From a copy of the dense phi (phi stays phi), which KeepSheets rewrites.
  if (!settings.OutputVolume)
  {
    outcome.Warnings.push_back(OneSheetNeedsGridWarning(false));
  }
  std::vector<float> phi(dense.Phi, dense.Phi + run.GetGrid().NumberOfNodes());
  std::int64_t cavities = 0;
  const bool done = run.GetStageTimes().Time(
    "surface", [&]() { return ContourDense(run, phi.data(), sink, run.GetMonitor(), cavities); });
  noInnerSheet = NoInnerSheet(settings, cavities);
  if (noInnerSheet)
  {
    outcome.Warnings.push_back(NoInnerSheetWarning());
  }
  return done;
}

/// Steps 7 and 8: the surface of this process's piece into the sink, and
/// its small pieces removed (phi follows in the same regions). Returns false
/// if the monitor stopped it. noInnerSheet: as MakeShell's.
bool MakeSurface(Reconstruction& run, SurfaceSink& sink, const VolumeArrays& dense, bool distributed,
  const std::vector<double>& scan, Outcome& outcome, bool& noInnerSheet)
{
  const Settings& settings = run.GetSettings();
  Monitor* monitor = run.GetMonitor();
  if (monitor)
  {
    monitor->Stage(run.OutputBegin(), 1.0 - run.OutputBegin());
  }
  const bool printing = Printing(settings), scanning = ScanSurface(settings, distributed);
  const bool done = printing ? MakePrintPart(run, sink, dense, scan, outcome)
    : scanning               ? MakeScan(run, sink, dense, scan, outcome)
                             : MakeShell(run, sink, dense, distributed, outcome, noInnerSheet);
  run.ReleaseBand(); // the surface is made: what follows needs neither
  const bool stopped = monitor && monitor->Aborted();
  if (done && !printing && !scanning && settings.RemoveSmallPieces && !distributed && !stopped)
  {
    const auto start = StageTimes::Clock::now();
    outcome.Removed = RemoveSmallPieces(sink, run.GetParameters().OffsetDistance, run.GetGrid(),
      outcome.DenseArrays ? dense.Phi : nullptr, outcome.VolumeBegin, outcome.VolumeEnd - outcome.VolumeBegin);
    run.GetStageTimes().Add("small pieces", start);
  }
  return done && !(monitor && monitor->Aborted());
}

/// Step 9, on the first process: the warnings about the whole result, in
/// the order they are given. surfacePoints: all processes'; explained: a
/// warning said already why the surface is empty.
void WarnAboutResult(const Reconstruction& run, bool distributed, double surfacePoints, bool explained,
  Outcome& outcome)
{
  const Settings& settings = run.GetSettings();
  const Plan& plan = run.GetPlan();
  const double offset = run.GetParameters().OffsetDistance;
  if (plan.Diagonal > 0.0 && offset > plan.Diagonal)
  {
    outcome.Warnings.push_back(OffsetOverCloudWarning(offset, plan.Diagonal));
  }
  if (plan.CoarsenedFrom > 0.0)
  {
    outcome.Warnings.push_back(CoarsenedGridWarning(run));
  }
  if (offset < LeastCellsPerOffset * run.GetGrid().Spacing)
  {
    outcome.Warnings.push_back(CoarseGridWarning(run));
  }
  for (std::string& warning : GapWarnings(run.GetGaps(), plan.ClosingRadius, offset, Printing(settings)))
  {
    outcome.Warnings.push_back(std::move(warning));
  }
  // The cavities are counted with the small pieces, on the whole surface
  // of both sheets.
  const bool counted =
    settings.RemoveSmallPieces && !distributed && settings.Sheets == Sheets::Both && !Printing(settings);
  if (counted && surfacePoints > 0 && outcome.Removed.Cavities == 0 && plan.Diagonal > 0.0 &&
    !(offset > plan.Diagonal))
  {
    outcome.Warnings.push_back(OpenShellWarning(run.GetGaps(), plan.ClosingRadius, offset));
  }
  if (Printing(settings))
  {
    if (settings.Sheets != Sheets::Both)
    {
      outcome.Warnings.push_back(SheetsWithWallWarning(settings));
    }
    for (std::string& warning : PartWarnings(settings, run, outcome.Print, surfacePoints))
    {
      outcome.Warnings.push_back(std::move(warning));
    }
  }
  else if (settings.NumberOfDrainHoles > 0 || !settings.DrainHolePositions.empty())
  {
    outcome.Warnings.push_back(DrainHolesWithoutWallWarning(settings));
  }
  if (ScanSurface(settings, distributed))
  {
    for (std::string& warning : ScanWarnings(run, outcome.Scan))
    {
      outcome.Warnings.push_back(std::move(warning));
    }
  }
  if (surfacePoints == 0 && !Printing(settings) && !ScanSurface(settings, distributed) && !explained)
  {
    outcome.Warnings.push_back(EmptySurfaceWarning(offset, run.GetGrid().Spacing));
  }
}

/// Step 9: the figures of the part to print, in the volume's field data
/// before StageSeconds.
std::vector<SummaryArray> PartSummary(const Settings& settings, const PrintReport& print)
{
  return {
    { "WallThickness", SummaryArray::Double, 1, { settings.WallThickness } },
    { "MaterialVolume", SummaryArray::Double, 1, { print.MaterialVolume } },
    { "CavityVolume", SummaryArray::Double, 1, { print.CavityVolume } },
    { "MinimumWallThickness", SummaryArray::Double, 1, { print.MinimumWallThickness } },
    { "KeptCavities", SummaryArray::Double, 1, { static_cast<double>(print.KeptCavities) } },
    { "RemovedCavities", SummaryArray::Double, 1, { static_cast<double>(print.RemovedCavities) } },
    { "MinimumCavityVolume", SummaryArray::Double, 1, { print.MinimumCavityVolume } },
    { "PartBounds", SummaryArray::Double, 6, { print.Bounds.begin(), print.Bounds.end() } },
    { "DrainHoles", SummaryArray::Double, 1, { static_cast<double>(print.DrainHoles) } },
    { "PartPieces", SummaryArray::Double, 1, { static_cast<double>(print.Pieces) } },
    { "ThinnestWallAt", SummaryArray::Double, 3,
      { print.ThinnestWallAt[0], print.ThinnestWallAt[1], print.ThinnestWallAt[2] } },
    { "LostDistance", SummaryArray::Double, 1, { print.LostDistance } },
    { "LostPoints", SummaryArray::Double, 1, { static_cast<double>(print.LostPoints) } },
    { "LostRegionCenter", SummaryArray::Double, 3,
      { print.LostRegions.empty() ? 0.0 : print.LostRegions[0].Center[0],
        print.LostRegions.empty() ? 0.0 : print.LostRegions[0].Center[1],
        print.LostRegions.empty() ? 0.0 : print.LostRegions[0].Center[2] } },
    { "RestoredPoints", SummaryArray::Double, 1, { static_cast<double>(print.RestoredPoints) } },
  };
}

/// Step 9: the scan surface's figures, in the volume's field data before
/// StageSeconds (distances in cells).
std::vector<SummaryArray> ScanSummary(const ScanReport& scan)
{
  return {
    // 1: closed pieces only, 2: open ones only (an open scan), 3: both (0: empty).
    { "ScanSurface", SummaryArray::Int, 1,
      { (scan.Pieces > 0 ? 1.0 : 0.0) + (scan.OpenPieces > 0 ? 2.0 : 0.0) } },
    { "ScanSurfacePieces", SummaryArray::Double, 1, { static_cast<double>(scan.Pieces) } },
    { "ScanSurfaceOpenPieces", SummaryArray::Double, 1, { static_cast<double>(scan.OpenPieces) } },
    { "ScanSurfaceVolume", SummaryArray::Double, 1, { scan.Volume } },
    { "ScanDistanceMean", SummaryArray::Double, 1, { scan.MeanDistance } },
    { "ScanDistance95", SummaryArray::Double, 1, { scan.Distance95 } },
    { "ScanDepth", SummaryArray::Double, 1, { scan.MedianDepth } },
  };
}

/// Steps 1-9 (Reconstruct, in its thread scope).
Outcome ReconstructSteps(Reconstruction& run, std::vector<double> xyz, std::shared_ptr<const Sampling> sampling,
  SurfaceSink& sink, const VolumeRequest& volume, bool distributed)
{
  Outcome outcome;
  if (Printing(run.GetSettings()) && distributed)
  {
    outcome.Error = PrintDistributedError();
    return outcome;
  }
  // Step 5's dense arrays, which the run fills: for output 0, or for
  // keeping one sheet (KeepSheets works on the whole grid, so not when
  // distributed) or printing.
  VolumeArrays dense;
  if (NeedsDenseVolume(run.GetSettings(), distributed))
  {
    const std::int64_t ghosts = run.GetSettings().OutputVolume ? volume.GhostLayers : 0;
    run.RequestVolume(ghosts, [&](std::int64_t kBegin, std::int64_t kEnd) {
      dense = volume.Allocate(kBegin, kEnd);
      outcome.DenseArrays = true;
      return dense;
    });
  }
  // Steps 1-6. The part to print is checked against the scan's own points
  // (not the bridging ones the run adds), and the scan surface placed
  // among them: a copy.
  const bool scanning = ScanSurface(run.GetSettings(), distributed);
  const std::vector<double> scan = Printing(run.GetSettings()) || scanning ? xyz : std::vector<double>();
  if (!run.Run(std::move(xyz), std::move(sampling)))
  {
    outcome.Error = run.Error();
    return outcome;
  }
  outcome.Ran = true;
  outcome.Chosen = ResultsOf(run);
  // Steps 7 and 8: the surface of this process's piece, its small pieces removed.
  const auto start = std::chrono::steady_clock::now();
  bool done = true;
  bool explained = false;
  if (!run.EmptyPiece())
  {
    outcome.VolumeBegin = outcome.DenseArrays ? run.VolumeBegin() : run.PieceBegin();
    outcome.VolumeEnd = outcome.DenseArrays ? run.VolumeEnd() : run.PieceEnd();
    done = MakeSurface(run, sink, dense, distributed, scan, outcome, explained);
  }
  outcome.OutputSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!done && !run.Error().empty())
  {
    outcome.Error = run.Error(); // the device failed making the surface (nvEngine.h's one rule)
    return outcome;
  }
  // Step 9. Every process agrees whether the run is done, whatever stage it
  // stopped in; the first speaks for the whole result.
  outcome.Done = !run.Anywhere(!done);
  const double surfacePoints = run.SumAll(static_cast<double>(sink.View().NumberOfPoints));
  if (!outcome.Done)
  {
    return outcome;
  }
  if (run.FirstProcess())
  {
    WarnAboutResult(run, distributed, surfacePoints, explained, outcome);
  }
  outcome.Summary = RunSummary(run, outcome.Removed);
  if (outcome.Printed)
  {
    const std::vector<SummaryArray> part = PartSummary(run.GetSettings(), outcome.Print);
    outcome.Summary.insert(outcome.Summary.end() - 1, part.begin(), part.end()); // StageSeconds stays last
  }
  if (outcome.Scanned)
  {
    const std::vector<SummaryArray> figures = ScanSummary(outcome.Scan);
    outcome.Summary.insert(outcome.Summary.end() - 1, figures.begin(), figures.end());
  }
  return outcome;
}
} // namespace

std::shared_ptr<const Sampling> SamplingCache::Get(const Key& key,
  const std::function<std::vector<double>()>& points, Communicator* communicator, Monitor& monitor, int threads,
  bool* measured)
{
  bool stale = !this->Measured || !(key == this->MeasuredKey) || (communicator != nullptr) != this->MeasuredShared;
  if (communicator)
  {
    stale = communicator->MaxAll(stale ? 1.0 : 0.0) > 0.0; // all measure, or none
  }
  if (measured)
  {
    *measured = stale;
  }
  if (!stale)
  {
    return this->Measured;
  }
  this->Measured = nullptr; // until this measurement is complete
  struct Clock // the seconds count even when the measurement throws
  {
    double& Seconds;
    const std::chrono::steady_clock::time_point Start = std::chrono::steady_clock::now();
    ~Clock() { this->Seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - this->Start).count(); }
  } clock{ this->Unreported };
  monitor.Stage(0.0, SamplingStage);
  auto sampling = std::make_shared<Sampling>();
  bool complete = false;
  WithThreads(threads, [&]() { complete = sampling->Measure(points(), communicator, &monitor); });
  if (!complete)
  {
    return nullptr;
  }
  this->Measured = sampling;
  this->MeasuredKey = key;
  this->MeasuredShared = communicator != nullptr;
  return sampling;
}

double SamplingCache::TakeSeconds()
{
  const double seconds = this->Unreported;
  this->Unreported = 0.0;
  return seconds;
}

std::string InPanelWords(std::string message)
{
  static const std::pair<const char*, const char*> labels[] = {
#define NV_LABEL(Name, Label) { #Name, Label },
    NV_PANEL_LABELS(NV_LABEL)
#undef NV_LABEL
  };
  const auto inWord = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  for (const auto& label : labels)
  {
    const std::string name = label.first;
    for (std::size_t at = message.find(name); at != std::string::npos; at = message.find(name, at))
    {
      const std::size_t end = at + name.size();
      if ((at > 0 && inWord(message[at - 1])) || (end < message.size() && inWord(message[end])))
      {
        at = end;
        continue;
      }
      message.replace(at, name.size(), label.second);
      at += std::strlen(label.second);
    }
  }
  return message;
}

std::string TableInputError()
{
  return "The input is a table (a CSV file read as columns), not points.\n"
         "Apply Table To Points to it (its X, Y and Z columns) and reconstruct from that, or open the file with "
         "the Point Cloud Text Reader.";
}

Outcome Reconstruct(Reconstruction& run, std::vector<double> xyz, std::shared_ptr<const Sampling> sampling,
  SurfaceSink& sink, const VolumeRequest& volume, bool distributed)
{
  // One thread scope for the whole call (the run's own, nested, has the same count).
  Outcome outcome;
  WithThreads(run.GetSettings().NumberOfThreads, [&]() {
    outcome = ReconstructSteps(run, std::move(xyz), std::move(sampling), sink, volume, distributed);
  });
  return outcome;
}

} // namespace nv
