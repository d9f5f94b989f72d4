// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The PCD format of the Point Cloud Library (PCL): a text header, then the
// points as text ("DATA ascii"), packed binary records ("DATA binary") or
// LZF-compressed columns ("DATA binary_compressed").
//
// The header is one keyword per line, in this order: VERSION, FIELDS (the
// names), SIZE (bytes of one value: 1, 2, 4 or 8), TYPE (I signed, U
// unsigned, F floating point), COUNT (values per field, default 1), WIDTH,
// HEIGHT (an organized cloud is WIDTH x HEIGHT, an unorganized one has
// HEIGHT 1), VIEWPOINT (the sensor's pose: tx ty tz qw qx qy qz), POINTS
// (= WIDTH x HEIGHT) and DATA. Lines starting with # are comments.
//
// Binary records hold the fields one after the other (SIZE x COUNT bytes
// each), in the byte order of the machine that wrote them (little-endian
// in practice). binary_compressed data is two 32-bit sizes (compressed,
// uncompressed) then the LZF stream, which decompresses to the fields one
// column at a time: all the points' first field, then all their second
// field, and so on.
#ifndef nvPCD_h
#define nvPCD_h

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace nv
{
namespace pcd
{
enum class Encoding
{
  Ascii,
  Binary,
  BinaryCompressed
};

struct Field
{
  std::string Name;
  int Size = 4;    // bytes of one value: 1, 2, 4 or 8
  char Type = 'F'; // 'I', 'U' or 'F'
  int Count = 1;   // values per point
  /// Where the field starts in a packed binary record.
  std::size_t Offset = 0;
  std::size_t Bytes() const { return static_cast<std::size_t>(this->Size) * this->Count; }
  /// "_" fields are padding, never data.
  bool IsPadding() const { return this->Name == "_"; }
};

struct Header
{
  std::string Version;
  std::vector<Field> Fields;
  std::uint64_t Width = 0;
  std::uint64_t Height = 0;
  std::uint64_t Points = 0;
  double Viewpoint[7] = { 0, 0, 0, 1, 0, 0, 0 };
  Encoding Data = Encoding::Ascii;
  /// Bytes of one packed record (the sum of the fields' bytes).
  std::size_t PointSize = 0;
  /// Where the data starts in the file: just after the DATA line.
  std::size_t DataOffset = 0;
  /// Values on one line of ASCII data (the sum of the fields' counts).
  std::size_t ValuesPerPoint = 0;
  /// The index of a field by name, or -1.
  int Find(const std::string& name) const;
};

/// Read at most this many bytes of a file for its header.
constexpr std::size_t MaximumHeaderSize = 1 << 20;

/// Parses the header from the first `size` bytes of a file of `fileSize`
/// bytes and checks it: known keywords, as many SIZE/TYPE/COUNT entries as
/// FIELDS, sizes 1/2/4/8, F only in 4 or 8 bytes, x, y and z fields of one
/// value each, POINTS = WIDTH x HEIGHT, and for ascii and binary data that
/// the file can hold the announced points (binary_compressed data is checked
/// by CheckCompressedSizes once its two sizes are read). On failure returns
/// false with a sentence for the user in `error`.
bool ParseHeader(const char* text, std::size_t size, std::uint64_t fileSize, Header& header,
  std::string& error);

/// Where each field's values lie in decompressed binary_compressed data:
/// field f of point i at ColumnStart[f] + i * Fields[f].Bytes(), or nowhere
/// (ColumnStart[f] = -1) for a padding field the writer left out.
struct ColumnLayout
{
  std::vector<std::int64_t> ColumnStart;
};

/// Checks the two sizes that open binary_compressed data against the header
/// and the file (the compressed bytes lie within the file, the uncompressed
/// size is that of the announced points and at most what LZF can expand the
/// compressed bytes to) and gives the columns' layout. Writers differ on
/// whether padding fields ("_") are stored, which the uncompressed size
/// tells.
bool CheckCompressedSizes(const Header& header, std::uint64_t compressedSize,
  std::uint64_t uncompressedSize, std::uint64_t fileSize, ColumnLayout& layout, std::string& error);

/// Parses one ASCII value of `field` ("1.5", "-3", "nan", ...) into its
/// binary form (field.Size bytes, machine byte order) at `destination`.
/// False if the text is not a number of the field's type and range. A
/// float "rgb" / "rgba" field written as a whole number (as PCL does in
/// ascii files) holds the bits of the packed colour.
bool ParseAsciiValue(const std::string& text, const Field& field, std::uint8_t* destination);

/// One binary value of `field` (field.Size bytes at `value`) as a double.
double ValueAsDouble(const std::uint8_t* value, const Field& field);

/// The data of every point, decoded to binary values: field f of point i at
/// Bytes + Start[f] + i * Stride[f] (packed records, or the columns of
/// binary_compressed data). Start[f] < 0: the field is not stored (a padding
/// field the writer left out).
struct Data
{
  std::vector<std::uint8_t> Bytes;
  std::vector<std::int64_t> Start;
  std::vector<std::size_t> Stride;
  const std::uint8_t* At(std::size_t f, std::uint64_t i) const
  {
    return this->Bytes.data() + this->Start[f] + static_cast<std::size_t>(i) * this->Stride[f];
  }
};

enum class ReadResult
{
  Read,
  Failed,
  Stopped
};

/// Reads a .pcd file: its header (ParseHeader), then the data of every point
/// (ascii, binary or binary_compressed) decoded into `data`. Every
/// allocation is bounded by the file's size. On failure returns Failed with
/// the sentence for the user, naming the file, in `error`. `keepGoing`, when
/// given, is called every 65536 points of ascii data with the fraction read;
/// when it returns false the reading stops (Stopped). The VTK reader
/// (vtkPCDPointCloudReader) and the wheel's binding (narrowvolume._core.read_pcd)
/// both read with it.
ReadResult ReadFile(const std::string& fileName, Header& header, Data& data, std::string& error,
  const std::function<bool(double)>& keepGoing = nullptr);
} // namespace pcd
} // namespace nv

#endif
