// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvOutputs.h"

#include <algorithm>
#include <sstream>

namespace nv
{

bool SurfaceBySlabs(const Settings& settings, bool distributed)
{
  return !settings.OutputVolume && (settings.KeptSheets == Sheets::Both || distributed);
}

std::vector<Slab> SurfaceSlabs(
  const TruncatedDistance& distance, const NarrowBand& band, std::int64_t kFirst, std::int64_t kLast)
{
  const std::int64_t nz = kLast < 0 ? distance.GetGrid().Dims[2] : kLast;
  // Brick layers that hold band nodes.
  const std::int64_t bricksPerLayer = distance.GetBrickDims()[0] * distance.GetBrickDims()[1];
  std::vector<bool> layerHasBand(static_cast<std::size_t>(distance.GetBrickDims()[2]), false);
  for (std::size_t b = 0; b < band.Bricks.size(); ++b)
  {
    if (band.RedStart[b + 1] > band.RedStart[b] || band.BlackStart[b + 1] > band.BlackStart[b])
    {
      layerHasBand[static_cast<std::size_t>(band.Bricks[b] / bricksPerLayer)] = true;
    }
  }
  std::vector<Slab> slabs;
  for (std::int64_t kBegin = kFirst; kBegin + 1 < nz; kBegin += SlabCells)
  {
    const std::int64_t kEnd = std::min(kBegin + SlabCells + 1, nz); // one shared layer with the next slab
    bool any = false;
    for (std::int64_t layer = kBegin >> BrickShift; layer <= (kEnd - 1) >> BrickShift; ++layer)
    {
      any = any || layerHasBand[static_cast<std::size_t>(layer)];
    }
    if (any)
    {
      slabs.push_back({ kBegin, kEnd });
    }
  }
  return slabs;
}

bool NoInnerSheet(const Settings& settings, std::int64_t cavities)
{
  return settings.KeptSheets == Sheets::Inner && cavities == 0;
}

std::string EmptySurfaceWarning(const Settings& settings, double spacing)
{
  std::ostringstream text;
  text << "The surface is empty: the shell did not survive the evolution. The offset distance ("
       << settings.OffsetDistance << ") is probably small against the gaps between points or the grid spacing ("
       << spacing << "): increase OffsetDistance or XiCells, or refine the grid.";
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
