// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The OpenVDB route to a smoothed offset shell, for the benchmark: the union
// of balls of radius l around the points (ParticlesToLevelSet; its boundary
// is the paper's phi0 = 0), mean-curvature smoothing steps (LevelSetFilter),
// and both sheets as a mesh (volumeToMesh at 0). Prints one JSON line of
// timings and sizes.
//
//   openvdb_shell POINTS.xyz VOXEL_SIZE OFFSET STEPS
//
// POINTS.xyz: little-endian float32 x, y, z triples.
#include <openvdb/openvdb.h>
#include <openvdb/tools/LevelSetFilter.h>
#include <openvdb/tools/ParticlesToLevelSet.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <vector>

namespace
{
// The particle list interface ParticlesToLevelSet asks for.
struct Particles
{
  using PosType = openvdb::Vec3R;
  std::vector<openvdb::Vec3R> Points;
  openvdb::Real Radius = 0;
  size_t size() const { return Points.size(); }
  void getPos(size_t n, openvdb::Vec3R& p) const { p = Points[n]; }
  void getPosRad(size_t n, openvdb::Vec3R& p, openvdb::Real& r) const
  {
    p = Points[n];
    r = Radius;
  }
};

double Since(std::chrono::steady_clock::time_point t)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}
} // namespace

int main(int argc, char** argv)
{
  if (argc != 5)
  {
    std::fprintf(stderr, "usage: %s POINTS.xyz VOXEL_SIZE OFFSET STEPS\n", argv[0]);
    return 2;
  }
  openvdb::initialize();
  const double voxel = std::atof(argv[2]);
  const double offset = std::atof(argv[3]);
  const int steps = std::atoi(argv[4]);

  Particles particles;
  particles.Radius = offset;
  std::ifstream in(argv[1], std::ios::binary);
  float xyz[3];
  while (in.read(reinterpret_cast<char*>(xyz), sizeof(xyz)))
  {
    particles.Points.emplace_back(xyz[0], xyz[1], xyz[2]);
  }

  auto start = std::chrono::steady_clock::now();
  // Narrow band half-width of 3 voxels (OpenVDB's default), wide enough for the smoothing.
  auto grid = openvdb::createLevelSet<openvdb::FloatGrid>(voxel, 3.0);
  openvdb::tools::ParticlesToLevelSet<openvdb::FloatGrid> raster(*grid);
  raster.setRmin(0.0);
  raster.rasterizeSpheres(particles); // radius l (world units) from getPosRad
  raster.finalize(true);
  const double rasterize = Since(start);

  start = std::chrono::steady_clock::now();
  openvdb::tools::LevelSetFilter<openvdb::FloatGrid> filter(*grid);
  for (int n = 0; n < steps; ++n)
  {
    filter.meanCurvature();
  }
  const double smooth = Since(start);

  start = std::chrono::steady_clock::now();
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  openvdb::tools::volumeToMesh(*grid, points, triangles, quads, 0.0, 0.0);
  const double mesh = Since(start);

  std::printf("{\"points\": %zu, \"active_voxels\": %llu, \"grid_bytes\": %llu, \"rasterize\": %.4f, "
              "\"smooth\": %.4f, \"mesh\": %.4f, \"mesh_points\": %zu, \"mesh_faces\": %zu}\n",
    particles.size(), static_cast<unsigned long long>(grid->activeVoxelCount()),
    static_cast<unsigned long long>(grid->memUsage()), rasterize, smooth, mesh, points.size(),
    triangles.size() + 2 * quads.size());
  return 0;
}
