// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvPCD.h"

#include "nvLZF.h"
#include "nvTextParts.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

namespace
{
using nv::text::Fail;
using nv::text::Tokens;

// Limits that no real cloud reaches, so that a damaged header cannot make
// the reader allocate without bound.
constexpr std::size_t MaximumFields = 4096;
constexpr int MaximumCount = 1 << 20;
constexpr std::size_t MaximumPointSize = 1 << 24;

/// A whole non-negative decimal integer, at most `maximum`.
bool ParseUnsigned(const std::string& text, std::uint64_t maximum, std::uint64_t& value)
{
  if (text.empty() || text.size() > 20 || text.find_first_not_of("0123456789") != std::string::npos)
  {
    return false;
  }
  errno = 0;
  const unsigned long long parsed = std::strtoull(text.c_str(), nullptr, 10);
  if (errno == ERANGE || parsed > maximum)
  {
    return false;
  }
  value = parsed;
  return true;
}

template <typename T>
void Store(T value, std::uint8_t* destination)
{
  std::memcpy(destination, &value, sizeof value);
}

template <typename T>
T Load(const std::uint8_t* source)
{
  T value;
  std::memcpy(&value, source, sizeof value);
  return value;
}

/// Packed records: each field at its offset, one record after the other.
void PackedLayout(const nv::pcd::Header& header, nv::pcd::Data& data)
{
  for (const nv::pcd::Field& field : header.Fields)
  {
    data.Start.push_back(static_cast<std::int64_t>(field.Offset));
    data.Stride.push_back(header.PointSize);
  }
}

/// "rgb (F4)": a field as the messages name it.
std::string Describe(const nv::pcd::Field& field)
{
  std::ostringstream text;
  text << field.Name << " (" << field.Type << field.Size << ")";
  return text.str();
}
} // namespace

int nv::pcd::Header::Find(const std::string& name) const
{
  for (std::size_t f = 0; f < this->Fields.size(); ++f)
  {
    if (this->Fields[f].Name == name)
    {
      return static_cast<int>(f);
    }
  }
  return -1;
}

