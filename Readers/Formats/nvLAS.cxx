// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvLAS.h"

#include "nvLittleEndian.h"
#include "nvTextParts.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

namespace
{
using nv::text::Fail;

// Byte offsets of the public header block's fields (LAS 1.4 specification,
// table 3; LAS 1.0-1.3 are its prefixes).
constexpr std::size_t VersionMajorAt = 24;
constexpr std::size_t VersionMinorAt = 25;
constexpr std::size_t SystemIdentifierAt = 26;
constexpr std::size_t GeneratingSoftwareAt = 58;
constexpr std::size_t HeaderSizeAt = 94;
constexpr std::size_t PointDataOffsetAt = 96;
constexpr std::size_t NumberOfVLRsAt = 100;
constexpr std::size_t PointFormatAt = 104;
constexpr std::size_t PointRecordLengthAt = 105;
constexpr std::size_t LegacyNumberOfPointsAt = 107;
constexpr std::size_t ScaleAt = 131;
constexpr std::size_t OffsetAt = 155;
constexpr std::size_t BoundsAt = 179; // max x, min x, max y, min y, max z, min z
constexpr std::size_t NumberOfPointsAt = 247; // LAS 1.4: 64-bit

/// The smallest header each minor version of LAS 1.x may have.
std::size_t MinimumHeaderSize(int minor)
{
  return minor <= 2 ? 227 : (minor == 3 ? 235 : 375);
}

std::string Text(const std::uint8_t* bytes, std::size_t length)
{
  std::string text(reinterpret_cast<const char*>(bytes), length);
  const auto end = text.find('\0');
  if (end != std::string::npos)
  {
    text.resize(end);
  }
  while (!text.empty() && text.back() == ' ')
  {
    text.pop_back();
  }
  return text;
}

} // namespace

int nv::las::StandardRecordLength(int format)
{
  static const int lengths[11] = { 20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67 };
  return format >= 0 && format <= 10 ? lengths[format] : 0;
}

bool nv::las::HasGpsTime(int format)
{
  return format == 1 || (format >= 3 && format <= 10);
}

bool nv::las::HasColor(int format)
{
  return format == 2 || format == 3 || format == 5 || format == 7 || format == 8 || format == 10;
}

bool nv::las::HasNearInfrared(int format)
{
  return format == 8 || format == 10;
}

bool nv::las::IsExtendedFormat(int format)
{
  return format >= 6 && format <= 10;
}

bool nv::las::ParseHeader(const std::uint8_t* bytes, std::size_t size, std::uint64_t fileSize,
  Header& header, std::string& error)
{
  header = Header();
  if (size < 4 || bytes[0] != 'L' || bytes[1] != 'A' || bytes[2] != 'S' || bytes[3] != 'F')
  {
    return Fail(error, "not a LAS file: it does not start with \"LASF\"");
  }
  if (size < MinimumHeaderSize(0))
  {
    return Fail(error, "the file ends inside its header: ", fileSize,
      " bytes, where a LAS header alone has at least ", MinimumHeaderSize(0));
  }
  header.VersionMajor = bytes[VersionMajorAt];
  header.VersionMinor = bytes[VersionMinorAt];
  if (header.VersionMajor != 1 || header.VersionMinor > 4)
  {
    return Fail(error, "LAS version ", header.VersionMajor, ".", header.VersionMinor,
      " is not supported (1.0 to 1.4 are)");
  }
  header.SystemIdentifier = Text(bytes + SystemIdentifierAt, 32);
  header.GeneratingSoftware = Text(bytes + GeneratingSoftwareAt, 32);
  header.HeaderSize = U16(bytes + HeaderSizeAt);
  header.PointDataOffset = U32(bytes + PointDataOffsetAt);
  header.NumberOfVariableLengthRecords = U32(bytes + NumberOfVLRsAt);
  const std::size_t minimumHeader = MinimumHeaderSize(header.VersionMinor);
  if (header.HeaderSize < minimumHeader)
  {
    return Fail(error, "the header size field says ", header.HeaderSize, " bytes, but a LAS 1.",
      header.VersionMinor, " header has at least ", minimumHeader);
  }
  if (header.HeaderSize > fileSize || size < minimumHeader)
  {
    return Fail(error, "the file ends inside its header: the header size field says ",
      header.HeaderSize, " bytes, the file has ", fileSize);
  }
  if (header.PointDataOffset < header.HeaderSize)
  {
    return Fail(error, "the offset to the point data (", header.PointDataOffset,
      ") lies inside the header (", header.HeaderSize, " bytes)");
  }
  if (header.PointDataOffset > fileSize)
  {
    return Fail(error, "the offset to the point data (", header.PointDataOffset,
      ") lies beyond the end of the file (", fileSize, " bytes)");
  }

  const int formatByte = bytes[PointFormatAt];
  if (formatByte & 0xC0)
  {
    // LASzip marks compressed points by setting bit 7 (and bit 6) of the format.
    return Fail(error, "the points are compressed (LAZ; point format byte ", formatByte,
      "): this reader reads uncompressed LAS only, open the file with the LAZ Point Cloud Reader "
      "(laspy)");
  }
  if (formatByte > 10)
  {
    return Fail(error, "point data record format ", formatByte, " is not a LAS format (0 to 10 are)");
  }
  header.PointFormat = formatByte;
  header.PointRecordLength = U16(bytes + PointRecordLengthAt);
  if (header.PointRecordLength < StandardRecordLength(header.PointFormat))
  {
    return Fail(error, "the point record length (", header.PointRecordLength,
      " bytes) is shorter than point format ", header.PointFormat, "'s ",
      StandardRecordLength(header.PointFormat), " bytes");
  }

  for (int a = 0; a < 3; ++a)
  {
    header.Scale[a] = F64(bytes + ScaleAt + 8 * a);
    header.Offset[a] = F64(bytes + OffsetAt + 8 * a);
    header.Maximum[a] = F64(bytes + BoundsAt + 16 * a);
    header.Minimum[a] = F64(bytes + BoundsAt + 16 * a + 8);
    if (!std::isfinite(header.Scale[a]) || header.Scale[a] == 0 || !std::isfinite(header.Offset[a]))
    {
      return Fail(error, "the ", "xyz"[a], " scale factor (", header.Scale[a], ") or offset (",
        header.Offset[a], ") is not a finite non-zero number");
    }
  }

  header.NumberOfPoints = U32(bytes + LegacyNumberOfPointsAt);
  if (header.VersionMinor >= 4)
  {
    const std::uint64_t count = U64(bytes + NumberOfPointsAt);
    if (count != 0)
    {
      header.NumberOfPoints = count;
    }
  }
  // Divide rather than multiply: an absurd count must not overflow the check.
  const std::uint64_t available = fileSize - header.PointDataOffset;
  if (header.NumberOfPoints > available / header.PointRecordLength)
  {
    return Fail(error, "the header announces ", header.NumberOfPoints, " points of ",
      header.PointRecordLength, " bytes, but the file holds ", available,
      " bytes after the offset to the point data (", header.PointDataOffset,
      "): it is truncated or its header is wrong");
  }
  return true;
}

