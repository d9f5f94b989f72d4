// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvPLY.h"

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

/// A whole decimal integer that fits in 63 bits; `negative` tells a count
/// written with a minus sign, which the user's message names.
bool ParseCount(const std::string& text, std::uint64_t& value, bool& negative)
{
  negative = !text.empty() && text[0] == '-';
  const std::string digits = negative ? text.substr(1) : text;
  if (digits.empty() || digits.size() > 19 || digits.find_first_not_of("0123456789") != std::string::npos)
  {
    return false;
  }
  errno = 0;
  const unsigned long long parsed = std::strtoull(digits.c_str(), nullptr, 10);
  if (errno == ERANGE || parsed > static_cast<unsigned long long>(std::numeric_limits<std::int64_t>::max()))
  {
    return false;
  }
  value = parsed;
  return !negative || parsed == 0;
}

/// `text` as a message quotes it: at most 40 characters, a byte that is not
/// printable text as '?'.
std::string Printable(const std::string& text)
{
  std::string shown = text.substr(0, 40);
  for (char& c : shown)
  {
    const unsigned char byte = static_cast<unsigned char>(c);
    c = byte < 32 || byte > 126 ? '?' : c;
  }
  return shown + (text.size() > 40 ? "..." : "");
}

/// The whole of `text` as a number (strtod's syntax: "1", "-2.5e3", "nan").
bool ParseNumber(const std::string& text, double& value)
{
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return !text.empty() && end == text.c_str() + text.size();
}

bool ParseType(const std::string& name, nv::ply::Type& type)
{
  using nv::ply::Type;
  static const struct
  {
    const char* Name;
    Type Value;
  } names[] = { { "char", Type::Int8 }, { "int8", Type::Int8 }, { "uchar", Type::UInt8 },
    { "uint8", Type::UInt8 }, { "short", Type::Int16 }, { "int16", Type::Int16 },
    { "ushort", Type::UInt16 }, { "uint16", Type::UInt16 }, { "int", Type::Int32 },
    { "int32", Type::Int32 }, { "uint", Type::UInt32 }, { "uint32", Type::UInt32 },
    { "float", Type::Float32 }, { "float32", Type::Float32 }, { "double", Type::Float64 },
    { "float64", Type::Float64 } };
  for (const auto& entry : names)
  {
    if (name == entry.Name)
    {
      type = entry.Value;
      return true;
    }
  }
  return false;
}

bool IsInteger(nv::ply::Type type)
{
  return type != nv::ply::Type::Float32 && type != nv::ply::Type::Float64;
}

/// One binary value of `type` at `bytes`, in the file's byte order.
double BinaryValue(const unsigned char* bytes, nv::ply::Type type, bool bigEndian)
{
  using nv::ply::Type;
  unsigned char value[8];
  const int size = nv::ply::SizeOf(type);
  for (int b = 0; b < size; ++b)
  {
    // The machine's order is little-endian on every platform VTK targets here.
    value[b] = bytes[bigEndian ? size - 1 - b : b];
  }
  auto load = [&value](auto number) {
    std::memcpy(&number, value, sizeof number);
    return static_cast<double>(number);
  };
  switch (type)
  {
    case Type::Int8:
      return load(std::int8_t());
    case Type::UInt8:
      return load(std::uint8_t());
    case Type::Int16:
      return load(std::int16_t());
    case Type::UInt16:
      return load(std::uint16_t());
    case Type::Int32:
      return load(std::int32_t());
    case Type::UInt32:
      return load(std::uint32_t());
    case Type::Float32:
      return load(float());
    default:
      return load(double());
  }
}

/// True if the start of a file that is not a PLY reads as lines of numbers
/// (a point cloud saved as text under a .ply name).
bool LooksLikeTextNumbers(const char* text, std::size_t size)
{
  std::istringstream lines(std::string(text, std::min<std::size_t>(size, 4096)));
  std::string line;
  int numeric = 0;
  for (int read = 0; read < 8 && std::getline(lines, line); ++read)
  {
    for (unsigned char c : line)
    {
      if (c < 32 && c != '\t' && c != '\r')
      {
        return false; // binary bytes
      }
    }
    std::string spaced = line;
    for (char& c : spaced)
    {
      c = (c == ',' || c == ';') ? ' ' : c;
    }
    const std::vector<std::string> tokens = Tokens(spaced);
    double value = 0;
    bool numbers = tokens.size() >= 3;
    for (const std::string& token : tokens)
    {
      numbers = numbers && ParseNumber(token, value);
    }
    numeric += numbers ? 1 : 0;
  }
  return numeric > 0;
}

