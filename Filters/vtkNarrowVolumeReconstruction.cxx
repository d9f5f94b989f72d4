// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNarrowVolumeReconstruction.h"

#include "nvOutputs.h"
#include "nvParallel.h"
#include "nvReconstruction.h"
#include "nvSampling.h"
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
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include <chrono>
#include <memory>

vtkStandardNewMacro(vtkNarrowVolumeReconstruction);

namespace
{

/// The core's progress to the filter, and the filter's abort flag to the
/// core, on the thread that runs the filter (see nv::CallerMonitor). Not
/// abortable in the information pass: the pipeline clears the abort flag as
/// a data pass begins, so there it may still hold the last run's.
class FilterMonitor : public nv::CallerMonitor
{
public:
  FilterMonitor(vtkAlgorithm* filter, bool abortable = true)
    : Filter(filter)
    , Abortable(abortable)
  {
  }

protected:
  void Report(double progress) override { this->Filter->UpdateProgress(progress); }
  bool Poll() override { return this->Abortable && this->Filter->GetAbortExecute() != 0; }

private:
  vtkAlgorithm* Filter;
  bool Abortable;
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

/// An array of `nodes` values named `name`.
template <class ArrayType>
vtkSmartPointer<ArrayType> NewArray(const char* name, vtkIdType nodes)
{
  auto array = vtkSmartPointer<ArrayType>::New();
  array->SetName(name);
  array->SetNumberOfTuples(nodes);
  return array;
}

} // namespace

/// The dense arrays of the volume piece (null: not asked for).
struct vtkNarrowVolumeReconstruction::DenseArrays
{
  vtkSmartPointer<vtkFloatArray> Phi;
  vtkSmartPointer<vtkFloatArray> InitialPhi;
  vtkSmartPointer<vtkFloatArray> Distance;
  vtkSmartPointer<vtkUnsignedCharArray> Band;
};

//------------------------------------------------------------------------------
vtkNarrowVolumeReconstruction::vtkNarrowVolumeReconstruction()
{
  // The properties' defaults are the core's (the property table's).
  const nv::Settings defaults;
#define NV_DEFAULT(Type, Name, Default) this->Name = static_cast<decltype(this->Name)>(defaults.Name);
  NV_SETTINGS(NV_DEFAULT)
#undef NV_DEFAULT
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
#define NV_COPY(Type, Name, Default) settings.Name = static_cast<Type>(this->Name);
  NV_SETTINGS(NV_COPY)
#undef NV_COPY
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
  }
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0], 0);
  if (input && input->GetNumberOfPoints() > 0)
  {
    input->GetBounds(bounds);
  }
  std::unique_ptr<vtkNarrowVolumeCommunicator> communicator;
  if (several)
  {
    communicator.reset(new vtkNarrowVolumeCommunicator(this->Controller));
    nv::GlobalBounds(*communicator, bounds);
  }
  // The measurement shows its progress (on a large cloud it takes seconds,
  // before the data pass begins) as the run's first stage; the data pass's
  // progress, which the pipeline starts again from 0, then fills the rest.
  std::shared_ptr<const nv::Sampling> sampling;
  bool measured = false;
  this->SetProgressShiftScale(0.0, 1.0);
  nv::WithThreads(this->NumberOfThreads, [&]() {
    FilterMonitor progress(this, false);
    progress.Stage(0.0, nv::SamplingStage);
    sampling = this->MeasureSampling(input, communicator.get(), progress, &measured);
  });
  if (measured)
  {
    this->SetProgressShiftScale(nv::SamplingStage, 1.0 - nv::SamplingStage);
  }
  const nv::Plan plan = nv::MakePlan(this->GetSettings(), bounds, sampling->Statistics());
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
  // The progress of the information pass's measurement (if any) ends here.
  struct ProgressReset
  {
    vtkAlgorithm* Filter;
    ~ProgressReset() { this->Filter->SetProgressShiftScale(0.0, 1.0); }
  } progressReset{ this };
  vtkImageData* volume = vtkImageData::GetData(outputVector, 0);
  vtkPolyData* surface = vtkPolyData::GetData(outputVector, 1);
  volume->Initialize();
  surface->Initialize();
  this->RelativeChanges.clear();
  this->OffsetDistanceUsed = this->SampleSpacingUsed = this->MedianPointSpacing = this->LargestGap = 0.0;
  this->ClosingRadiusUsed = 0.0;
  this->Gaps = this->RemovedPieces = this->RemovedVoids = 0;
  this->NumberOfBandNodes = 0;
  this->NumberOfGridNodes = 0;
  this->SamplingTime = this->SetupTime = this->EvolutionTime = this->OutputTime = 0.0;

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

  bool ok = false;
  std::vector<nv::SummaryArray> summary;
  nv::WithThreads(this->NumberOfThreads, [&]() {
    FilterMonitor monitor(this);
    const nv::Settings settings = this->GetSettings();
    nv::Reconstruction run(settings, communicator.get(), &monitor);
    // The dense arrays, filled by the run: for output 0, or for keeping one
    // sheet (KeepSheets works on the whole grid, so not when distributed).
    DenseArrays dense;
    if (nv::NeedsDenseVolume(settings, distributed))
    {
      const std::int64_t ghosts = distributed && this->OutputVolume
        ? outputVector->GetInformationObject(0)->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS())
        : 0;
      run.RequestVolume(ghosts, [&](std::int64_t kBegin, std::int64_t kEnd) {
        const vtkIdType nodes = static_cast<vtkIdType>(run.GetGrid().Dims[0] * run.GetGrid().Dims[1] * (kEnd - kBegin));
        const bool volume = this->OutputVolume;
        dense.Phi = NewArray<vtkFloatArray>("phi", nodes);
        dense.InitialPhi = volume && this->OutputInitialPhi ? NewArray<vtkFloatArray>("InitialPhi", nodes) : nullptr;
        dense.Distance = volume && this->OutputDistance ? NewArray<vtkFloatArray>("Distance", nodes) : nullptr;
        dense.Band = volume && this->OutputNarrowBand ? NewArray<vtkUnsignedCharArray>("NarrowBand", nodes) : nullptr;
        nv::VolumeArrays arrays;
        arrays.Phi = dense.Phi->GetPointer(0);
        arrays.InitialPhi = dense.InitialPhi ? dense.InitialPhi->GetPointer(0) : nullptr;
        arrays.Distance = dense.Distance ? dense.Distance->GetPointer(0) : nullptr;
        arrays.Band = dense.Band ? dense.Band->GetPointer(0) : nullptr;
        return arrays;
      });
    }
    vtkPointSet* input = vtkPointSet::GetData(inputVector[0], 0);
    monitor.Stage(0.0, nv::SamplingStage);
    const std::shared_ptr<const nv::Sampling> sampling = this->MeasureSampling(input, communicator.get(), monitor);
    // The measurement's seconds go to the first run that uses it (it may
    // have been made for this run's information pass).
    this->SamplingTime = this->SamplingUnreported;
    this->SamplingUnreported = 0.0;
    if (!sampling) // stopped (AbortExecute)
    {
      return;
    }
    if (!run.Run(PointsOf(input), sampling))
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
    this->OffsetDistanceUsed = run.GetParameters().OffsetDistance;
    this->SampleSpacingUsed = run.GetGrid().Spacing;
    this->ClosingRadiusUsed = run.GetPlan().ClosingRadius;
    this->MedianPointSpacing = run.GetSampling().MedianSpacing;
    this->Gaps = run.GetGaps().Gaps;
    this->LargestGap = run.GetGaps().LargestGap;
    std::copy(run.GetGaps().LargestGapCenter.begin(), run.GetGaps().LargestGapCenter.end(), this->LargestGapCenter);
    const auto start = std::chrono::steady_clock::now();
    bool explained = false;
    nv::RemovedPieces removed;
    ok = this->ProduceOutputs(run, monitor, dense, volume, surface, distributed, explained, removed);
    this->RemovedPieces = removed.Pieces;
    this->RemovedVoids = removed.Voids;
    this->OutputTime = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ok = !run.Anywhere(!ok); // every process, whatever stage it stopped in
    const double surfacePoints = run.SumAll(static_cast<double>(surface->GetNumberOfPoints()));
    const bool firstProcess = !communicator || communicator->Rank() == 0;
    if (ok && run.GetGaps().Gaps > 0 && firstProcess)
    {
      vtkWarningMacro(<< nv::GapWarning(run.GetGaps(), this->OffsetDistanceUsed, this->ClosingRadiusUsed));
    }
    if (ok && surfacePoints == 0 && !explained && firstProcess)
    {
      vtkWarningMacro(<< nv::EmptySurfaceWarning(this->OffsetDistanceUsed, run.GetGrid().Spacing));
    }
    summary = nv::RunSummary(run, removed);
  });
  if (!ok)
  {
    volume->Initialize();
    surface->Initialize();
    return 1;
  }
  this->AddRunSummary(volume, summary);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
