// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// Point cloud files for the C++ reader tests and the fuzzer's seeds, built
// byte by byte from the formats' specifications (the Python tests have
// fuller writers in Testing/Python/nvpointfiles.py): LAS 1.0-1.4 in every
// point format, PCD in ascii, binary and binary_compressed, plain text.
#ifndef nvTestPointFiles_h
#define nvTestPointFiles_h

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace nvtest
{
using Bytes = std::vector<std::uint8_t>;

template <typename T>
void Put(Bytes& bytes, std::size_t at, T value)
{
  if (bytes.size() < at + sizeof value)
  {
    bytes.resize(at + sizeof value);
  }
  std::memcpy(bytes.data() + at, &value, sizeof value); // little-endian machines only
}

inline int LASRecordLength(int format)
{
  static const int lengths[11] = { 20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67 };
  return lengths[format];
}

/// Field values of point i in the LAS files below.
inline std::uint16_t LASIntensity(int i)
{
  return static_cast<std::uint16_t>(1000 + 7 * i);
}
inline std::uint8_t LASClass(int i)
{
  return static_cast<std::uint8_t>(i % 19);
}
inline double LASGpsTime(int i)
{
  return 1.0e8 + 0.25 * i;
}
inline std::uint16_t LASRed(int i)
{
  return static_cast<std::uint16_t>(256 * (i % 256));
}

/// A LAS 1.`minor` file of the points xyz in point format `format`, with
/// scale 0.001 and the given offset.
inline Bytes LASFile(int minor, int format, const std::vector<double>& xyz, const double offset[3])
{
  const std::size_t headerSize = minor <= 2 ? 227 : (minor == 3 ? 235 : 375);
  const std::size_t n = xyz.size() / 3;
  const int length = LASRecordLength(format);
  Bytes bytes(headerSize + n * length, 0);
  std::memcpy(bytes.data(), "LASF", 4);
  bytes[24] = 1;
  bytes[25] = static_cast<std::uint8_t>(minor);
  Put<std::uint16_t>(bytes, 94, static_cast<std::uint16_t>(headerSize));
  Put<std::uint32_t>(bytes, 96, static_cast<std::uint32_t>(headerSize));
  bytes[104] = static_cast<std::uint8_t>(format);
  Put<std::uint16_t>(bytes, 105, static_cast<std::uint16_t>(length));
  Put<std::uint32_t>(bytes, 107, format <= 5 ? static_cast<std::uint32_t>(n) : 0);
  for (int a = 0; a < 3; ++a)
  {
    Put<double>(bytes, 131 + 8 * a, 0.001);
    Put<double>(bytes, 155 + 8 * a, offset[a]);
  }
  if (minor >= 4)
  {
    Put<std::uint64_t>(bytes, 247, n);
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    const std::size_t at = headerSize + i * length;
    for (int a = 0; a < 3; ++a)
    {
      Put<std::int32_t>(bytes, at + 4 * a, static_cast<std::int32_t>(std::lround((xyz[3 * i + a] - offset[a]) / 0.001)));
    }
    const int k = static_cast<int>(i);
    Put<std::uint16_t>(bytes, at + 12, LASIntensity(k));
    bytes[at + 14] = format <= 5 ? 0x09 : 0x11; // return 1 of 1
    if (format <= 5)
    {
      bytes[at + 15] = LASClass(k);
    }
    else
    {
      bytes[at + 16] = LASClass(k);
    }
    const int timeAt = format <= 5 ? 20 : 22;
    if (format == 1 || format >= 3)
    {
      Put<double>(bytes, at + timeAt, LASGpsTime(k));
    }
    const int colorAt = format == 2 ? 20 : (format == 3 || format == 5) ? 28 : (format == 7 || format == 8 || format == 10) ? 30 : -1;
    if (colorAt >= 0)
    {
      Put<std::uint16_t>(bytes, at + colorAt, LASRed(k));
    }
  }
  return bytes;
}

/// LZF as literal runs only (valid LZF, uncompressed): what binary_compressed
/// needs when the test is about the file and not the compression.
inline Bytes LZFLiterals(const Bytes& data)
{
  Bytes out;
  for (std::size_t at = 0; at < data.size(); at += 32)
  {
    const std::size_t run = std::min<std::size_t>(32, data.size() - at);
    out.push_back(static_cast<std::uint8_t>(run - 1));
    out.insert(out.end(), data.begin() + at, data.begin() + at + run);
  }
  return out;
}

inline std::uint16_t PCDIntensity(int i)
{
  return static_cast<std::uint16_t>(3 * i + 1);
}

/// A PCD file of the points xyz (fields x y z intensity rgb) in `encoding`
/// (ascii, binary, binary_compressed).
inline Bytes PCDFile(const std::string& encoding, const std::vector<double>& xyz)
{
  const std::size_t n = xyz.size() / 3;
  std::string header = "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\n"
                       "FIELDS x y z intensity rgb\nSIZE 4 4 4 2 4\nTYPE F F F U U\nCOUNT 1 1 1 1 1\n"
                       "WIDTH " + std::to_string(n) + "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " +
    std::to_string(n) + "\nDATA " + encoding + "\n";
  Bytes bytes(header.begin(), header.end());
  if (encoding == "ascii")
  {
    for (std::size_t i = 0; i < n; ++i)
    {
      char line[160];
      std::snprintf(line, sizeof line, "%.9g %.9g %.9g %u %u\n", static_cast<float>(xyz[3 * i]),
        static_cast<float>(xyz[3 * i + 1]), static_cast<float>(xyz[3 * i + 2]),
        static_cast<unsigned>(PCDIntensity(static_cast<int>(i))), 0x00102030u);
      bytes.insert(bytes.end(), line, line + std::strlen(line));
    }
    return bytes;
  }
  // Packed records (binary) or columns (binary_compressed).
  const std::size_t sizes[5] = { 4, 4, 4, 2, 4 };
  Bytes records, columns;
  for (int f = 0; f < 5; ++f)
  {
    for (std::size_t i = 0; i < n; ++i)
    {
      std::uint8_t value[4];
      if (f < 3)
      {
        const float v = static_cast<float>(xyz[3 * i + f]);
        std::memcpy(value, &v, 4);
      }
      else if (f == 3)
      {
        const std::uint16_t v = PCDIntensity(static_cast<int>(i));
        std::memcpy(value, &v, 2);
      }
      else
      {
        const std::uint32_t v = 0x00102030u;
        std::memcpy(value, &v, 4);
      }
      columns.insert(columns.end(), value, value + sizes[f]);
    }
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    std::size_t start = 0;
    for (int f = 0; f < 5; ++f)
    {
      records.insert(records.end(), columns.begin() + start + i * sizes[f],
        columns.begin() + start + (i + 1) * sizes[f]);
      start += n * sizes[f];
    }
  }
  if (encoding == "binary")
  {
    bytes.insert(bytes.end(), records.begin(), records.end());
    return bytes;
  }
  const Bytes packed = LZFLiterals(columns);
  const std::size_t at = bytes.size();
  Put<std::uint32_t>(bytes, at, static_cast<std::uint32_t>(packed.size()));
  Put<std::uint32_t>(bytes, at + 4, static_cast<std::uint32_t>(columns.size()));
  bytes.insert(bytes.end(), packed.begin(), packed.end());
  return bytes;
}

/// Plain text x y z intensity.
inline Bytes TextFile(const std::vector<double>& xyz)
{
  std::string text = "# x y z intensity\n";
  for (std::size_t i = 0; i < xyz.size() / 3; ++i)
  {
    char line[128];
    std::snprintf(line, sizeof line, "%.6f %.6f %.6f %d\n", xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2],
      static_cast<int>(i));
    text += line;
  }
  return Bytes(text.begin(), text.end());
}

