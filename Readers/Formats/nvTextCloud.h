// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// Plain-text point clouds (.xyz, .txt, .csv) as the pip package reads them:
// x y z in the first three fields of a line (fields split at spaces, tabs
// and commas), every other field ignored.
//
// - A line that is blank, or whose first field starts with # or //, is a
//   comment.
// - Before the first point, a line whose first three fields are not all
//   numbers is a header line (column names), and a line of one number is a
//   .pts file's point count: both are skipped.
// - After the first point, such a line, and anywhere a line of two fields,
//   is an error naming the line.
// Numbers are decimal as Python's float() writes and reads them ("1.5e-3",
// "nan", "inf"; digits grouped by "_").
//
// The CMake build's vtkPointCloudTextReader reads the same files with more
// (the extra columns as arrays) and refuses rows of different lengths.
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
