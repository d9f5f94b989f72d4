// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The readers' plain-C++ parsers (Readers/Formats) in narrowvolume._core,
// for the wheel, which has no VTK readers: the command line and the
// ParaView Python plugin (_readers.py) read LAS, PCD and text clouds with
// them, and turn the arrays into a vtkPolyData (_scanreaders.point_cloud).
// Parsing and its messages are the parsers'; this file only hands their
// results to numpy and their failures to Python as ValueError.
#include "nvLAS.h"
#include "nvPCD.h"
#include "nvTextCloud.h"

#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/string.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace nb = nanobind;
using namespace nb::literals;

namespace
{
/// A numpy array of n x components values of T that owns them (one column
/// when components is 1), filled by fill(values).
template <class T, class Fill>
nb::object NewArray(std::uint64_t n, std::size_t components, Fill fill)
{
  T* values = new T[std::max<std::size_t>(static_cast<std::size_t>(n) * components, 1)];
  nb::capsule owner(values, [](void* p) noexcept { delete[] static_cast<T*>(p); });
  fill(values);
  const std::size_t shape[2] = { static_cast<std::size_t>(n), components };
  return nb::cast(nb::ndarray<nb::numpy, T>(values, components > 1 ? 2 : 1, shape, owner));
}

/// A numpy array that takes over a column of nv::las::Points (no copy; the
/// capsule frees it with delete[], as the column would have).
template <class T>
nb::object Adopt(nv::las::Column<T>& column, std::uint64_t n, std::size_t components = 1)
{
  const std::size_t shape[2] = { static_cast<std::size_t>(n), components };
  T* values = column.Release();
  nb::capsule owner(values, [](void* p) noexcept { delete[] static_cast<T*>(p); });
  return nb::cast(nb::ndarray<nb::numpy, T>(values, components > 1 ? 2 : 1, shape, owner));
}

/// read_las: the points, the fields as the VTK reader's arrays, and the name of the colours.
nb::tuple ReadLAS(const std::string& path)
{
  nv::las::Header header;
  nv::las::Points read;
  std::string error;
  nv::las::ReadResult result;
  {
    nb::gil_scoped_release release;
    result = nv::las::ReadFile(path, header, read, error);
  }
  if (result != nv::las::ReadResult::Read)
  {
    throw nb::value_error(error.c_str());
  }
  const std::uint64_t n = header.NumberOfPoints;
  const int format = header.PointFormat;
  nb::dict arrays;
  nv::las::ForEachArray(format, read, [&](const char* name, auto& column, int components) {
    arrays[name] = Adopt(column, n, static_cast<std::size_t>(components));
  });
  const nb::object scalars = nv::las::HasColor(format) ? nb::object(nb::str("Colors")) : nb::none();
  return nb::make_tuple(Adopt(read.XYZ, n, 3), arrays, scalars);
}

/// Field f of every point as it is stored, in its own type.
template <class T>
nb::object Column(const nv::pcd::Header& header, const nv::pcd::Data& data, std::size_t f)
{
  const nv::pcd::Field& field = header.Fields[f];
  return NewArray<T>(header.Points, static_cast<std::size_t>(field.Count), [&](T* values) {
    for (std::uint64_t i = 0; i < header.Points; ++i)
    {
      std::memcpy(values + i * field.Count, data.At(f, i), field.Bytes());
    }
  });
}

nb::object FieldArray(const nv::pcd::Header& header, const nv::pcd::Data& data, std::size_t f)
{
  const nv::pcd::Field& field = header.Fields[f];
  switch (field.Type)
  {
    case 'F':
      return field.Size == 4 ? Column<float>(header, data, f) : Column<double>(header, data, f);
    case 'U':
      return field.Size == 1 ? Column<std::uint8_t>(header, data, f)
        : field.Size == 2    ? Column<std::uint16_t>(header, data, f)
        : field.Size == 4    ? Column<std::uint32_t>(header, data, f)
                             : Column<std::uint64_t>(header, data, f);
    default:
      return field.Size == 1 ? Column<std::int8_t>(header, data, f)
        : field.Size == 2    ? Column<std::int16_t>(header, data, f)
        : field.Size == 4    ? Column<std::int32_t>(header, data, f)
                             : Column<std::int64_t>(header, data, f);
  }
}

/// read_pcd: the points, the other fields as arrays, and the name of the colours.
nb::tuple ReadPCD(const std::string& path)
{
  nv::pcd::Header header;
  nv::pcd::Data data;
  std::string error;
  nv::pcd::ReadResult read;
  {
    nb::gil_scoped_release release;
    read = nv::pcd::ReadFile(path, header, data, error);
  }
  if (read != nv::pcd::ReadResult::Read)
  {
    throw nb::value_error(error.c_str());
  }
  const std::uint64_t n = header.Points;
  const int axes[3] = { header.Find("x"), header.Find("y"), header.Find("z") };
  nb::object xyz = NewArray<double>(n, 3, [&](double* values) {
    for (std::uint64_t i = 0; i < n; ++i)
    {
      for (int a = 0; a < 3; ++a)
      {
        values[3 * i + a] = nv::pcd::ValueAsDouble(data.At(axes[a], i), header.Fields[axes[a]]);
      }
    }
  });
  nb::dict arrays;
  nb::object scalars = nb::none();
  for (std::size_t f = 0; f < header.Fields.size(); ++f)
  {
    const nv::pcd::Field& field = header.Fields[f];
    if (field.IsPadding() || data.Start[f] < 0 || field.Name == "x" || field.Name == "y" || field.Name == "z")
    {
      continue;
    }
    if ((field.Name == "rgb" || field.Name == "rgba") && field.Size == 4 && field.Count == 1)
    {
      // PCL packs 0xAARRGGBB into 32 bits (and stores them as a float for "rgb").
      arrays["Colors"] = NewArray<std::uint8_t>(n, 3, [&](std::uint8_t* rgb) {
        for (std::uint64_t i = 0; i < n; ++i)
        {
          std::uint32_t packed;
          std::memcpy(&packed, data.At(f, i), 4);
          rgb[3 * i] = static_cast<std::uint8_t>(packed >> 16);
          rgb[3 * i + 1] = static_cast<std::uint8_t>(packed >> 8);
          rgb[3 * i + 2] = static_cast<std::uint8_t>(packed);
        }
      });
      scalars = nb::str("Colors");
      continue;
    }
    arrays[field.Name.c_str()] = FieldArray(header, data, f);
  }
  return nb::make_tuple(xyz, arrays, scalars);
}

/// read_text_cloud: the points of a text cloud; its problem in the words
/// the pip package's command line has always used.
nb::object ReadTextCloud(const std::string& path)
{
  std::string content;
  std::vector<double> xyz;
  nv::text::CloudProblem problem;
  bool opened, read = false;
  {
    nb::gil_scoped_release release;
    std::ifstream in(path, std::ios::binary);
    opened = static_cast<bool>(in);
    if (opened)
    {
      content.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
      read = nv::text::ReadCloudPoints(content.data(), content.size(), xyz, problem);
    }
  }
  if (!opened)
  {
    PyErr_SetFromErrnoWithFilename(PyExc_OSError, path.c_str());
    throw nb::python_error();
  }
  if (!read)
  {
    std::string message;
    if (problem.Line > 0)
    {
      nb::object line =
        nb::steal(PyUnicode_DecodeUTF8(problem.Text.data(), static_cast<Py_ssize_t>(problem.Text.size()), "replace"));
      message = path + ", line " + std::to_string(problem.Line) +
        ": not a point (x y z): " + nb::repr(line.attr("strip")()).c_str();
    }
    else
    {
      message = path + ": no line of x y z numbers in its " + std::to_string(problem.Lines) +
        " lines: not a text point cloud" + (problem.Binary ? " (it holds binary data)" : "");
    }
    throw nb::value_error(message.c_str());
  }
  return NewArray<double>(xyz.size() / 3, 3, [&](double* values) { std::copy(xyz.begin(), xyz.end(), values); });
}
} // namespace

