// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkPointCloudTextReader.h"

#include "nvTextCloud.h"

#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointCloudVertices.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <vector>

vtkStandardNewMacro(vtkPointCloudTextReader);

namespace
{

using nv::text::LineKind;

/// What a line is, and its numbers (nvTextCloud.h: the rule of every route).
LineKind KindOf(const std::string& line, std::vector<double>& values, std::size_t* fields = nullptr)
{
  return nv::text::ReadLine(line.data(), line.size(), values, fields);
}

/// "C 0.1 2.3 4.5": an element symbol, then x y z, as in molecular XYZ files
/// (ParaView's XYZ Reader also claims the .xyz extension).
bool LooksLikeAtom(const std::string& line)
{
  std::size_t at = line.find_first_not_of(" \t");
  std::size_t letters = 0;
  while (at < line.size() && std::isalpha(static_cast<unsigned char>(line[at])))
  {
    ++at;
    ++letters;
  }
  std::vector<double> values;
  return letters >= 1 && letters <= 3 && at < line.size() &&
    KindOf(line.substr(at), values) == LineKind::Point;
}

/// True if a line holds bytes that no text has (NUL and other control
/// characters): a binary file, or binary bytes inside a text one.
bool IsBinary(const std::string& line)
{
  for (unsigned char c : line)
  {
    if (c < 32 && c != '\t' && c != '\r')
      return true;
  }
  return false;
}

/// Whether the first bytes of a binary file can begin a PLOT3D grid (the
/// other format named .xyz): a block count or the first grid's size, whole
/// and positive, in either byte order (a Fortran record begins with its
/// length, 4 or 12 bytes and more, which passes too). Random bytes rarely do.
bool MayBePlot3D(const unsigned char head[4])
{
  const std::uint32_t little = head[0] | (head[1] << 8) | (head[2] << 16) | (std::uint32_t(head[3]) << 24);
  const std::uint32_t big = head[3] | (head[2] << 8) | (head[1] << 16) | (std::uint32_t(head[0]) << 24);
  constexpr std::uint32_t MostPlausible = 100000000;
  return (little >= 1 && little <= MostPlausible) || (big >= 1 && big <= MostPlausible);
}

/// A line as the messages quote it: at most 60 characters, a byte that is
/// not printable ASCII as '?' (a message must stay valid text).
std::string Quoted(const std::string& line)
{
  std::string shown = line.substr(0, 60);
  for (char& c : shown)
  {
    const unsigned char byte = static_cast<unsigned char>(c);
    c = byte < 32 || byte > 126 ? '?' : c;
  }
  return "\"" + shown + (line.size() > 60 ? "...\"" : "\"");
}

bool LooksLikeColour(const double* v)
{
  for (int c = 0; c < 3; ++c)
  {
    if (v[c] < 0 || v[c] > 255 || v[c] != std::floor(v[c]))
      return false;
  }
  return true;
}

/// What the columns after x, y, z hold.
struct Layout
{
  int IntensityColumn = -1;
  int ColorColumn = -1;
  int NormalColumn = -1;
  std::vector<int> Others;
};

Layout LayoutFor(const std::vector<double>& first)
{
  Layout layout;
  const int extra = static_cast<int>(first.size()) - 3;
  if (extra == 1)
  {
    layout.IntensityColumn = 3;
  }
  else if (extra == 3)
  {
    (LooksLikeColour(&first[3]) ? layout.ColorColumn : layout.NormalColumn) = 3;
  }
  else if (extra == 4)
  {
    layout.IntensityColumn = 3;
    layout.ColorColumn = 4;
  }
  else if (extra == 6)
  {
    const bool colourFirst = LooksLikeColour(&first[3]) && !LooksLikeColour(&first[6]);
    layout.ColorColumn = colourFirst ? 3 : 6;
    layout.NormalColumn = colourFirst ? 6 : 3;
  }
  else
  {
    for (int c = 3; c < static_cast<int>(first.size()); ++c)
      layout.Others.push_back(c);
  }
  return layout;
}

} // namespace

vtkPointCloudTextReader::vtkPointCloudTextReader()
{
  this->SetNumberOfInputPorts(0);
}

vtkPointCloudTextReader::~vtkPointCloudTextReader() = default;

