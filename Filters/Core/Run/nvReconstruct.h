// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// nv::Reconstruct, the core's entry point: a whole reconstruction as a
// filter runs it, outputs included. Both filters, the VTK filter
// (vtkNarrowVolumeReconstruction) and the Python filter of the wheel
// (Python/_filter.py), call it and only convert what it makes.
//
//   std::vector<double> xyz = ...;               // the points, x y z after one another
//   nv::Settings settings;                       // the property table's defaults
//   settings.OffsetDistance = 0.02;              // l; 0: from the cloud's spacing
//   settings.OutputVolume = false;               // no dense phi (a VolumeRequest takes it)
//   nv::Reconstruction run(settings, nullptr, nullptr); // one process, no monitor
//   nv::SurfaceMesh surface;                     // or a sink into the caller's arrays
//   nv::Outcome outcome = nv::Reconstruct(run, xyz, nullptr, surface, nv::VolumeRequest(), false);
//   if (!outcome.Done) { /* outcome.Error says why */ }
//   // surface.Points, .Normals, .Triangles; outcome.Warnings, .Chosen, .Summary
//
// The steps of a run, in the order of the paper's section 3; steps 1-6 are
// nv::Reconstruction::Run (nvReconstruction.h), the others are here
// (their helpers in nvReconstruct.cxx):
//
//   1. check the user's settings and the points (a message says what to change),
//      and choose where the run computes: the CPU or, with Device GPU, the
//      device back end (the engine, nvEngine.h, which steps 5-7 call);
//   2. the points' spacing (nvSampling.h), and the grid around the points'
//      box (all processes' box): offset l and spacing h given, from the
//      number of cells along the longest side, or chosen from the spacing
//      (MakePlan);
//   3. in a distributed run, the slab of brick layers this process owns
//      (nvPartition.h), balanced by the points per layer, and the points
//      within reach of it, moved here from the other processes; then the
//      points that bridge the holes of the sampling (nvGapClosing.h), and
//      the holes left open;
//   4. the memory budget: the dense output and the per-brick tables before
//      anything large exists, the band once its size is known;
//   5. the truncated distance (eq. 6, 7) and the narrow band (the paper's
//      band construction: collect, store, connect, nvNarrowBand.h), and the dense arrays asked for (output 0's
//      phi and DenseArraysAsked, or phi alone to keep one sheet), which the
//      caller allocates once the run knows its piece (VolumeRequest), from
//      the same distances (nvVolume.h);
//   6. the time steps of the operator-split scheme (eq. 10-12), then the
//      band's phi into the dense arrays, and whether each hole left open
//      pierces the evolved shell (GapReport);
//   7. the phi = 0 surface, into the caller's sink: from the band
//      (Reconstruction::ExtractSurface: nvSurface.h, or the device's
//      kernels), or, to keep one
//      sheet, from a copy of the dense phi that KeepSheets rewrote
//      (nvSheets.h), or the part to print (nvPrintPart.h), or the
//      surface on the scan (nvScanSurface.h);
//   8. its small pieces removed, and phi flipped in the same regions
//      (RemoveSmallPieces, nvPieces.h);
//   9. the warnings (a grid too coarse for the offset, holes left open, an
//      empty surface, no inner sheet), the results the filters' Get methods
//      give (Results, the property table's RESULTS) and the run's figures
//      for the volume's field data, the seconds of its stages among them
//      ("StageSeconds", one component per stage).
//
// The whole call runs in one thread scope of Settings::NumberOfThreads
// threads (WithThreads, nvParallel.h).
#ifndef nvReconstruct_h
#define nvReconstruct_h

#include "nvPieces.h"
#include "nvPrintPart.h"
#include "nvReconstruction.h"
#include "nvScanSurface.h"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <type_traits>
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

/// What the run chose that the filters' Get<Name> methods give and the
/// panel shows read-only (OffsetDistanceUsed, ...): one field per row of
/// the property table's RESULTS (NV_RESULTS, nvSettingsTable.h), filled in
/// one place, ResultsOf (nvReconstruct.cxx); all zero (and "") when the run
/// did not get as far as its figures.
struct Results
{
  using Text = std::string;
  /// A result's field: one value, or an array of Size.
  template <class Type, int Size>
  using Values = std::conditional_t<Size == 1, Type, std::array<Type, Size>>;
#define NV_RESULTS_FIELD(Type, Name, Size) Values<Type, Size> Name{};
  NV_RESULTS(NV_RESULTS_FIELD)
#undef NV_RESULTS_FIELD
};

/// What the caller of Reconstruct gets besides the arrays it owns (the
/// dense arrays it allocated, the surface in its sink).
struct Outcome
{
  bool Done = false;  ///< false: the run failed (Error) or was stopped
  bool Ran = false;   ///< whether steps 1-6 finished (the run's figures and results are there)
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
  bool Scanned = false; ///< whether the surface is the scan surface (Sheets Scan)
  ScanReport Scan;      ///< its figures
  Results Chosen;                    ///< the run's results (when Ran)
  std::vector<SummaryArray> Summary; ///< the volume's field data (when Done)
  double OutputSeconds = 0.0;        ///< wall-clock seconds of steps 7-9
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
 * The sampling of a filter's input (nvSampling.h), measured once per
 * points: the information pass and the data pass, and runs that only change
 * properties, share one measurement. Both filters keep one.
 */
class SamplingCache
{
public:
  /// What tells the points apart: the caller's object (its address as a
  /// text), their modification time and their count.
  struct Key
  {
    std::string Object;
    std::uint64_t Time = 0;
    std::int64_t Count = 0;
    bool operator==(const Key& other) const
    {
      return this->Object == other.Object && this->Time == other.Time && this->Count == other.Count;
    }
  };

  /**
   * The sampling of the points that `points` gives (xyz triples), measured
   * on `threads` threads unless the last measurement has the same key and
   * was shared alike (by the processes of `communicator`, or by none); with
   * a communicator every process measures, or none (collective). A
   * measurement is the monitor's stage [0, SamplingStage). Null if the
   * monitor stopped it. measured: whether this call measured.
   */
  std::shared_ptr<const Sampling> Get(const Key& key, const std::function<std::vector<double>()>& points,
    Communicator* communicator, Monitor& monitor, int threads, bool* measured = nullptr);
  /// The seconds of the measurements made since the last call: the first
  /// run that uses a measurement reports it (the filters' SamplingTime).
  double TakeSeconds();

private:
  std::shared_ptr<const Sampling> Measured;
  Key MeasuredKey;
  bool MeasuredShared = false;
  double Unreported = 0.0;
};

/// A message of the core (it names the properties: OffsetDistance) with
/// each property's name replaced by its label in ParaView's panel (Offset
/// Distance, NV_PANEL_LABELS): what both filters give with
/// PanelLabelsInMessages. Whole names only.
std::string InPanelWords(std::string message);

/// The error for a table given as input (a CSV file read as a vtkTable):
/// both filters refuse it with this message.
std::string TableInputError();

/**
 * Runs `run` on this process's points (xyz triples) with their sampling
 * (null: measured here) and makes the outputs: steps 1-9 above, with the
 * progress and abort of the run's monitor. The surface goes to `sink`. In a
 * distributed run every process calls it; Done and Error agree on all of
 * them, and the warnings about the whole result come on the first process.
 */
Outcome Reconstruct(Reconstruction& run, std::vector<double> xyz, std::shared_ptr<const Sampling> sampling,
  SurfaceSink& sink, const VolumeRequest& volume, bool distributed);

} // namespace nv

#endif
