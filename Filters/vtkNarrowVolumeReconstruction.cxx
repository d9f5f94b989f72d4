// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNarrowVolumeReconstruction.h"

#include "nvReconstruct.h"
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
#include "vtkTable.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <memory>
#include <sstream>
#include <utility>

vtkStandardNewMacro(vtkNarrowVolumeReconstruction);

//------------------------------------------------------------------------------
// The properties' Set/Get (declared one per line in the header) over the
// fields of the core's settings, for every row of the property table
// (NV_SETTINGS); a setter clamps as the table says (NV_SETTINGS_RANGES).
namespace
{
/// A property's name as a type (Range<PropertyName>).
#define NV_TAG(Type, Name, Default) struct Name##Property;
NV_SETTINGS(NV_TAG)
#undef NV_TAG

/// The range a property's setter clamps to: none, unless the table gives one.
template <class Property>
struct Range
{
  static constexpr bool Clamped = false;
  static constexpr double Low = 0.0, High = 0.0;
};
#define NV_RANGE(Name, LowValue, HighValue)                                                        \
  template <>                                                                                      \
  struct Range<Name##Property>                                                                     \
  {                                                                                                \
    static constexpr bool Clamped = true;                                                          \
    static constexpr double Low = LowValue, High = HighValue;                                      \
  };
NV_SETTINGS_RANGES(NV_RANGE)
#undef NV_RANGE

/// value clamped to Property's range, as vtkSetClampMacro clamps.
template <class Property, class T>
T Clamp(T value)
{
  if constexpr (Range<Property>::Clamped)
  {
    if (value < Range<Property>::Low)
    {
      return static_cast<T>(Range<Property>::Low);
    }
    if (value > Range<Property>::High)
    {
      return static_cast<T>(Range<Property>::High);
    }
  }
  return value;
}

/// Stores value in field; whether it changed (the filter is then Modified).
template <class Field, class T>
bool Store(Field& field, T value)
{
  const Field stored = static_cast<Field>(value);
  if (field != stored)
  {
    field = stored;
    return true;
  }
  return false;
}
} // namespace

