// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The warnings about the run's outputs (nvRunWarnings.h).
#include "nvRunWarnings.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace nv
{
namespace warnings
{
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

std::string OneSheetNeedsGridWarning(bool scan)
{
  return std::string(scan ? "The scan surface" : "Keeping one sheet") +
    " needs the dense grid: memory follows the whole box although OutputVolume is off.\n"
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

std::string SheetsWithWallWarning(const Settings& settings)
{
  std::ostringstream text;
  text << "Sheets is " << (settings.Sheets == Sheets::Scan ? "Scan" : settings.Sheets == Sheets::Outer ? "Outer" : "Inner")
       << ", but WallThickness is " << settings.WallThickness
       << ": the output is the part to print, whose outer surface lies on the scan, not "
       << (settings.Sheets == Sheets::Scan ? "the scan surface" : "one sheet") << ".\n"
       << "Set WallThickness to 0 for " << (settings.Sheets == Sheets::Scan ? "the scan surface" : "one sheet")
       << ", or Sheets to Both.";
  return text.str();
}

std::string PrintDistributedError()
{
  return "A part to print (WallThickness above 0) needs the whole grid on one process, and this run is "
         "distributed.\nRun on one process, or set WallThickness to 0.";
}

std::string OneSheetDistributedWarning()
{
  return "A distributed run outputs both sheets: keeping one, or the scan surface, needs the whole grid on one "
         "process.\nRun on one process to keep one sheet or make the scan surface.";
}

std::vector<std::string> ScanWarnings(const Reconstruction& run, const ScanReport& scan)
{
  const Plan& plan = run.GetPlan();
  const double l = run.GetParameters().OffsetDistance, h = run.GetGrid().Spacing;
  std::vector<std::string> warnings;
  std::ostringstream text;
  text << std::setprecision(3);
  if (!(scan.Bounds[1] > scan.Bounds[0]))
  {
    text << "The scan surface is empty: the shell neither encloses a solid nor has two sides to put a surface "
            "between, as around points along a curve rather than over a surface.\n"
         << "Keep the shell's sheets (Sheets Both), or refine the grid (SampleSpacing, now " << h
         << ") if the points are a surface.";
    warnings.push_back(text.str());
    return warnings;
  }
  const double diagonal = std::sqrt(std::pow(scan.Bounds[1] - scan.Bounds[0], 2) +
    std::pow(scan.Bounds[3] - scan.Bounds[2], 2) + std::pow(scan.Bounds[5] - scan.Bounds[4], 2));
  if (diagonal < LeastScanSurfaceShare * plan.Diagonal)
  {
    text << "The scan surface spans " << diagonal << " (its diagonal), " << 100.0 * diagonal / plan.Diagonal
         << " % of the cloud's " << plan.Diagonal
         << ": it lost most of the scan, where the points lie along curves rather than over a surface, or the "
            "grid is too coarse for them.\n"
         << "Keep the shell's sheets (Sheets Both), or refine the grid (SampleSpacing, now " << h << ").";
    warnings.push_back(text.str());
    text.str("");
  }
  if (scan.MedianDistance * h > l)
  {
    text << "Half of the scan's points lie farther than " << scan.MedianDistance * h
         << " from the scan surface, more than the offset distance (" << l
         << "): no surface goes through them (points along a curve), or their noise is thicker than the shell.\n"
         << "Raise OffsetDistance above the noise's thickness, or keep the shell's sheets (Sheets Both).";
    warnings.push_back(text.str());
  }
  return warnings;
}
} // namespace warnings
} // namespace nv