bool nv::pcd::ParseHeader(
  const char* text, std::size_t size, std::uint64_t fileSize, Header& header, std::string& error)
{
  header = Header();
  bool haveFields = false, haveSize = false, haveType = false, haveWidth = false, havePoints = false,
       haveData = false;
  std::size_t at = 0;
  int lineNumber = 0;
  while (at < size && !haveData)
  {
    const char* newline = static_cast<const char*>(std::memchr(text + at, '\n', size - at));
    if (!newline && size < fileSize)
    {
      return Fail(error, "the header ends without a DATA line in its first ", size, " bytes");
    }
    // The last line of a file may lack its newline.
    const char* end = newline ? newline : text + size;
    const std::string line(text + at, end);
    at = static_cast<std::size_t>(end - text) + (newline ? 1 : 0);
    ++lineNumber;
    const std::vector<std::string> tokens = Tokens(line);
    if (tokens.empty() || tokens[0][0] == '#')
    {
      continue;
    }
    const std::string& key = tokens[0];
    const std::size_t values = tokens.size() - 1;
    auto perField = [&](const char* what) {
      if (!haveFields)
      {
        return Fail(error, "header line ", lineNumber, ": ", what, " comes before FIELDS");
      }
      if (values != header.Fields.size())
      {
        return Fail(error, "header line ", lineNumber, ": ", values, " ", what, " entries for ",
          header.Fields.size(), " FIELDS");
      }
      return true;
    };
    if (key == "VERSION")
    {
      header.Version = values ? tokens[1] : "";
    }
    else if (key == "FIELDS" || key == "COLUMNS")
    {
      if (values == 0 || values > MaximumFields)
      {
        return Fail(error, "header line ", lineNumber, ": ", values, " FIELDS (1 to ", MaximumFields,
          " are possible)");
      }
      header.Fields.assign(values, Field());
      for (std::size_t f = 0; f < values; ++f)
      {
        header.Fields[f].Name = tokens[f + 1];
      }
      haveFields = true;
    }
    else if (key == "SIZE")
    {
      if (!perField("SIZE"))
      {
        return false;
      }
      for (std::size_t f = 0; f < values; ++f)
      {
        const std::string& s = tokens[f + 1];
        if (s != "1" && s != "2" && s != "4" && s != "8")
        {
          return Fail(error, "header line ", lineNumber, ": SIZE ", s, " of field ",
            header.Fields[f].Name, " is not 1, 2, 4 or 8");
        }
        header.Fields[f].Size = s[0] - '0';
      }
      haveSize = true;
    }
    else if (key == "TYPE")
    {
      if (!perField("TYPE"))
      {
        return false;
      }
      for (std::size_t f = 0; f < values; ++f)
      {
        const std::string& t = tokens[f + 1];
        if (t != "I" && t != "U" && t != "F")
        {
          return Fail(error, "header line ", lineNumber, ": TYPE ", t, " of field ",
            header.Fields[f].Name, " is not I, U or F");
        }
        header.Fields[f].Type = t[0];
      }
      haveType = true;
    }
    else if (key == "COUNT")
    {
      if (!perField("COUNT"))
      {
        return false;
      }
      for (std::size_t f = 0; f < values; ++f)
      {
        std::uint64_t count = 0;
        if (!ParseUnsigned(tokens[f + 1], MaximumCount, count) || count == 0)
        {
          return Fail(error, "header line ", lineNumber, ": COUNT ", tokens[f + 1], " of field ",
            header.Fields[f].Name, " is not a whole number from 1 to ", MaximumCount);
        }
        header.Fields[f].Count = static_cast<int>(count);
      }
    }
    else if (key == "WIDTH" || key == "HEIGHT" || key == "POINTS")
    {
      std::uint64_t value = 0;
      if (values != 1 || !ParseUnsigned(tokens[1], std::numeric_limits<std::int64_t>::max(), value))
      {
        return Fail(error, "header line ", lineNumber, ": ", key, " is not one whole number");
      }
      (key == "WIDTH" ? header.Width : key == "HEIGHT" ? header.Height : header.Points) = value;
      haveWidth = haveWidth || key == "WIDTH";
      havePoints = havePoints || key == "POINTS";
    }
    else if (key == "VIEWPOINT")
    {
      if (values != 7)
      {
        return Fail(error, "header line ", lineNumber, ": VIEWPOINT has ", values,
          " numbers instead of 7 (tx ty tz qw qx qy qz)");
      }
      for (int k = 0; k < 7; ++k)
      {
        header.Viewpoint[k] = std::strtod(tokens[k + 1].c_str(), nullptr);
      }
    }
    else if (key == "DATA")
    {
      const std::string kind = values ? tokens[1] : "";
      if (kind == "ascii")
      {
        header.Data = Encoding::Ascii;
      }
      else if (kind == "binary")
      {
        header.Data = Encoding::Binary;
      }
      else if (kind == "binary_compressed")
      {
        header.Data = Encoding::BinaryCompressed;
      }
      else
      {
        return Fail(error, "header line ", lineNumber, ": DATA \"", kind,
          "\" is not ascii, binary or binary_compressed");
      }
      haveData = true;
    }
    else
    {
      return Fail(error, "header line ", lineNumber, ": unknown keyword \"", key,
        "\" (a PCD header has VERSION, FIELDS, SIZE, TYPE, COUNT, WIDTH, HEIGHT, VIEWPOINT, "
        "POINTS and DATA)");
    }
  }
  if (!haveData)
  {
    return Fail(error, "the header ends without a DATA line");
  }
  if (!haveFields || !haveSize || !haveType)
  {
    return Fail(error, "the header lacks ", !haveFields ? "FIELDS" : !haveSize ? "SIZE" : "TYPE");
  }
  header.DataOffset = at;

  // Field layout and the record size, with the limits checked as we go.
  for (Field& field : header.Fields)
  {
    if (field.Type == 'F' && field.Size != 4 && field.Size != 8)
    {
      return Fail(error, "field ", field.Name, " is of TYPE F with SIZE ", field.Size,
        " (floating point values have 4 or 8 bytes)");
    }
    field.Offset = header.PointSize;
    header.PointSize += field.Bytes();
    header.ValuesPerPoint += field.Count;
    if (header.PointSize > MaximumPointSize)
    {
      return Fail(error, "a point would take more than ", MaximumPointSize, " bytes");
    }
  }
  for (const char* axis : { "x", "y", "z" })
  {
    const int f = header.Find(axis);
    if (f < 0 || header.Fields[f].Count != 1)
    {
      return Fail(error, "the FIELDS have no ", axis, " coordinate (of COUNT 1)");
    }
  }

  // The number of points: POINTS, WIDTH x HEIGHT, or both, which must agree.
  if (!haveWidth && !havePoints)
  {
    return Fail(error, "the header has neither POINTS nor WIDTH");
  }
  // As PCL reads them: no HEIGHT (or 0) is an unorganized cloud, WIDTH and
  // HEIGHT both 0 (old writers) mean POINTS x 1.
  if (haveWidth && header.Width == 0 && header.Height == 0 && havePoints)
  {
    header.Width = header.Points;
  }
  if (header.Height == 0)
  {
    header.Height = 1;
  }
  if (!haveWidth)
  {
    header.Width = header.Points;
  }
  const bool productFits = header.Height == 0 ||
    header.Width <= static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()) / header.Height;
  if (!productFits)
  {
    return Fail(error, "WIDTH ", header.Width, " x HEIGHT ", header.Height, " overflows");
  }
  if (!havePoints)
  {
    header.Points = header.Width * header.Height;
  }
  else if (header.Points != header.Width * header.Height)
  {
    return Fail(error, "POINTS (", header.Points, ") is not WIDTH x HEIGHT (", header.Width, " x ",
      header.Height, ")");
  }

  // Can the file hold that many points? (Divisions: the counts may be absurd.)
  const std::uint64_t remaining = fileSize > header.DataOffset ? fileSize - header.DataOffset : 0;
  if (header.Data == Encoding::Binary && header.Points > remaining / header.PointSize)
  {
    return Fail(error, "the header announces ", header.Points, " points of ", header.PointSize,
      " bytes, but the file holds ", remaining, " bytes of binary data: it is truncated or its header is wrong");
  }
  if (header.Data == Encoding::Ascii && header.Points > (remaining + 1) / (2 * header.ValuesPerPoint))
  {
    // Every value takes at least one character and one separator.
    return Fail(error, "the header announces ", header.Points, " points of ", header.ValuesPerPoint,
      " values, more than the ", remaining, " bytes of ascii data can hold: it is truncated or its header is wrong");
  }
  if (header.Data == Encoding::BinaryCompressed && header.Points > 0 && remaining < 8)
  {
    return Fail(error, "the file ends before the sizes of its compressed data");
  }
  return true;
}