/// "the vertex element": how the messages name an element.
std::string Describe(const nv::ply::Element& element)
{
  return "the " + Printable(element.Name) + " element";
}

/// Sequential reads of binary data through a buffer, with the position in the file.
class ByteReader
{
public:
  explicit ByteReader(std::istream& in)
    : In(in)
  {
  }

  /// The next `n` bytes (n <= 8), or nullptr at the end of the file.
  const unsigned char* Next(std::size_t n)
  {
    if (this->End - this->At < n)
    {
      std::memmove(this->Buffer.data(), this->Buffer.data() + this->At, this->End - this->At);
      this->End -= this->At;
      this->At = 0;
      this->In.read(reinterpret_cast<char*>(this->Buffer.data() + this->End),
        static_cast<std::streamsize>(this->Buffer.size() - this->End));
      this->End += static_cast<std::size_t>(this->In.gcount());
      if (this->End < n)
      {
        return nullptr;
      }
    }
    const unsigned char* bytes = this->Buffer.data() + this->At;
    this->At += n;
    return bytes;
  }

  /// Skips `n` bytes; false if the file ends first.
  bool Skip(std::uint64_t n)
  {
    const std::uint64_t buffered = this->End - this->At;
    if (n <= buffered)
    {
      this->At += static_cast<std::size_t>(n);
      return true;
    }
    const std::streampos here = this->In.tellg();
    this->In.seekg(0, std::ios::end);
    const std::streampos end = this->In.tellg();
    if (here < 0 || end < 0 || static_cast<std::uint64_t>(end - here) < n - buffered)
    {
      return false;
    }
    this->In.seekg(here + static_cast<std::streamoff>(n - buffered));
    this->At = this->End = 0;
    return true;
  }

private:
  std::istream& In;
  std::vector<unsigned char> Buffer = std::vector<unsigned char>(1 << 16);
  std::size_t At = 0;
  std::size_t End = 0;
};

/// A face's vertex index list, which must name vertices of the file.
bool IsVertexIndexList(const nv::ply::Element& element, const nv::ply::Property& property)
{
  return element.Name == "face" && property.IsList &&
    (property.Name == "vertex_indices" || property.Name == "vertex_index");
}

bool CheckBinaryData(const nv::ply::Header& header, std::istream& data, std::string& error)
{
  using namespace nv::ply;
  const bool bigEndian = header.DataFormat == Format::BinaryBigEndian;
  const int vertex = header.Find("vertex");
  const double vertices = static_cast<double>(header.Elements[vertex].Count);
  ByteReader reader(data);
  for (const Element& element : header.Elements)
  {
    bool lists = false;
    std::uint64_t recordSize = 0;
    for (const Property& property : element.Properties)
    {
      lists = lists || property.IsList;
      recordSize += static_cast<std::uint64_t>(SizeOf(property.ValueType));
    }
    if (!lists)
    {
      // ParseHeader bounded count x recordSize by the file's size.
      if (!reader.Skip(element.Count * recordSize))
      {
        return Fail(error, "the file ends within ", Describe(element), " (", element.Count,
          " records of ", recordSize, " bytes): it is truncated or the count is wrong");
      }
      continue;
    }
    for (std::uint64_t record = 0; record < element.Count; ++record)
    {
      for (const Property& property : element.Properties)
      {
        const int valueSize = SizeOf(property.ValueType);
        std::uint64_t values = 1;
        if (property.IsList)
        {
          const unsigned char* count = reader.Next(static_cast<std::size_t>(SizeOf(property.CountType)));
          const double n = count ? BinaryValue(count, property.CountType, bigEndian) : 0;
          if (!count)
          {
            return Fail(error, "the file ends at record ", record + 1, " of ", element.Count, " of ",
              Describe(element), ": it is truncated or its count is wrong (copy or export the file again)");
          }
          if (n < 0)
          {
            return Fail(error, "record ", record + 1, " of ", Describe(element), " has a list of ", n,
              " values (a negative count): the data is damaged (export the file again)");
          }
          values = static_cast<std::uint64_t>(n);
        }
        const bool indices = IsVertexIndexList(element, property);
        if (!indices)
        {
          if (!reader.Skip(values * static_cast<std::uint64_t>(valueSize)))
          {
            return Fail(error, "the file ends at record ", record + 1, " of ", element.Count, " of ",
              Describe(element), ": it is truncated or a count is wrong (copy or export the file again)");
          }
          continue;
        }
        for (std::uint64_t v = 0; v < values; ++v)
        {
          const unsigned char* value = reader.Next(static_cast<std::size_t>(valueSize));
          if (!value)
          {
            return Fail(error, "the file ends at record ", record + 1, " of ", element.Count, " of ",
              Describe(element), ": it is truncated or a count is wrong (copy or export the file again)");
          }
          const double index = BinaryValue(value, property.ValueType, bigEndian);
          if (!(index >= 0 && index < vertices))
          {
            return Fail(error, "face ", record + 1, " names vertex ", index, ", but the file has ",
              header.Elements[vertex].Count, " vertices (0 to ", header.Elements[vertex].Count - 1,
              "): the data is damaged (export the file again)");
          }
        }
      }
    }
  }
  return true;
}