bool vtkNarrowVolumeReconstruction::ProduceOutputs(nv::Reconstruction& run, nv::Monitor& monitor,
  const DenseArrays& dense, vtkImageData* volume, vtkPolyData* surface, bool distributed, bool& explained,
  nv::RemovedPieces& removed)
{
  const nv::Grid& grid = run.GetGrid();
  if (run.EmptyPiece())
  {
    return true;
  }
  // Output 0: the volume, this process's piece of it (its geometry always,
  // its arrays on request), with ghost layers if the pipeline asked.
  const std::int64_t volumeBegin = dense.Phi ? run.VolumeBegin() : run.PieceBegin();
  const std::int64_t volumeEnd = dense.Phi ? run.VolumeEnd() : run.PieceEnd();
  volume->SetOrigin(grid.Origin[0], grid.Origin[1], grid.Origin[2]);
  volume->SetSpacing(grid.Spacing, grid.Spacing, grid.Spacing);
  volume->SetExtent(0, static_cast<int>(grid.Dims[0] - 1), 0, static_cast<int>(grid.Dims[1] - 1),
    static_cast<int>(volumeBegin), static_cast<int>(volumeEnd - 1));
  if (run.GetSettings().OutputVolume)
  {
    volume->GetPointData()->SetScalars(dense.Phi);
    for (vtkDataArray* array : { static_cast<vtkDataArray*>(dense.InitialPhi), static_cast<vtkDataArray*>(dense.Distance),
           static_cast<vtkDataArray*>(dense.Band) })
    {
      if (array)
      {
        volume->GetPointData()->AddArray(array);
      }
    }
    if (volumeBegin < run.PieceBegin() || volumeEnd > run.PieceEnd())
    {
      // The piece without its ghost layers; the last node layer is shared
      // with the next piece, which owns the cells above it.
      int piece[6] = { 0, static_cast<int>(grid.Dims[0] - 1), 0, static_cast<int>(grid.Dims[1] - 1),
        static_cast<int>(run.PieceBegin()), static_cast<int>(run.PieceEnd() - 1) };
      volume->GenerateGhostArray(piece);
    }
  }

  // Output 1: the phi = 0 surfaces of the piece, from the band; or, to keep
  // some of them, from a copy of the dense phi (phi stays phi).
  monitor.Stage(nv::OutputStage[0], nv::OutputStage[1]);
  const nv::Settings& settings = run.GetSettings();
  nv::PolyDataSink sink;
  bool done = true;
  if (!nv::SurfaceFromDenseCopy(settings, distributed))
  {
    if (settings.Sheets != nv::Sheets::Both)
    {
      vtkWarningMacro(<< nv::OneSheetDistributedWarning());
    }
    done = run.ExtractSurface(sink);
  }
  else
  {
    if (!settings.OutputVolume)
    {
      vtkWarningMacro(<< nv::OneSheetNeedsGridWarning());
    }
    std::vector<float> phi(dense.Phi->GetPointer(0), dense.Phi->GetPointer(0) + dense.Phi->GetNumberOfValues());
    std::int64_t cavities = 0;
    done = nv::ContourDense(run, phi.data(), sink, &monitor, cavities);
    explained = nv::NoInnerSheet(settings, cavities);
    if (explained)
    {
      vtkWarningMacro(<< nv::NoInnerSheetWarning());
    }
  }
  run.ReleaseBand(); // the surface is made: what follows needs neither
  if (done && settings.RemoveSmallPieces && !distributed && !monitor.Aborted())
  {
    // The surface's small parts go, and phi follows in the same regions.
    removed = sink.RemoveSmallPieces(run.GetParameters().OffsetDistance, grid,
      dense.Phi ? dense.Phi->GetPointer(0) : nullptr, volumeBegin, volumeEnd - volumeBegin);
  }
  surface->ShallowCopy(sink.Finish());
  return done && !monitor.Aborted();
}