bool nv::pcd::CheckCompressedSizes(const Header& header, std::uint64_t compressedSize,
  std::uint64_t uncompressedSize, std::uint64_t fileSize, ColumnLayout& layout, std::string& error)
{
  const std::uint64_t remaining =
    fileSize > header.DataOffset + 8 ? fileSize - header.DataOffset - 8 : 0;
  if (compressedSize > remaining)
  {
    return Fail(error, "the compressed data is said to take ", compressedSize,
      " bytes, but the file holds ", remaining, " after the header: it is truncated or its header is wrong");
  }
  std::size_t withoutPadding = 0;
  for (const Field& field : header.Fields)
  {
    withoutPadding += field.IsPadding() ? 0 : field.Bytes();
  }
  // Points x bytes per point, without overflow (the points fit in int64).
  auto size = [&](std::size_t pointSize) {
    return pointSize == 0 || header.Points <= std::numeric_limits<std::uint64_t>::max() / pointSize
      ? header.Points * pointSize
      : std::numeric_limits<std::uint64_t>::max();
  };
  const bool withPadding = uncompressedSize == size(header.PointSize);
  if (!withPadding && uncompressedSize != size(withoutPadding))
  {
    return Fail(error, "the compressed data decompresses to ", uncompressedSize, " bytes, but ",
      header.Points, " points of ", header.PointSize, " bytes take ", size(header.PointSize));
  }
  if (uncompressedSize / LZFMaximumRatio > compressedSize)
  {
    return Fail(error, "the compressed data (", compressedSize, " bytes) cannot decompress to the ",
      uncompressedSize, " bytes it announces");
  }
  layout.ColumnStart.assign(header.Fields.size(), -1);
  std::uint64_t start = 0;
  for (std::size_t f = 0; f < header.Fields.size(); ++f)
  {
    if (header.Fields[f].IsPadding() && !withPadding)
    {
      continue;
    }
    layout.ColumnStart[f] = static_cast<std::int64_t>(start);
    start += header.Points * header.Fields[f].Bytes();
  }
  return true;
}

