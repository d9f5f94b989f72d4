// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvOutputs.h"

#include "nvParallel.h"
#include "nvSheets.h"
#include "nvSurface.h"
#include "nvSurfaceField.h"

#include <sstream>

namespace nv
{

bool NeedsDenseVolume(const Settings& settings, bool distributed)
{
  return settings.OutputVolume || (settings.Sheets != Sheets::Both && !distributed);
}

bool SurfaceFromDenseCopy(const Settings& settings, bool distributed)
{
  return settings.Sheets != Sheets::Both && !distributed;
}

bool ContourDense(
  const Reconstruction& run, float* phi, SurfaceSink& sink, Monitor* monitor, std::int64_t& cavities)
{
  const Grid& grid = run.GetGrid();
  bool done = false;
  WithThreads(run.GetSettings().NumberOfThreads, [&]() {
    cavities = KeepSheets(grid, phi, run.GetSettings().Sheets);
    const DenseField field(grid, phi, 0, grid.Dims[2], run.GetParameters());
    done = ContourBricks(grid, field, sink, 0, -1, monitor);
  });
  return done;
}

bool NoInnerSheet(const Settings& settings, std::int64_t cavities)
{
  return settings.Sheets == Sheets::Inner && cavities == 0;
}

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
    { "LargestGap", SummaryArray::Double, 1, { gaps.LargestGap } },
    { "LargestGapCenter", SummaryArray::Double, 3,
      { gaps.LargestGapCenter[0], gaps.LargestGapCenter[1], gaps.LargestGapCenter[2] } },
    { "RemovedPieces", SummaryArray::Double, 1, { static_cast<double>(removed.Pieces) } },
    { "RemovedVoids", SummaryArray::Double, 1, { static_cast<double>(removed.Voids) } },
  };
}

std::string GapWarning(const GapReport& gaps, double offset, double closingRadius)
{
  std::ostringstream text;
  text << "The sampled surface has " << gaps.Gaps << (gaps.Gaps == 1 ? " gap" : " gaps")
       << (closingRadius > 0.0 ? " left open" : "") << ": holes wider than the offset distance " << offset
       << ", empty discs on the surface whose centre is farther than the offset from every point. The shell's wall "
          "is pierced there, and its outer and inner sheets may join. The largest has radius "
       << gaps.LargestGap << ", at (" << gaps.LargestGapCenter[0] << ", " << gaps.LargestGapCenter[1] << ", "
       << gaps.LargestGapCenter[2] << "). ";
  if (closingRadius > 0.0)
  {
    text << "Gaps up to ClosingRadius (" << closingRadius << ") are bridged with points; to bridge these too "
         << "(if they are gaps, not the surface's own openings), set ClosingRadius to at least " << gaps.LargestGap
         << ", or OffsetDistance above it.";
  }
  else
  {
    text << "Turn CloseGaps on to bridge gaps up to " << AutomaticClosingRadius << " times the offset with "
         << "points, or set OffsetDistance to at least " << gaps.LargestGap << ".";
  }
  text << " Field data NumberOfGaps, LargestGap and LargestGapCenter hold these figures.";
  return text.str();
}

std::string EmptySurfaceWarning(double offset, double spacing)
{
  std::ostringstream text;
  text << "The surface is empty: the shell did not survive the evolution. The offset distance (" << offset
       << ") is probably small against the gaps between points or the grid spacing (" << spacing
       << "): increase OffsetDistance or XiCells, or refine the grid.";
  return text.str();
}

std::string NoInnerSheetWarning()
{
  return "There is no inner sheet: the shell encloses no cavity, so its two sheets join into one. The input's "
         "surface is open (a one-sided scan, or holes wider than twice the offset distance); its shell has "
         "only an outer sheet.";
}

std::string OneSheetNeedsGridWarning()
{
  return "Keeping one sheet needs the dense grid: memory follows the box although OutputVolume is off.";
}

std::string OneSheetDistributedWarning()
{
  return "Keeping one sheet needs the whole grid on one process: both sheets are output in a distributed run.";
}

} // namespace nv
