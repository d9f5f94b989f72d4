// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNarrowVolumeReconstruction.h"

#include "nvOutputs.h"
#include "nvParallel.h"
#include "nvReconstruction.h"
#include "vtkNarrowVolumeCommunicator.h"
#include "vtkNarrowVolumeSurface.h"

#include "vtkAlgorithmOutput.h"
#include "vtkDoubleArray.h"
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
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include <chrono>
#include <memory>

vtkStandardNewMacro(vtkNarrowVolumeReconstruction);

namespace
{

/// The core's progress to the filter, and the filter's abort flag to the
/// core, on the thread that runs the filter (see nv::CallerMonitor).
class FilterMonitor : public nv::CallerMonitor
{
public:
  FilterMonitor(vtkAlgorithm* filter)
    : Filter(filter)
  {
  }

protected:
  void Report(double progress) override { this->Filter->UpdateProgress(progress); }
  bool Poll() override { return this->Filter->GetAbortExecute() != 0; }

private:
  vtkAlgorithm* Filter;
};

/// The points of a point set as xyz triples in double precision.
std::vector<double> PointsOf(vtkPointSet* input)
{
  std::vector<double> xyz;
  vtkPoints* points = input ? input->GetPoints() : nullptr;
  if (points)
  {
    xyz.resize(static_cast<std::size_t>(3 * points->GetNumberOfPoints()));
    for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p)
    {
      points->GetPoint(p, &xyz[3 * p]);
    }
  }
  return xyz;
}

/// An array of `nodes` values named `name`, attached to the volume; its values.
template <class ArrayType>
auto* AddArray(vtkImageData* volume, const char* name, vtkIdType nodes)
{
  vtkNew<ArrayType> array;
  array->SetName(name);
  array->SetNumberOfTuples(nodes);
  volume->GetPointData()->AddArray(array);
  return array->GetPointer(0);
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
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_INFORMATION()))
  {
    return this->RequestInformation(request, inputVector, outputVector);
  }
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

bool vtkNarrowVolumeReconstruction::HasSeveralProcesses() const
{
  return this->Controller && this->Controller->GetNumberOfProcesses() > 1;
}