void nv::las::DecodePoint(const std::uint8_t* record, int format, Point& point)
{
  point.X = I32(record);
  point.Y = I32(record + 4);
  point.Z = I32(record + 8);
  point.Intensity = U16(record + 12);
  const std::uint8_t returns = record[14];
  if (!IsExtendedFormat(format))
  {
    // Formats 0-5: 3-bit return numbers, a 5-bit class with three flags in
    // the same byte, the scan angle in whole degrees.
    point.ReturnNumber = returns & 7;
    point.NumberOfReturns = (returns >> 3) & 7;
    point.ScanDirectionFlag = (returns >> 6) & 1;
    point.EdgeOfFlightLine = (returns >> 7) & 1;
    point.Classification = record[15] & 31;
    point.ClassificationFlags = record[15] >> 5; // synthetic, key-point, withheld
    point.ScannerChannel = 0;
    point.ScanAngle = static_cast<std::int8_t>(record[16]);
    point.UserData = record[17];
    point.PointSourceId = U16(record + 18);
    point.GpsTime = HasGpsTime(format) ? F64(record + 20) : 0.0;
  }
  else
  {
    // Formats 6-10: 4-bit return numbers, flags and channel in their own
    // byte, an 8-bit class, the scan angle in units of 0.006 degree.
    point.ReturnNumber = returns & 15;
    point.NumberOfReturns = returns >> 4;
    const std::uint8_t flags = record[15];
    point.ClassificationFlags = flags & 15;
    point.ScannerChannel = (flags >> 4) & 3;
    point.ScanDirectionFlag = (flags >> 6) & 1;
    point.EdgeOfFlightLine = (flags >> 7) & 1;
    point.Classification = record[16];
    point.UserData = record[17];
    point.ScanAngle = static_cast<float>(I16(record + 18) * 0.006);
    point.PointSourceId = U16(record + 20);
    point.GpsTime = F64(record + 22);
  }
  // Colours follow the GPS time (or the common fields in format 2).
  int colorAt = -1;
  switch (format)
  {
    case 2:
      colorAt = 20;
      break;
    case 3:
    case 5:
      colorAt = 28;
      break;
    case 7:
    case 8:
    case 10:
      colorAt = 30;
      break;
    default:
      break;
  }
  if (colorAt >= 0)
  {
    point.Red = U16(record + colorAt);
    point.Green = U16(record + colorAt + 2);
    point.Blue = U16(record + colorAt + 4);
  }
  point.NearInfrared = HasNearInfrared(format) ? U16(record + 36) : 0;
}