bool CheckAsciiData(const nv::ply::Header& header, std::istream& data, std::string& error)
{
  using namespace nv::ply;
  const int vertex = header.Find("vertex");
  const double vertices = static_cast<double>(header.Elements[vertex].Count);
  std::string line;
  std::uint64_t lineNumber = header.HeaderLines; // line numbers in the file, as an editor shows them
  for (const Element& element : header.Elements)
  {
    for (std::uint64_t record = 0; record < element.Count; ++record)
    {
      if (!std::getline(data, line))
      {
        return Fail(error, "the file ends after ", record, " of the ", element.Count, " records of ",
          Describe(element), ": it is truncated or its count is wrong (copy or export the file again)");
      }
      if (data.eof())
      {
        // vtkPLYReader aborts on a last record without its newline.
        return Fail(error, "line ", lineNumber + 1, ", the last, has no end of line: the file is truncated (if "
          "it is whole, add a newline at its end)");
      }
      ++lineNumber;
      const std::vector<std::string> tokens = Tokens(line);
      std::size_t at = 0;
      for (const Property& property : element.Properties)
      {
        double value = 0;
        std::uint64_t values = 1;
        if (property.IsList)
        {
          bool negative = false;
          if (at >= tokens.size() || !ParseCount(tokens[at], values, negative))
          {
            return Fail(error, "line ", lineNumber, " (", Describe(element), ", record ", record + 1,
              "): the count of the list ", Printable(property.Name), " is ",
              at < tokens.size() ? "\"" + Printable(tokens[at]) + "\", not a whole number of 0 or more" : "missing");
          }
          ++at;
        }
        for (std::uint64_t v = 0; v < values; ++v, ++at)
        {
          if (at >= tokens.size())
          {
            return Fail(error, "line ", lineNumber, " (", Describe(element), ", record ", record + 1,
              ") holds ", tokens.size(), " values, fewer than the header's properties need");
          }
          if (!ParseNumber(tokens[at], value))
          {
            return Fail(error, "line ", lineNumber, " (", Describe(element), ", record ", record + 1,
              "): \"", Printable(tokens[at]), "\" is not a number (binary data in an ASCII PLY?)");
          }
          if (IsVertexIndexList(element, property) && !(value >= 0 && value < vertices))
          {
            return Fail(error, "line ", lineNumber, ": face ", record + 1, " names vertex ", value,
              ", but the file has ", header.Elements[vertex].Count, " vertices");
          }
        }
      }
    }
  }
  return true;
}
} // namespace

int nv::ply::SizeOf(Type type)
{
  switch (type)
  {
    case Type::Int8:
    case Type::UInt8:
      return 1;
    case Type::Int16:
    case Type::UInt16:
      return 2;
    case Type::Float64:
      return 8;
    default:
      return 4;
  }
}

int nv::ply::Element::Find(const std::string& name) const
{
  for (std::size_t p = 0; p < this->Properties.size(); ++p)
  {
    if (this->Properties[p].Name == name)
    {
      return static_cast<int>(p);
    }
  }
  return -1;
}

int nv::ply::Header::Find(const std::string& name) const
{
  for (std::size_t e = 0; e < this->Elements.size(); ++e)
  {
    if (this->Elements[e].Name == name)
    {
      return static_cast<int>(e);
    }
  }
  return -1;
}