/// A PLY file of the points (float x y z and a uchar intensity) and one
/// triangle per three points, in `format`: "ascii", "binary_little_endian"
/// or "binary_big_endian".
inline Bytes PLYFile(const std::string& format, const std::vector<double>& xyz)
{
  const std::size_t n = xyz.size() / 3;
  std::string header = "ply\nformat " + format + " 1.0\ncomment a seed\nelement vertex " + std::to_string(n) +
    "\nproperty float x\nproperty float y\nproperty float z\nproperty uchar intensity\nelement face " +
    std::to_string(n / 3) + "\nproperty list uchar int vertex_indices\nend_header\n";
  Bytes bytes(header.begin(), header.end());
  const bool big = format == "binary_big_endian";
  auto put = [&bytes, big](const void* value, std::size_t size) {
    const auto* p = static_cast<const std::uint8_t*>(value);
    for (std::size_t b = 0; b < size; ++b)
    {
      bytes.push_back(p[big ? size - 1 - b : b]); // little-endian machines only
    }
  };
  for (std::size_t i = 0; i < n; ++i)
  {
    if (format == "ascii")
    {
      char line[128];
      std::snprintf(line, sizeof line, "%g %g %g %d\n", xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2],
        static_cast<int>(i % 256));
      bytes.insert(bytes.end(), line, line + std::strlen(line));
      continue;
    }
    for (int c = 0; c < 3; ++c)
    {
      const float value = static_cast<float>(xyz[3 * i + c]);
      put(&value, sizeof value);
    }
    bytes.push_back(static_cast<std::uint8_t>(i % 256));
  }
  for (std::size_t f = 0; f + 2 < n; f += 3)
  {
    if (format == "ascii")
    {
      const std::string line = "3 " + std::to_string(f) + " " + std::to_string(f + 1) + " " +
        std::to_string(f + 2) + "\n";
      bytes.insert(bytes.end(), line.begin(), line.end());
      continue;
    }
    bytes.push_back(3);
    for (std::size_t k = 0; k < 3; ++k)
    {
      const std::int32_t index = static_cast<std::int32_t>(f + k);
      put(&index, sizeof index);
    }
  }
  return bytes;
}

inline bool WriteFile(const std::string& path, const Bytes& bytes)
{
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file)
  {
    return false;
  }
  const bool ok = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
  return std::fclose(file) == 0 && ok;
}
} // namespace nvtest

#endif
