// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// A whole reconstruction as a filter runs it, outputs included: both
// filters, the VTK filter (vtkNarrowVolumeReconstruction) and the Python
// filter of the wheel (Python/_filter.py), call Reconstruct and only convert
// what it makes. In order:
//
//   1. the dense arrays asked for (NeedsDenseVolume, VolumeContents), which
//      the caller allocates when the run knows its piece (RequestVolume);
//   2. the run itself, steps 1-6 (Reconstruction::Run);
//   3. the surface, progress stage OutputStage: from the band
//      (Reconstruction::ExtractSurface), or, to keep one sheet, from a copy
//      of the dense phi that KeepSheets rewrote (SurfaceFromDenseCopy,
//      ContourDense);
//   4. its small pieces removed, and phi flipped in the same regions
//      (RemoveSmallPieces, nvPieces.h);
//   5. the warnings below, and the run's figures for the volume's field
//      data (RunSummary).
#ifndef nvOutputs_h
#define nvOutputs_h

#include "nvPieces.h"
#include "nvReconstruction.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace nv
{
class Monitor;
class SurfaceSink;

/// The progress stage of the outputs (the run itself takes [0, 0.65)): begin, width.
constexpr double OutputStage[2] = { 0.65, 0.35 };

/// The dense arrays of the volume output beside phi, as the settings ask
/// (none without OutputVolume: phi alone then serves KeepSheets).
struct VolumeContents
{
  bool InitialPhi = false;
  bool Distance = false;
  bool Band = false;
};
VolumeContents DenseArraysAsked(const Settings& settings);

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

/// What the caller of Reconstruct gets besides the arrays it owns (the
/// dense arrays it allocated, the surface in its sink).
struct Outcome
{
  bool Done = false;  ///< false: the run failed (Error) or was stopped
  bool Ran = false;   ///< whether steps 1-6 finished (the run's figures are there)
  std::string Error;  ///< why it failed (the same on every process); empty when stopped
  std::vector<std::string> Warnings; ///< in the order they arose
  /// The node layers along z the volume output covers: the dense arrays'
  /// (the piece and its ghost layers), or the piece's when there are none;
  /// empty when this process has no piece.
  std::int64_t VolumeBegin = 0;
  std::int64_t VolumeEnd = 0;
  bool DenseArrays = false; ///< whether the caller's dense arrays were filled
  RemovedPieces Removed;
  std::vector<SummaryArray> Summary; ///< the volume's field data (when Done)
  double OutputSeconds = 0.0;        ///< wall-clock seconds of steps 3-5
};

/// How the caller takes the dense arrays: up to GhostLayers node layers on
/// each side of its piece (a distributed run's ghost levels), in arrays
/// Allocate returns (phi, and those DenseArraysAsked names).
struct VolumeRequest
{
  std::int64_t GhostLayers = 0;
  Reconstruction::VolumeAllocator Allocate;
};

/**
 * Runs `run` on this process's points (xyz triples) with their sampling
 * (null: measured here) and makes the outputs: steps 1-5 above, with the
 * progress and abort of the run's monitor. The surface goes to `sink`. In a
 * distributed run every process calls it; Done and Error agree on all of
 * them, and the warnings about the whole result come on the first process.
 */
Outcome Reconstruct(Reconstruction& run, std::vector<double> xyz, std::shared_ptr<const Sampling> sampling,
  SurfaceSink& sink, const VolumeRequest& volume, bool distributed);

/// The warnings a filter gives about its outputs.
std::string GapWarning(const GapReport& gaps, double offset, double closingRadius);
std::string EmptySurfaceWarning(double offset, double spacing);
std::string NoInnerSheetWarning();
std::string OneSheetNeedsGridWarning();
std::string OneSheetDistributedWarning();

} // namespace nv

#endif
