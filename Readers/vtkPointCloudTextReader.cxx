// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkPointCloudTextReader.h"

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

/// The numbers of one line; false if a field is not a number.
bool ParseLine(const std::string& line, std::vector<double>& values)
{
  values.clear();
  const char* p = line.c_str();
  while (*p)
  {
    while (*p == ' ' || *p == '\t' || *p == ',' || *p == ';' || *p == '\r')
      ++p;
    if (!*p)
      break;
    char* end = nullptr;
    const double v = std::strtod(p, &end);
    if (end == p)
      return false;
    values.push_back(v);
    p = end;
  }
  return true;
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
  return letters >= 1 && letters <= 3 && at < line.size() && ParseLine(line.substr(at), values) &&
    values.size() >= 3;
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

bool IsComment(const std::string& line)
{
  const auto first = line.find_first_not_of(" \t\r");
  return first == std::string::npos || line[first] == '#' || line.compare(first, 2, "//") == 0;
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
  int checked = 0;
  bool header = false;
  while (checked < 1 && std::getline(in, line))
  {
    if (IsComment(line))
      continue;
    if (checked == 0 && !header && !ParseLine(line, values))
    {
      header = true; // column names
      continue;
    }
    if (!ParseLine(line, values) || (values.size() < 3 && !(checked == 0 && values.size() == 1)))
      return xyz ? 1 : 0;
    ++checked;
  }
  return checked > 0 || xyz ? 1 : 0;
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
  vtkNew<vtkFloatArray> intensity, normals;
  vtkNew<vtkUnsignedCharArray> colors;
  std::vector<vtkSmartPointer<vtkFloatArray>> others;
  Layout layout;
  std::size_t columns = 0;
  std::string line;
  std::vector<double> v;
  long lineNumber = 0;
  bool first = true;
  bool headerSkipped = false;
  while (std::getline(in, line))
  {
    ++lineNumber;
    if (IsComment(line))
      continue;
    if (!ParseLine(line, v) && first && !headerSkipped)
    {
      headerSkipped = true; // a header line of column names, as CSV files have
      continue;
    }
    if (!ParseLine(line, v))
    {
      if (IsBinary(line))
      {
        vtkErrorMacro(<< this->FileName << ", line " << lineNumber
                      << ": binary data, not text: a text point cloud holds lines of x y z numbers.");
        return nv::ReadFailed(output);
      }
      vtkErrorMacro(<< this->FileName << ", line " << lineNumber << ": not a list of numbers: " << Quoted(line)
                    << "."
                    << (LooksLikeAtom(line)
                           ? " This looks like a molecular XYZ file (an element, then x y z): open it with "
                             "ParaView's XYZ Reader (File > Open, file type \"XMol Molecule Files\")."
                           : ""));
      output->Initialize();
      return nv::ReadFailed(output);
    }
    if (first && v.size() == 1)
    {
      continue; // the point count of a .pts file
    }
    if (first)
    {
      if (v.size() < 3)
      {
        vtkErrorMacro(<< this->FileName << ", line " << lineNumber << ": fewer than 3 coordinates.");
        return nv::ReadFailed(output);
      }
      columns = v.size();
      layout = LayoutFor(v);
      intensity->SetName("Intensity");
      normals->SetName("Normals");
      normals->SetNumberOfComponents(3);
      colors->SetName("Colors");
      colors->SetNumberOfComponents(3);
      for (int c : layout.Others)
      {
        auto array = vtkSmartPointer<vtkFloatArray>::New();
        array->SetName(("Column" + std::to_string(c + 1)).c_str());
        others.push_back(array);
      }
      first = false;
    }
    if (v.size() != columns)
    {
      vtkErrorMacro(<< this->FileName << ", line " << lineNumber << ": " << v.size() << " columns where the first point had "
                    << columns << ".");
      output->Initialize();
      return nv::ReadFailed(output);
    }
    points->InsertNextPoint(v.data());
    if (layout.IntensityColumn >= 0)
      intensity->InsertNextValue(static_cast<float>(v[layout.IntensityColumn]));
    if (layout.NormalColumn >= 0)
      normals->InsertNextTuple(&v[layout.NormalColumn]);
    if (layout.ColorColumn >= 0)
      colors->InsertNextTuple(&v[layout.ColorColumn]);
    for (std::size_t o = 0; o < others.size(); ++o)
      others[o]->InsertNextValue(static_cast<float>(v[layout.Others[o]]));
  }

  if (points->GetNumberOfPoints() == 0)
  {
    vtkErrorMacro(<< this->FileName << ": no line of x y z numbers: "
                  << (lineNumber == 0 ? "the file is empty." : "this is not a text point cloud."));
    return nv::ReadFailed(output);
  }
  output->SetPoints(points);
  output->SetVerts(nv::VertexCells(points->GetNumberOfPoints()));
  if (layout.IntensityColumn >= 0)
    output->GetPointData()->AddArray(intensity);
  if (layout.NormalColumn >= 0)
    output->GetPointData()->SetNormals(normals);
  if (layout.ColorColumn >= 0)
    output->GetPointData()->SetScalars(colors);
  for (auto& array : others)
    output->GetPointData()->AddArray(array);
  return 1;
}

void vtkPointCloudTextReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
}