#define NV_ACCESSORS(Type, Name, Default)                                                          \
  void vtkNarrowVolumeReconstruction::Set##Name(                                                   \
    decltype(std::declval<const vtkNarrowVolumeReconstruction&>().Get##Name()) value)              \
  {                                                                                                \
    if (Store(this->Settings->Name, Clamp<Name##Property>(value)))                                 \
    {                                                                                              \
      this->Modified();                                                                            \
    }                                                                                              \
  }                                                                                                \
  decltype(std::declval<const vtkNarrowVolumeReconstruction&>().Get##Name())                       \
    vtkNarrowVolumeReconstruction::Get##Name() const                                               \
  {                                                                                                \
    return static_cast<decltype(std::declval<const vtkNarrowVolumeReconstruction&>().Get##Name())>( \
      this->Settings->Name);                                                                       \
  }
NV_SETTINGS(NV_ACCESSORS)
#undef NV_ACCESSORS

//------------------------------------------------------------------------------
void vtkNarrowVolumeReconstruction::SetNumberOfDrainHolePositions(int number)
{
  const std::size_t values = 3 * static_cast<std::size_t>(std::max(0, number));
  if (values != this->Settings->DrainHolePositions.size())
  {
    this->Settings->DrainHolePositions.resize(values, 0.0);
    this->Modified();
  }
}

int vtkNarrowVolumeReconstruction::GetNumberOfDrainHolePositions() const
{
  return static_cast<int>(this->Settings->DrainHolePositions.size() / 3);
}

void vtkNarrowVolumeReconstruction::SetDrainHolePosition(int i, double x, double y, double z)
{
  if (i < 0)
  {
    return;
  }
  if (i >= this->GetNumberOfDrainHolePositions())
  {
    this->SetNumberOfDrainHolePositions(i + 1);
  }
  double* at = &this->Settings->DrainHolePositions[3 * static_cast<std::size_t>(i)];
  if (at[0] != x || at[1] != y || at[2] != z)
  {
    at[0] = x;
    at[1] = y;
    at[2] = z;
    this->Modified();
  }
}

void vtkNarrowVolumeReconstruction::AddDrainHolePosition(double x, double y, double z)
{
  this->SetDrainHolePosition(this->GetNumberOfDrainHolePositions(), x, y, z);
}

double* vtkNarrowVolumeReconstruction::GetDrainHolePosition(int i)
{
  return i >= 0 && i < this->GetNumberOfDrainHolePositions()
    ? &this->Settings->DrainHolePositions[3 * static_cast<std::size_t>(i)]
    : nullptr;
}

void vtkNarrowVolumeReconstruction::RemoveAllDrainHolePositions()
{
  this->SetNumberOfDrainHolePositions(0);
}

//------------------------------------------------------------------------------
// The results' Get methods (declared by NV_RESULTS in the header) over the
// fields of the last run's nv::Results: a number as it is, a text as a C
// string, three values as a pointer to them.
namespace
{
double ResultValue(double value)
{
  return value;
}
int ResultValue(int value)
{
  return value;
}
const char* ResultValue(const std::string& text)
{
  return text.c_str();
}
template <class T>
T* ResultValue(std::array<T, 3>& values)
{
  return values.data();
}
} // namespace

#define NV_RESULT_GETTER(Type, Name, Size)                                                         \
  decltype(std::declval<vtkNarrowVolumeReconstruction&>().Get##Name()) vtkNarrowVolumeReconstruction::Get##Name() \
    NV_RESULT_CONST_##Size                                                                         \
  {                                                                                                \
    return ResultValue(this->Chosen->Name);                                                        \
  }
#define NV_RESULT_CONST_1 const
#define NV_RESULT_CONST_3
NV_RESULTS(NV_RESULT_GETTER)
#undef NV_RESULT_GETTER
#undef NV_RESULT_CONST_1
#undef NV_RESULT_CONST_3

namespace
{

/// The core's progress to the filter, and the filter's abort flag to the
/// core, on the thread that runs the filter (see nv::CallerMonitor); not
/// abortable where all processes must go on together.
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

/// Ends the share of the progress that the information pass's measurement
/// took (vtkAlgorithm::SetProgressShiftScale) when the data pass ends.
class ProgressReset
{
public:
  explicit ProgressReset(vtkAlgorithm* filter)
    : Filter(filter)
  {
  }
  ~ProgressReset() { this->Filter->SetProgressShiftScale(0.0, 1.0); }

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

/// An array of `nodes` values named `name`.
template <class ArrayType>
vtkSmartPointer<ArrayType> NewArray(const char* name, vtkIdType nodes)
{
  auto array = vtkSmartPointer<ArrayType>::New();
  array->SetName(name);
  array->SetNumberOfTuples(nodes);
  return array;
}

/// Brings the output of `connection` (null: no input) up to date for piece
/// `piece` of `pieces`, without ghost levels.
void UpdateInputPiece(vtkAlgorithmOutput* connection, int piece, int pieces)
{
  if (!connection)
  {
    return;
  }
  vtkNew<vtkInformationVector> requests;
  requests->SetNumberOfInformationObjects(connection->GetProducer()->GetNumberOfOutputPorts());
  vtkInformation* request = requests->GetInformationObject(connection->GetIndex());
  request->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), piece);
  request->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), pieces);
  request->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
  connection->GetProducer()->Update(connection->GetIndex(), requests);
}

/// The volume's grid as the pipeline information of output 0 (whole extent,
/// origin, spacing, float scalars); an empty extent for an invalid plan
/// (RequestData then says why).
void DeclareGrid(vtkInformation* info, const nv::Plan& plan)
{
  if (!plan.Valid())
  {
    const int empty[6] = { 0, -1, 0, -1, 0, -1 };
    info->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), empty, 6);
    return;
  }
  const nv::Grid& grid = plan.TheGrid;
  const int wholeExtent[6] = { 0, static_cast<int>(grid.Dims[0] - 1), 0, static_cast<int>(grid.Dims[1] - 1), 0,
    static_cast<int>(grid.Dims[2] - 1) };
  info->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), wholeExtent, 6);
  info->Set(vtkDataObject::ORIGIN(), grid.Origin.data(), 3);
  const double spacing[3] = { grid.Spacing, grid.Spacing, grid.Spacing };
  info->Set(vtkDataObject::SPACING(), spacing, 3);
  vtkDataObject::SetPointDataActiveScalarInfo(info, VTK_FLOAT, 1);
}

} // namespace