bool nv::pcd::ParseAsciiValue(const std::string& text, const Field& field, std::uint8_t* destination)
{
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  const bool packedColor = (field.Name == "rgb" || field.Name == "rgba") && field.Size == 4;
  if (field.Type == 'F' && packedColor && !text.empty() &&
    text.find_first_not_of("0123456789") == std::string::npos)
  {
    // PCL writes the packed colour of its float "rgb" field as the unsigned
    // integer of its bits in ascii files (opaque colours are NaN as floats).
    Field asInteger = field;
    asInteger.Type = 'U';
    return ParseAsciiValue(text, asInteger, destination);
  }
  if (field.Type == 'F')
  {
    const double value = std::strtod(begin, &end);
    if (end == begin || *end != '\0')
    {
      return false;
    }
    if (field.Size == 4)
    {
      Store(static_cast<float>(value), destination);
    }
    else
    {
      Store(value, destination);
    }
    return true;
  }
  if (field.Type == 'U')
  {
    if (text[0] == '-')
    {
      return false;
    }
    const unsigned long long value = std::strtoull(begin, &end, 10);
    const unsigned long long maximum =
      field.Size == 8 ? std::numeric_limits<std::uint64_t>::max() : (1ull << (8 * field.Size)) - 1;
    if (end == begin || *end != '\0' || errno == ERANGE || value > maximum)
    {
      return false;
    }
    switch (field.Size)
    {
      case 1:
        Store(static_cast<std::uint8_t>(value), destination);
        break;
      case 2:
        Store(static_cast<std::uint16_t>(value), destination);
        break;
      case 4:
        Store(static_cast<std::uint32_t>(value), destination);
        break;
      default:
        Store(static_cast<std::uint64_t>(value), destination);
    }
    return true;
  }
  const long long value = std::strtoll(begin, &end, 10);
  const long long maximum =
    field.Size == 8 ? std::numeric_limits<std::int64_t>::max() : (1ll << (8 * field.Size - 1)) - 1;
  if (end == begin || *end != '\0' || errno == ERANGE || value > maximum || value < -maximum - 1)
  {
    return false;
  }
  switch (field.Size)
  {
    case 1:
      Store(static_cast<std::int8_t>(value), destination);
      break;
    case 2:
      Store(static_cast<std::int16_t>(value), destination);
      break;
    case 4:
      Store(static_cast<std::int32_t>(value), destination);
      break;
    default:
      Store(static_cast<std::int64_t>(value), destination);
  }
  return true;
}

double nv::pcd::ValueAsDouble(const std::uint8_t* value, const Field& field)
{
  switch (field.Type)
  {
    case 'F':
      return field.Size == 4 ? Load<float>(value) : Load<double>(value);
    case 'U':
      switch (field.Size)
      {
        case 1:
          return value[0];
        case 2:
          return Load<std::uint16_t>(value);
        case 4:
          return Load<std::uint32_t>(value);
        default:
          return static_cast<double>(Load<std::uint64_t>(value));
      }
    default:
      switch (field.Size)
      {
        case 1:
          return static_cast<std::int8_t>(value[0]);
        case 2:
          return Load<std::int16_t>(value);
        case 4:
          return Load<std::int32_t>(value);
        default:
          return static_cast<double>(Load<std::int64_t>(value));
      }
  }
}

