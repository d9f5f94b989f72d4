// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// Writes the seed corpus of FuzzPointCloudReaders into the folder given as
// its argument (emptied first): small valid LAS files (1.0 to 1.4, formats
// 0, 1, 3, 6, 8, 10), PCD files in the three encodings, PLY files in the
// three formats (points and triangles) and a text cloud, so
// that the fuzzer starts from inputs that pass the signature and header
// checks and mutates its way into the data.
#include "nvTestPointFiles.h"
#include "nvTestUtilities.h"

#include <cstdio>
#include <string>
#include <sys/stat.h>
#include <vtksys/SystemTools.hxx>

int main(int argc, char* argv[])
{
  if (argc != 2)
  {
    std::printf("usage: MakeReaderSeeds FOLDER\n");
    return 2;
  }
  const std::string folder = argv[1];
  vtksys::SystemTools::RemoveADirectory(folder);
  vtksys::SystemTools::MakeDirectory(folder);
  const double center[3] = { 500010.5, 4000020.25, 12.0 };
  const double offset[3] = { 500000.0, 4000000.0, 0.0 };
  const std::vector<double> xyz = nvtest::SpherePoints(6, 2.0, center);
  const int pairs[][2] = { { 0, 0 }, { 1, 1 }, { 2, 3 }, { 3, 5 }, { 4, 6 }, { 4, 8 }, { 4, 10 } };
  int written = 0;
  for (const auto& pair : pairs)
  {
    written += nvtest::WriteFile(folder + "/las-1" + std::to_string(pair[0]) + "-format" +
        std::to_string(pair[1]) + ".las",
      nvtest::LASFile(pair[0], pair[1], xyz, offset));
  }
  for (const char* encoding : { "ascii", "binary", "binary_compressed" })
  {
    written += nvtest::WriteFile(folder + "/" + encoding + ".pcd", nvtest::PCDFile(encoding, xyz));
  }
  for (const char* format : { "ascii", "binary_little_endian", "binary_big_endian" })
  {
    written += nvtest::WriteFile(folder + "/" + format + ".ply", nvtest::PLYFile(format, xyz));
  }
  written += nvtest::WriteFile(folder + "/cloud.xyz", nvtest::TextFile(xyz));
  std::printf("MakeReaderSeeds: %d seeds in %s\n", written, folder.c_str());
  return written == 14 ? 0 : 1;
}
