// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvDeviceSurface.h"

#include "nvMarchingCubes.h"
#include "nvSurfaceField.h"
#include "nvTruncatedDistance.h"

#include <algorithm>
#include <cmath>

namespace nv
{

std::vector<std::int64_t> CutBricksOf(const NarrowBand& band)
{
  const std::array<std::int64_t, 3> dims = BrickDimensions(band.GridNodes);
  std::vector<std::int64_t> cut;
  for (std::size_t a = 0; a < band.Bricks.size(); ++a)
  {
    bool inside;
    if (UniformBandBrick(band, static_cast<std::int64_t>(a), inside))
    {
      continue; // one value of psi, as in BandField::Layer
    }
    const std::int64_t brick = band.Bricks[a];
    const std::int64_t bx = brick % dims[0], by = (brick / dims[0]) % dims[1], bz = brick / (dims[0] * dims[1]);
    for (int dz = 0; dz < 2 && bz - dz >= 0; ++dz)
    {
      for (int dy = 0; dy < 2 && by - dy >= 0; ++dy)
      {
        for (int dx = 0; dx < 2 && bx - dx >= 0; ++dx)
        {
          cut.push_back((bx - dx) + dims[0] * ((by - dy) + dims[1] * (bz - dz)));
        }
      }
    }
  }
  std::sort(cut.begin(), cut.end());
  cut.erase(std::unique(cut.begin(), cut.end()), cut.end());
  return cut;
}

void ContourOnDevice(const Grid& grid, const NarrowBand& band, const BandValues& phi, const Parameters& parameters,
  device::SurfaceLauncher& launcher, SurfaceSink& sink, const MemoryCheck& check)
{
  device::ContourConstants constants;
  const std::array<std::int64_t, 3> dims = BrickDimensions(grid);
  for (int a = 0; a < 3; ++a)
  {
    constants.GridDims[a] = grid.Dims[a];
    constants.BrickDims[a] = dims[a];
    constants.Origin[a] = grid.Origin[a];
  }
  constants.Spacing = grid.Spacing;
  // psi = sqrt(2) xi atanh(phi), clamped to eta/2: ImpliedDistance's constants.
  const ImpliedDistance psi(parameters);
  constants.Scale = psi.GetScale();
  constants.Cap = psi.GetCap();

  device::ContourArrays arrays;
  arrays.NumberOfBricks = static_cast<std::int64_t>(band.Bricks.size());
  arrays.Bricks = band.Bricks.data();
  arrays.RedStart = band.RedStart.data();
  arrays.BlackStart = band.BlackStart.data();
  arrays.Offset = band.Offset.data();
  arrays.Inside = band.Inside.data();
  arrays.Phi = phi.data();
  // The cut bricks by the launcher's kernels: CutBricksOf's list.
  std::vector<std::int64_t> cutBricks;
  launcher.CutBricks(arrays, constants, cutBricks);
  const std::int64_t cut = static_cast<std::int64_t>(cutBricks.size());
  arrays.NumberOfCutBricks = cut;
  arrays.CutBricks = cutBricks.data();
  arrays.Cases = &MarchingCubesTable();
  if (check)
  {
    check(device::SurfaceTableBytes(arrays.NumberOfBricks, band.Size(), cut), "for the surface's tables");
  }
  std::vector<std::int32_t> vertices(static_cast<std::size_t>(cut)), triangles(static_cast<std::size_t>(cut));
  launcher.ContourCounts(arrays, band.Size(), constants, vertices.data(), triangles.data());

  // Each cut brick's first vertex and triangle, in brick order: the CPU
  // core's numbering (nvSurface.h).
  std::vector<std::int64_t> firstVertex(static_cast<std::size_t>(cut)), firstTriangle(static_cast<std::size_t>(cut));
  std::int64_t numberOfVertices = 0, numberOfTriangles = 0;
  for (std::int64_t r = 0; r < cut; ++r)
  {
    firstVertex[r] = numberOfVertices;
    firstTriangle[r] = numberOfTriangles;
    numberOfVertices += vertices[r];
    numberOfTriangles += triangles[r];
  }
  if (check)
  {
    // The largest slab's outputs, as the CUDA launcher holds them.
    double largest = 0.0;
    for (const device::SurfaceSlab& slab : device::SurfaceSlabs(firstVertex.data(), firstTriangle.data(), cut,
           numberOfVertices, numberOfTriangles, device::SurfaceSlabBytes))
    {
      largest = std::max(largest, slab.Bytes());
    }
    check(largest, "for the surface's " + std::to_string(numberOfVertices) + " vertices and " +
        std::to_string(numberOfTriangles) + " triangles");
  }
  double* xyz = nullptr;
  float* normals = nullptr;
  sink.AddPoints(numberOfVertices, xyz, normals);
  VertexId* ids = sink.AddTriangles(numberOfTriangles);
  launcher.ContourGeometry(firstVertex.data(), firstTriangle.data(), numberOfVertices, numberOfTriangles, xyz, normals,
    ids);
}

} // namespace nv