bool nv::ply::ParseHeader(
  const char* text, std::size_t size, std::uint64_t fileSize, Header& header, std::string& error)
{
  header = Header();
  if (fileSize == 0)
  {
    return Fail(error, "the file is empty");
  }
  if (size < 3 || std::memcmp(text, "ply", 3) != 0 ||
    (size > 3 && text[3] != '\n' && text[3] != '\r'))
  {
    if (LooksLikeTextNumbers(text, size))
    {
      return Fail(error, "this is a text file of numbers, not a PLY file (which starts with the line "
                         "\"ply\"); if its lines are points (x y z), rename it .xyz to read it as a text "
                         "point cloud");
    }
    return Fail(error, "not a PLY file: it does not start with the line \"ply\"");
  }
  bool haveFormat = false, ended = false;
  std::size_t at = 0;
  int lineNumber = 0;
  while (at < size && !ended)
  {
    const char* newline = static_cast<const char*>(std::memchr(text + at, '\n', size - at));
    if (!newline)
    {
      break;
    }
    const std::string line(text + at, newline);
    at = static_cast<std::size_t>(newline - text) + 1;
    ++lineNumber;
    const std::vector<std::string> tokens = Tokens(line);
    if (tokens.empty())
    {
      // vtkPLYReader crashes on an empty header line.
      return Fail(error, "header line ", lineNumber, " is empty: a PLY header has no empty lines");
    }
    if (lineNumber == 1 || tokens[0] == "comment" || tokens[0] == "obj_info")
    {
      continue;
    }
    const std::string& key = tokens[0];
    if (key == "format")
    {
      const std::string kind = tokens.size() > 1 ? tokens[1] : "";
      if (kind == "ascii")
      {
        header.DataFormat = Format::Ascii;
      }
      else if (kind == "binary_little_endian")
      {
        header.DataFormat = Format::BinaryLittleEndian;
      }
      else if (kind == "binary_big_endian")
      {
        header.DataFormat = Format::BinaryBigEndian;
      }
      else
      {
        return Fail(error, "header line ", lineNumber, ": format \"", Printable(kind),
          "\" is not ascii, binary_little_endian or binary_big_endian");
      }
      haveFormat = true;
    }
    else if (key == "element")
    {
      if (tokens.size() != 3)
      {
        return Fail(error, "header line ", lineNumber, ": an element line is \"element NAME COUNT\"");
      }
      Element element;
      element.Name = tokens[1];
      bool negative = false;
      if (!ParseCount(tokens[2], element.Count, negative))
      {
        return Fail(error, "header line ", lineNumber, ": the count of the ", Printable(element.Name),
          " element, ", Printable(tokens[2]), ", is ", negative ? "negative" : "not a whole number",
          " (the header is damaged)");
      }
      header.Elements.push_back(element);
    }
    else if (key == "property")
    {
      if (header.Elements.empty())
      {
        return Fail(error, "header line ", lineNumber, ": a property before any element");
      }
      Property property;
      const bool list = tokens.size() > 1 && tokens[1] == "list";
      if (tokens.size() != (list ? 5u : 3u))
      {
        return Fail(error, "header line ", lineNumber,
          ": a property line is \"property TYPE NAME\" or \"property list COUNT_TYPE TYPE NAME\"");
      }
      property.IsList = list;
      const std::string& valueType = tokens[list ? 3 : 1];
      if ((list && !ParseType(tokens[2], property.CountType)) || !ParseType(valueType, property.ValueType))
      {
        return Fail(error, "header line ", lineNumber, ": unknown type \"",
          Printable(list && !ParseType(tokens[2], property.CountType) ? tokens[2] : valueType),
          "\" (char, uchar, short, ushort, int, uint, float, double or int8 ... float64)");
      }
      if (list && !IsInteger(property.CountType))
      {
        return Fail(error, "header line ", lineNumber, ": the count of the list ", Printable(tokens[4]),
          " has the type ", Printable(tokens[2]), ", not a whole-number type");
      }
      property.Name = tokens[list ? 4 : 2];
      header.Elements.back().Properties.push_back(property);
    }
    else if (key == "end_header")
    {
      ended = true;
      header.HeaderLines = static_cast<std::size_t>(lineNumber);
    }
    else
    {
      return Fail(error, "header line ", lineNumber, ": unknown keyword \"", Printable(key),
        "\" (a PLY header has format, element, property, comment, obj_info and end_header lines)");
    }
  }
  if (!ended)
  {
    if (size < fileSize && size >= MaximumHeaderSize)
    {
      return Fail(error, "the header has no end_header line in its first ", size, " bytes");
    }
    return Fail(error, "the header does not end: the file has no end_header line");
  }
  if (!haveFormat)
  {
    return Fail(error, "the header has no format line");
  }
  header.DataOffset = at;

  const int vertex = header.Find("vertex");
  if (vertex < 0)
  {
    std::string names;
    for (const Element& element : header.Elements)
    {
      names += (names.empty() ? "" : ", ") + Printable(element.Name);
    }
    return Fail(error, "the file has no vertex element (no points)",
      names.empty() ? std::string() : "; it holds only " + names);
  }
  for (const char* axis : { "x", "y", "z" })
  {
    const int p = header.Elements[vertex].Find(axis);
    if (p < 0)
    {
      return Fail(error, "the vertex element has no ", axis, " property: a point needs x, y and z");
    }
    if (header.Elements[vertex].Properties[p].IsList)
    {
      return Fail(error, "the vertex element's ", axis, " property is a list, not one value");
    }
  }

  // vtkPLYReader reads the corners of faces from this list, whatever it finds.
  const int face = header.Find("face");
  if (face >= 0 && header.Elements[face].Count > 0)
  {
    const Element& faces = header.Elements[face];
    int corners = faces.Find("vertex_indices");
    corners = corners >= 0 ? corners : faces.Find("vertex_index");
    if (corners < 0 || !faces.Properties[corners].IsList)
    {
      return Fail(error, "the face element has no vertex_indices list (the corners of each face)");
    }
  }

  // The least the data can take: binary values and list counts at their
  // sizes (lists may be empty), ASCII values at 2 bytes ("0" and a space).
  const std::uint64_t available = fileSize - header.DataOffset;
  std::uint64_t needed = 0;
  for (const Element& element : header.Elements)
  {
    if (element.Count > 0 && element.Properties.empty())
    {
      return Fail(error, Describe(element), " has ", element.Count, " records but no properties");
    }
    std::uint64_t least = 0;
    for (const Property& property : element.Properties)
    {
      least += header.DataFormat == Format::Ascii
        ? 2
        : static_cast<std::uint64_t>(SizeOf(property.IsList ? property.CountType : property.ValueType));
    }
    if (least > 0 && element.Count > (available - needed) / least)
    {
      return Fail(error, "the header announces ", element.Count, " records of ", Describe(element), " (at least ", element.Count, " x ", least, " bytes), but the file holds ", available,
        " bytes after its header: it is truncated or the count is wrong (copy or export the file again)");
    }
    needed += element.Count * least;
  }
  return true;
}

