// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNarrowVolumeReconstruction.h"

#include "nvAllenCahnSolver.h"
#include "nvControllerCommunicator.h"
#include "nvGrid.h"
#include "nvHalo.h"
#include "nvNarrowBand.h"
#include "nvParallel.h"
#include "nvParameters.h"
#include "nvPartition.h"
#include "nvSheets.h"
#include "nvSurface.h"
#include "nvTruncatedDistance.h"
#include "nvVolume.h"

#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkEventForwarderCommand.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include <vtksys/SystemInformation.hxx>

#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>
#include <sstream>
#include <string>
#include <thread>

vtkStandardNewMacro(vtkNarrowVolumeReconstruction);

namespace
{

double Seconds(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Forwards the core's progress to the filter (main thread only) and polls
/// the filter's abort flag there; worker threads see the cached answer.
class FilterMonitor : public nv::Monitor
{
public:
  FilterMonitor(vtkAlgorithm* filter)
    : Filter(filter)
    , MainThread(std::this_thread::get_id())
  {
  }
  void SetStage(double begin, double width)
  {
    this->Begin = begin;
    this->Width = width;
  }
  void Progress(double fraction) override
  {
    if (std::this_thread::get_id() == this->MainThread)
    {
      this->Filter->UpdateProgress(this->Begin + this->Width * fraction);
      this->Stop = this->Stop || this->Filter->GetAbortExecute();
    }
  }
  bool Aborted() override
  {
    if (std::this_thread::get_id() == this->MainThread)
    {
      this->Stop = this->Stop || this->Filter->GetAbortExecute();
    }
    return this->Stop;
  }

private:
  vtkAlgorithm* Filter;
  std::thread::id MainThread;
  double Begin = 0.0;
  double Width = 1.0;
  std::atomic<bool> Stop{ false };
};

/// The points as a flat xyz array of doubles, with their bounding box.
/// Returns the index of the first non-finite point, or -1.
vtkIdType GatherPoints(vtkPoints* points, std::vector<double>& xyz, double bounds[6])
{
  const vtkIdType n = points->GetNumberOfPoints();
  xyz.resize(static_cast<std::size_t>(3 * n));
  for (int a = 0; a < 3; ++a)
  {
    bounds[2 * a] = VTK_DOUBLE_MAX;
    bounds[2 * a + 1] = -VTK_DOUBLE_MAX;
  }
  for (vtkIdType p = 0; p < n; ++p)
  {
    double* x = &xyz[3 * p];
    points->GetPoint(p, x);
    for (int a = 0; a < 3; ++a)
    {
      if (!std::isfinite(x[a]))
      {
        return p;
      }
      bounds[2 * a] = std::min(bounds[2 * a], x[a]);
      bounds[2 * a + 1] = std::max(bounds[2 * a + 1], x[a]);
    }
  }
  return -1;
}

/// Marks the node layers of `volume` outside [pieceBegin, pieceEnd) (its
/// ghost layers) as duplicate points, and the cells outside the piece's cell
/// layers as duplicate cells, as ParaView expects of ghost levels.
void MarkGhostLayers(vtkImageData* volume, std::int64_t pieceBegin, std::int64_t pieceEnd)
{
  int extent[6];
  volume->GetExtent(extent);
  const vtkIdType layerPoints = static_cast<vtkIdType>(extent[1] - extent[0] + 1) * (extent[3] - extent[2] + 1);
  const vtkIdType layerCells = static_cast<vtkIdType>(std::max(extent[1] - extent[0], 1)) *
    std::max(extent[3] - extent[2], 1);
  vtkUnsignedCharArray* pointGhosts = volume->AllocatePointGhostArray();
  vtkUnsignedCharArray* cellGhosts = volume->AllocateCellGhostArray();
  for (int k = extent[4]; k <= extent[5]; ++k)
  {
    if (k < pieceBegin || k >= pieceEnd)
    {
      const vtkIdType first = layerPoints * (k - extent[4]);
      std::fill(pointGhosts->GetPointer(first), pointGhosts->GetPointer(first) + layerPoints,
        static_cast<unsigned char>(vtkDataSetAttributes::DUPLICATEPOINT));
    }
    if (k < extent[5] && (k < pieceBegin || k >= pieceEnd - 1))
    {
      const vtkIdType first = layerCells * (k - extent[4]);
      std::fill(cellGhosts->GetPointer(first), cellGhosts->GetPointer(first) + layerCells,
        static_cast<unsigned char>(vtkDataSetAttributes::DUPLICATECELL));
    }
  }
}

} // namespace

//------------------------------------------------------------------------------
vtkNarrowVolumeReconstruction::vtkNarrowVolumeReconstruction()
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(2);
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

vtkNarrowVolumeReconstruction::~vtkNarrowVolumeReconstruction()
{
  this->SetController(nullptr);
}

//------------------------------------------------------------------------------
int vtkNarrowVolumeReconstruction::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

int vtkNarrowVolumeReconstruction::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkImageData" : "vtkPolyData");
  return 1;
}

