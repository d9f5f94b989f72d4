// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// What a filter makes of a finished run (step 7), in the order both filters
// follow, the VTK filter (vtkNarrowVolumeReconstruction) and the Python
// filter of the wheel (Python/_filter.py):
//
//   1. before the run, the dense arrays asked for (NeedsDenseVolume,
//      Reconstruction::RequestVolume): output 0's phi and optional arrays;
//   2. the surface, progress stage OutputStage: from the band
//      (Reconstruction::ExtractSurface), or, to keep one sheet, from a copy
//      of the dense phi that KeepSheets rewrote (SurfaceFromDenseCopy,
//      ContourDense);
//   3. its small pieces removed, and phi flipped in the same regions
//      (RemoveSmallPieces, nvPieces.h);
//   4. the warnings below, and the run's figures in the volume's field data
//      (RunSummary).
#ifndef nvOutputs_h
#define nvOutputs_h

#include "nvPieces.h"
#include "nvReconstruction.h"

#include <cstdint>
#include <string>
#include <vector>

namespace nv
{
class Monitor;
class SurfaceSink;

/// The progress stage of the outputs (the run itself takes [0, 0.65)): begin, width.
constexpr double OutputStage[2] = { 0.65, 0.35 };

/// Whether the run fills dense arrays (RequestVolume): for output 0, or to
/// keep one sheet (KeepSheets needs the whole grid, which a distributed run
/// does not have: there both sheets are kept).
bool NeedsDenseVolume(const Settings& settings, bool distributed);

/// Whether the surface comes from a copy of the dense phi (one sheet kept)
/// rather than from the band.
bool SurfaceFromDenseCopy(const Settings& settings, bool distributed);

/**
 * The surface of the sheets the settings keep, from `phi`, a copy of the
 * dense phi on the whole grid, which KeepSheets rewrites. Returns false if
 * the monitor stopped it; `cavities`: KeepSheets' count (NoInnerSheet).
 */
bool ContourDense(const Reconstruction& run, float* phi, SurfaceSink& sink, Monitor* monitor,
  std::int64_t& cavities);

/// Whether the chosen sheets left nothing because the shell encloses no
/// cavity: an open input has no inner sheet.
bool NoInnerSheet(const Settings& settings, std::int64_t cavities);

/// One array of the run's summary in the volume's field data.
struct SummaryArray
{
  enum Type
  {
    Int,    ///< vtkIntArray
    Id,     ///< vtkIdTypeArray
    Double  ///< vtkDoubleArray
  };
  std::string Name;
  Type Kind;
  int Components;
  std::vector<double> Values;
};

/// The run's figures, as the field data of output 0.
std::vector<SummaryArray> RunSummary(const Reconstruction& run, const RemovedPieces& removed);

/// The warnings a filter gives about its outputs.
std::string GapWarning(const GapReport& gaps, double offset, double closingRadius);
std::string EmptySurfaceWarning(double offset, double spacing);
std::string NoInnerSheetWarning();
std::string OneSheetNeedsGridWarning();
std::string OneSheetDistributedWarning();

} // namespace nv

#endif
