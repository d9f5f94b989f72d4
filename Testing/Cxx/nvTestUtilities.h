// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// Small helpers shared by the C++ tests: checks that report what failed and
// where, and sampled point clouds.
#ifndef nvTestUtilities_h
#define nvTestUtilities_h

#include <cmath>
#include <cstdio>
#include <vector>

namespace nvtest
{

inline int& Failures()
{
  static int failures = 0;
  return failures;
}

#define NV_CHECK(condition)                                                                        \
  do                                                                                               \
  {                                                                                                \
    if (!(condition))                                                                              \
    {                                                                                              \
      std::printf("FAILED %s:%d: %s\n", __FILE__, __LINE__, #condition);                           \
      ++nvtest::Failures();                                                                        \
    }                                                                                              \
  } while (0)

#define NV_CHECK_NEAR(actual, expected, tolerance)                                                 \
  do                                                                                               \
  {                                                                                                \
    const double nvActual = (actual);                                                              \
    const double nvExpected = (expected);                                                          \
    if (!(std::fabs(nvActual - nvExpected) <= (tolerance)))                                        \
    {                                                                                              \
      std::printf("FAILED %s:%d: %s = %.17g, expected %.17g within %g\n", __FILE__, __LINE__,      \
        #actual, nvActual, nvExpected, static_cast<double>(tolerance));                            \
      ++nvtest::Failures();                                                                        \
    }                                                                                              \
  } while (0)

/// Exit code for main(): 0 when every check passed.
inline int Result(const char* name)
{
  std::printf("%s: %s (%d failed checks)\n", name, Failures() ? "FAILED" : "passed", Failures());
  return Failures() ? 1 : 0;
}

/// n points spread evenly on a sphere (Fibonacci lattice), as xyz triples.
inline std::vector<double> SpherePoints(int n, double radius, const double center[3])
{
  std::vector<double> xyz;
  xyz.reserve(3 * static_cast<std::size_t>(n));
  const double golden = M_PI * (1.0 + std::sqrt(5.0));
  for (int i = 0; i < n; ++i)
  {
    const double polar = std::acos(1.0 - 2.0 * (i + 0.5) / n);
    const double azimuth = golden * (i + 0.5);
    xyz.push_back(center[0] + radius * std::cos(azimuth) * std::sin(polar));
    xyz.push_back(center[1] + radius * std::sin(azimuth) * std::sin(polar));
    xyz.push_back(center[2] + radius * std::cos(polar));
  }
  return xyz;
}

} // namespace nvtest

#endif
