// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvReconstruct.h"

#include "nvCommunicator.h"
#include "nvParallel.h"
#include "nvPrintPart.h"
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
/// Whether the surface is the part to print (nvPrintPart.h) rather than the shell.
bool Printing(const Settings& settings)
{
  return settings.WallThickness > 0.0;
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

// The warnings about the outputs: one line of what happened, one of what to
// change, with the properties' names (the VTK filter puts the panel's
// labels in their place in ParaView, the command line its options). The
// figures are in the Volume output's field data (RunSummary).
std::string Plural(std::int64_t count, const char* one, const char* many)
{
  return std::to_string(count) + " " + (count == 1 ? one : many);
}

std::string HoleFigures(const OpenHole& widest, std::int64_t count)
{
  std::ostringstream text;
  text << (count == 1 ? "(radius " : "(the widest has radius ") << widest.Radius << ", centre (" << widest.Center[0]
       << ", " << widest.Center[1] << ", " << widest.Center[2] << "); field data PiercedGaps)";
  return text.str();
}

/// The warnings about the holes left open that pierce the evolved shell
/// (OpenHole::Pierced; the others are covered by the wall and only counted
/// in NumberOfGaps), in two kinds, each with the change that covers it:
/// holes wider than ClosingRadius (or than l when nothing is bridged), which
/// a larger radius bridges, and holes the bridging left open although they
/// are narrower (its rounds ran out, or their rim is not flat enough to
/// bridge: nvGapClosing.h), which only a thicker wall covers.
std::vector<std::string> GapWarnings(const GapReport& gaps, double closingRadius, double offset, bool printing)
{
  // The part to print is made from the shell: its wall is the one pierced.
  const char* wall = printing ? " the wall of the shell the part is made from " : " the shell's wall ";
  const OpenHole* widest[2] = { nullptr, nullptr };
  std::int64_t count[2] = { 0, 0 };
  for (const OpenHole& hole : gaps.Holes) // widest first
  {
    if (hole.Pierced)
    {
      const int left = closingRadius > 0.0 && hole.Radius <= closingRadius ? 1 : 0;
      ++count[left];
      widest[left] = widest[left] ? widest[left] : &hole;
    }
  }
  std::vector<std::string> warnings;
  if (count[0] > 0)
  {
    std::ostringstream text;
    text << Plural(count[0], "hole", "holes") << " in the sampling " << (count[0] == 1 ? "is" : "are")
         << " wider than " << (closingRadius > 0.0 ? "ClosingRadius (" : "OffsetDistance (")
         << (closingRadius > 0.0 ? closingRadius : offset) << ") and pierce" << (count[0] == 1 ? "s" : "")
         << wall << HoleFigures(*widest[0], count[0])
         << ".\n";
    if (closingRadius > 0.0)
    {
      text << (count[0] == 1 ? "If it is a gap, not an opening of the surface itself"
                             : "If they are gaps, not the surface's own openings")
           << ", set ClosingRadius to " << ThreeDigits(widest[0]->Radius, true) << " or more to bridge "
           << (count[0] == 1 ? "it." : "them.");
    }
    else
    {
      text << "Turn CloseGaps on, or set OffsetDistance to " << ThreeDigits(widest[0]->Radius / BridgeTarget, true)
           << " or more to cover " << (count[0] == 1 ? "it." : "them.");
    }
    warnings.push_back(text.str());
  }
  if (count[1] > 0)
  {
    std::ostringstream text;
    text << Plural(count[1], "hole", "holes") << " narrower than ClosingRadius (" << closingRadius << ") "
         << (count[1] == 1 ? "was" : "were")
         << " left open by the gap closing (its rounds ran out, or the rim is too uneven to bridge) and pierce"
         << (count[1] == 1 ? "s" : "") << wall << HoleFigures(*widest[1], count[1]) << ".\n"
         << "A larger ClosingRadius does not change that: set OffsetDistance to "
         << ThreeDigits(widest[1]->Radius / BridgeTarget, true) << " or more, and the wall covers "
         << (count[1] == 1 ? "it." : "them.");
    warnings.push_back(text.str());
  }
  return warnings;
}

std::string OffsetOverCloudWarning(double offset, double diagonal)
{
  std::ostringstream text;
  text << "OffsetDistance (" << offset << ") is larger than the cloud itself (the diagonal of its bounds is "
       << diagonal << "): the shell is a ball around all the points, with none of their shape.\n"
       << "Set OffsetDistance well below " << diagonal << ", or to 0 for the value the sampling asks for.";
  return text.str();
}

std::string CoarsenedGridWarning(const Reconstruction& run)
{
  const Plan& plan = run.GetPlan();
  const Grid& grid = run.GetGrid();
  std::ostringstream text;
  text << "The grid was coarsened to keep it within " << AutomaticMaximumDimension
       << " cells on its longest side: SampleSpacing " << grid.Spacing << " instead of " << plan.CoarsenedFrom;
  if (plan.AutomaticOffset && run.GetParameters().OffsetDistance > plan.OffsetBeforeCoarsening)
  {
    text << ", and OffsetDistance raised from " << plan.OffsetBeforeCoarsening << " (what the sampling asks for) to "
         << run.GetParameters().OffsetDistance << " (4 cells)";
  }
  text << ".\nFor the finer grid set SampleSpacing to " << plan.CoarsenedFrom << " (or MaximumDimension to "
       << static_cast<long long>(std::ceil(AutomaticMaximumDimension * grid.Spacing / plan.CoarsenedFrom))
       << "), memory permitting.";
  return text.str();
}

std::string OpenShellWarning(const GapReport& gaps, double closingRadius, double offset)
{
  std::ostringstream text;
  text << "The shell encloses no cavity, so it is a thickened sheet or a solid, not a hollow: the sampled surface is "
          "open (right for an open scan), or the object is thinner than twice OffsetDistance ("
       << offset << ") and the wall fills it.\n";
  if (gaps.PiercedGaps() > 0)
  {
    text << "For a hollow, bridge the holes that pierce the wall (the warning before this one), or lower "
            "OffsetDistance for a thin object; a scan's own open edges stay open.";
  }
  else
  {
    text << "For a hollow, lower OffsetDistance for a thin object; an opening is bridged only up to ClosingRadius ("
         << closingRadius << "): raise it to the opening's radius, or scan the missing side.";
  }
  return text.str();
}

/// The least offset / spacing ratio that keeps the shell whole: the
/// initial profile and the band span 2 XiCells = 4 cells (eq. 2, 5), which
/// the wall of 2 l must hold with room to spare.
constexpr double LeastCellsPerOffset = 3.0;

std::string CoarseGridWarning(const Reconstruction& run)
{
  const double offset = run.GetParameters().OffsetDistance;
  const Grid& grid = run.GetGrid();
  const double longest = (std::max({ grid.Dims[0], grid.Dims[1], grid.Dims[2] }) - 1) * grid.Spacing;
  std::ostringstream text;
  text << "The grid is coarse for the offset distance (offset / spacing " << offset / grid.Spacing << ", below "
       << LeastCellsPerOffset << "): the shell may break into pieces.\n"
       << "Set SampleSpacing to " << offset / LeastCellsPerOffset << " or less (or MaximumDimension to "
       << static_cast<long long>(std::ceil(longest * LeastCellsPerOffset / offset))
       << "), memory permitting, or raise OffsetDistance.";
  return text.str();
}

std::string EmptySurfaceWarning(double offset, double spacing)
{
  std::ostringstream text;
  text << "The surface is empty: the shell did not survive the evolution.\n"
       << "Raise OffsetDistance (now " << offset << ") or XiCells, or refine the grid (SampleSpacing, now " << spacing
       << ").";
  return text.str();
}

std::string NoInnerSheetWarning()
{
  return "There is no inner sheet: the shell encloses no cavity, as the surface is open (a one-sided scan, or "
         "holes wider than twice the offset distance).\n"
         "Keep both sheets or the outer one (Sheets), or close the holes (CloseGaps, ClosingRadius).";
}

std::string OneSheetNeedsGridWarning()
{
  return "Keeping one sheet needs the dense grid: memory follows the whole box although OutputVolume is off.\n"
         "Keep both sheets (Sheets) where memory is short.";
}

std::string EmptyPartWarning()
{
  return "The part to print is empty: the shell's outer sheet encloses no solid wider than twice the offset "
         "distance (an open scan's shell is a thin sheet, whose closing is empty).\n"
         "Close the scan's holes (CloseGaps, ClosingRadius), or set WallThickness to 0 to print the shell itself.";
}

/// A place, as a message writes it: "(x, y, z)".
std::string Place(const std::array<double, 3>& x)
{
  std::ostringstream text;
  text << std::setprecision(4) << "(" << x[0] << ", " << x[1] << ", " << x[2] << ")";
  return text.str();
}

std::string ThinWallWarning(double wall, double spacing)
{
  std::ostringstream text;
  text << std::setprecision(3) << "The wall spans only " << wall / spacing
       << " cells of the grid (WallThickness " << wall << ", SampleSpacing " << spacing << "): a wall under "
       << LeastCellsPerWall << " cells breaks into fragments and holes, and its pieces are removed as small.\n"
       << "Set SampleSpacing to " << wall / LeastCellsPerWall
       << " or less (or 0: the automatic grid follows the wall), memory permitting, or raise WallThickness.";
  return text.str();
}

/// "N points around (x, y, z), a x b x c" for the largest region, and how
/// many there are.
std::string RegionFigures(const std::vector<LostRegion>& regions)
{
  const LostRegion& largest = regions.front();
  std::ostringstream text;
  text << std::setprecision(4) << (regions.size() == 1 ? "" : "the largest of " + std::to_string(regions.size()) + " places: ")
       << largest.Points << " points around " << Place(largest.Center) << ", " << largest.Size[0] << " x "
       << largest.Size[1] << " x " << largest.Size[2];
  return text.str();
}

/// The scan points the part still lost (PrintReport::LostPoints), and where.
std::string LostPointsWarning(const PrintReport& print)
{
  std::ostringstream text;
  const double share = static_cast<double>(print.LostPoints) / static_cast<double>(print.ScanPoints);
  text << std::setprecision(3) << print.LostPoints << " of the scan's " << print.ScanPoints << " points ("
       << 100.0 * share << " %) lie outside the part, up to " << print.FarthestLost + print.LostDistance
       << " from it (" << RegionFigures(print.LostRegions) << "; field data LostPoints, LostRegionCenter).\n";
  if (share > RestorableShare)
  {
    // Most of the scan, not a limb: the closing itself is (nearly) empty.
    text << "The scan's closing is mostly empty, as for an open scan or one with wide holes: close the scan's holes "
            "(CloseGaps, ClosingRadius), or set WallThickness to 0 to print the shell itself.";
  }
  else
  {
    text << "The shell holds them: set WallThickness to 0 to print the shell itself.";
  }
  return text.str();
}

std::string RestoredWarning(const PrintReport& print)
{
  std::ostringstream text;
  text << std::setprecision(4) << "The part had lost " << Plural(print.RestoredPoints, "scan point", "scan points")
       << " (" << RegionFigures(print.RestoredRegions)
       << "): a limb or piece thinner than the closing holds. Material was put back around them, so there the "
          "part's surface lies up to "
       << print.LostDistance << " outside the points, not on them (field data RestoredPoints).\n"
       << "Check the part there, or set WallThickness to 0 to print the shell itself.";
  return text.str();
}

/// The warnings about the part to print, after it is made: each says what
/// is wrong with the part and what to change.
std::vector<std::string> PartWarnings(const Settings& settings, const Reconstruction& run, const PrintReport& print,
  double surfacePoints)
{
  std::vector<std::string> warnings;
  const double h = run.GetGrid().Spacing, w = settings.WallThickness, l = run.GetParameters().OffsetDistance;
  if (w < LeastCellsPerWall * h * (1.0 - 1e-9))
  {
    warnings.push_back(ThinWallWarning(w, h));
  }
  if (surfacePoints == 0)
  {
    if (!(w < LeastCellsPerWall * h * (1.0 - 1e-9)))
    {
      warnings.push_back(EmptyPartWarning());
    }
    return warnings;
  }
  if (print.RestoredPoints > 0)
  {
    warnings.push_back(RestoredWarning(print));
  }
  if (print.LostPoints > 0)
  {
    warnings.push_back(LostPointsWarning(print));
  }
  // A wall of w around a surface of area A holds about A w of material, the
  // shell about A 2 l: a part with under a quarter of that share lost most
  // of the closing.
  const double share = std::min(1.0, w / (2.0 * l));
  const bool collapsed = print.ShellVolume > 0.0 && print.MaterialVolume < 0.25 * share * print.ShellVolume;
  if (collapsed)
  {
    std::ostringstream text;
    text << std::setprecision(3) << "The part holds " << 100.0 * print.MaterialVolume / print.ShellVolume
         << " % of the shell's material, where a wall of WallThickness " << w << " should hold about "
         << 100.0 * share << " % of it (WallThickness / (2 OffsetDistance), at most all): the part lost most of "
         << "the scan's closing.\n"
         << "Close the scan's holes (CloseGaps, ClosingRadius), or set WallThickness to 0 to print the shell itself.";
    warnings.push_back(text.str());
  }
  if (print.KeptCavities > 0 && print.MinimumWallThickness < w - h)
  {
    std::ostringstream text;
    text << std::setprecision(4) << "The part's wall is " << print.MinimumWallThickness << " at its thinnest, at "
         << Place(print.ThinnestWallAt) << ", below WallThickness (" << w << ") by more than a grid cell ("
         << h << ").\nSet SampleSpacing to " << w / LeastCellsPerWall << " or less, memory permitting.";
    warnings.push_back(text.str());
  }
  if (print.Pieces > 1 && !collapsed)
  {
    std::ostringstream text;
    text << "The part is " << print.Pieces << " separate pieces of material, each of which holds scan points ("
         << print.RemovedPieces << " smaller ones without were removed; field data PartPieces).\n"
         << "If the scan is of one object, its pieces are apart where the scan has a gap wider than "
            "ClosingRadius: raise it to bridge the gap.";
    warnings.push_back(text.str());
  }
  const bool placed = !settings.DrainHolePositions.empty();
  const std::int64_t positions = static_cast<std::int64_t>(settings.DrainHolePositions.size() / 3);
  if (placed && print.KeptCavities == 0)
  {
    std::ostringstream text;
    text << "DrainHolePositions gives " << Plural(positions, "place", "places")
         << " for drain holes, but the part has no cavity: it is solid, and no hole was made.\n"
         << "A part is hollow where the model is thicker than twice WallThickness; remove the "
            "positions for a solid part.";
    warnings.push_back(text.str());
  }
  if (print.DrainHoles < print.DrainHolesAsked)
  {
    std::ostringstream text;
    if (placed)
    {
      text << Plural(positions, "drain hole position was", "drain hole positions were")
           << " given (DrainHolePositions), and " << print.DrainHoles << " made";
    }
    else
    {
      text << Plural(print.DrainHolesAsked, "drain hole was", "drain holes were") << " asked for ("
           << "NumberOfDrainHoles " << settings.NumberOfDrainHoles << " for each of "
           << Plural(print.KeptCavities, "cavity", "cavities") << "), and " << print.DrainHoles
           << " made: holes start at least three diameters apart on a cavity's lowest points";
    }
    if (print.DrainPositionsAway > 0)
    {
      text << std::setprecision(4) << ": " << Plural(print.DrainPositionsAway, "position lies", "positions lie")
           << " farther than 2 (OffsetDistance + WallThickness) from every cavity (the first at "
           << Place(print.FirstPositionAway) << ")";
    }
    if (print.DrainHolesTooLong > 0)
    {
      text << (placed && print.DrainPositionsAway == 0 ? ": " : ", and ")
           << Plural(print.DrainHolesTooLong, "place was", "places were") << " passed over where the hole's way ("
           << (placed ? "from the cavity through its position, or from a position in a cavity the shortest "
                      : "the shortest ")
           << "within DrainHoleAngle (" << settings.DrainHoleAngle
           << " degrees) of DrainHoleAxis) runs through more than 2 (OffsetDistance + WallThickness) of the "
              "part (down or along a limb, or through a wall at a slant)";
    }
    if (placed)
    {
      text << ".\nPlace each position on the part's surface where a cavity lies behind the wall, raise "
              "DrainHoleAngle, or choose another DrainHoleAxis.";
    }
    else
    {
      text << ", and the cavities' floors have room for no more.\n"
           << "Lower DrainHoleDiameter for more holes, raise DrainHoleAngle, or choose another DrainHoleAxis.";
    }
    warnings.push_back(text.str());
  }
  if (print.CavitiesWithoutHoles > 0 && print.DrainHolesAsked > 0)
  {
    std::ostringstream text;
    text << Plural(print.CavitiesWithoutHoles, "cavity", "cavities") << " of the "
         << print.KeptCavities << " kept " << (print.CavitiesWithoutHoles == 1 ? "has" : "have")
         << " no drain hole: resin or powder stays sealed in "
         << (print.CavitiesWithoutHoles == 1 ? "it" : "them") << ".\n"
         << (placed ? "Give a position in DrainHolePositions near each cavity, or raise MinimumCavityVolume to merge "
                      "small ones into the wall."
                    : "Raise DrainHoleAngle, choose another DrainHoleAxis, or give DrainHolePositions.");
    warnings.push_back(text.str());
  }
  return warnings;
}

std::string DrainHolesWithoutWallWarning(const Settings& settings)
{
  std::ostringstream text;
  if (settings.DrainHolePositions.empty())
  {
    text << "NumberOfDrainHoles is " << settings.NumberOfDrainHoles;
  }
  else
  {
    text << "DrainHolePositions gives " << Plural(static_cast<std::int64_t>(settings.DrainHolePositions.size() / 3),
                                             "place", "places");
  }
  text << ", but WallThickness is 0: the output is the shell, which has no drain holes.\n"
       << "Set WallThickness to the wall to print for a hollow part with drain holes, or "
       << (settings.DrainHolePositions.empty() ? "NumberOfDrainHoles to 0." : "remove DrainHolePositions.");
  return text.str();
}

std::string PrintDistributedError()
{
  return "A part to print (WallThickness above 0) needs the whole grid on one process, and this run is "
         "distributed.\nRun on one process, or set WallThickness to 0.";
}

std::string OneSheetDistributedWarning()
{
  return "A distributed run outputs both sheets: keeping one needs the whole grid on one process.\n"
         "Run on one process to keep one sheet.";
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

/// Step 7, printing: the part (nvPrintPart.h), from a copy of the dense phi
/// whose cavities KeepSheets fills. Returns false if the monitor stopped it.
bool MakePrintPart(Reconstruction& run, SurfaceSink& sink, const VolumeArrays& dense,
  const std::vector<double>& scan, Outcome& outcome)
{
  const Settings& settings = run.GetSettings();
  const Grid& grid = run.GetGrid();
  std::vector<float> outer(dense.Phi, dense.Phi + grid.NumberOfNodes());
  // A node where phi is exactly 0 (a sheet through a plane of nodes, as a
  // cloud whose faces lie on the grid's planes gives) counts as the shell's:
  // KeepSheets fills only phi < 0, and a plane of zeros inside the outer
  // sheet would stop the distance D there and open a cavity in the wall.
  std::replace(outer.begin(), outer.end(), 0.0f, std::numeric_limits<float>::min());
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
    KeepSheets(grid, outer.data(), Sheets::Outer, run.GetMonitor());
    return !StopAsked(run.GetMonitor()) &&
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
    outcome.Warnings.push_back(OneSheetNeedsGridWarning());
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
  const bool printing = Printing(settings);
  const bool done = printing ? MakePrintPart(run, sink, dense, scan, outcome)
                             : MakeShell(run, sink, dense, distributed, outcome, noInnerSheet);
  run.ReleaseBand(); // the surface is made: what follows needs neither
  const bool stopped = monitor && monitor->Aborted();
  if (done && !printing && settings.RemoveSmallPieces && !distributed && !stopped)
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
    for (std::string& warning : PartWarnings(settings, run, outcome.Print, surfacePoints))
    {
      outcome.Warnings.push_back(std::move(warning));
    }
  }
  else if (settings.NumberOfDrainHoles > 0 || !settings.DrainHolePositions.empty())
  {
    outcome.Warnings.push_back(DrainHolesWithoutWallWarning(settings));
  }
  if (surfacePoints == 0 && !Printing(settings) && !explained)
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
  // (not the bridging ones the run adds): a copy.
  const std::vector<double> scan = Printing(run.GetSettings()) ? xyz : std::vector<double>();
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