void BindReaders(nb::module_& m)
{
  m.def("read_las", &ReadLAS, "path"_a,
    "A LAS 1.0-1.4 file, point formats 0-10 (nv::las::ReadFile, as vtkLASPointCloudReader reads it) as "
    "(xyz, arrays, scalars): the points (n x 3 doubles, X * scale + offset), the fields as the C++ "
    "reader's arrays (Intensity, Classification, ..., GpsTime, NearInfrared where the format has them), "
    "the colours as \"Colors\" (n x 3 bytes), and the name of the colours or None. ValueError says why a "
    "file cannot be read.");
  m.def("read_pcd", &ReadPCD, "path"_a,
    "A PCL .pcd file (ascii, binary or binary_compressed; nv::pcd::ReadFile, as vtkPCDPointCloudReader "
    "reads it) as (xyz, arrays, scalars): the points (n x 3 doubles), the other fields by name in their "
    "own types (n values, or n x COUNT), a packed \"rgb\" / \"rgba\" as the colours \"Colors\" (n x 3 "
    "bytes), and the name of the colours or None. ValueError says why a file cannot be read.");
  m.def("read_text_cloud", &ReadTextCloud, "path"_a,
    "The points (n x 3 doubles) of a plain-text cloud, .xyz, .txt or .csv (nv::text::ReadCloudPoints): "
    "x y z in the first three fields, header lines, a point count and # or // comments skipped. "
    "ValueError names the line that is not a point.");
}
