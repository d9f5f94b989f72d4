// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// Generated from Python/_properties.py (the property table) by
// cmake/generate-properties.py --header: edit the table, then run it (the
// PropertyTable test checks that this file is the table's).
//
// NV_SETTINGS(X) calls X(Type, Name, Default) for each property of the
// filter, in the table's order: nv::Settings declares its fields with it
// (nvSettings.h), the VTK filter defines its Set/Get over them, the
// binding binds them.
#ifndef nvSettingsTable_h
#define nvSettingsTable_h

#define NV_SETTINGS(X) \
  X(double, OffsetDistance, 0.0) \
  X(bool, CloseGaps, true) \
  X(double, ClosingRadius, 0.0) \
  X(double, SampleSpacing, 0.0) \
  X(int, MaximumDimension, 0) \
  X(double, XiCells, 2.0) \
  X(double, EpsilonCells, 6.0) \
  X(nv::EdgeStopping, EdgeStoppingFunction, nv::EdgeStopping(4)) \
  X(nv::Domain, Domain, nv::Domain(0)) \
  X(int, MaximumNumberOfIterations, 3) \
  X(bool, PreserveOffset, false) \
  X(double, ConvergenceTolerance, 0.0) \
  X(double, TimeStep, 0.0) \
  X(double, GaussSeidelTolerance, 1e-06) \
  X(int, NumberOfThreads, 0) \
  X(double, MemoryLimit, 0.0) \
  X(nv::ComputeDevice, Device, nv::ComputeDevice(0)) \
  X(nv::Sheets, Sheets, nv::Sheets(0)) \
  X(bool, RemoveSmallPieces, true) \
  X(bool, OutputVolume, true) \
  X(bool, OutputInitialPhi, false) \
  X(bool, OutputDistance, false) \
  X(bool, OutputNarrowBand, false) \
  X(double, WallThickness, 0.0) \
  X(double, MinimumCavityVolume, 0.0) \
  X(double, CavityClosingDistance, 0.0) \
  X(int, NumberOfDrainHoles, 0) \
  X(nv::DrainAxis, DrainHoleAxis, nv::DrainAxis(4)) \
  X(double, DrainHoleAngle, 30.0) \
  X(double, DrainHoleDiameter, 0.0)

// NV_SETTINGS_RANGES(X) calls X(Name, Low, High) for each property whose
// setter clamps its value to [Low, High] (as vtkSetClampMacro).
#define NV_SETTINGS_RANGES(X) \
  X(MaximumDimension, 0, 100000) \
  X(EdgeStoppingFunction, 3, 4) \
  X(Domain, 0, 1) \
  X(MaximumNumberOfIterations, 0, 100000) \
  X(ConvergenceTolerance, 0.0, 1.0) \
  X(GaussSeidelTolerance, 1e-14, 1.0) \
  X(NumberOfThreads, 0, 1024) \
  X(MemoryLimit, 0.0, 1000000000000.0) \
  X(Device, 0, 2) \
  X(Sheets, 0, 3) \
  X(NumberOfDrainHoles, 0, 64) \
  X(DrainHoleAxis, 0, 5) \
  X(DrainHoleAngle, 0.0, 90.0)

// NV_SETTINGS_VALID(X) calls X(Name, Low, High) for each property whose
// values outside [Low, High] a run refuses with an error (nv::MakePlan).
#define NV_SETTINGS_VALID(X) \
  X(XiCells, 1.0, 64.0) \
  X(EpsilonCells, 0.5, 256.0)

// NV_PANEL_LABELS(X) calls X(Name, "Label") for each property: the VTK
// filter's messages name the properties by their panel labels in ParaView.
#define NV_PANEL_LABELS(X) \
  X(OffsetDistance, "Offset Distance") \
  X(CloseGaps, "Close Gaps") \
  X(ClosingRadius, "Closing Radius") \
  X(SampleSpacing, "Sample Spacing") \
  X(MaximumDimension, "Maximum Dimension") \
  X(XiCells, "Xi Cells") \
  X(EpsilonCells, "Epsilon Cells") \
  X(EdgeStoppingFunction, "Edge Stopping Function") \
  X(Domain, "Domain") \
  X(MaximumNumberOfIterations, "Maximum Number Of Iterations") \
  X(PreserveOffset, "Preserve Offset") \
  X(ConvergenceTolerance, "Convergence Tolerance") \
  X(TimeStep, "Time Step") \
  X(GaussSeidelTolerance, "Gauss-Seidel Tolerance") \
  X(NumberOfThreads, "Number Of Threads") \
  X(MemoryLimit, "Memory Limit") \
  X(Device, "Device") \
  X(Sheets, "Sheets") \
  X(RemoveSmallPieces, "Remove Small Pieces") \
  X(OutputVolume, "Output Volume") \
  X(OutputInitialPhi, "Output Initial Phi") \
  X(OutputDistance, "Output Distance") \
  X(OutputNarrowBand, "Output Narrow Band") \
  X(WallThickness, "Wall Thickness") \
  X(MinimumCavityVolume, "Minimum Cavity Volume") \
  X(CavityClosingDistance, "Cavity Closing Distance") \
  X(NumberOfDrainHoles, "Number Of Drain Holes") \
  X(DrainHoleAxis, "Drain Hole Axis") \
  X(DrainHoleAngle, "Drain Hole Angle") \
  X(DrainHoleDiameter, "Drain Hole Diameter") \
  X(DrainHolePositions, "Drain Hole Positions")

// NV_RESULTS(X) calls X(Type, Name, Size) for each result of a run (the
// table's RESULTS: a value the run chose, which the panel shows read-only):
// Type double, int or Text (a string), Size values. nv::Results declares its
// fields with it (nvReconstruct.h), the VTK filter its Get methods, the binding
// binds them.
#define NV_RESULTS(X) \
  X(double, OffsetDistanceUsed, 1) \
  X(double, ClosingRadiusUsed, 1) \
  X(double, SampleSpacingUsed, 1) \
  X(Text, GridUsed, 1) \
  X(int, GridDimensionsUsed, 3) \
  X(Text, PartSizeUsed, 1)

#endif
