// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// What a filter makes of a finished run (step 7), in the order both filters
// follow, the VTK filter (vtkNarrowVolumeReconstruction) and the Python
// filter of the wheel (narrowvolume/_filter.py):
//
//   1. the volume piece: its geometry always; phi and the optional arrays on
//      request (Reconstruction::FillVolume), progress stage VolumeStage;
//   2. the surface, stage SurfaceStage: phi = 0 by vtkFlyingEdges3D, on a
//      copy of phi from which KeepSheets removed the unwanted sheets; or,
//      without the volume, slab by slab (SurfaceSlabs), stage SlabStage;
//   3. the warnings below, and the run's summary in the volume's field data
//      (NumberOfIterations, NarrowBandNodes, RelativeChange).
#ifndef nvOutputs_h
#define nvOutputs_h

#include "nvReconstruction.h"

#include <cstdint>
#include <string>
#include <vector>

namespace nv
{

/// Progress stages of the outputs (the run itself takes [0, 0.65)): begin, width.
constexpr double VolumeStage[2] = { 0.65, 0.15 };
constexpr double SurfaceStage[2] = { 0.8, 0.2 };
constexpr double SlabStage[2] = { 0.65, 0.35 };

/// Slab thickness in cells of the surface without the volume (a multiple of the brick size).
constexpr int SlabCells = 16;

/// Whether the surface is made slab by slab, without a dense phi: the volume
/// is off and every sheet is kept (choosing sheets needs the whole grid,
/// which a distributed run does not have: there both sheets are kept).
bool SurfaceBySlabs(const Settings& settings, bool distributed);

/// A slab of node layers [Begin, End) to contour; consecutive slabs share a layer.
struct Slab
{
  std::int64_t Begin;
  std::int64_t End;
};

/// The slabs of the layers [kFirst, kLast) (kLast < 0: to the grid's end)
/// that hold band nodes: elsewhere phi has no zero.
std::vector<Slab> SurfaceSlabs(
  const TruncatedDistance& distance, const NarrowBand& band, std::int64_t kFirst, std::int64_t kLast);

/// Whether the chosen sheets left nothing because the shell encloses no
/// cavity (KeepSheets found none): an open input has no inner sheet.
bool NoInnerSheet(const Settings& settings, std::int64_t cavities);

/// The warnings a filter gives about its outputs.
std::string EmptySurfaceWarning(const Settings& settings, double spacing);
std::string NoInnerSheetWarning();
std::string OneSheetNeedsGridWarning();
std::string OneSheetDistributedWarning();

} // namespace nv

#endif
