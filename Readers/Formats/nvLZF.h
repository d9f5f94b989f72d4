// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// LZF decompression: the compression of PCD's "binary_compressed" data.
//
// An LZF stream is a sequence of chunks, each opened by a control byte c:
// - c < 32: a literal run, the next c + 1 bytes are copied as they are;
// - c >= 32: a back reference, copy len bytes starting dist bytes back in
//   the output, where len = (c >> 5) + 2 (when c >> 5 is 7, the next byte is
//   added to it) and dist = ((c & 31) << 8) + next byte + 1. The copy may
//   overlap what it writes (dist < len repeats a pattern).
#ifndef nvLZF_h
#define nvLZF_h

#include <cstddef>
#include <cstdint>

namespace nv
{
/// Decompresses `input` into exactly `outputSize` bytes at `output`. Returns
/// false, having written nothing outside [output, output + outputSize), if the
/// stream is malformed: a chunk runs past the end of the input, a reference
/// points before the start of the output, or the output does not come out at
/// exactly outputSize bytes.
bool LZFDecompress(const std::uint8_t* input, std::size_t inputSize, std::uint8_t* output,
  std::size_t outputSize);

/// The largest output an LZF stream of inputSize bytes can produce: a 3-byte
/// back reference yields at most 264 bytes, 88 per input byte.
constexpr std::size_t LZFMaximumRatio = 88;
} // namespace nv

#endif