//------------------------------------------------------------------------------
void vtkNarrowVolumeReconstruction::AddRunSummary(
  vtkImageData* volume, const std::vector<nv::SummaryArray>& summary)
{
  // The run's figures in the volume's field data (nvOutputs.h), for scripts
  // and the GUI's Information panel.
  for (const nv::SummaryArray& values : summary)
  {
    vtkSmartPointer<vtkDataArray> array;
    switch (values.Kind)
    {
      case nv::SummaryArray::Int:
        array = vtkSmartPointer<vtkIntArray>::New();
        break;
      case nv::SummaryArray::Id:
        array = vtkSmartPointer<vtkIdTypeArray>::New();
        break;
      default:
        array = vtkSmartPointer<vtkDoubleArray>::New();
    }
    array->SetName(values.Name.c_str());
    array->SetNumberOfComponents(values.Components);
    array->SetNumberOfTuples(static_cast<vtkIdType>(values.Values.size()) / values.Components);
    for (std::size_t v = 0; v < values.Values.size(); ++v)
    {
      array->SetVariantValue(static_cast<vtkIdType>(v), values.Values[v]);
    }
    volume->GetFieldData()->AddArray(array);
  }
}

//------------------------------------------------------------------------------
std::shared_ptr<const nv::Sampling> vtkNarrowVolumeReconstruction::MeasureSampling(
  vtkPointSet* input, nv::Communicator* communicator, nv::Monitor& monitor, bool* measured)
{
  // The same points (object, modification time, count) are measured once:
  // the information pass and the data pass, and runs that only change
  // properties, share one measurement.
  vtkPoints* points = input ? input->GetPoints() : nullptr;
  const vtkMTimeType time = points ? points->GetMTime() : 0;
  const vtkIdType count = points ? points->GetNumberOfPoints() : 0;
  bool stale = !this->Sampled || time != this->SampledTime || count != this->SampledPoints ||
    (communicator != nullptr) != this->SampledShared;
  if (communicator)
  {
    stale = communicator->MaxAll(stale ? 1.0 : 0.0) > 0.0; // all measure, or none
  }
  if (stale)
  {
    const auto start = std::chrono::steady_clock::now();
    auto sampling = std::make_shared<nv::Sampling>();
    const bool complete = sampling->Measure(PointsOf(input), communicator, &monitor);
    this->SamplingUnreported += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (measured)
    {
      *measured = true;
    }
    if (!complete)
    {
      this->Sampled = nullptr;
      return nullptr;
    }
    this->Sampled = sampling;
    this->SampledTime = time;
    this->SampledPoints = count;
    this->SampledShared = communicator != nullptr;
  }
  return this->Sampled;
}


//------------------------------------------------------------------------------
void vtkNarrowVolumeReconstruction::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
#define NV_PRINT(Type, Name, Default) os << indent << #Name ": " << this->Name << "\n";
  NV_SETTINGS(NV_PRINT)
#undef NV_PRINT
  os << indent << "Controller: " << this->Controller << "\n";
}
