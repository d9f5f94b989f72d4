// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// Small pieces the format readers share: a failure with its message, and
// the words of a header line.
#ifndef nvTextParts_h
#define nvTextParts_h

#include <sstream>
#include <string>
#include <vector>

namespace nv
{
namespace text
{

/// Sets `error` to the parts written one after the other; returns false.
template <typename... Parts>
bool Fail(std::string& error, const Parts&... parts)
{
  std::ostringstream message;
  (message << ... << parts);
  error = message.str();
  return false;
}

/// The words of a line, split at spaces, tabs and carriage returns.
inline std::vector<std::string> Tokens(const std::string& line)
{
  std::vector<std::string> tokens;
  std::size_t at = 0;
  while (true)
  {
    at = line.find_first_not_of(" \t\r", at);
    if (at == std::string::npos)
    {
      break;
    }
    const std::size_t end = line.find_first_of(" \t\r", at);
    tokens.push_back(line.substr(at, end == std::string::npos ? std::string::npos : end - at));
    at = end;
  }
  return tokens;
}

} // namespace text
} // namespace nv

#endif
