// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nvTextCloud.h"

#include <cctype>
#include <cstdlib>
#include <cstring>

namespace
{
/// Bytes that split fields: ASCII white space (Python's str.split), commas
/// and semicolons (a CSV of a locale whose decimal mark is the comma).
bool IsSeparator(unsigned char c)
{
  return c == ' ' || c == '\t' || c == '\v' || c == '\f' || c == '\r' || (c >= 0x1c && c <= 0x1f) || c == ',' ||
    c == ';';
}

/// The length of the line break at `at` (0 where there is none): \r\n, and
/// the single breaks of str.splitlines, ASCII and UTF-8 (NEL, LS, PS).
std::size_t LineBreak(const char* text, std::size_t size, std::size_t at)
{
  const unsigned char c = static_cast<unsigned char>(text[at]);
  if (c == '\r')
  {
    return at + 1 < size && text[at + 1] == '\n' ? 2 : 1;
  }
  if (c == '\n' || c == '\v' || c == '\f' || (c >= 0x1c && c <= 0x1e))
  {
    return 1;
  }
  const auto byte = [&](std::size_t k) { return at + k < size ? static_cast<unsigned char>(text[at + k]) : 0; };
  if (c == 0xc2 && byte(1) == 0x85)
  {
    return 2;
  }
  if (c == 0xe2 && byte(1) == 0x80 && (byte(2) == 0xa8 || byte(2) == 0xa9))
  {
    return 3;
  }
  return 0;
}

/// Whether the bytes are UTF-8 without NUL (what Python decodes without a
/// replacement character).
bool IsText(const char* text, std::size_t size)
{
  for (std::size_t i = 0; i < size;)
  {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c == 0)
    {
      return false;
    }
    std::size_t more = c < 0x80 ? 0 : (c >> 5) == 0x6 ? 1 : (c >> 4) == 0xe ? 2 : (c >> 3) == 0x1e ? 3 : 4;
    if (more == 4 || (more == 1 && c < 0xc2) || (more == 3 && c > 0xf4) || i + more >= size + (more ? 0 : 1))
    {
      return false;
    }
    for (std::size_t k = 1; k <= more; ++k)
    {
      if ((static_cast<unsigned char>(text[i + k]) & 0xc0) != 0x80)
      {
        return false;
      }
    }
    if (more >= 2)
    {
      const unsigned char next = static_cast<unsigned char>(text[i + 1]);
      if ((c == 0xe0 && next < 0xa0) || (c == 0xed && next >= 0xa0) || (c == 0xf0 && next < 0x90) ||
        (c == 0xf4 && next >= 0x90))
      {
        return false; // overlong, a surrogate, or past U+10FFFF
      }
    }
    i += more + 1;
  }
  return true;
}

} // namespace

bool nv::text::ParseNumber(const std::string& field, double& value)
{
  // Python's float(): decimal only (no hexadecimal, no "nan(...)"), and "_"
  // only between two digits.
  std::string digits;
  digits.reserve(field.size());
  for (std::size_t i = 0; i < field.size(); ++i)
  {
    const char c = field[i];
    if (c == 'x' || c == 'X' || c == '(' || c == 'p' || c == 'P')
    {
      return false;
    }
    if (c == '_')
    {
      if (i == 0 || i + 1 == field.size() || !std::isdigit(static_cast<unsigned char>(field[i - 1])) ||
        !std::isdigit(static_cast<unsigned char>(field[i + 1])))
      {
        return false;
      }
      continue;
    }
    digits += c;
  }
  if (digits.empty() || std::isspace(static_cast<unsigned char>(digits[0])))
  {
    return false;
  }
  char* end = nullptr;
  value = std::strtod(digits.c_str(), &end);
  return end == digits.c_str() + digits.size();
}

nv::text::LineKind nv::text::ReadLine(
  const char* line, std::size_t size, std::vector<double>& values, std::size_t* fields)
{
  values.clear();
  std::size_t at = 0;
  std::size_t count = 0;
  bool numbers = true; // the fields so far
  std::string field;
  while (at < size)
  {
    while (at < size && IsSeparator(static_cast<unsigned char>(line[at])))
    {
      ++at;
    }
    if (at == size)
    {
      break;
    }
    std::size_t end = at;
    while (end < size && !IsSeparator(static_cast<unsigned char>(line[end])))
    {
      ++end;
    }
    field.assign(line + at, end - at);
    at = end;
    if (count == 0 && (field[0] == '#' || field.compare(0, 2, "//") == 0))
    {
      return LineKind::Comment;
    }
    ++count;
    double value = 0.0;
    if (numbers && ParseNumber(field, value))
    {
      values.push_back(value);
    }
    else
    {
      numbers = false;
      if (count <= 3)
      {
        return LineKind::Words;
      }
    }
  }
  if (fields)
  {
    *fields = count;
  }
  if (count == 0)
  {
    return LineKind::Comment;
  }
  if (count >= 3)
  {
    return LineKind::Point;
  }
  return count == 1 ? LineKind::Count : LineKind::Short;
}

bool nv::text::ReadCloudPoints(const char* text, std::size_t size, std::vector<double>& xyz, CloudProblem& problem)
{
  xyz.clear();
  std::size_t lineNumber = 0;
  std::vector<double> values;
  for (std::size_t start = 0; start < size;)
  {
    std::size_t end = start;
    std::size_t breakSize = 0;
    while (end < size && (breakSize = LineBreak(text, size, end)) == 0)
    {
      ++end;
    }
    ++lineNumber;
    const char* line = text + start;
    const std::size_t length = end - start;
    start = end + breakSize;
    const LineKind kind = ReadLine(line, length, values);
    if (kind == LineKind::Comment)
    {
      continue;
    }
    if (kind == LineKind::Point)
    {
      xyz.insert(xyz.end(), values.begin(), values.begin() + 3);
    }
    else if (xyz.empty() && kind != LineKind::Short)
    {
      continue; // a header line, or a .pts file's point count
    }
    else
    {
      problem.Line = lineNumber;
      problem.Text.assign(line, length);
      return false;
    }
  }
  if (xyz.empty())
  {
    problem.Line = 0;
    problem.Lines = lineNumber;
    problem.Binary = !IsText(text, size);
    return false;
  }
  return true;
}