int vtkPointCloudTextReader::CanReadFile(const char* fileName)
{
  // A .xyz of text is this reader's (below). Otherwise the first line of
  // data decides (after comments, and a header of column names or a point
  // count): a cloud whose later line is damaged is still this reader's,
  // which names the line, rather than the next reader's of the extension.
  std::ifstream in(fileName, std::ios::binary);
  const std::string name = fileName ? fileName : "";
  const std::string extension = name.size() >= 4 ? name.substr(name.size() - 4) : "";
  const bool xyz = extension.size() == 4 && extension[0] == '.' && std::tolower(extension[1]) == 'x' &&
    std::tolower(extension[2]) == 'y' && std::tolower(extension[3]) == 'z';
  // Binary bytes: a .xyz that cannot begin a PLOT3D grid is this reader's to
  // refuse with its message (ParaView's PLOT3D reader aborts on it).
  char head[4096];
  in.read(head, sizeof(head));
  const std::string start(head, static_cast<std::size_t>(in.gcount()));
  if (start.find('\0') != std::string::npos)
  {
    return xyz && start.size() >= 4 && !MayBePlot3D(reinterpret_cast<const unsigned char*>(start.data())) ? 1 : 0;
  }
  // Text in a .xyz (empty, words, a molecule's elements): this reader's,
  // which says what is wrong with it. ParaView's PLOT3D reader, the other of
  // the extension, reads text only as numbers (its ASCII grids), which this
  // reader takes too, and crashes on the rest in pvpython. Other extensions
  // (.txt, .csv) leave text that is not a cloud to the readers of tables:
  // there the first line of data decides.
  in.clear();
  in.seekg(0);
  std::string line;
  std::vector<double> values;
  std::size_t fields = 0;
  bool header = false, counted = false;
  while (std::getline(in, line))
  {
    const LineKind kind = KindOf(line, values, &fields);
    if (kind == LineKind::Comment)
      continue;
    if (kind == LineKind::Words && !header && !counted)
    {
      header = true; // column names
      continue;
    }
    if (kind == LineKind::Count && !counted && !header)
    {
      counted = true; // a .pts file's point count
      continue;
    }
    // A point whose every field is a number: a table with a text column is
    // left to ParaView's CSV reader (which a .xyz has not).
    return (kind == LineKind::Point && fields == values.size()) || xyz ? 1 : 0;
  }
  return xyz ? 1 : 0;
}

int vtkPointCloudTextReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  std::ifstream in(this->FileName);
  if (this->FileName.empty() || !in)
  {
    vtkErrorMacro("Cannot open the point cloud file \"" << this->FileName << "\".");
    return nv::ReadFailed(output);
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  // The rule of every route (nvTextCloud.h): x y z, then the numbers that
  // follow; the columns every row has become arrays, the rest are dropped.
  std::vector<double> v, firstRow;
  std::vector<std::vector<float>> extra; // the further columns every row so far has
  std::string line;
  long lineNumber = 0;
  while (std::getline(in, line))
  {
    ++lineNumber;
    const LineKind kind = KindOf(line, v);
    if (kind == LineKind::Comment)
      continue;
    if (kind != LineKind::Point)
    {
      const bool atom = LooksLikeAtom(line), binary = IsBinary(line);
      if (firstRow.empty() && kind != LineKind::Short && !atom && !binary)
        continue; // before the first point: a header of column names, or a .pts file's point count
      if (binary)
      {
        vtkErrorMacro(<< this->FileName << ", line " << lineNumber
                      << ": binary data, not text: a text point cloud holds lines of x y z numbers.");
        return nv::ReadFailed(output);
      }
      vtkErrorMacro(<< this->FileName << ", line " << lineNumber << ": not a point (x y z): " << Quoted(line)
                    << "."
                    << (atom ? " This looks like a molecular XYZ file (an element, then x y z): open it with "
                               "ParaView's XYZ Reader (File > Open, file type \"XMol Molecule Files\")."
                             : ""));
      output->Initialize();
      return nv::ReadFailed(output);
    }
    if (firstRow.empty())
    {
      firstRow = v;
      extra.resize(v.size() - 3);
    }
    extra.resize(std::min(extra.size(), v.size() - 3)); // a row with fewer: those columns are dropped
    points->InsertNextPoint(v.data());
    for (std::size_t c = 0; c < extra.size(); ++c)
      extra[c].push_back(static_cast<float>(v[3 + c]));
  }

  if (points->GetNumberOfPoints() == 0)
  {
    vtkErrorMacro(<< this->FileName << ": no line of x y z numbers: "
                  << (lineNumber == 0 ? "the file is empty." : "this is not a text point cloud."));
    return nv::ReadFailed(output);
  }
  output->SetPoints(points);
  output->SetVerts(nv::VertexCells(points->GetNumberOfPoints()));
  firstRow.resize(3 + extra.size());
  const Layout layout = LayoutFor(firstRow);
  const vtkIdType n = points->GetNumberOfPoints();
  // The array of `components` columns from `column` on (3, 4, ...), named.
  const auto columnsOf = [&](vtkDataArray* array, int column, int components, const char* name) {
    array->SetName(name);
    array->SetNumberOfComponents(components);
    array->SetNumberOfTuples(n);
    for (vtkIdType p = 0; p < n; ++p)
      for (int c = 0; c < components; ++c)
        array->SetComponent(p, c, extra[static_cast<std::size_t>(column - 3 + c)][static_cast<std::size_t>(p)]);
  };
  if (layout.IntensityColumn >= 0)
  {
    vtkNew<vtkFloatArray> intensity;
    columnsOf(intensity, layout.IntensityColumn, 1, "Intensity");
    output->GetPointData()->AddArray(intensity);
  }
  if (layout.NormalColumn >= 0)
  {
    vtkNew<vtkFloatArray> normals;
    columnsOf(normals, layout.NormalColumn, 3, "Normals");
    output->GetPointData()->SetNormals(normals);
  }
  if (layout.ColorColumn >= 0)
  {
    vtkNew<vtkUnsignedCharArray> colors;
    columnsOf(colors, layout.ColorColumn, 3, "Colors");
    output->GetPointData()->SetScalars(colors);
  }
  for (int c : layout.Others)
  {
    vtkNew<vtkFloatArray> other;
    columnsOf(other, c, 1, ("Column" + std::to_string(c + 1)).c_str());
    output->GetPointData()->AddArray(other);
  }
  return 1;
}

void vtkPointCloudTextReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
}
