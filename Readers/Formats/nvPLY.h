// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The PLY format (Stanford's polygon files), checked before VTK's
// vtkPLYReader reads a file. That reader trusts the header: a missing vertex
// element or z coordinate, a negative count or one beyond the file, or data
// shorter than the header announces crash it, abort the process or give
// made-up points. CheckFile refuses such a file with a sentence for the
// user instead; the readers of every route call it first
// (vtkPLYPointCloudReader in ParaView and the CMake build's Python package,
// the wheel's narrowvolume._core.check_ply_file on the command line).
//
// A PLY file is a text header, then the data:
//
//   ply
//   format ascii 1.0            (or binary_little_endian 1.0, binary_big_endian 1.0)
//   comment ...                 (comment and obj_info lines anywhere)
//   element vertex 8            (an element: a name and a count of records)
//   property float x            (its properties, in the order of the data)
//   property float y
//   property float z
//   element face 6
//   property list uchar int vertex_indices   (a count, then that many values)
//   end_header
//
// ASCII data holds one record per line; binary data the records one after
// the other, each value in its type's size (char/int8 and uchar/uint8 1
// byte, short/int16 and ushort/uint16 2, int/int32, uint/uint32 and
// float/float32 4, double/float64 8), in the byte order of the format line.
#ifndef nvPLY_h
#define nvPLY_h

#include <cstddef>
#include <cstdint>
#include <istream>
#include <string>
#include <vector>

namespace nv
{
namespace ply
{
enum class Format
{
  Ascii,
  BinaryLittleEndian,
  BinaryBigEndian
};

enum class Type
{
  Int8,
  UInt8,
  Int16,
  UInt16,
  Int32,
  UInt32,
  Float32,
  Float64
};

/// Bytes of one value of `type` in binary data.
int SizeOf(Type type);

struct Property
{
  std::string Name;
  Type ValueType = Type::Float32;
  /// A list: a count of CountType, then that many values of ValueType.
  bool IsList = false;
  Type CountType = Type::UInt8;
};

struct Element
{
  std::string Name;
  std::uint64_t Count = 0;
  std::vector<Property> Properties;
  /// The index of a property by name, or -1.
  int Find(const std::string& name) const;
};

struct Header
{
  Format DataFormat = Format::Ascii;
  std::vector<Element> Elements;
  /// Where the data starts in the file: just after the end_header line.
  std::size_t DataOffset = 0;
  /// The lines of the header, end_header included.
  std::size_t HeaderLines = 0;
  /// The index of an element by name, or -1.
  int Find(const std::string& name) const;
};

/// Read at most this many bytes of a file for its header.
constexpr std::size_t MaximumHeaderSize = 1 << 20;

/// Parses the header from the first `size` bytes of a file of `fileSize`
/// bytes and checks what the readers rely on: the "ply" line, a known
/// format, elements with whole non-negative counts, properties of known
/// types, an end_header line, a vertex element with x, y and z (single
/// values, not lists), and that the file holds at least the bytes the
/// counts need. On failure returns false with a sentence for the user in
/// `error` (a text file of x y z numbers is named as such).
bool ParseHeader(const char* text, std::size_t size, std::uint64_t fileSize, Header& header,
  std::string& error);

/// Walks the data after the header (`data` positioned at DataOffset) and
/// checks that it holds every record the header announces: ASCII lines with
/// enough numbers, binary records and list counts within the file, and the
/// faces' vertex indices within the vertex count.
bool CheckData(const Header& header, std::istream& data, std::string& error);

/// ParseHeader, then CheckData, on the file at `path`.
bool CheckFile(const std::string& path, std::string& error);

/// ParseHeader, then CheckData, on a whole PLY file held in `text`.
bool CheckText(const std::string& text, std::string& error);
} // namespace ply
} // namespace nv

#endif
