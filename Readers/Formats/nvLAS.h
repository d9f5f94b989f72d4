// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The LAS format (ASPRS LAS 1.0 to 1.4, uncompressed): its public header
// block, checked against the file's size, and its point data records in the
// eleven point data record formats 0-10. All numbers are little-endian.
//
// A file is: the public header block (227 bytes in LAS 1.0-1.2, 235 in 1.3,
// 375 in 1.4), variable length records, then at "offset to point data" the
// points, each "point data record length" bytes (the format's fields, then
// optional extra bytes), then in 1.3/1.4 optional waveform data and extended
// variable length records. A point stores X, Y, Z as 32-bit integers: the
// coordinate is X * scale + offset, in double precision (the header's scale
// and offset are doubles; airborne data at UTM coordinates needs all of it).
#ifndef nvLAS_h
#define nvLAS_h

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace nv
{
namespace las
{
/// The largest public header block (LAS 1.4): read this many bytes (or the
/// whole file if shorter) and pass them to ParseHeader.
constexpr std::size_t MaximumHeaderSize = 375;

struct Header
{
  int VersionMajor = 0;
  int VersionMinor = 0;
  std::string SystemIdentifier;
  std::string GeneratingSoftware;
  std::uint16_t HeaderSize = 0;
  std::uint32_t PointDataOffset = 0;
  std::uint32_t NumberOfVariableLengthRecords = 0;
  int PointFormat = 0;
  std::uint16_t PointRecordLength = 0;
  /// The 64-bit count of LAS 1.4 when it is set, else the legacy 32-bit one.
  std::uint64_t NumberOfPoints = 0;
  double Scale[3] = { 1, 1, 1 };
  double Offset[3] = { 0, 0, 0 };
  /// Bounds as the header states them: minimum x, y, z then maximum x, y, z.
  double Minimum[3] = { 0, 0, 0 };
  double Maximum[3] = { 0, 0, 0 };
};

/// Parses the public header block from the first `size` bytes of a file of
/// `fileSize` bytes, and checks it against the file: signature "LASF",
/// version 1.0 to 1.4, a header size the version allows and the file holds,
/// point format 0-10 (the LAZ compression bit gives its own message), a
/// record length at least the format's, finite non-zero scales, finite
/// offsets, and the announced points within the file. On failure returns
/// false and a sentence for the user in `error`.
bool ParseHeader(const std::uint8_t* bytes, std::size_t size, std::uint64_t fileSize, Header& header,
  std::string& error);

/// The bytes of the standard fields of point format 0-10 (20, 28, 26, 34,
/// 57, 63, 30, 36, 38, 59, 67); 0 for any other format.
int StandardRecordLength(int format);

bool HasGpsTime(int format);      // formats 1, 3-10
bool HasColor(int format);        // 2, 3, 5, 7, 8, 10
bool HasNearInfrared(int format); // 8, 10
bool IsExtendedFormat(int format); // 6-10: 4-bit returns, 8-bit classes, scanner channel

/// The fields of one point record.
struct Point
{
  std::int32_t X = 0, Y = 0, Z = 0;
  std::uint16_t Intensity = 0;
  std::uint8_t ReturnNumber = 0;
  std::uint8_t NumberOfReturns = 0;
  std::uint8_t ScanDirectionFlag = 0;
  std::uint8_t EdgeOfFlightLine = 0;
  std::uint8_t Classification = 0;
  /// Bit 0 synthetic, 1 key-point, 2 withheld, 3 overlap (formats 6-10 only).
  std::uint8_t ClassificationFlags = 0;
  std::uint8_t ScannerChannel = 0;
  std::uint8_t UserData = 0;
  /// Degrees: the scan angle rank (formats 0-5) or 0.006 degree units (6-10).
  float ScanAngle = 0;
  std::uint16_t PointSourceId = 0;
  double GpsTime = 0;
  std::uint16_t Red = 0, Green = 0, Blue = 0, NearInfrared = 0;
};

/// Decodes one record of point format `format` (0-10; the record holds at
/// least StandardRecordLength(format) bytes).
void DecodePoint(const std::uint8_t* record, int format, Point& point);

/// The values of one field for every point (points x components of them),
/// in an array its user may take over (Release): it is freed with delete[],
/// as VTK's arrays do with VTK_DATA_ARRAY_DELETE and the wheel's binding
/// does with its numpy arrays, so neither copies it.
template <class T>
struct Column
{
  using Value = T;
  std::unique_ptr<T[]> Values;
  std::size_t Size = 0; ///< values; 0: the file's point format lacks the field

  void Allocate(std::size_t size)
  {
    this->Values.reset(new T[size > 0 ? size : 1]);
    this->Size = size;
  }
  T* Release() { return this->Values.release(); }
};

/// Every point of a file: its coordinates and its fields as the readers'
/// point arrays, the same in the VTK reader (vtkLASPointCloudReader) and
/// the wheel's (narrowvolume._core.read_las). A field the point format
/// lacks is empty.
struct Points
{
  Column<double> XYZ; ///< x y z of each point: X * scale + offset, in double
  Column<std::uint16_t> Intensity;
  Column<std::uint8_t> Classification;
  Column<std::uint8_t> ReturnNumber;
  Column<std::uint8_t> NumberOfReturns;
  Column<std::uint8_t> ClassificationFlags;
  Column<std::uint8_t> ScanDirectionFlag;
  Column<std::uint8_t> EdgeOfFlightLine;
  Column<std::uint8_t> UserData;
  Column<float> ScanAngle;
  Column<std::uint16_t> PointSourceId;
  Column<std::uint8_t> ScannerChannel; ///< formats 6-10
  Column<double> GpsTime;              ///< HasGpsTime
  Column<std::uint16_t> NearInfrared;  ///< HasNearInfrared
  /// HasColor: r g b of each point in 8 bits (16-bit colours shifted down,
  /// unless no value exceeds 255: the file stores 8-bit values already).
  Column<std::uint8_t> Colors;
};

/// The point arrays of a file of point format `format`, in the readers'
/// order: fn(name, column, components) for each (Colors last, r g b). The
/// one list of them, which the VTK reader and the wheel's read_las both
/// walk.
template <class Fn>
void ForEachArray(int format, Points& points, Fn&& fn)
{
  fn("Intensity", points.Intensity, 1);
  fn("Classification", points.Classification, 1);
  fn("ReturnNumber", points.ReturnNumber, 1);
  fn("NumberOfReturns", points.NumberOfReturns, 1);
  fn("ClassificationFlags", points.ClassificationFlags, 1);
  fn("ScanDirectionFlag", points.ScanDirectionFlag, 1);
  fn("EdgeOfFlightLine", points.EdgeOfFlightLine, 1);
  fn("UserData", points.UserData, 1);
  fn("ScanAngle", points.ScanAngle, 1);
  fn("PointSourceId", points.PointSourceId, 1);
  if (IsExtendedFormat(format))
  {
    fn("ScannerChannel", points.ScannerChannel, 1);
  }
  if (HasGpsTime(format))
  {
    fn("GpsTime", points.GpsTime, 1);
  }
  if (HasNearInfrared(format))
  {
    fn("NearInfrared", points.NearInfrared, 1);
  }
  if (HasColor(format))
  {
    fn("Colors", points.Colors, 3);
  }
}

enum class ReadResult
{
  Read,
  Failed,
  Stopped
};

/// Reads a .las file: its header (ParseHeader, checked against the file),
/// then every point record decoded into `points`, 65536 at a time. Every
/// allocation is bounded by the file's size. On failure returns Failed with
/// the sentence for the user, naming the file, in `error`. `keepGoing`, when
/// given, is called after each 65536 points with the fraction read; when it
/// returns false the reading stops (Stopped).
ReadResult ReadFile(const std::string& fileName, Header& header, Points& points, std::string& error,
  const std::function<bool(double)>& keepGoing = nullptr);
} // namespace las
} // namespace nv

#endif