/// The dense arrays of the volume piece (null: not asked for), which the
/// run fills (nv::VolumeRequest).
struct vtkNarrowVolumeReconstruction::DenseArrays
{
  vtkSmartPointer<vtkFloatArray> Phi;
  vtkSmartPointer<vtkFloatArray> InitialPhi;
  vtkSmartPointer<vtkFloatArray> Distance;
  vtkSmartPointer<vtkUnsignedCharArray> Band;

  /// The run's request: these arrays on the node layers it asks for.
  nv::VolumeRequest Request(const nv::Reconstruction& run, vtkIdType ghostLayers)
  {
    nv::VolumeRequest request;
    request.GhostLayers = ghostLayers;
    request.Allocate = [this, &run](std::int64_t kBegin, std::int64_t kEnd) {
      const nv::Grid& grid = run.GetGrid();
      return this->Allocate(grid.Dims[0] * grid.Dims[1] * (kEnd - kBegin), nv::DenseArraysAsked(run.GetSettings()));
    };
    return request;
  }

  /// phi and the arrays the settings ask for, on `nodes` nodes.
  nv::VolumeArrays Allocate(vtkIdType nodes, const nv::VolumeContents& contents)
  {
    this->Phi = NewArray<vtkFloatArray>("phi", nodes);
    this->InitialPhi = contents.InitialPhi ? NewArray<vtkFloatArray>("InitialPhi", nodes) : nullptr;
    this->Distance = contents.Distance ? NewArray<vtkFloatArray>("Distance", nodes) : nullptr;
    this->Band = contents.Band ? NewArray<vtkUnsignedCharArray>("NarrowBand", nodes) : nullptr;
    nv::VolumeArrays arrays;
    arrays.Phi = this->Phi->GetPointer(0);
    arrays.InitialPhi = this->InitialPhi ? this->InitialPhi->GetPointer(0) : nullptr;
    arrays.Distance = this->Distance ? this->Distance->GetPointer(0) : nullptr;
    arrays.Band = this->Band ? this->Band->GetPointer(0) : nullptr;
    return arrays;
  }
};

//------------------------------------------------------------------------------
vtkNarrowVolumeReconstruction::vtkNarrowVolumeReconstruction()
  : Settings(new nv::Settings()) // the property table's defaults
  , Chosen(new nv::Results())
  , Samplings(new nv::SamplingCache())
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
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkTable"); // refused with a message (RequestData)
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

//------------------------------------------------------------------------------
int vtkNarrowVolumeReconstruction::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // The grid follows the points, so port 0 can declare its geometry only
  // from the cloud's bounds: the input is brought up to date here (the piece
  // this process will ask for, see RequestUpdateExtent), and under several
  // processes their bounds are combined. The data pass then finds the input
  // up to date and derives the same grid.
  const bool several = this->HasSeveralProcesses();
  UpdateInputPiece(this->GetInputConnection(0, 0), several ? this->Controller->GetLocalProcessId() : 0,
    several ? this->Controller->GetNumberOfProcesses() : 1);
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0], 0);
  double bounds[6] = { 1.0, 0.0, 1.0, 0.0, 1.0, 0.0 };
  if (input && input->GetNumberOfPoints() > 0)
  {
    input->GetBounds(bounds);
  }
  std::unique_ptr<vtkNarrowVolumeCommunicator> communicator(
    several ? new vtkNarrowVolumeCommunicator(this->Controller) : nullptr);
  if (communicator)
  {
    nv::GlobalBounds(*communicator, bounds);
  }
  // The measurement shows its progress (on a large cloud it takes seconds,
  // before the data pass begins) as the run's first stage; the data pass's
  // progress, which the pipeline starts again from 0, then fills the rest.
  // It stops when asked (a GUI's abort, Ctrl-C in Python): the abort flag
  // is cleared first, as the data pass does, since it may still hold the
  // last run's; the data pass then leaves the outputs empty. Under several
  // processes every one measures to the end, as one alone cannot stop.
  bool measured = false;
  this->SetProgressShiftScale(0.0, 1.0);
  this->AbortExecute = 0; // not SetAbortExecute, which would mark the filter modified
  FilterMonitor progress(this, !several);
  const std::shared_ptr<const nv::Sampling> sampling =
    this->MeasureSampling(input, communicator.get(), progress, &measured);
  this->StoppedBeforeData = !sampling;
  if (!sampling)
  {
    return 1;
  }
  if (measured)
  {
    this->SetProgressShiftScale(nv::SamplingStage, 1.0 - nv::SamplingStage);
  }
  DeclareGrid(outputVector->GetInformationObject(0), nv::MakePlan(this->GetSettings(), bounds, sampling->Statistics()));
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
  ProgressReset progressReset(this); // the information pass's measurement's share ends here
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0], 0);
  vtkImageData* volume = vtkImageData::GetData(outputVector, 0);
  vtkPolyData* surface = vtkPolyData::GetData(outputVector, 1);
  volume->Initialize();
  surface->Initialize();
  this->KeepResults(nullptr, nv::Outcome());
  if (this->StoppedBeforeData)
  {
    this->StoppedBeforeData = false; // stopped in the information pass: no run, empty outputs
    return 1;
  }
  if (vtkTable::GetData(inputVector[0], 0))
  {
    vtkErrorMacro(<< this->InWordsOfReader(nv::TableInputError()));
    return 1;
  }
  // Distributed (see SetController), or one process computes everything:
  // then the requests for pieces other than 0 leave their outputs empty, so
  // that gathered pieces hold the serial result once.
  const bool distributed = this->IsDistributed(outputVector);
  vtkInformation* volumeInfo = outputVector->GetInformationObject(0);
  if (!distributed &&
    outputVector->GetInformationObject(1)->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()) > 0)
  {
    return 1;
  }
  const vtkIdType ghosts =
    distributed ? volumeInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS()) : 0;
  this->Reconstruct(input, distributed, ghosts, volume, surface);
  return 1;
}