vtkImageData* vtkNarrowVolumeReconstruction::GetVolumeOutput()
{
  return vtkImageData::SafeDownCast(this->GetOutputDataObject(0));
}

vtkPolyData* vtkNarrowVolumeReconstruction::GetSurfaceOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

//------------------------------------------------------------------------------
vtkTypeBool vtkNarrowVolumeReconstruction::ProcessRequest(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (request->Has(vtkStreamingDemandDrivenPipeline::REQUEST_UPDATE_EXTENT()))
  {
    return this->RequestUpdateExtent(request, inputVector, outputVector);
  }
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA()))
  {
    return this->RequestData(request, inputVector, outputVector);
  }
  return this->Superclass::ProcessRequest(request, inputVector, outputVector);
}

//------------------------------------------------------------------------------
void vtkNarrowVolumeReconstruction::SetController(vtkMultiProcessController* controller)
{
  vtkSetObjectBodyMacro(Controller, vtkMultiProcessController, controller);
}

bool vtkNarrowVolumeReconstruction::IsDistributed(vtkInformationVector* outputVector) const
{
  if (!this->Controller || this->Controller->GetNumberOfProcesses() < 2)
  {
    return false;
  }
  for (int port = 0; port < 2; ++port)
  {
    vtkInformation* info = outputVector->GetInformationObject(port);
    if (info && info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()))
    {
      return info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()) ==
        this->Controller->GetNumberOfProcesses() &&
        info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()) ==
        this->Controller->GetLocalProcessId();
    }
  }
  return false;
}

//------------------------------------------------------------------------------
int vtkNarrowVolumeReconstruction::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // A distributed run takes each process's piece of the cloud and moves the
  // points where they are needed (RequestData). Otherwise the shell depends
  // on every point: ask for the whole cloud, and the piece 0 request alone
  // produces the output.
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  const bool distributed = this->IsDistributed(outputVector);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(),
    distributed ? this->Controller->GetLocalProcessId() : 0);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(),
    distributed ? this->Controller->GetNumberOfProcesses() : 1);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
  return 1;
}

