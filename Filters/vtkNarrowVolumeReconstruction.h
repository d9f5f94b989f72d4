// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkNarrowVolumeReconstruction
 * @brief   Reconstructs a narrow volume (a thick shell) around an unorganized point cloud.
 *
 * vtkNarrowVolumeReconstruction implements the phase-field method of Li et
 * al., "Fast and efficient narrow volume reconstruction from scattered data",
 * Pattern Recognition 48 (2015). Given points X_p and an offset distance l,
 * it builds a uniform grid of spacing h around the points, finds the narrow
 * band of nodes whose distance d to the nearest point is within eta/2 of l,
 * starts from phi0 = tanh((l - d) / (sqrt(2) xi)) (eq. 2) and evolves the
 * Allen-Cahn equation with the edge-stopping function g (eq. 1, 4) on the band
 * only: an implicit diffusion step solved by red-black Gauss-Seidel (eq. 10,
 * 11) and a closed-form reaction step (eq. 12) per time step. phi is close to
 * +1 inside the shell and -1 outside; phi = 0 is the pair of offset surfaces
 * at distance l on either side of the points.
 *
 * Input: any vtkPointSet (only its points are used).
 *
 * With only the input set, the offset and the grid follow the cloud's
 * sampling: l from the distances between neighbouring points, so that the
 * shell closes where the sampling allows and keeps detail near the sampling
 * scale, and h = l / 4 (see OffsetDistance and SampleSpacing). Holes in
 * the sampled surface up to 3 l wide (radius) are bridged with points
 * before the distance is computed (CloseGaps, ClosingRadius), so that a
 * closed scan gives a closed shell with a cavity; a warning names the holes
 * left open that pierce the evolved shell.
 * Output port 0 (vtkImageData): point array "phi" (float, in [-1, 1]), and on
 * request "InitialPhi" (eq. 2), "Distance" (eq. 6) and "NarrowBand" (1 on
 * band nodes). Its field data holds "NumberOfIterations", "NarrowBandNodes",
 * "RelativeChange" (one value per time step), the "OffsetDistance" and
 * "SampleSpacing" used, the cloud's "MedianPointSpacing", the gap closing
 * ("ClosingRadius" used, "AddedPoints"), the holes left open ("NumberOfGaps",
 * "LargestGap", the radius of the widest, "LargestGapCenter"; "PiercedGaps",
 * those that pierce the evolved shell) and the small pieces
 * removed ("RemovedPieces", "RemovedVoids").
 * Output port 1 (vtkPolyData): the phi = 0 surfaces, with point normals out
 * of the shell, contoured by marching cubes in the band's bricks from the
 * signed distance that phi implies, sqrt(2) xi atanh(phi) (same zero set,
 * not saturated: smooth surfaces come out smooth); closed and manifold.
 *
 * @warning
 * The work runs in parallel on vtkSMPTools' threads when its backend is TBB
 * or OpenMP. When it is Sequential (the default of Debian's ParaView) or
 * STDThread, the filter's loops run on a pool of std::threads of its own
 * with NumberOfThreads threads (0: all cores), as VTK 9.2's STDThread
 * backend starts new threads for every loop. Results are bit-identical for
 * any number of threads.
 *
 * Under MPI (pvbatch, pvserver) each process brings its piece of the cloud.
 * The grid is cut along z into one slab per process; each process receives
 * the points within reach of its slab, evolves the band there while it
 * exchanges one ghost brick layer with its neighbours per half sweep, and
 * outputs its piece of phi (with ghost layers on request) and its part of the
 * surface. phi is the serial run's. See SetController.
 *
 * @sa
 * vtkUnsignedDistance vtkFlyingEdges3D vtkExtractSurface
 */
#ifndef vtkNarrowVolumeReconstruction_h
#define vtkNarrowVolumeReconstruction_h

#include "NarrowVolumeFiltersModule.h" // for export macro
#include "vtkAlgorithm.h"

#include <cstdint> // for the counts
#include <memory> // for the cached sampling
#include <string> // for the messages
#include <vector> // for the per-step history

namespace nv
{
class Communicator;
class Monitor;
class Reconstruction;
class Sampling;
struct Outcome;
struct Settings;
struct SummaryArray;
}

class vtkImageData;
class vtkInformation;
class vtkMultiProcessController;
class vtkPointSet;
class vtkPolyData;

class NARROWVOLUMEFILTERS_EXPORT vtkNarrowVolumeReconstruction : public vtkAlgorithm
{
public:
  static vtkNarrowVolumeReconstruction* New();
  vtkTypeMacro(vtkNarrowVolumeReconstruction, vtkAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum DomainType
  {
    NARROW_BAND = 0,
    WHOLE_DOMAIN = 1
  };
  /// Where the distance and the evolution run (SetDevice).
  enum DeviceType
  {
    DEVICE_AUTOMATIC = 0,
    DEVICE_CPU = 1,
    DEVICE_GPU = 2
  };
  /// Edge-stopping functions, numbered by their equation in the paper.
  enum EdgeStoppingFunctionType
  {
    EQUATION_3 = 3, ///< g = 1 - phi0^2
    EQUATION_4 = 4  ///< g = (1 - |phi0|) |phi0|
  };

  ///@{
  /**
   * Offset distance l in world units: the half-thickness of the shell, the
   * distance of both phi = 0 sheets from the points. 0 (the default) chooses
   * it from the cloud: l = max(1.5 m, q), where m is the median and q the
   * 99.9th percentile of the distances from each point to its nearest
   * neighbour (at least 4 h when the grid is capped, see SampleSpacing).
   * GetOffsetDistanceUsed() tells the value of the last run.
   */
  vtkSetMacro(OffsetDistance, double);
  vtkGetMacro(OffsetDistance, double);
  ///@}

  ///@{
  /**
   * Bridge the holes of the sampling (default on). A hole is an empty disc
   * on the sampled surface wider than l (radius): the shell's wall is
   * pierced there, and one such tunnel joins its outer and inner sheets.
   * Holes up to ClosingRadius are filled with points before the distance is
   * computed, so that the wall over them stays at least 0.66 l thick on each
   * side; wider openings (a scan's border, the mouth of a cup, an open base)
   * are left open and reported. Concavities are not filled. Off: the points
   * as given (the paper's method).
   */
  vtkSetMacro(CloseGaps, bool);
  vtkGetMacro(CloseGaps, bool);
  vtkBooleanMacro(CloseGaps, bool);
  ///@}

  ///@{
  /**
   * The widest hole bridged, as the radius of its empty disc, in world
   * units; 0 (the default): 3 l. GetClosingRadiusUsed() tells the value of
   * the last run (0 with CloseGaps off).
   */
  vtkSetMacro(ClosingRadius, double);
  vtkGetMacro(ClosingRadius, double);
  ///@}

  ///@{
  /**
   * Grid spacing h in world units. When <= 0 (the default), h comes from
   * MaximumDimension, or, when that is 0 too, h = l / 4 (the paper's ratio)
   * with at most 320 cells along the longest side of the padded box.
   * GetSampleSpacingUsed() tells the value of the last run.
   */
  vtkSetMacro(SampleSpacing, double);
  vtkGetMacro(SampleSpacing, double);
  ///@}

  ///@{
  /**
   * Number of cells along the longest side of the padded box when
   * SampleSpacing <= 0 (at least 16); 0 (the default): h follows l, see
   * SampleSpacing.
   */
  vtkSetClampMacro(MaximumDimension, int, 0, 100000);
  vtkGetMacro(MaximumDimension, int);
  ///@}

  ///@{
  /**
   * xi = eps_m with m = XiCells (eq. 2): the width of the initial profile, and
   * of the band, 2 m cells. Larger values close small holes and thin gaps.
   * Range [1, 64] (below 1 cell the band's Dirichlet rule, eq. 5, no longer
   * holds); other values are refused when the filter runs. Default 2 (the paper's).
   */
  vtkSetMacro(XiCells, double);
  vtkGetMacro(XiCells, double);
  ///@}

  ///@{
  /**
   * eps = eps_m with m = EpsilonCells (eq. 1, 12): the interface width of the
   * Allen-Cahn evolution. Larger values smooth more. Range [0.5, 256]; other
   * values are refused when the filter runs. Default 6 (the paper's).
   */
  vtkSetMacro(EpsilonCells, double);
  vtkGetMacro(EpsilonCells, double);
  ///@}

  ///@{
  /**
   * Time step dt. When <= 0 (the default), dt = eps^2 (the paper's).
   */
  vtkSetMacro(TimeStep, double);
  vtkGetMacro(TimeStep, double);
  ///@}

  ///@{
  /**
   * Largest number of time steps. Default 3: see ConvergenceTolerance.
   */
  vtkSetClampMacro(MaximumNumberOfIterations, int, 0, 100000);
  vtkGetMacro(MaximumNumberOfIterations, int);
  ///@}

  ///@{
  /**
   * Stop when ||phi^{n+1} - phi^n||_2 / ||phi^n||_2 over the updated nodes
   * drops below this value (the paper's rule, section 4, with 1e-5). 0 runs
   * exactly MaximumNumberOfIterations steps. Default 0: the documentation
   * (doc/explanation/choices.md, the stopping rule) says why the default
   * stopping rule is a fixed number of steps.
   */
  vtkSetClampMacro(ConvergenceTolerance, double, 0.0, 1.0);
  vtkGetMacro(ConvergenceTolerance, double);
  ///@}

  ///@{
  /**
   * Tolerance of the Gauss-Seidel iteration of the implicit step (10): sweeps
   * stop when no node changes by this much or more. Default 1e-6 (the paper's).
   */
  vtkSetClampMacro(GaussSeidelTolerance, double, 1e-14, 1.0);
  vtkGetMacro(GaussSeidelTolerance, double);
  ///@}

  ///@{
  /**
   * Where the scheme runs: NARROW_BAND (default), only on band nodes; or
   * WHOLE_DOMAIN, on every node of the grid, for comparison.
   */
  vtkSetClampMacro(Domain, int, NARROW_BAND, WHOLE_DOMAIN);
  vtkGetMacro(Domain, int);
  void SetDomainToNarrowBand() { this->SetDomain(NARROW_BAND); }
  void SetDomainToWholeDomain() { this->SetDomain(WHOLE_DOMAIN); }
  ///@}

  ///@{
  /**
   * Edge-stopping function g: EQUATION_4 (default), (1 - |phi0|) |phi0|; or
   * EQUATION_3, 1 - phi0^2.
   */
  vtkSetClampMacro(EdgeStoppingFunction, int, EQUATION_3, EQUATION_4);
  vtkGetMacro(EdgeStoppingFunction, int);
  void SetEdgeStoppingFunctionToEquation3() { this->SetEdgeStoppingFunction(EQUATION_3); }
  void SetEdgeStoppingFunctionToEquation4() { this->SetEdgeStoppingFunction(EQUATION_4); }
  ///@}

  ///@{
  /**
   * Keep the sheets at the offset distance while they are smoothed: after
   * each step, the local mean translation of the sheets (their drift by
   * mean-curvature motion) is cancelled, so that 10 to 20 steps smooth noise
   * and sampling wrinkles without shrinking curved parts. Off (default):
   * exactly the paper's scheme. Costs about a third of a step more.
   */
  vtkSetMacro(PreserveOffset, bool);
  vtkGetMacro(PreserveOffset, bool);
  vtkBooleanMacro(PreserveOffset, bool);
  ///@}

  enum SheetsType
  {
    BOTH_SHEETS = 0,
    OUTER_SHEET = 1,
    INNER_SHEETS = 2
  };

  ///@{
  /**
   * Which phi = 0 sheets the surface output holds: BOTH_SHEETS (default);
   * OUTER_SHEET, the one facing the outside (for a closed input, its dilation
   * by OffsetDistance); or INNER_SHEETS, those facing cavities enclosed by the
   * shell (its erosion). An open input (a one-sided scan) has only an outer
   * sheet. Choosing one sheet needs the dense grid even when OutputVolume is off.
   */
  vtkSetClampMacro(Sheets, int, BOTH_SHEETS, INNER_SHEETS);
  vtkGetMacro(Sheets, int);
  void SetSheetsToBoth() { this->SetSheets(BOTH_SHEETS); }
  void SetSheetsToOuter() { this->SetSheets(OUTER_SHEET); }
  void SetSheetsToInner() { this->SetSheets(INNER_SHEETS); }
  ///@}

  ///@{
  /**
   * Whether output port 0 carries the phase field on the grid. Off: the
   * volume output keeps only its geometry (origin, spacing, extent) and the
   * surface is extracted slab by slab, so memory follows the band and not
   * the box. The extra arrays below need the volume. Default on.
   */
  vtkSetMacro(OutputVolume, bool);
  vtkGetMacro(OutputVolume, bool);
  vtkBooleanMacro(OutputVolume, bool);
  ///@}

  ///@{
  /**
   * Whether to remove the small pieces of the shell: loose pieces smaller than
   * a ball of radius 2 l (the balls around lone points) and voids inside the
   * wall smaller than a ball of radius l. Field data "RemovedPieces" and
   * "RemovedVoids" count them. Not applied in a distributed run (a piece may
   * span processes). Default on.
   */
  vtkSetMacro(RemoveSmallPieces, bool);
  vtkGetMacro(RemoveSmallPieces, bool);
  vtkBooleanMacro(RemoveSmallPieces, bool);
  ///@}

  ///@{
  /**
   * Extra point arrays on output port 0: "InitialPhi" (phi0 of eq. 2),
   * "Distance" (the truncated distance of eq. 6) and "NarrowBand" (1 on band
   * nodes). All off by default.
   */
  vtkSetMacro(OutputInitialPhi, bool);
  vtkGetMacro(OutputInitialPhi, bool);
  vtkBooleanMacro(OutputInitialPhi, bool);
  vtkSetMacro(OutputDistance, bool);
  vtkGetMacro(OutputDistance, bool);
  vtkBooleanMacro(OutputDistance, bool);
  vtkSetMacro(OutputNarrowBand, bool);
  vtkGetMacro(OutputNarrowBand, bool);
  vtkBooleanMacro(OutputNarrowBand, bool);
  ///@}

  ///@{
  /**
   * Printing: above 0, the Surface output is a hollow part to print, its
   * outer surface on the scan (the cloud's closing) and its inner surface
   * WallThickness inside it (world units); 0 (default): the shell. Cavities
   * below MinimumCavityVolume (0: 1 % of the largest) are merged into the
   * wall. See the parameter reference.
   */
  vtkSetMacro(WallThickness, double);
  vtkGetMacro(WallThickness, double);
  vtkSetMacro(MinimumCavityVolume, double);
  vtkGetMacro(MinimumCavityVolume, double);
  ///@}

  ///@{
  /**
   * Threads for the parallel loops; 0 (default) uses all cores.
   */
  vtkSetClampMacro(NumberOfThreads, int, 0, 1024);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  ///@{
  /**
   * Largest memory, in MiB, that the filter may allocate for one run; a grid
   * that needs more is refused before any large allocation. 0 (default) means
   * half of the machine's physical memory.
   */
  vtkSetClampMacro(MemoryLimit, double, 0.0, 1e12);
  vtkGetMacro(MemoryLimit, double);
  ///@}

  ///@{
  /**
   * Where the evolution (phi0, g and the time steps) runs: DEVICE_AUTOMATIC
   * (default), for now the CPU; DEVICE_CPU, the CPU's threads; DEVICE_GPU,
   * an NVIDIA GPU through CUDA (one process, PreserveOffset off), with the
   * same scheme and stopping rule. DEVICE_GPU on a build without CUDA, or
   * on a machine without a CUDA device, stops the run with an error that
   * says which. The GPU back end has not yet run on a GPU, so Automatic
   * stays on the CPU. Field data "DeviceUsed": 1 (CPU) or 2 (GPU).
   */
  vtkSetClampMacro(Device, int, DEVICE_AUTOMATIC, DEVICE_GPU);
  vtkGetMacro(Device, int);
  void SetDeviceToAutomatic() { this->SetDevice(DEVICE_AUTOMATIC); }
  void SetDeviceToCPU() { this->SetDevice(DEVICE_CPU); }
  void SetDeviceToGPU() { this->SetDevice(DEVICE_GPU); }
  ///@}

  ///@{
  /**
   * The processes that share the work (default: the global controller, the
   * MPI ranks under pvbatch or pvserver). The run is distributed when the
   * controller has several processes and the pipeline asks each for its
   * piece; otherwise one process computes the whole result.
   */
  void SetController(vtkMultiProcessController* controller);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  ///@}

  ///@{
  /**
   * Whether the warnings and errors name the properties by the labels of
   * ParaView's panel ("Offset Distance") instead of their names
   * (OffsetDistance, the default). The ParaView plugins turn it on; it is
   * not a setting of the method.
   */
  vtkSetMacro(PanelLabelsInMessages, bool);
  vtkGetMacro(PanelLabelsInMessages, bool);
  ///@}

  ///@{
  /**
   * Results of the last run: time steps taken, band nodes and all grid nodes
   * (over all processes in a distributed run), the offset l and spacing h
   * used (the automatic ones, or those set), the grid's nodes along x, y, z,
   * the relative change of each step, and wall-clock seconds of the set-up
   * (distance and band), the evolution and the output (volume and surface)
   * on this process. SamplingTime: seconds spent measuring the points'
   * spacing (nearest neighbours, for the automatic offset and
   * MedianPointSpacing) in the last update; 0 when the points had not
   * changed and the last measurement served. GridUsed: the grid's nodes as
   * one text, "221 x 260 x 200" ("" before a run), which ParaView's panel
   * shows as Grid Used.
   */
  int GetNumberOfIterations() const { return static_cast<int>(this->RelativeChanges.size()); }
  vtkGetMacro(NumberOfBandNodes, vtkIdType);
  vtkGetMacro(NumberOfGridNodes, vtkIdType);
  const std::vector<double>& GetRelativeChanges() const { return this->RelativeChanges; }
  vtkGetMacro(OffsetDistanceUsed, double);
  vtkGetMacro(SampleSpacingUsed, double);
  vtkGetMacro(ClosingRadiusUsed, double);
  vtkGetVector3Macro(GridDimensionsUsed, int);
  const char* GetGridUsed();
  vtkGetMacro(SamplingTime, double);
  vtkGetMacro(SetupTime, double);
  vtkGetMacro(EvolutionTime, double);
  vtkGetMacro(OutputTime, double);
  ///@}

  ///@{
  /**
   * The input point set (any vtkPointSet), as in vtkPolyDataAlgorithm.
   */
  void SetInputData(vtkDataObject* input) { this->SetInputDataObject(0, input); }
  ///@}

  ///@{
  /**
   * The two outputs: port 0 the volume (vtkImageData), port 1 the surface (vtkPolyData).
   */
  vtkDataObject* GetOutput(int port) { return this->GetOutputDataObject(port); }
  vtkImageData* GetVolumeOutput();
  vtkPolyData* GetSurfaceOutput();
  ///@}

  vtkTypeBool ProcessRequest(
    vtkInformation* request, vtkInformationVector** inInfo, vtkInformationVector* outInfo) override;

protected:
  vtkNarrowVolumeReconstruction();
  ~vtkNarrowVolumeReconstruction() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  /// Declares the volume's grid (whole extent, origin, spacing, float
  /// scalars), which follows the input's points.
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*);
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*);
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*);
  /// Whether the controller has several processes (a run may be distributed).
  bool HasSeveralProcesses() const;
  /// Whether this request is one piece of a distributed run (see SetController).
  bool IsDistributed(vtkInformationVector* outputVector) const;
  /// The properties, as the core takes them.
  nv::Settings GetSettings() const;
  /// The results of the last run (run null: none yet), for the Get...() methods.
  void KeepResults(const nv::Reconstruction* run, const nv::Outcome& outcome);
  /// A message of the core with the properties named as PanelLabelsInMessages says.
  std::string InWordsOfReader(std::string message) const;
  /// Output 0 of a finished run: the grid's piece and the dense arrays.
  struct DenseArrays;
  void MakeVolume(
    vtkImageData* volume, const nv::Reconstruction& run, const nv::Outcome& outcome, const DenseArrays& dense);
  /// The run's figures (nv::RunSummary) as the volume's field data.
  void AddRunSummary(vtkImageData* volume, const std::vector<nv::SummaryArray>& summary);
  /// The sampling of the input's points, measured once per input (collective
  /// when the processes share the cloud), with its progress to the monitor;
  /// null if the monitor stopped it. measured: whether this call measured.
  std::shared_ptr<const nv::Sampling> MeasureSampling(
    vtkPointSet* input, nv::Communicator* communicator, nv::Monitor& monitor, bool* measured = nullptr);

  // The properties: their defaults come from the core's nv::Settings (the
  // property table, Python/_properties.py), set by the constructor.
  double OffsetDistance;
  bool CloseGaps;
  double ClosingRadius;
  double SampleSpacing;
  int MaximumDimension;
  double XiCells;
  double EpsilonCells;
  double TimeStep;
  int MaximumNumberOfIterations;
  double ConvergenceTolerance;
  double GaussSeidelTolerance;
  int Domain;
  int EdgeStoppingFunction;
  bool PreserveOffset;
  int Sheets;
  bool RemoveSmallPieces;
  bool OutputVolume;
  bool OutputInitialPhi;
  bool OutputDistance;
  bool OutputNarrowBand;
  double WallThickness;
  double MinimumCavityVolume;
  int NumberOfThreads;
  double MemoryLimit;
  int Device;
  vtkMultiProcessController* Controller = nullptr;

  vtkIdType NumberOfBandNodes = 0;
  vtkIdType NumberOfGridNodes = 0;
  std::vector<double> RelativeChanges;
  double OffsetDistanceUsed = 0.0;
  double SampleSpacingUsed = 0.0;
  double ClosingRadiusUsed = 0.0;
  int GridDimensionsUsed[3] = { 0, 0, 0 };
  std::string GridUsed; // GetGridUsed()'s text
  bool PanelLabelsInMessages = false;
  std::shared_ptr<const nv::Sampling> Sampled; ///< of the input at SampledTime
  vtkMTimeType SampledTime = 0;
  vtkIdType SampledPoints = -1;
  bool SampledShared = false;
  double SamplingTime = 0.0;
  double SamplingUnreported = 0.0; ///< seconds of measurements no run has reported yet
  double SetupTime = 0.0;
  double EvolutionTime = 0.0;
  double OutputTime = 0.0;

private:
  vtkNarrowVolumeReconstruction(const vtkNarrowVolumeReconstruction&) = delete;
  void operator=(const vtkNarrowVolumeReconstruction&) = delete;
};

#endif