//------------------------------------------------------------------------------
void vtkNarrowVolumeReconstruction::Reconstruct(
  vtkPointSet* input, bool distributed, vtkIdType ghosts, vtkImageData* volume, vtkPolyData* surface)
{
  // The run and its outputs (nvReconstruct.h), into VTK's arrays.
  std::unique_ptr<vtkNarrowVolumeCommunicator> communicator(
    distributed ? new vtkNarrowVolumeCommunicator(this->Controller) : nullptr);
  FilterMonitor monitor(this);
  nv::Reconstruction run(this->GetSettings(), communicator.get(), &monitor);
  const std::shared_ptr<const nv::Sampling> sampling = this->MeasureSampling(input, communicator.get(), monitor);
  DenseArrays dense;
  nv::PolyDataSink sink;
  const nv::Outcome outcome = sampling // null: stopped (AbortExecute)
    ? nv::Reconstruct(run, PointsOf(input), sampling, sink, dense.Request(run, ghosts), distributed)
    : nv::Outcome();
  this->KeepResults(&run, outcome);
  this->ReportMessages(outcome);
  if (outcome.Done)
  {
    this->MakeVolume(volume, run, outcome, dense);
    surface->ShallowCopy(sink.Finish());
    this->AddRunSummary(volume, outcome.Summary);
    this->UpdateProgress(1.0);
  }
}

//------------------------------------------------------------------------------
void vtkNarrowVolumeReconstruction::ReportMessages(const nv::Outcome& outcome)
{
  // The run's error and warnings, in the words of the reader (the panel's
  // labels in ParaView).
  if (!outcome.Error.empty())
  {
    vtkErrorMacro(<< this->InWordsOfReader(outcome.Error));
  }
  for (const std::string& warning : outcome.Warnings)
  {
    vtkWarningMacro(<< this->InWordsOfReader(warning));
  }
}

//------------------------------------------------------------------------------
std::string vtkNarrowVolumeReconstruction::InWordsOfReader(const std::string& message) const
{
  // The core names the properties (OffsetDistance); the panel's reader knows
  // their labels (Offset Distance).
  return this->PanelLabelsInMessages ? nv::InPanelWords(message) : message;
}