bool nv::ply::CheckData(const Header& header, std::istream& data, std::string& error)
{
  return header.DataFormat == Format::Ascii ? CheckAsciiData(header, data, error)
                                            : CheckBinaryData(header, data, error);
}

namespace
{
/// ParseHeader and CheckData on a stream that holds a whole file.
bool CheckStream(std::istream& in, std::string& error)
{
  in.seekg(0, std::ios::end);
  const std::streamoff end = in.tellg();
  in.seekg(0);
  if (end < 0)
  {
    return Fail(error, "cannot read the file");
  }
  const std::uint64_t fileSize = static_cast<std::uint64_t>(end);
  std::vector<char> head(
    static_cast<std::size_t>(std::min<std::uint64_t>(fileSize, nv::ply::MaximumHeaderSize)));
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  nv::ply::Header header;
  if (!in || !nv::ply::ParseHeader(head.data(), head.size(), fileSize, header, error))
  {
    return error.empty() ? Fail(error, "cannot read the header") : false;
  }
  in.clear();
  in.seekg(static_cast<std::streamoff>(header.DataOffset));
  return nv::ply::CheckData(header, in, error);
}
} // namespace

bool nv::ply::CheckFile(const std::string& path, std::string& error)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    return Fail(error, "cannot open the file");
  }
  return CheckStream(in, error);
}

bool nv::ply::CheckText(const std::string& text, std::string& error)
{
  std::istringstream in(text, std::ios::binary);
  return CheckStream(in, error);
}
