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
#include "nvSettingsTable.h"          // for NV_RESULTS, from the property table
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
class SamplingCache;
struct Outcome;
struct Results;
struct Settings;
struct SummaryArray;
}

class vtkImageData;
class vtkInformation;
class vtkMultiProcessController;
class vtkPointSet;
class vtkPolyData;

// Set/Get of a property over its field of the core's settings (the filter's
// nv::Settings), as vtkSetMacro/vtkGetMacro declare them over a member; the
// definitions, made for every property from the property table, are in the
// .cxx. A switch adds <name>On/Off (vtkBooleanMacro); a clamped value, its
// range (vtkSetClampMacro: the setter clamps to the table's range).
#define vtkNarrowVolumeSettingMacro(name, type)                                                     \
  virtual void Set##name(type value);                                                                 \
  virtual type Get##name() const
#define vtkNarrowVolumeSwitchMacro(name)                                                            \
  virtual void name##On() { this->Set##name(true); }                                                 \
  virtual void name##Off() { this->Set##name(false); }                                               \
  vtkNarrowVolumeSettingMacro(name, bool)
#define vtkNarrowVolumeClampMacro(name, type, low, high)                                            \
  virtual type Get##name##MinValue() { return low; }                                                 \
  virtual type Get##name##MaxValue() { return high; }                                                \
  vtkNarrowVolumeSettingMacro(name, type)

