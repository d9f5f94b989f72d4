// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkPCDPointCloudReader.h"

#include "nvPCD.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointCloudVertices.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <vector>

vtkStandardNewMacro(vtkPCDPointCloudReader);

namespace
{
/// The VTK type of a PCD field: I1 signed char, U1 unsigned char, ..., F8 double.
int VTKType(const nv::pcd::Field& field)
{
  switch (field.Type)
  {
    case 'F':
      return field.Size == 4 ? VTK_FLOAT : VTK_DOUBLE;
    case 'U':
      return field.Size == 1 ? VTK_UNSIGNED_CHAR
                             : field.Size == 2 ? VTK_UNSIGNED_SHORT
                                               : field.Size == 4 ? VTK_UNSIGNED_INT : VTK_UNSIGNED_LONG_LONG;
    default:
      return field.Size == 1 ? VTK_SIGNED_CHAR
                             : field.Size == 2 ? VTK_SHORT : field.Size == 4 ? VTK_INT : VTK_LONG_LONG;
  }
}
} // namespace

vtkPCDPointCloudReader::vtkPCDPointCloudReader()
{
  this->SetNumberOfInputPorts(0);
}

vtkPCDPointCloudReader::~vtkPCDPointCloudReader() = default;

int vtkPCDPointCloudReader::CanReadFile(const char* fileName)
{
  // The first line that is not a comment opens a PCD header.
  std::ifstream in(fileName ? fileName : "", std::ios::binary);
  std::string line;
  for (int lines = 0; lines < 32 && std::getline(in, line); ++lines)
  {
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#')
    {
      continue;
    }
    return line.compare(first, 7, "VERSION") == 0 || line.compare(first, 6, "FIELDS") == 0 ||
        line.compare(first, 7, "COLUMNS") == 0
      ? 1
      : 0;
  }
  return 0;
}

int vtkPCDPointCloudReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  // 1. The data of every point, decoded to binary values (nv::pcd::ReadFile).
  nv::pcd::Header header;
  nv::pcd::Data data;
  std::string error;
  const nv::pcd::ReadResult read = nv::pcd::ReadFile(this->FileName, header, data, error, [this](double fraction) {
    this->UpdateProgress(0.9 * fraction);
    return !this->GetAbortExecute();
  });
  if (read == nv::pcd::ReadResult::Failed)
  {
    vtkErrorMacro(<< error);
    return nv::ReadFailed(output);
  }
  if (read == nv::pcd::ReadResult::Stopped)
  {
    output->Initialize();
    return 1;
  }
  const vtkIdType n = static_cast<vtkIdType>(header.Points);
  const std::size_t fieldCount = header.Fields.size();

  // 2. The points, without the invalid ones unless asked to keep them.
  const int axes[3] = { header.Find("x"), header.Find("y"), header.Find("z") };
  std::vector<vtkIdType> kept; // empty: every point is kept
  std::vector<double> xyz(3 * static_cast<std::size_t>(n));
  bool allFinite = true;
  for (vtkIdType i = 0; i < n; ++i)
  {
    bool finite = true;
    for (int a = 0; a < 3; ++a)
    {
      const double v = nv::pcd::ValueAsDouble(data.At(axes[a], i), header.Fields[axes[a]]);
      xyz[3 * i + a] = v;
      finite = finite && std::isfinite(v);
    }
    allFinite = allFinite && finite;
  }
  if (!allFinite && this->SkipInvalidPoints)
  {
    for (vtkIdType i = 0; i < n; ++i)
    {
      if (std::isfinite(xyz[3 * i]) && std::isfinite(xyz[3 * i + 1]) && std::isfinite(xyz[3 * i + 2]))
      {
        kept.push_back(i);
      }
    }
  }
  const bool compact = !allFinite && this->SkipInvalidPoints;
  const vtkIdType m = compact ? static_cast<vtkIdType>(kept.size()) : n;
  auto source = [&](vtkIdType k) { return compact ? kept[k] : k; };
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(m);
  for (vtkIdType k = 0; k < m; ++k)
  {
    points->SetPoint(k, &xyz[3 * source(k)]);
  }
  xyz = std::vector<double>();

  // 3. The other fields as arrays; packed colours and normals combined.
  vtkPointData* pd = output->GetPointData();
  const int normalFields[3] = { header.Find("normal_x"), header.Find("normal_y"), header.Find("normal_z") };
  const bool hasNormals = std::all_of(normalFields, normalFields + 3, [&](int f) {
    return f >= 0 && data.Start[f] >= 0 && header.Fields[f].Type == 'F' && header.Fields[f].Count == 1;
  });
  if (hasNormals)
  {
    vtkNew<vtkFloatArray> normals;
    normals->SetName("Normals");
    normals->SetNumberOfComponents(3);
    normals->SetNumberOfTuples(m);
    for (vtkIdType k = 0; k < m; ++k)
    {
      for (int a = 0; a < 3; ++a)
      {
        normals->SetTypedComponent(k, a,
          static_cast<float>(nv::pcd::ValueAsDouble(data.At(normalFields[a], source(k)), header.Fields[normalFields[a]])));
      }
    }
    pd->SetNormals(normals);
  }
  for (std::size_t f = 0; f < fieldCount; ++f)
  {
    const nv::pcd::Field& field = header.Fields[f];
    const bool isAxis = static_cast<int>(f) == axes[0] || static_cast<int>(f) == axes[1] || static_cast<int>(f) == axes[2];
    const bool isNormal = hasNormals &&
      (static_cast<int>(f) == normalFields[0] || static_cast<int>(f) == normalFields[1] ||
        static_cast<int>(f) == normalFields[2]);
    if (isAxis || isNormal || field.IsPadding() || data.Start[f] < 0)
    {
      continue;
    }
    if ((field.Name == "rgb" || field.Name == "rgba") && field.Size == 4 && field.Count == 1)
    {
      // PCL packs 0xAARRGGBB into 32 bits (and stores them as a float for "rgb").
      const int components = field.Name == "rgba" ? 4 : 3;
      vtkNew<vtkUnsignedCharArray> colors;
      colors->SetName("Colors");
      colors->SetNumberOfComponents(components);
      colors->SetNumberOfTuples(m);
      for (vtkIdType k = 0; k < m; ++k)
      {
        std::uint32_t packed;
        std::memcpy(&packed, data.At(f, source(k)), 4);
        const unsigned char rgba[4] = { static_cast<unsigned char>(packed >> 16),
          static_cast<unsigned char>(packed >> 8), static_cast<unsigned char>(packed),
          static_cast<unsigned char>(packed >> 24) };
        for (int c = 0; c < components; ++c)
        {
          colors->SetTypedComponent(k, c, rgba[c]);
        }
      }
      pd->SetScalars(colors);
      continue;
    }
    auto array = vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(VTKType(field)));
    array->SetName(field.Name.c_str());
    array->SetNumberOfComponents(field.Count);
    array->SetNumberOfTuples(m);
    auto* bytes = static_cast<std::uint8_t*>(array->GetVoidPointer(0));
    const std::size_t tuple = field.Bytes();
    for (vtkIdType k = 0; k < m; ++k)
    {
      std::memcpy(bytes + static_cast<std::size_t>(k) * tuple, data.At(f, source(k)), tuple);
    }
    pd->AddArray(array);
  }
  output->SetPoints(points);
  output->SetVerts(nv::VertexCells(m));
  this->UpdateProgress(1.0);
  return 1;
}

void vtkPCDPointCloudReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
  os << indent << "SkipInvalidPoints: " << this->SkipInvalidPoints << "\n";
}
