// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvLZF.h"

#include <cstring>

bool nv::LZFDecompress(
  const std::uint8_t* input, std::size_t inputSize, std::uint8_t* output, std::size_t outputSize)
{
  std::size_t in = 0;
  std::size_t out = 0;
  while (in < inputSize)
  {
    const unsigned control = input[in++];
    if (control < 32)
    {
      const std::size_t length = control + 1;
      if (length > inputSize - in || length > outputSize - out)
      {
        return false;
      }
      std::memcpy(output + out, input + in, length);
      in += length;
      out += length;
      continue;
    }
    std::size_t length = control >> 5;
    if (length == 7)
    {
      if (in >= inputSize)
      {
        return false;
      }
      length += input[in++];
    }
    length += 2;
    if (in >= inputSize)
    {
      return false;
    }
    const std::size_t distance = ((static_cast<std::size_t>(control & 31) << 8) | input[in++]) + 1;
    if (distance > out || length > outputSize - out)
    {
      return false;
    }
    // Byte by byte: when distance < length the copy reads what it just wrote.
    for (std::size_t k = 0; k < length; ++k, ++out)
    {
      output[out] = output[out - distance];
    }
  }
  return out == outputSize;
}
