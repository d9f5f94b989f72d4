// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// A whole reconstruction as a filter runs it, outputs included: both
// filters, the VTK filter (vtkNarrowVolumeReconstruction) and the Python
// filter of the wheel (Python/_filter.py), call Reconstruct and only convert
// what it makes. In order (the steps' helpers are in nvOutputs.cxx):
//
//   1. the dense arrays asked for (output 0's phi and DenseArraysAsked, or
//      phi alone to keep one sheet), which the caller allocates when the run
//      knows its piece (VolumeRequest);
//   2. the run itself, steps 1-6 (Reconstruction::Run);
//   3. the surface, into the caller's sink: from the band
//      (Reconstruction::ExtractSurface), or, to keep one sheet, from a copy
//      of the dense phi that KeepSheets rewrote (nvSheets.h);
//   4. its small pieces removed, and phi flipped in the same regions
//      (RemoveSmallPieces, nvPieces.h);
//   5. the warnings (a grid too coarse for the offset, holes left open, an
//      empty surface, no inner sheet) and the run's figures for the
//      volume's field data, the seconds of its stages among them
//      ("StageSeconds", one component per stage).
#ifndef nvOutputs_h
#define nvOutputs_h

#include "nvPieces.h"
#include "nvPrintPart.h"
#include "nvReconstruction.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace nv
{
class SurfaceSink;

/// The dense arrays of the volume output beside phi, as the settings ask
/// (none without OutputVolume: phi alone then serves KeepSheets).
struct VolumeContents
{
  bool InitialPhi = false;
  bool Distance = false;
  bool Band = false;
};
VolumeContents DenseArraysAsked(const Settings& settings);

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
  std::vector<std::string> ComponentNames; ///< empty, or one per component
};

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
  bool Printed = false; ///< whether the surface is the part to print (WallThickness > 0)
  PrintReport Print;    ///< its figures
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

/// The error for a table given as input (a CSV file read as a vtkTable):
/// both filters refuse it with this message.
std::string TableInputError();

/**
 * Runs `run` on this process's points (xyz triples) with their sampling
 * (null: measured here) and makes the outputs: steps 1-5 above, with the
 * progress and abort of the run's monitor. The surface goes to `sink`. In a
 * distributed run every process calls it; Done and Error agree on all of
 * them, and the warnings about the whole result come on the first process.
 */
Outcome Reconstruct(Reconstruction& run, std::vector<double> xyz, std::shared_ptr<const Sampling> sampling,
  SurfaceSink& sink, const VolumeRequest& volume, bool distributed);

} // namespace nv

#endif
