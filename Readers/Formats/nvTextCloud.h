// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// Plain-text point clouds (.xyz, .txt, .csv): the one rule of every route
// (the pip package's command line, vtkPointCloudTextReader in ParaView, the
// CMake build's package and C++), which the formats page states.
//
// - Fields split at white space, commas and semicolons.
// - A line that is blank, or whose first field starts with # or //, is a
//   comment.
// - A point: x y z in the first three fields, all numbers. The numbers that
//   follow, up to the first field that is not one, are the row's further
//   columns (vtkPointCloudTextReader makes arrays of those every row has;
//   the pip package reads the points only); a text column ends them.
// - Before the first point, a line whose first three fields are not all
//   numbers is a header line (column names), and a line of one number is a
//   .pts file's point count: both are skipped.
// - After the first point, such a line, and anywhere a line of two numbers,
//   is an error naming the line.
// Numbers are decimal as Python's float() writes and reads them ("1.5e-3",
// "nan", "inf"; digits grouped by "_").
#ifndef nvTextCloud_h
#define nvTextCloud_h

#include <cstddef>
#include <string>
#include <vector>

namespace nv
{
namespace text
{
/// Why a text is not a point cloud: the line that is not a point (its
/// number from 1 and its bytes), or, with Line 0, that no line is one.
struct CloudProblem
{
  std::size_t Line = 0;
  std::string Text;
  /// The number of lines of the text.
  std::size_t Lines = 0;
  /// The text holds bytes that text has not: a NUL, or bytes that are not UTF-8.
  bool Binary = false;
};

/// What a line of a text cloud is (the rule above).
enum class LineKind
{
  Comment, ///< blank, or # or // first
  Point,   ///< x y z, and maybe further numbers
  Count,   ///< one number: a .pts file's point count
  Short,   ///< two numbers: a point short of a coordinate
  Words    ///< anything else: column names, an element and x y z
};

/// The kind of the `size` bytes at `line` (no line break); for a Point,
/// `values` gets x y z and the numbers that follow them, up to the first
/// field that is not a number, and `fields` (if given) its number of fields.
LineKind ReadLine(const char* line, std::size_t size, std::vector<double>& values, std::size_t* fields = nullptr);

/// The points (x y z, one after the other in `xyz`) of a text cloud's
/// `size` bytes at `text`. Lines end at \n, \r\n, \r and the other breaks
/// of Python's str.splitlines. False, with `problem` filled, when a line
/// is not a point or no line is.
bool ReadCloudPoints(const char* text, std::size_t size, std::vector<double>& xyz, CloudProblem& problem);

/// A field as a number, as Python's float() reads it; false if it is not one.
bool ParseNumber(const std::string& field, double& value);
} // namespace text
} // namespace nv

#endif
