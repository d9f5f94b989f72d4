// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// Little-endian numbers from a byte buffer, whatever the machine's byte
// order (LAS is little-endian by its specification).
#ifndef nvLittleEndian_h
#define nvLittleEndian_h

#include <cstdint>
#include <cstring>

namespace nv
{
inline std::uint16_t U16(const std::uint8_t* p)
{
  return static_cast<std::uint16_t>(p[0] | (p[1] << 8));
}
inline std::uint32_t U32(const std::uint8_t* p)
{
  return static_cast<std::uint32_t>(p[0]) | (static_cast<std::uint32_t>(p[1]) << 8) |
    (static_cast<std::uint32_t>(p[2]) << 16) | (static_cast<std::uint32_t>(p[3]) << 24);
}
inline std::uint64_t U64(const std::uint8_t* p)
{
  return static_cast<std::uint64_t>(U32(p)) | (static_cast<std::uint64_t>(U32(p + 4)) << 32);
}
inline std::int32_t I32(const std::uint8_t* p)
{
  return static_cast<std::int32_t>(U32(p));
}
inline std::int16_t I16(const std::uint8_t* p)
{
  return static_cast<std::int16_t>(U16(p));
}
inline double F64(const std::uint8_t* p)
{
  const std::uint64_t bits = U64(p);
  double value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}
} // namespace nv

#endif
