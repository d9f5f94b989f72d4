#include "vtkNarrowVolumeReconstruction.h"

#include "nvAllenCahnSolver.h"
#include "nvGrid.h"
#include "nvNarrowBand.h"
#include "nvParallel.h"
#include "nvParameters.h"
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

#include <atomic>
#include <chrono>
#include <cmath>
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

} // namespace

//------------------------------------------------------------------------------
vtkNarrowVolumeReconstruction::vtkNarrowVolumeReconstruction()
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(2);
}

vtkNarrowVolumeReconstruction::~vtkNarrowVolumeReconstruction() = default;

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
int vtkNarrowVolumeReconstruction::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // The shell depends on every point: each process asks for the whole cloud.
  // (Under MPI the first process alone then produces the output; see RequestData.)
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
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

  // In a data-parallel run (pvbatch or pvserver under MPI) every process has
  // the whole cloud (RequestUpdateExtent); the piece 0 process computes the
  // shell and the others leave their pieces empty, so the result is the
  // serial one, without duplicates.
  vtkInformation* surfaceInfo = outputVector->GetInformationObject(1);
  if (surfaceInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()) > 0)
  {
    return 1;
  }

  // --- Validate the input and the parameters before allocating anything large.
  if (!input || !input->GetPoints() || input->GetNumberOfPoints() < 1)
  {
    vtkErrorMacro("The input has no points: nothing to reconstruct.");
    return 1;
  }
  std::vector<double> points;
  double bounds[6];
  const vtkIdType bad = GatherPoints(input->GetPoints(), points, bounds);
  if (bad >= 0)
  {
    vtkErrorMacro("Input point " << bad << " has a non-finite coordinate (NaN or infinity); "
                                 << "remove such points before reconstructing.");
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

  // Memory, checked in two stages. Here, before any allocation that grows with
  // the grid, in floating point so that no integer can overflow: the dense
  // output (phi, the optional arrays, the isosurfacer's working memory), the
  // per-brick tables (24 bytes a brick of 512 nodes), the points, and in Whole
  // Domain mode the band arrays on every node. The narrow band's own size is
  // known only once its distances are computed: BuildNarrowBand refuses it
  // then, before allocating its arrays, if it would not fit in what is left.
  const double padding = nv::GridPadding(parameters.Reach(), parameters.Spacing);
  double nodesEstimate = 1.0;
  for (int a = 0; a < 3; ++a)
  {
    nodesEstimate *= (bounds[2 * a + 1] - bounds[2 * a] + 2.0 * padding) / parameters.Spacing + 2.0;
  }
  const double pointsCount = static_cast<double>(points.size() / 3);
  const bool whole = parameters.Mode == nv::Domain::WholeDomain;
  constexpr double BytesPerBandNode = 72.0 + 16.0; // arrays and solver vectors, plus the transient lists
  const double perNode = this->OutputVolume ? 4.0 + (this->OutputInitialPhi ? 4.0 : 0.0) +
      (this->OutputDistance ? 4.0 : 0.0) + (this->OutputNarrowBand ? 1.0 : 0.0) + 2.0
                                           : 0.0;
  const double bytesEstimate = nodesEstimate * (perNode + 24.0 / 512.0 + (whole ? BytesPerBandNode : 0.0)) +
    pointsCount * 48.0;
  double limitMiB = this->MemoryLimit;
  if (limitMiB <= 0.0)
  {
    vtksys::SystemInformation info;
    info.RunMemoryCheck();
    limitMiB = 0.5 * static_cast<double>(info.GetTotalPhysicalMemory());
  }
  const double limitBytes = limitMiB * 1048576.0;
  if (bytesEstimate > limitBytes || nodesEstimate > static_cast<double>(VTK_ID_MAX) ||
    (whole && nodesEstimate > static_cast<double>(nv::MaximumBandSize)))
  {
    vtkErrorMacro("The grid is too large: about " << nodesEstimate << " nodes (spacing "
                                                  << parameters.Spacing << ") need about "
                                                  << bytesEstimate / 1048576.0 << " MiB, over the limit of "
                                                  << limitMiB << " MiB. Increase SampleSpacing, lower "
                                                  << "MaximumDimension, raise MemoryLimit"
                                                  << (this->OutputVolume ? " or turn OutputVolume off." : "."));
    return 1;
  }
  if (!whole)
  {
    parameters.MaximumBandNodes = static_cast<std::int64_t>((limitBytes - bytesEstimate) / BytesPerBandNode);
  }
  const nv::Grid grid = nv::MakeGrid(bounds, parameters.Spacing, padding);
  this->NumberOfGridNodes = static_cast<vtkIdType>(grid.NumberOfNodes());

  // --- Run, with all cores when the process-wide backend is Sequential.
  std::string backend = vtkSMPTools::GetBackend() ? vtkSMPTools::GetBackend() : "Sequential";
  if (backend == "Sequential")
  {
    backend = "STDThread";
  }
  bool aborted = false;
  std::int64_t refusedBand = 0;
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ this->NumberOfThreads, backend, false }, [&]() {
    FilterMonitor monitor(this);
    auto start = std::chrono::steady_clock::now();

    // Distance (eq. 6, 7) and band (steps 1-3).
    monitor.SetStage(0.0, 0.2);
    nv::TruncatedDistance distance(grid, points.data(), static_cast<std::int64_t>(points.size() / 3),
      parameters.Reach());
    std::vector<double>().swap(points);
    const nv::NarrowBand band = nv::BuildNarrowBand(distance, parameters, &monitor);
    this->SetupTime = Seconds(start);
    if (band.RefusedSize > 0)
    {
      refusedBand = band.RefusedSize;
      return;
    }
    if (monitor.Aborted())
    {
      aborted = true;
      return;
    }
    this->NumberOfBandNodes = static_cast<vtkIdType>(band.Size());

    // Evolution: (10)-(12) per time step.
    start = std::chrono::steady_clock::now();
    monitor.SetStage(0.2, 0.7);
    nv::AllenCahnSolver solver(band, parameters);
    for (const nv::StepReport& step : solver.Run(&monitor))
    {
      this->RelativeChanges.push_back(step.RelativeChange);
    }
    this->EvolutionTime = Seconds(start);
    if (monitor.Aborted())
    {
      aborted = true;
      return;
    }

    // Output 0: the volume (its geometry always, its arrays on request).
    start = std::chrono::steady_clock::now();
    volume->SetOrigin(grid.Origin[0], grid.Origin[1], grid.Origin[2]);
    volume->SetSpacing(grid.Spacing, grid.Spacing, grid.Spacing);
    volume->SetExtent(0, static_cast<int>(grid.Dims[0] - 1), 0, static_cast<int>(grid.Dims[1] - 1), 0,
      static_cast<int>(grid.Dims[2] - 1));
    monitor.SetStage(0.9, 0.1);
    if (!this->OutputVolume && this->Sheets == BOTH_SHEETS)
    {
      // Output 1 without a dense volume: slab by slab.
      surface->ShallowCopy(nv::ExtractSurfaceBySlabs(distance, band, solver.GetPhi(), parameters, &monitor));
      this->OutputTime = Seconds(start);
      aborted = monitor.Aborted();
      return;
    }
    const vtkIdType nodes = static_cast<vtkIdType>(grid.NumberOfNodes());
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
    nv::FillVolume(distance, band, solver.GetPhi(), parameters, distance.ReachedBricks(), arrays);
    this->UpdateProgress(0.92);

    // Output 1: the phi = 0 surfaces, all or some of them.
    vtkNew<vtkFloatArray> chosen;
    if (this->Sheets != BOTH_SHEETS)
    {
      chosen->DeepCopy(phi);
      nv::KeepSheets(grid, chosen->GetPointer(0),
        this->Sheets == OUTER_SHEET ? nv::Sheets::Outer : nv::Sheets::Inner);
    }
    surface->ShallowCopy(nv::ExtractSurface(grid, this->Sheets != BOTH_SHEETS ? chosen.Get() : phi.Get()));
    this->OutputTime = Seconds(start);
  });
  if (refusedBand > 0)
  {
    vtkErrorMacro("The narrow band is too large: " << refusedBand << " nodes need about "
                    << refusedBand * BytesPerBandNode / 1048576.0 << " MiB, more than the "
                    << (limitBytes - bytesEstimate) / 1048576.0 << " MiB left under the limit of " << limitMiB
                    << " MiB. Increase SampleSpacing, lower MaximumDimension, raise MemoryLimit"
                    << (this->OutputVolume ? " or turn OutputVolume off." : "."));
    volume->Initialize();
    surface->Initialize();
    return 1;
  }
  if (aborted)
  {
    volume->Initialize();
    surface->Initialize();
    return 1;
  }

  volumeInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), volume->GetExtent(), 6);
  if (surface->GetNumberOfPoints() == 0)
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
}