//------------------------------------------------------------------------------
void vtkNarrowVolumeReconstruction::KeepResults(const nv::Reconstruction* run, const nv::Outcome& outcome)
{
  // The figures of the last run for the Get...() methods; none when it did
  // not run (MeasureSampling keeps the sampling's own seconds).
  const bool ran = run && outcome.Ran;
  this->NumberOfGridNodes = ran ? static_cast<vtkIdType>(run->GetGrid().NumberOfNodes()) : 0;
  this->NumberOfBandNodes = ran ? static_cast<vtkIdType>(run->NumberOfBandNodes()) : 0;
  this->RelativeChanges = ran ? run->RelativeChanges() : std::vector<double>();
  *this->Chosen = outcome.Chosen; // all zero when it did not run
  this->SetupTime = ran ? run->SetupSeconds() : 0.0;
  this->EvolutionTime = ran ? run->EvolutionSeconds() : 0.0;
  this->OutputTime = ran ? outcome.OutputSeconds : 0.0;
  // The measurement's seconds go to the first run that uses it (it may have
  // been made for this run's information pass).
  this->SamplingTime = run ? this->Samplings->TakeSeconds() : 0.0;
}

//------------------------------------------------------------------------------
void vtkNarrowVolumeReconstruction::MakeVolume(
  vtkImageData* volume, const nv::Reconstruction& run, const nv::Outcome& outcome, const DenseArrays& dense)
{
  // This process's piece of the grid (its geometry always, its arrays on
  // request), with ghost layers if the pipeline asked; nothing without a piece.
  if (outcome.VolumeEnd <= outcome.VolumeBegin)
  {
    return;
  }
  const nv::Grid& grid = run.GetGrid();
  const int nx = static_cast<int>(grid.Dims[0] - 1);
  const int ny = static_cast<int>(grid.Dims[1] - 1);
  volume->SetOrigin(grid.Origin[0], grid.Origin[1], grid.Origin[2]);
  volume->SetSpacing(grid.Spacing, grid.Spacing, grid.Spacing);
  volume->SetExtent(0, nx, 0, ny, static_cast<int>(outcome.VolumeBegin), static_cast<int>(outcome.VolumeEnd - 1));
  if (!this->Settings->OutputVolume)
  {
    return;
  }
  volume->GetPointData()->SetScalars(dense.Phi);
  for (vtkDataArray* array : { static_cast<vtkDataArray*>(dense.InitialPhi),
         static_cast<vtkDataArray*>(dense.Distance), static_cast<vtkDataArray*>(dense.Band) })
  {
    if (array)
    {
      volume->GetPointData()->AddArray(array);
    }
  }
  if (outcome.VolumeBegin < run.PieceBegin() || outcome.VolumeEnd > run.PieceEnd())
  {
    // The piece without its ghost layers; the last node layer is shared
    // with the next piece, which owns the cells above it.
    int piece[6] = { 0, nx, 0, ny, static_cast<int>(run.PieceBegin()), static_cast<int>(run.PieceEnd() - 1) };
    volume->GenerateGhostArray(piece);
  }
}

//------------------------------------------------------------------------------
void vtkNarrowVolumeReconstruction::AddRunSummary(
  vtkImageData* volume, const std::vector<nv::SummaryArray>& summary)
{
  // The run's figures in the volume's field data (nvReconstruct.h), for scripts
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
    array->SetNumberOfComponents(std::max(1, values.Components));
    for (std::size_t c = 0; c < values.ComponentNames.size(); ++c)
    {
      array->SetComponentName(static_cast<vtkIdType>(c), values.ComponentNames[c].c_str());
    }
    array->SetNumberOfTuples(static_cast<vtkIdType>(values.Values.size()) / std::max(1, values.Components));
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
  // The same points (object, modification time, count) are measured once
  // (nv::SamplingCache).
  vtkPoints* points = input ? input->GetPoints() : nullptr;
  nv::SamplingCache::Key key;
  if (points)
  {
    std::ostringstream object;
    object << static_cast<const void*>(points);
    key = { object.str(), points->GetMTime(), points->GetNumberOfPoints() };
  }
  return this->Samplings->Get(
    key, [input]() { return PointsOf(input); }, communicator, monitor, this->Settings->NumberOfThreads, measured);
}

//------------------------------------------------------------------------------
void vtkNarrowVolumeReconstruction::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
#define NV_PRINT(Type, Name, Default) os << indent << #Name ": " << this->Get##Name() << "\n";
  NV_SETTINGS(NV_PRINT)
#undef NV_PRINT
  os << indent << "Controller: " << this->Controller << "\n";
}