nv::las::ReadResult nv::las::ReadFile(const std::string& fileName, Header& header, Points& points,
  std::string& error, const std::function<bool(double)>& keepGoing)
{
  std::ifstream in(fileName, std::ios::binary);
  if (fileName.empty() || !in)
  {
    error = "Cannot open the LAS file \"" + fileName + "\".";
    return ReadResult::Failed;
  }
  in.seekg(0, std::ios::end);
  const std::streamoff end = in.tellg();
  const std::uint64_t fileSize = end > 0 ? static_cast<std::uint64_t>(end) : 0;
  in.seekg(0);
  std::vector<std::uint8_t> head(static_cast<std::size_t>(std::min<std::uint64_t>(fileSize, MaximumHeaderSize)));
  in.read(reinterpret_cast<char*>(head.data()), static_cast<std::streamsize>(head.size()));
  if (!in || !ParseHeader(head.data(), head.size(), fileSize, header, error))
  {
    error = fileName + ": " + (error.empty() ? "cannot read the header" : error) + ".";
    return ReadResult::Failed;
  }

  // ParseHeader checked that the file holds every announced point, so these
  // arrays are at most a small multiple of the file's size.
  const std::size_t n = static_cast<std::size_t>(header.NumberOfPoints);
  const int format = header.PointFormat;
  const bool extended = IsExtendedFormat(format);
  const bool hasTime = HasGpsTime(format);
  const bool hasColor = HasColor(format);
  const bool hasInfrared = HasNearInfrared(format);
  points = Points();
  points.XYZ.Allocate(3 * n);
  points.Intensity.Allocate(n);
  points.Classification.Allocate(n);
  points.ReturnNumber.Allocate(n);
  points.NumberOfReturns.Allocate(n);
  points.ClassificationFlags.Allocate(n);
  points.ScanDirectionFlag.Allocate(n);
  points.EdgeOfFlightLine.Allocate(n);
  points.UserData.Allocate(n);
  points.ScanAngle.Allocate(n);
  points.PointSourceId.Allocate(n);
  points.ScannerChannel.Allocate(extended ? n : 0);
  points.GpsTime.Allocate(hasTime ? n : 0);
  points.NearInfrared.Allocate(hasInfrared ? n : 0);
  std::vector<std::uint16_t> rgb(hasColor ? 3 * n : 0);

  in.clear();
  in.seekg(static_cast<std::streamoff>(header.PointDataOffset));
  constexpr std::size_t PointsPerChunk = 1 << 16;
  const std::size_t length = header.PointRecordLength;
  std::vector<std::uint8_t> chunk(std::min(n, PointsPerChunk) * length);
  double* xyz = points.XYZ.Values.get();
  Point p;
  for (std::size_t first = 0; first < n; first += PointsPerChunk)
  {
    const std::size_t count = std::min(PointsPerChunk, n - first);
    in.read(reinterpret_cast<char*>(chunk.data()), static_cast<std::streamsize>(count * length));
    if (!in)
    {
      error = fileName + ": the file ends in point " +
        std::to_string(first + static_cast<std::size_t>(in.gcount()) / length) + " of " + std::to_string(n) +
        " (it changed while being read?).";
      points = Points();
      return ReadResult::Failed;
    }
    for (std::size_t k = 0; k < count; ++k)
    {
      const std::size_t i = first + k;
      DecodePoint(chunk.data() + k * length, format, p);
      // The coordinate is the integer times the scale plus the offset, in double.
      xyz[3 * i] = p.X * header.Scale[0] + header.Offset[0];
      xyz[3 * i + 1] = p.Y * header.Scale[1] + header.Offset[1];
      xyz[3 * i + 2] = p.Z * header.Scale[2] + header.Offset[2];
      points.Intensity.Values[i] = p.Intensity;
      points.Classification.Values[i] = p.Classification;
      points.ReturnNumber.Values[i] = p.ReturnNumber;
      points.NumberOfReturns.Values[i] = p.NumberOfReturns;
      points.ClassificationFlags.Values[i] = p.ClassificationFlags;
      points.ScanDirectionFlag.Values[i] = p.ScanDirectionFlag;
      points.EdgeOfFlightLine.Values[i] = p.EdgeOfFlightLine;
      points.UserData.Values[i] = p.UserData;
      points.ScanAngle.Values[i] = p.ScanAngle;
      points.PointSourceId.Values[i] = p.PointSourceId;
      if (extended)
      {
        points.ScannerChannel.Values[i] = p.ScannerChannel;
      }
      if (hasTime)
      {
        points.GpsTime.Values[i] = p.GpsTime;
      }
      if (hasColor)
      {
        rgb[3 * i] = p.Red;
        rgb[3 * i + 1] = p.Green;
        rgb[3 * i + 2] = p.Blue;
      }
      if (hasInfrared)
      {
        points.NearInfrared.Values[i] = p.NearInfrared;
      }
    }
    if (keepGoing && !keepGoing(static_cast<double>(first + count) / static_cast<double>(n)))
    {
      points = Points();
      return ReadResult::Stopped;
    }
  }
  if (hasColor)
  {
    // 16-bit colours to 8 bits, unless the file stores 8-bit values already.
    const bool sixteenBit = std::any_of(rgb.begin(), rgb.end(), [](std::uint16_t c) { return c > 255; });
    points.Colors.Allocate(rgb.size());
    for (std::size_t k = 0; k < rgb.size(); ++k)
    {
      points.Colors.Values[k] = static_cast<std::uint8_t>(sixteenBit ? rgb[k] >> 8 : rgb[k]);
    }
  }
  return ReadResult::Read;
}