bool vtkNarrowVolumeReconstruction::IsDistributed(vtkInformationVector* outputVector) const
{
  if (!this->HasSeveralProcesses())
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

nv::Settings vtkNarrowVolumeReconstruction::GetSettings() const
{
  nv::Settings settings;
  settings.OffsetDistance = this->OffsetDistance;
  settings.SampleSpacing = this->SampleSpacing;
  settings.MaximumDimension = this->MaximumDimension;
  settings.XiCells = this->XiCells;
  settings.EpsilonCells = this->EpsilonCells;
  settings.TimeStep = this->TimeStep;
  settings.MaximumNumberOfIterations = this->MaximumNumberOfIterations;
  settings.ConvergenceTolerance = this->ConvergenceTolerance;
  settings.GaussSeidelTolerance = this->GaussSeidelTolerance;
  settings.Mode = this->Domain == WHOLE_DOMAIN ? nv::Domain::WholeDomain : nv::Domain::NarrowBand;
  settings.EdgeFunction = this->EdgeStoppingFunction == EQUATION_3 ? nv::EdgeStopping::Eq3 : nv::EdgeStopping::Eq4;
  settings.KeptSheets = static_cast<nv::Sheets>(this->Sheets);
  settings.OutputVolume = this->OutputVolume;
  settings.OutputInitialPhi = this->OutputInitialPhi;
  settings.OutputDistance = this->OutputDistance;
  settings.OutputNarrowBand = this->OutputNarrowBand;
  settings.NumberOfThreads = this->NumberOfThreads;
  settings.MemoryLimit = this->MemoryLimit;
  return settings;
}

//------------------------------------------------------------------------------
int vtkNarrowVolumeReconstruction::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // The grid follows the points, so port 0 can declare its geometry only
  // from the cloud's bounds: the input is brought up to date here (the piece
  // this process will ask for, see RequestUpdateExtent), and under several
  // processes their bounds are combined. The data pass then finds the input
  // up to date and derives the same grid.
  vtkInformation* volumeInfo = outputVector->GetInformationObject(0);
  const bool several = this->HasSeveralProcesses();
  double bounds[6] = { 1.0, 0.0, 1.0, 0.0, 1.0, 0.0 };
  vtkAlgorithmOutput* connection = this->GetInputConnection(0, 0);
  if (connection)
  {
    vtkNew<vtkInformationVector> requests;
    requests->SetNumberOfInformationObjects(connection->GetProducer()->GetNumberOfOutputPorts());
    vtkInformation* request = requests->GetInformationObject(connection->GetIndex());
    request->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(),
      several ? this->Controller->GetLocalProcessId() : 0);
    request->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(),
      several ? this->Controller->GetNumberOfProcesses() : 1);
    request->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
    connection->GetProducer()->Update(connection->GetIndex(), requests);
    vtkPointSet* input = vtkPointSet::GetData(inputVector[0], 0);
    if (input && input->GetNumberOfPoints() > 0)
    {
      input->GetBounds(bounds);
    }
  }
  if (several)
  {
    vtkNarrowVolumeCommunicator communicator(this->Controller);
    nv::GlobalBounds(communicator, bounds);
  }
  const nv::Plan plan = nv::MakePlan(this->GetSettings(), bounds);
  if (!plan.Valid())
  {
    // No grid: RequestData says why.
    const int empty[6] = { 0, -1, 0, -1, 0, -1 };
    volumeInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), empty, 6);
    return 1;
  }
  const nv::Grid& grid = plan.TheGrid;
  const int wholeExtent[6] = { 0, static_cast<int>(grid.Dims[0] - 1), 0, static_cast<int>(grid.Dims[1] - 1), 0,
    static_cast<int>(grid.Dims[2] - 1) };
  volumeInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), wholeExtent, 6);
  volumeInfo->Set(vtkDataObject::ORIGIN(), grid.Origin.data(), 3);
  const double spacing[3] = { grid.Spacing, grid.Spacing, grid.Spacing };
  volumeInfo->Set(vtkDataObject::SPACING(), spacing, 3);
  vtkDataObject::SetPointDataActiveScalarInfo(volumeInfo, VTK_FLOAT, 1);
  return 1;
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
  if (!distributed &&
    outputVector->GetInformationObject(1)->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()) > 0)
  {
    return 1;
  }
  std::unique_ptr<vtkNarrowVolumeCommunicator> communicator;
  if (distributed)
  {
    communicator.reset(new vtkNarrowVolumeCommunicator(this->Controller));
  }

  // Run, with NumberOfThreads threads for the core and for VTK's filters
  // inside (all cores when the process-wide backend is Sequential).
  bool ok = false;
  const nv::Settings settings = this->GetSettings();
  nv::WithThreads(settings.NumberOfThreads, [&]() {
    FilterMonitor monitor(this);
    nv::Reconstruction run(settings, communicator.get(), &monitor);
    if (!run.Run(PointsOf(vtkPointSet::GetData(inputVector[0], 0))))
    {
      if (!run.Error().empty())
      {
        vtkErrorMacro(<< run.Error());
      }
      return;
    }
    this->NumberOfGridNodes = static_cast<vtkIdType>(run.GetGrid().NumberOfNodes());
    this->NumberOfBandNodes = static_cast<vtkIdType>(run.NumberOfBandNodes());
    this->RelativeChanges = run.RelativeChanges();
    this->SetupTime = run.SetupSeconds();
    this->EvolutionTime = run.EvolutionSeconds();
    const auto start = std::chrono::steady_clock::now();
    bool explained = false;
    ok = this->ProduceOutputs(
      run, monitor, outputVector->GetInformationObject(0), volume, surface, distributed, explained);
    this->OutputTime = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ok = !run.Anywhere(!ok); // every process, whatever stage it stopped in
    const double surfacePoints = run.SumAll(static_cast<double>(surface->GetNumberOfPoints()));
    if (ok && surfacePoints == 0 && !explained && (!communicator || communicator->Rank() == 0))
    {
      vtkWarningMacro(<< nv::EmptySurfaceWarning(settings, run.GetGrid().Spacing));
    }
  });
  if (!ok)
  {
    volume->Initialize();
    surface->Initialize();
    return 1;
  }
  this->AddRunSummary(volume);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