nv::pcd::ReadResult nv::pcd::ReadFile(const std::string& fileName, Header& header, Data& data,
  std::string& error, const std::function<bool(double)>& keepGoing)
{
  std::ifstream in(fileName, std::ios::binary);
  if (fileName.empty() || !in)
  {
    error = "Cannot open the PCD file \"" + fileName + "\".";
    return ReadResult::Failed;
  }
  in.seekg(0, std::ios::end);
  const std::streamoff end = in.tellg();
  const std::uint64_t fileSize = end > 0 ? static_cast<std::uint64_t>(end) : 0;
  in.seekg(0);
  std::vector<char> head(static_cast<std::size_t>(std::min<std::uint64_t>(fileSize, MaximumHeaderSize)));
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  if (!in || !ParseHeader(head.data(), head.size(), fileSize, header, error))
  {
    error = fileName + ": " + (error.empty() ? "cannot read the header" : error) + ".";
    return ReadResult::Failed;
  }
  auto fail = [&](const std::string& what) {
    error = fileName + ": " + what + ".";
    return ReadResult::Failed;
  };
  const std::uint64_t n = header.Points;
  in.clear();
  in.seekg(static_cast<std::streamoff>(header.DataOffset));
  data = Data();
  if (n == 0)
  {
    PackedLayout(header, data);
  }
  else if (header.Data == Encoding::Binary)
  {
    data.Bytes.resize(static_cast<std::size_t>(n) * header.PointSize);
    in.read(reinterpret_cast<char*>(data.Bytes.data()), static_cast<std::streamsize>(data.Bytes.size()));
    if (!in)
    {
      return fail("the binary data ends early (the file changed while being read?)");
    }
    PackedLayout(header, data);
  }
  else if (header.Data == Encoding::BinaryCompressed)
  {
    std::uint8_t sizes[8];
    in.read(reinterpret_cast<char*>(sizes), 8);
    std::uint32_t compressedSize, uncompressedSize;
    std::memcpy(&compressedSize, sizes, 4);
    std::memcpy(&uncompressedSize, sizes + 4, 4);
    ColumnLayout layout;
    if (!in || !CheckCompressedSizes(header, compressedSize, uncompressedSize, fileSize, layout, error))
    {
      return fail(error.empty() ? "cannot read the sizes of the compressed data" : error);
    }
    std::vector<std::uint8_t> compressed(compressedSize);
    in.read(reinterpret_cast<char*>(compressed.data()), compressedSize);
    data.Bytes.resize(uncompressedSize);
    if (!in || !LZFDecompress(compressed.data(), compressed.size(), data.Bytes.data(), data.Bytes.size()))
    {
      return fail("the compressed (LZF) data is damaged: it does not decompress to the " +
        std::to_string(uncompressedSize) + " bytes it announces");
    }
    data.Start = layout.ColumnStart;
    for (const Field& field : header.Fields)
    {
      data.Stride.push_back(field.Bytes());
    }
  }
  else
  {
    // ascii: one point per line, the fields' values in order.
    data.Bytes.resize(static_cast<std::size_t>(n) * header.PointSize);
    PackedLayout(header, data);
    const long headerLines = static_cast<long>(std::count(head.begin(), head.begin() + header.DataOffset, '\n'));
    long lineNumber = headerLines;
    std::string line, token;
    for (std::uint64_t i = 0; i < n;)
    {
      if (!std::getline(in, line))
      {
        return fail("the ascii data ends after " + std::to_string(i) + " of the " + std::to_string(n) +
          " points the header announces");
      }
      ++lineNumber;
      std::istringstream values(line);
      std::vector<std::string> tokens;
      while (values >> token)
      {
        tokens.push_back(token);
      }
      if (tokens.empty())
      {
        continue;
      }
      if (tokens.size() != header.ValuesPerPoint)
      {
        return fail("line " + std::to_string(lineNumber) + " holds " + std::to_string(tokens.size()) +
          " values where the fields have " + std::to_string(header.ValuesPerPoint));
      }
      std::size_t t = 0;
      std::uint8_t* record = data.Bytes.data() + static_cast<std::size_t>(i) * header.PointSize;
      for (const Field& field : header.Fields)
      {
        for (int c = 0; c < field.Count; ++c, ++t)
        {
          if (!ParseAsciiValue(tokens[t], field, record + field.Offset + c * field.Size))
          {
            return fail("line " + std::to_string(lineNumber) + ": \"" + tokens[t] +
              "\" is not a value of field " + Describe(field));
          }
        }
      }
      ++i;
      if (i % 65536 == 0 && keepGoing && !keepGoing(static_cast<double>(i) / n))
      {
        return ReadResult::Stopped;
      }
    }
  }
  return ReadResult::Read;
}