// The Get method of a result of the last run (a row of the property
// table's RESULTS, NV_RESULTS(X) calling X(Type, Name, Size)), by its type
// and size: a number, a text, or three values as vtkGetVector3Macro gives
// them. Defined over the filter's nv::Results in the .cxx.
#define vtkNarrowVolumeResultMacro(type, name, size) vtkNarrowVolumeResult_##type##_##size(name)
#define vtkNarrowVolumeResult_double_1(name) virtual double Get##name() const;
#define vtkNarrowVolumeResult_int_1(name) virtual int Get##name() const;
#define vtkNarrowVolumeResult_Text_1(name) virtual const char* Get##name() const;
#define vtkNarrowVolumeResult_double_3(name) vtkNarrowVolumeResultVector3(name, double)
#define vtkNarrowVolumeResult_int_3(name) vtkNarrowVolumeResultVector3(name, int)
#define vtkNarrowVolumeResultVector3(name, type)                                                    \
  virtual type* Get##name() VTK_SIZEHINT(3);                                                         \
  virtual void Get##name(type& x, type& y, type& z)                                                  \
  {                                                                                                  \
    const type* values = this->Get##name();                                                          \
    x = values[0];                                                                                   \
    y = values[1];                                                                                   \
    z = values[2];                                                                                   \
  }                                                                                                  \
  virtual void Get##name(type values[3]) { this->Get##name(values[0], values[1], values[2]); }

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
  /// Which sheets the surface output holds (SetSheets).
  enum SheetsType
  {
    BOTH_SHEETS = 0,
    OUTER_SHEET = 1,
    INNER_SHEETS = 2,
    SCAN_SURFACE = 3
  };
  /// The way down for the drain holes (SetDrainHoleAxis).
  enum DrainHoleAxisType
  {
    DRAIN_MINUS_X = 0,
    DRAIN_PLUS_X = 1,
    DRAIN_MINUS_Y = 2,
    DRAIN_PLUS_Y = 3,
    DRAIN_MINUS_Z = 4,
    DRAIN_PLUS_Z = 5
  };

  ///@{
  /**
   * The properties of the method, one per line, in the panel's order. What
   * each means, its unit, default and range: the parameter reference
   * (doc/reference/parameters.md, made from the property table,
   * Python/_properties.py, as are ParaView's tooltips). Each line declares
   * Set<Name> and Get<Name>, and as VTK's macros do, <Name>On and <Name>Off
   * for a switch (vtkNarrowVolumeSwitchMacro), Get<Name>MinValue and
   * Get<Name>MaxValue for a value the setter clamps
   * (vtkNarrowVolumeClampMacro). The values live in the core's settings
   * (nv::Settings, whose fields and defaults the table makes), which the
   * filter hands to the core as they are; the test PythonApi checks the
   * names, defaults and ranges here against the table. An enumerated
   * property also has a setter per value (SetSheetsToOuter) and the class's
   * constants (OUTER_SHEET) below.
   */
  vtkNarrowVolumeSettingMacro(OffsetDistance, double);
  vtkNarrowVolumeSwitchMacro(CloseGaps);
  vtkNarrowVolumeSettingMacro(ClosingRadius, double);
  vtkNarrowVolumeSettingMacro(SampleSpacing, double);
  vtkNarrowVolumeClampMacro(MaximumDimension, int, 0, 100000);
  vtkNarrowVolumeSettingMacro(XiCells, double);
  vtkNarrowVolumeSettingMacro(EpsilonCells, double);
  vtkNarrowVolumeClampMacro(EdgeStoppingFunction, int, EQUATION_3, EQUATION_4);
  vtkNarrowVolumeClampMacro(Domain, int, NARROW_BAND, WHOLE_DOMAIN);
  vtkNarrowVolumeClampMacro(MaximumNumberOfIterations, int, 0, 100000);
  vtkNarrowVolumeSwitchMacro(PreserveOffset);
  vtkNarrowVolumeClampMacro(ConvergenceTolerance, double, 0.0, 1.0);
  vtkNarrowVolumeSettingMacro(TimeStep, double);
  vtkNarrowVolumeClampMacro(GaussSeidelTolerance, double, 1e-14, 1.0);
  vtkNarrowVolumeClampMacro(NumberOfThreads, int, 0, 1024);
  vtkNarrowVolumeClampMacro(MemoryLimit, double, 0.0, 1e12);
  vtkNarrowVolumeClampMacro(Device, int, DEVICE_AUTOMATIC, DEVICE_GPU);
  vtkNarrowVolumeClampMacro(Sheets, int, BOTH_SHEETS, SCAN_SURFACE);
  vtkNarrowVolumeSwitchMacro(RemoveSmallPieces);
  vtkNarrowVolumeSwitchMacro(OutputVolume);
  vtkNarrowVolumeSwitchMacro(OutputInitialPhi);
  vtkNarrowVolumeSwitchMacro(OutputDistance);
  vtkNarrowVolumeSwitchMacro(OutputNarrowBand);
  vtkNarrowVolumeSettingMacro(WallThickness, double);
  vtkNarrowVolumeSettingMacro(MinimumCavityVolume, double);
  vtkNarrowVolumeSettingMacro(CavityClosingDistance, double);
  vtkNarrowVolumeClampMacro(NumberOfDrainHoles, int, 0, 64);
  vtkNarrowVolumeClampMacro(DrainHoleAxis, int, DRAIN_MINUS_X, DRAIN_PLUS_Z);
  vtkNarrowVolumeClampMacro(DrainHoleAngle, double, 0.0, 90.0);
  vtkNarrowVolumeSettingMacro(DrainHoleDiameter, double);
  ///@}

  ///@{
  /**
   * The enumerated properties by their values' names (EdgeStoppingFunction,
   * Domain, Device, Sheets, DrainHoleAxis: see the parameter reference).
   */
  void SetEdgeStoppingFunctionToEquation3() { this->SetEdgeStoppingFunction(EQUATION_3); }
  void SetEdgeStoppingFunctionToEquation4() { this->SetEdgeStoppingFunction(EQUATION_4); }
  void SetDomainToNarrowBand() { this->SetDomain(NARROW_BAND); }
  void SetDomainToWholeDomain() { this->SetDomain(WHOLE_DOMAIN); }
  void SetDeviceToAutomatic() { this->SetDevice(DEVICE_AUTOMATIC); }
  void SetDeviceToCPU() { this->SetDevice(DEVICE_CPU); }
  void SetDeviceToGPU() { this->SetDevice(DEVICE_GPU); }
  void SetSheetsToBoth() { this->SetSheets(BOTH_SHEETS); }
  void SetSheetsToOuter() { this->SetSheets(OUTER_SHEET); }
  void SetSheetsToInner() { this->SetSheets(INNER_SHEETS); }
  void SetSheetsToScan() { this->SetSheets(SCAN_SURFACE); }
  void SetDrainHoleAxisToMinusX() { this->SetDrainHoleAxis(DRAIN_MINUS_X); }
  void SetDrainHoleAxisToPlusX() { this->SetDrainHoleAxis(DRAIN_PLUS_X); }
  void SetDrainHoleAxisToMinusY() { this->SetDrainHoleAxis(DRAIN_MINUS_Y); }
  void SetDrainHoleAxisToPlusY() { this->SetDrainHoleAxis(DRAIN_PLUS_Y); }
  void SetDrainHoleAxisToMinusZ() { this->SetDrainHoleAxis(DRAIN_MINUS_Z); }
  void SetDrainHoleAxisToPlusZ() { this->SetDrainHoleAxis(DRAIN_PLUS_Z); }
  ///@}

  ///@{
  /**
   * DrainHolePositions: where the drain holes go, a list of points (world
   * units; empty by default: NumberOfDrainHoles at each cavity's lowest
   * points). Set as vtkContourFilter's values are: SetNumberOf... then
   * SetDrainHolePosition(i, x, y, z), or AddDrainHolePosition(x, y, z);
   * ParaView's panel edits it as rows of x y z. See the parameter reference.
   */
  void SetNumberOfDrainHolePositions(int number);
  int GetNumberOfDrainHolePositions() const;
  void SetDrainHolePosition(int i, double x, double y, double z);
  void AddDrainHolePosition(double x, double y, double z);
  double* GetDrainHolePosition(int i) VTK_SIZEHINT(3); ///< null for no such point
  void RemoveAllDrainHolePositions();
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
   * What the last run chose, which ParaView's panel shows read-only: one Get
   * method per row of the property table's RESULTS, GetOffsetDistanceUsed
   * and the others (the parameter reference says what each is). 0 (or "")
   * before a run or after one that failed.
   */
  NV_RESULTS(vtkNarrowVolumeResultMacro)
  ///@}

  ///@{
  /**
   * Figures of the last run: time steps taken, band nodes and all grid nodes
   * (over all processes in a distributed run), the relative change of each
   * step, and wall-clock seconds of the set-up (distance and band), the
   * evolution and the output (volume and surface) on this process.
   * SamplingTime: seconds spent measuring the points' spacing (nearest
   * neighbours, for the automatic offset and MedianPointSpacing) in the
   * last update; 0 when the points had not changed and the last
   * measurement served.
   */
  int GetNumberOfIterations() const { return static_cast<int>(this->RelativeChanges.size()); }
  vtkGetMacro(NumberOfBandNodes, vtkIdType);
  vtkGetMacro(NumberOfGridNodes, vtkIdType);
  const std::vector<double>& GetRelativeChanges() const { return this->RelativeChanges; }
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
  const nv::Settings& GetSettings() const { return *this->Settings; }
  /// The results of the last run (run null: none yet), for the Get...() methods.
  void KeepResults(const nv::Reconstruction* run, const nv::Outcome& outcome);
  /// The run on the input's points and its outputs, into VTK's arrays (the
  /// data pass, once it knows the piece): ghosts, the volume's ghost layers.
  void Reconstruct(vtkPointSet* input, bool distributed, vtkIdType ghosts, vtkImageData* volume, vtkPolyData* surface);
  /// The run's error and warnings as vtkErrorMacro and vtkWarningMacro give them.
  void ReportMessages(const nv::Outcome& outcome);
  /// A message of the core with the properties named as PanelLabelsInMessages says.
  std::string InWordsOfReader(const std::string& message) const;
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

  // The properties, as the core takes them (defaults: the property table's).
  std::unique_ptr<nv::Settings> Settings;
  vtkMultiProcessController* Controller = nullptr;

  vtkIdType NumberOfBandNodes = 0;
  vtkIdType NumberOfGridNodes = 0;
  std::vector<double> RelativeChanges;
  std::unique_ptr<nv::Results> Chosen; ///< the last run's results (NV_RESULTS)
  bool PanelLabelsInMessages = false;
  std::unique_ptr<nv::SamplingCache> Samplings; ///< the input's sampling, measured once per points
  bool StoppedBeforeData = false; ///< the information pass's measurement was stopped (abort)
  double SamplingTime = 0.0;
  double SetupTime = 0.0;
  double EvolutionTime = 0.0;
  double OutputTime = 0.0;

private:
  vtkNarrowVolumeReconstruction(const vtkNarrowVolumeReconstruction&) = delete;
  void operator=(const vtkNarrowVolumeReconstruction&) = delete;
};

#endif
