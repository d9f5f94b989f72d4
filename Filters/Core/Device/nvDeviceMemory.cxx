// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvDeviceMemory.h"

#include "nvPointSort.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#ifdef _WIN32
#include <windows.h>
#else
#include <unistd.h>
#endif

namespace nv
{
namespace device
{

std::string ByteWords(double bytes)
{
  char text[64];
  if (bytes >= 1e9)
  {
    std::snprintf(text, sizeof(text), "%.3g GB", bytes / 1e9);
  }
  else
  {
    std::snprintf(text, sizeof(text), "%.3g MB", bytes / 1e6);
  }
  return text;
}

void DeviceLedger::CheckLimit(std::size_t bytes, const char* what) const
{
  if (this->Bytes + static_cast<double>(bytes) > this->Limit)
  {
    throw DeviceError(std::string("The GPU failed (allocating ") + what + ", " + ByteWords(static_cast<double>(bytes)) +
      "): out of memory (the launcher's limit of " + ByteWords(this->Limit) + ")");
  }
}

double BandBuildBytes(std::int64_t points, std::int64_t bricks, std::int64_t batch, double dense)
{
  const double p = static_cast<double>(points), b = static_cast<double>(bricks);
  const double chunks = static_cast<double>((bricks + ChunkBricks - 1) / ChunkBricks);
  const double sort = 56.0 * p + 17.0 * b + 16.0 * chunks;
  const double batches = 24.0 * p + 8.0 * b + dense + 4193.0 * static_cast<double>(batch);
  return std::max(sort, batches);
}

double EvolutionBytes(std::int64_t nodes)
{
  // max(phi over the band's arrays, phi^n, the coupling and the decay once
  // the distances (8) and node places (2) are let go): 28 - 10 = 18.
  return 18.0 * static_cast<double>(nodes) + 16.0;
}

double SurfaceTableBytes(std::int64_t bandBricks, std::int64_t nodes, std::int64_t cutBricks)
{
  return 2136.0 * static_cast<double>(bandBricks) + 2.0 * static_cast<double>(nodes) +
    386.0 * static_cast<double>(cutBricks);
}

double DenseBytes(std::int64_t nodes, int floatArrays, bool bandFlags)
{
  return static_cast<double>(nodes) * (4.0 * floatArrays + (bandFlags ? 1.0 : 0.0));
}

double HostAvailableBytes()
{
#ifdef _WIN32
  MEMORYSTATUSEX status;
  status.dwLength = sizeof(status);
  return GlobalMemoryStatusEx(&status) ? static_cast<double>(status.ullAvailPhys)
                                       : std::numeric_limits<double>::infinity();
#else
  // MemAvailable counts the page cache the kernel would give up; the free
  // pages alone (sysconf) where /proc/meminfo has no such line.
  std::ifstream meminfo("/proc/meminfo");
  std::string line;
  while (std::getline(meminfo, line))
  {
    std::istringstream fields(line);
    std::string name;
    double kilobytes = 0.0;
    if (fields >> name >> kilobytes && name == "MemAvailable:")
    {
      return kilobytes * 1024.0;
    }
  }
#ifdef _SC_AVPHYS_PAGES
  const long pages = sysconf(_SC_AVPHYS_PAGES);
  const long pageSize = sysconf(_SC_PAGE_SIZE);
  if (pages > 0 && pageSize > 0)
  {
    return static_cast<double>(pages) * static_cast<double>(pageSize);
  }
#endif
  return std::numeric_limits<double>::infinity();
#endif
}

} // namespace device
} // namespace nv