//------------------------------------------------------------------------------
int vtkNarrowVolumeReconstruction::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0], 0);
  vtkInformation* volumeInfo = outputVector->GetInformationObject(0);
  vtkImageData* volume = vtkImageData::GetData(outputVector, 0);
  vtkPolyData* surface = vtkPolyData::GetData(outputVector, 1);
  volume->Initialize();
  surface->Initialize();
  this->RelativeChanges.clear();
  this->NumberOfBandNodes = 0;
  this->NumberOfGridNodes = 0;
  this->SetupTime = this->EvolutionTime = this->OutputTime = 0.0;

  // Distributed (see SetController), or one process computes everything:
  // then the requests for pieces other than 0 leave their outputs empty, so
  // that gathered pieces hold the serial result once.
  const bool distributed = this->IsDistributed(outputVector);
  vtkInformation* surfaceInfo = outputVector->GetInformationObject(1);
  if (!distributed && surfaceInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()) > 0)
  {
    return 1;
  }
  std::unique_ptr<nv::ControllerCommunicator> communicator;
  if (distributed)
  {
    communicator.reset(new nv::ControllerCommunicator(this->Controller));
  }
  // In a distributed run every error must be every process's: a flag raised
  // on one process is seen by all (a maximum over them).
  auto anywhere = [&](bool flag) { return communicator ? communicator->MaxAll(flag ? 1.0 : 0.0) > 0.0 : flag; };

  // --- Validate the input and the parameters before allocating anything large.
  std::vector<double> points;
  double bounds[6] = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX,
    -VTK_DOUBLE_MAX };
  vtkIdType bad = -1;
  if (input && input->GetPoints())
  {
    bad = GatherPoints(input->GetPoints(), points, bounds);
  }
  double totals[2] = { static_cast<double>(points.size() / 3), bad >= 0 ? 1.0 : 0.0 };
  if (communicator)
  {
    communicator->SumAll(totals, 2);
    // The global box: maxima of (-xmin, xmax, -ymin, ...).
    double box[6];
    for (int a = 0; a < 6; ++a)
    {
      box[a] = a % 2 ? bounds[a] : -bounds[a];
    }
    communicator->MaxAll(box, 6);
    for (int a = 0; a < 6; ++a)
    {
      bounds[a] = a % 2 ? box[a] : -box[a];
    }
  }
  if (totals[0] < 1.0)
  {
    vtkErrorMacro("The input has no points: nothing to reconstruct.");
    return 1;
  }
  if (totals[1] > 0.0)
  {
    if (bad >= 0)
    {
      vtkErrorMacro("Input point " << bad << " has a non-finite coordinate (NaN or infinity); "
                                   << "remove such points before reconstructing.");
    }
    else
    {
      vtkErrorMacro("A point of another process's piece has a non-finite coordinate (NaN or "
                    "infinity); remove such points before reconstructing.");
    }
    return 1;
  }
  if (!std::isfinite(this->OffsetDistance) || this->OffsetDistance <= 0.0)
  {
    vtkErrorMacro("OffsetDistance must be a finite value > 0, not "
      << this->OffsetDistance
      << ". (In ParaView its default follows the input's size: in a script, update the input "
         "before creating the filter, or set OffsetDistance.)");
    return 1;
  }
  if (!std::isfinite(this->SampleSpacing))
  {
    vtkErrorMacro("SampleSpacing must be finite, not " << this->SampleSpacing << ".");
    return 1;
  }
  if (!std::isfinite(this->TimeStep))
  {
    vtkErrorMacro("TimeStep must be finite, not " << this->TimeStep << ".");
    return 1;
  }
  if (!(this->XiCells >= 1.0 && this->XiCells <= 64.0))
  {
    vtkErrorMacro("XiCells must be in [1, 64], not " << this->XiCells << ".");
    return 1;
  }
  if (!(this->EpsilonCells >= 0.5 && this->EpsilonCells <= 256.0))
  {
    vtkErrorMacro("EpsilonCells must be in [0.5, 256], not " << this->EpsilonCells << ".");
    return 1;
  }

  nv::Parameters parameters;
  parameters.OffsetDistance = this->OffsetDistance;
  parameters.XiCells = this->XiCells;
  parameters.EpsilonCells = this->EpsilonCells;
  parameters.TimeStep = this->TimeStep;
  parameters.MaximumNumberOfIterations = this->MaximumNumberOfIterations;
  parameters.ConvergenceTolerance = this->ConvergenceTolerance;
  parameters.GaussSeidelTolerance = this->GaussSeidelTolerance;
  parameters.Mode = this->Domain == WHOLE_DOMAIN ? nv::Domain::WholeDomain : nv::Domain::NarrowBand;
  parameters.EdgeFunction =
    this->EdgeStoppingFunction == EQUATION_3 ? nv::EdgeStopping::Eq3 : nv::EdgeStopping::Eq4;
  parameters.Spacing = this->SampleSpacing > 0.0
    ? this->SampleSpacing
    : nv::SpacingForMaximumDimension(bounds, this->OffsetDistance, this->XiCells, this->MaximumDimension);
  if (!(parameters.Spacing > 0.0) || !std::isfinite(parameters.Spacing))
  {
    vtkErrorMacro("Cannot derive a grid spacing from MaximumDimension " << this->MaximumDimension
                                                                       << "; set SampleSpacing.");
    return 1;
  }

  // The grid's size, in floating point so that no integer can overflow.
  const double padding = nv::GridPadding(parameters.Reach(), parameters.Spacing);
  double cells[3];
  for (int a = 0; a < 3; ++a)
  {
    cells[a] = (bounds[2 * a + 1] - bounds[2 * a] + 2.0 * padding) / parameters.Spacing + 2.0;
  }
  const double gridNodes = cells[0] * cells[1] * cells[2];
  if (gridNodes > static_cast<double>(VTK_ID_MAX) || cells[2] > static_cast<double>(VTK_INT_MAX))
  {
    vtkErrorMacro("The grid is too large: about " << gridNodes << " nodes (spacing " << parameters.Spacing
                                                  << "). Increase SampleSpacing or lower MaximumDimension.");
    return 1;
  }
  const nv::Grid grid = nv::MakeGrid(bounds, parameters.Spacing, padding);
  this->NumberOfGridNodes = static_cast<vtkIdType>(grid.NumberOfNodes());

  // This process's part of the grid: all of it, or a slab of brick layers
  // balanced by the number of points per layer (nvPartition.h).
  const std::int64_t layers = (grid.Dims[2] + nv::BrickSize - 1) >> nv::BrickShift;
  nv::Subdomain part = nv::Subdomain::Whole(layers);
  std::vector<nv::LayerRange> owners(1, part.Owned);
  if (communicator)
  {
    std::vector<double> weights(static_cast<std::size_t>(layers), 0.0);
    for (std::size_t p = 0; p < points.size(); p += 3)
    {
      const std::int64_t k = static_cast<std::int64_t>((points[p + 2] - grid.Origin[2]) / grid.Spacing);
      weights[static_cast<std::size_t>(std::min(layers - 1, std::max<std::int64_t>(0, k >> nv::BrickShift)))] += 1.0;
    }
    communicator->SumAll(weights.data(), static_cast<int>(layers));
    owners = nv::SplitLayers(weights, communicator->Size());
    part = nv::Subdomain::Around(owners[communicator->Rank()], layers);
  }
  // The node layers this process computes, and those of its output piece
  // (its owned layers and the first layer of the next piece, which both share).
  const std::int64_t computedBegin = part.Computed.Begin * nv::BrickSize;
  const std::int64_t computedEnd = std::min(part.Computed.End * nv::BrickSize, grid.Dims[2]);
  const std::int64_t pieceBegin = part.Owned.Begin * nv::BrickSize;
  const std::int64_t pieceEnd = std::min(part.Owned.End * nv::BrickSize + 1, grid.Dims[2]);
  const bool emptyPiece = part.Owned.Empty();

  // Memory, checked in two stages. Here, before any allocation that grows with
  // the grid: the dense output (phi, the optional arrays, the isosurfacer's
  // working memory), the per-brick tables (24 bytes a brick of 512 nodes), the
  // points, and in Whole Domain mode the band arrays on every computed node.
  // The narrow band's own size is known only once its distances are
  // computed: BuildNarrowBand refuses it then, before allocating its arrays,
  // if it would not fit in what is left.
  const double layerNodes = static_cast<double>(grid.Dims[0] * grid.Dims[1]);
  const double computedNodes = layerNodes * static_cast<double>(computedEnd - computedBegin);
  const double pieceNodes = layerNodes * static_cast<double>(pieceEnd - pieceBegin);
  const double pointsCount = static_cast<double>(points.size() / 3);
  const bool whole = parameters.Mode == nv::Domain::WholeDomain;
  constexpr double BytesPerBandNode = 72.0 + 16.0; // arrays and solver vectors, plus the transient lists
  const double perNode = this->OutputVolume ? 4.0 + (this->OutputInitialPhi ? 4.0 : 0.0) +
      (this->OutputDistance ? 4.0 : 0.0) + (this->OutputNarrowBand ? 1.0 : 0.0) + 2.0
                                           : 0.0;
  const double bytesEstimate = pieceNodes * perNode + gridNodes * 24.0 / 512.0 +
    (whole ? computedNodes * BytesPerBandNode : 0.0) + pointsCount * 48.0;
  double limitMiB = this->MemoryLimit;
  if (limitMiB <= 0.0)
  {
    vtksys::SystemInformation info;
    info.RunMemoryCheck();
    limitMiB = 0.5 * static_cast<double>(info.GetTotalPhysicalMemory());
  }
  const double limitBytes = limitMiB * 1048576.0;
  if (anywhere(bytesEstimate > limitBytes || (whole && computedNodes > static_cast<double>(nv::MaximumBandSize))))
  {
    vtkErrorMacro("The grid is too large: about " << gridNodes << " nodes (spacing " << parameters.Spacing
                                                  << ") need about " << bytesEstimate / 1048576.0
                                                  << " MiB" << (communicator ? " on some process" : "")
                                                  << ", over the limit of " << limitMiB
                                                  << " MiB. Increase SampleSpacing, lower "
                                                  << "MaximumDimension, raise MemoryLimit"
                                                  << (this->OutputVolume ? " or turn OutputVolume off." : "."));
    return 1;
  }
  if (!whole)
  {
    parameters.MaximumBandNodes = static_cast<std::int64_t>((limitBytes - bytesEstimate) / BytesPerBandNode);
  }

  // A distributed run moves the points within reach of each slab (with one
  // spare cell) to its process.
  if (communicator)
  {
    std::vector<std::array<double, 2>> zRanges(owners.size());
    for (std::size_t q = 0; q < owners.size(); ++q)
    {
      const nv::Subdomain other = nv::Subdomain::Around(owners[q], layers);
      const double margin = parameters.Reach() + grid.Spacing;
      zRanges[q] = { grid.Origin[2] + other.Computed.Begin * nv::BrickSize * grid.Spacing - margin,
        grid.Origin[2] + (std::min(other.Computed.End * nv::BrickSize, grid.Dims[2]) - 1) * grid.Spacing + margin };
      if (other.Computed.Empty())
      {
        zRanges[q] = { 1.0, 0.0 }; // nothing
      }
    }
    points = nv::ExchangePoints(this->Controller, points, zRanges);
  }

  // --- Run, with all cores when the process-wide backend is Sequential.
  std::string backend = vtkSMPTools::GetBackend() ? vtkSMPTools::GetBackend() : "Sequential";
  if (backend == "Sequential")
  {
    backend = "STDThread";
  }
  bool aborted = false;
  bool disagree = false;
  double refusedBand = 0;
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ this->NumberOfThreads, backend, false }, [&]() {
    FilterMonitor monitor(this);
    auto start = std::chrono::steady_clock::now();

    // Distance (eq. 6, 7) and band (steps 1-3).
    monitor.SetStage(0.0, 0.2);
    nv::TruncatedDistance distance(grid, points.data(), static_cast<std::int64_t>(points.size() / 3),
      parameters.Reach());
    std::vector<double>().swap(points);
    const nv::NarrowBand band = nv::BuildNarrowBand(distance, parameters, &monitor, &part);
    this->SetupTime = Seconds(start);
    double failed[2] = { static_cast<double>(band.RefusedSize), monitor.Aborted() ? 1.0 : 0.0 };
    if (communicator)
    {
      communicator->MaxAll(failed, 2);
    }
    refusedBand = failed[0];
    aborted = failed[1] > 0.0;
    if (refusedBand > 0 || aborted)
    {
      return;
    }
    std::int64_t redBegin, redEnd, blackBegin, blackEnd;
    band.OwnedNodes(true, redBegin, redEnd);
    band.OwnedNodes(false, blackBegin, blackEnd);
    double bandNodes = static_cast<double>(redEnd - redBegin + blackEnd - blackBegin);
    if (communicator)
    {
      communicator->SumAll(&bandNodes, 1);
    }
    this->NumberOfBandNodes = static_cast<vtkIdType>(bandNodes);

    // Evolution: (10)-(12) per time step.
    start = std::chrono::steady_clock::now();
    monitor.SetStage(0.2, 0.7);
    std::unique_ptr<nv::Halo> halo;
    if (communicator)
    {
      halo.reset(new nv::Halo(band, part, owners, *communicator));
      if (!halo->Agree())
      {
        disagree = true;
        return;
      }
    }
    nv::AllenCahnSolver solver(band, parameters, halo.get());
    for (const nv::StepReport& step : solver.Run(&monitor))
    {
      this->RelativeChanges.push_back(step.RelativeChange);
    }
    this->EvolutionTime = Seconds(start);
    aborted = anywhere(monitor.Aborted());
    if (aborted || emptyPiece)
    {
      return;
    }

    // Output 0: the volume, this process's piece of it (its geometry always,
    // its arrays on request), with ghost layers if the pipeline asks.
    start = std::chrono::steady_clock::now();
    const std::int64_t ghosts = communicator && this->OutputVolume
      ? volumeInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS())
      : 0;
    const std::int64_t volumeBegin = std::max(computedBegin, pieceBegin - ghosts);
    const std::int64_t volumeEnd = std::min(computedEnd, pieceEnd + ghosts);
    volume->SetOrigin(grid.Origin[0], grid.Origin[1], grid.Origin[2]);
    volume->SetSpacing(grid.Spacing, grid.Spacing, grid.Spacing);
    volume->SetExtent(0, static_cast<int>(grid.Dims[0] - 1), 0, static_cast<int>(grid.Dims[1] - 1),
      static_cast<int>(volumeBegin), static_cast<int>(volumeEnd - 1));
    monitor.SetStage(0.9, 0.1);
    if (!this->OutputVolume && (this->Sheets == BOTH_SHEETS || communicator))
    {
      // Output 1 without a dense volume: slab by slab.
      surface->ShallowCopy(nv::ExtractSurfaceBySlabs(
        distance, band, solver.GetPhi(), parameters, &monitor, pieceBegin, pieceEnd));
      this->OutputTime = Seconds(start);
      aborted = monitor.Aborted(); // the slabs stop early: a partial surface is no result
      return;
    }
    const vtkIdType nodes = static_cast<vtkIdType>(layerNodes) * (volumeEnd - volumeBegin);
    nv::VolumeArrays arrays;
    vtkNew<vtkFloatArray> phi;
    phi->SetName("phi");
    phi->SetNumberOfTuples(nodes);
    arrays.Phi = phi->GetPointer(0);
    if (this->OutputVolume)
    {
      volume->GetPointData()->SetScalars(phi);
    }
    else
    {
      vtkWarningMacro("Keeping one sheet needs the dense grid: memory follows the box although "
                      "OutputVolume is off.");
    }
    // The optional arrays: named, sized and attached to the volume.
    auto addArray = [&](auto* array, const char* name) {
      array->SetName(name);
      array->SetNumberOfTuples(nodes);
      volume->GetPointData()->AddArray(array);
      array->Delete(); // the point data holds it now
      return array->GetPointer(0);
    };
    if (this->OutputVolume && this->OutputInitialPhi)
    {
      arrays.InitialPhi = addArray(vtkFloatArray::New(), "InitialPhi");
    }
    if (this->OutputVolume && this->OutputDistance)
    {
      arrays.Distance = addArray(vtkFloatArray::New(), "Distance");
    }
    if (this->OutputVolume && this->OutputNarrowBand)
    {
      arrays.Band = addArray(vtkUnsignedCharArray::New(), "NarrowBand");
    }
    nv::FillVolume(
      distance, band, solver.GetPhi(), parameters, distance.ReachedBricks(), arrays, volumeBegin, volumeEnd);
    if (volumeBegin < pieceBegin || volumeEnd > pieceEnd)
    {
      MarkGhostLayers(volume, pieceBegin, pieceEnd);
    }
    this->UpdateProgress(0.92);

    // Output 1: the phi = 0 surfaces of the piece (without its ghost layers),
    // all or some of them.
    vtkNew<vtkFloatArray> contoured;
    contoured->SetArray(arrays.Phi + static_cast<vtkIdType>(layerNodes) * (pieceBegin - volumeBegin),
      static_cast<vtkIdType>(layerNodes) * (pieceEnd - pieceBegin), 1); // borrowed
    if (this->Sheets != BOTH_SHEETS)
    {
      if (communicator)
      {
        vtkWarningMacro("Keeping one sheet needs the whole grid on one process: both sheets are "
                        "output in a distributed run.");
      }
      else
      {
        contoured->DeepCopy(phi);
        nv::KeepSheets(grid, contoured->GetPointer(0),
          this->Sheets == OUTER_SHEET ? nv::Sheets::Outer : nv::Sheets::Inner);
      }
    }
    surface->ShallowCopy(nv::ExtractSurface(grid, contoured, pieceBegin, pieceEnd));
    this->OutputTime = Seconds(start);
  });
  if (refusedBand > 0)
  {
    vtkErrorMacro("The narrow band is too large: " << refusedBand << " nodes"
                    << (communicator ? " on one process" : "") << " need about "
                    << refusedBand * BytesPerBandNode / 1048576.0 << " MiB, more than the "
                    << (limitBytes - bytesEstimate) / 1048576.0 << " MiB left under the limit of " << limitMiB
                    << " MiB. Increase SampleSpacing, lower MaximumDimension, raise MemoryLimit"
                    << (this->OutputVolume ? " or turn OutputVolume off." : "."));
    volume->Initialize();
    surface->Initialize();
    return 1;
  }
  if (disagree)
  {
    vtkErrorMacro("Internal error: neighbouring processes disagree on their shared band layers.");
    volume->Initialize();
    surface->Initialize();
    return 1;
  }
  aborted = anywhere(aborted); // every process, whatever stage it stopped in
  if (aborted)
  {
    volume->Initialize();
    surface->Initialize();
    return 1;
  }

  const int wholeExtent[6] = { 0, static_cast<int>(grid.Dims[0] - 1), 0, static_cast<int>(grid.Dims[1] - 1), 0,
    static_cast<int>(grid.Dims[2] - 1) };
  // The grid follows the points, so the whole extent is known only now, not
  // in the information pass. (ParaView's .pvti writer reads it from there and
  // so writes the first piece's extent as the whole one; see the README.)
  volumeInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), wholeExtent, 6);
  double surfacePoints = static_cast<double>(surface->GetNumberOfPoints());
  if (communicator)
  {
    communicator->SumAll(&surfacePoints, 1);
  }
  if (surfacePoints == 0 && (!communicator || communicator->Rank() == 0))
  {
    vtkWarningMacro("The surface is empty: the shell did not survive the evolution. The offset "
                    "distance ("
      << this->OffsetDistance << ") is probably small against the gaps between points or the "
      << "grid spacing (" << parameters.Spacing << "): increase OffsetDistance or XiCells, or refine the grid.");
  }

  // Run summary in the volume's field data, for scripts and the GUI's Information panel.
  vtkNew<vtkIntArray> iterations;
  iterations->SetName("NumberOfIterations");
  iterations->InsertNextValue(this->GetNumberOfIterations());
  vtkNew<vtkIdTypeArray> bandNodes;
  bandNodes->SetName("NarrowBandNodes");
  bandNodes->InsertNextValue(this->NumberOfBandNodes);
  vtkNew<vtkDoubleArray> changes;
  changes->SetName("RelativeChange");
  for (double c : this->RelativeChanges)
  {
    changes->InsertNextValue(c);
  }
  volume->GetFieldData()->AddArray(iterations);
  volume->GetFieldData()->AddArray(bandNodes);
  volume->GetFieldData()->AddArray(changes);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkNarrowVolumeReconstruction::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "OffsetDistance: " << this->OffsetDistance << "\n";
  os << indent << "SampleSpacing: " << this->SampleSpacing << "\n";
  os << indent << "MaximumDimension: " << this->MaximumDimension << "\n";
  os << indent << "XiCells: " << this->XiCells << "\n";
  os << indent << "EpsilonCells: " << this->EpsilonCells << "\n";
  os << indent << "TimeStep: " << this->TimeStep << "\n";
  os << indent << "MaximumNumberOfIterations: " << this->MaximumNumberOfIterations << "\n";
  os << indent << "ConvergenceTolerance: " << this->ConvergenceTolerance << "\n";
  os << indent << "GaussSeidelTolerance: " << this->GaussSeidelTolerance << "\n";
  os << indent << "Domain: " << (this->Domain == WHOLE_DOMAIN ? "Whole Domain" : "Narrow Band") << "\n";
  os << indent << "EdgeStoppingFunction: eq. (" << this->EdgeStoppingFunction << ")\n";
  os << indent << "Sheets: " << this->Sheets << "\n";
  os << indent << "OutputVolume: " << this->OutputVolume << "\n";
  os << indent << "OutputInitialPhi: " << this->OutputInitialPhi << "\n";
  os << indent << "OutputDistance: " << this->OutputDistance << "\n";
  os << indent << "OutputNarrowBand: " << this->OutputNarrowBand << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "MemoryLimit: " << this->MemoryLimit << " MiB\n";
  os << indent << "Controller: " << this->Controller << "\n";
}
