// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The case table of marching cubes (Lorensen and Cline, 1987): for each of
// the 256 sign patterns of a cell's corners, the triangles of the level
// surface, as triples of cell edges (a vertex sits on each cut edge).
//
// The table is built from one rule rather than typed in: on a face whose
// diagonal corners have the same sign, the two corners at or above the level
// are cut off from each other (the corners below are joined across the
// face). A rule that reads only the face's corners gives both cells of a face
// the same cut, so the surface is closed. It is the rule of VTK's table:
// vtkFlyingEdges3D makes the same number of triangles, with the same
// vertices, for every case (TestSurfaceContour checks).
#ifndef nvMarchingCubes_h
#define nvMarchingCubes_h

#include "nvSurfaceTerms.h" // the cells' corners and edges: EdgeCorner, EdgeAxis, CellEdges

#include <array>
#include <cstdint>

namespace nv
{

/// The triangles of one case (bit c set: corner c is at or above the level),
/// each as three cell edges, ordered so that the triangle's normal (right-hand
/// rule) points towards the corners below the level.
struct CellCase
{
  int Count = 0;
  std::array<std::array<std::uint8_t, 3>, 5> Triangles{};
};

const std::array<CellCase, 256>& MarchingCubesCases();

/// The same table as plain bytes (nvSurfaceTerms.h's CellCases), as the
/// CPU core's contouring and the device's kernels read it.
const CellCases& MarchingCubesTable();

} // namespace nv

#endif