bool vtkNarrowVolumeReconstruction::ProduceOutputs(nv::Reconstruction& run, nv::Monitor& monitor,
  vtkInformation* volumeInfo, vtkImageData* volume, vtkPolyData* surface, bool distributed, bool& explained)
{
  const nv::Grid& grid = run.GetGrid();
  const nv::Settings& settings = run.GetSettings();
  if (run.EmptyPiece())
  {
    return true;
  }
  // Output 0: the volume, this process's piece of it (its geometry always,
  // its arrays on request), with ghost layers if the pipeline asks.
  const std::int64_t ghosts = distributed && settings.OutputVolume
    ? volumeInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS())
    : 0;
  const std::int64_t volumeBegin = std::max(run.ComputedBegin(), run.PieceBegin() - ghosts);
  const std::int64_t volumeEnd = std::min(run.ComputedEnd(), run.PieceEnd() + ghosts);
  volume->SetOrigin(grid.Origin[0], grid.Origin[1], grid.Origin[2]);
  volume->SetSpacing(grid.Spacing, grid.Spacing, grid.Spacing);
  volume->SetExtent(0, static_cast<int>(grid.Dims[0] - 1), 0, static_cast<int>(grid.Dims[1] - 1),
    static_cast<int>(volumeBegin), static_cast<int>(volumeEnd - 1));
  if (nv::SurfaceBySlabs(settings, distributed))
  {
    // Output 1 without a dense volume: slab by slab.
    monitor.Stage(nv::SlabStage[0], nv::SlabStage[1]);
    surface->ShallowCopy(nv::ExtractSurfaceBySlabs(run.GetDistance(), run.GetBand(), run.GetPhi(),
      run.GetParameters(), &monitor, run.PieceBegin(), run.PieceEnd()));
    return !monitor.Aborted(); // the slabs stop early: a partial surface is no result
  }
  const vtkIdType layerNodes = static_cast<vtkIdType>(grid.Dims[0] * grid.Dims[1]);
  const vtkIdType nodes = layerNodes * (volumeEnd - volumeBegin);
  vtkNew<vtkFloatArray> phi;
  phi->SetName("phi");
  phi->SetNumberOfTuples(nodes);
  nv::VolumeArrays arrays;
  arrays.Phi = phi->GetPointer(0);
  if (settings.OutputVolume)
  {
    volume->GetPointData()->SetScalars(phi);
    if (settings.OutputInitialPhi)
    {
      arrays.InitialPhi = AddArray<vtkFloatArray>(volume, "InitialPhi", nodes);
    }
    if (settings.OutputDistance)
    {
      arrays.Distance = AddArray<vtkFloatArray>(volume, "Distance", nodes);
    }
    if (settings.OutputNarrowBand)
    {
      arrays.Band = AddArray<vtkUnsignedCharArray>(volume, "NarrowBand", nodes);
    }
  }
  else
  {
    vtkWarningMacro(<< nv::OneSheetNeedsGridWarning());
  }
  monitor.Stage(nv::VolumeStage[0], nv::VolumeStage[1]);
  run.FillVolume(arrays, volumeBegin, volumeEnd);
  if (monitor.Aborted())
  {
    return false;
  }
  if (volumeBegin < run.PieceBegin() || volumeEnd > run.PieceEnd())
  {
    // The piece without its ghost layers; the last node layer is shared with
    // the next piece, which owns the cells above it.
    int piece[6] = { 0, static_cast<int>(grid.Dims[0] - 1), 0, static_cast<int>(grid.Dims[1] - 1),
      static_cast<int>(run.PieceBegin()), static_cast<int>(run.PieceEnd() - 1) };
    volume->GenerateGhostArray(piece);
  }

  // Output 1: the phi = 0 surfaces of the piece (without its ghost layers),
  // all or some of them. Choosing sheets works on a copy: phi stays phi.
  monitor.Stage(nv::SurfaceStage[0], nv::SurfaceStage[1]);
  vtkNew<vtkFloatArray> contoured;
  contoured->SetArray(arrays.Phi + layerNodes * (run.PieceBegin() - volumeBegin),
    layerNodes * (run.PieceEnd() - run.PieceBegin()), 1); // borrowed
  if (settings.KeptSheets != nv::Sheets::Both)
  {
    if (distributed)
    {
      vtkWarningMacro(<< nv::OneSheetDistributedWarning());
    }
    else
    {
      vtkNew<vtkFloatArray> copy;
      copy->DeepCopy(phi);
      contoured->ShallowCopy(copy);
      const std::int64_t cavities = nv::KeepSheets(grid, contoured->GetPointer(0), settings.KeptSheets);
      explained = nv::NoInnerSheet(settings, cavities);
      if (explained)
      {
        vtkWarningMacro(<< nv::NoInnerSheetWarning());
      }
    }
  }
  surface->ShallowCopy(nv::ExtractSurface(grid, contoured, run.PieceBegin(), run.PieceEnd(), &monitor));
  return !monitor.Aborted();
}

//------------------------------------------------------------------------------
void vtkNarrowVolumeReconstruction::AddRunSummary(vtkImageData* volume)
{
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
