// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLASPointCloudReader.h"

#include "nvLAS.h"
#include "vtkCellArray.h"
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
#include "vtkUnsignedCharArray.h"
#include "vtkUnsignedShortArray.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <type_traits>

vtkStandardNewMacro(vtkLASPointCloudReader);

namespace
{
/// The VTK array class of a column's values.
template <typename T>
struct ArrayOf;
template <>
struct ArrayOf<std::uint8_t>
{
  using Type = vtkUnsignedCharArray;
};
template <>
struct ArrayOf<std::uint16_t>
{
  using Type = vtkUnsignedShortArray;
};
template <>
struct ArrayOf<float>
{
  using Type = vtkFloatArray;
};
template <>
struct ArrayOf<double>
{
  using Type = vtkDoubleArray;
};

/// A named VTK array of n tuples that takes over a column of nv::las::Points
/// (no copy: VTK frees it with delete[], as the column would have).
template <typename ArrayT, typename T>
vtkSmartPointer<ArrayT> Adopt(const char* name, nv::las::Column<T>& column, int components = 1)
{
  auto array = vtkSmartPointer<ArrayT>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  const vtkIdType size = static_cast<vtkIdType>(column.Size);
  array->SetArray(column.Release(), size, 0, vtkAbstractArray::VTK_DATA_ARRAY_DELETE);
  return array;
}
} // namespace

vtkLASPointCloudReader::vtkLASPointCloudReader()
{
  this->SetNumberOfInputPorts(0);
}

vtkLASPointCloudReader::~vtkLASPointCloudReader() = default;

int vtkLASPointCloudReader::CanReadFile(const char* fileName)
{
  // The signature only: a damaged or compressed file is then ours to explain.
  std::ifstream in(fileName ? fileName : "", std::ios::binary);
  char signature[4] = { 0, 0, 0, 0 };
  in.read(signature, 4);
  return in && std::equal(signature, signature + 4, "LASF") ? 1 : 0;
}

int vtkLASPointCloudReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  // The file is read and checked by nv::las::ReadFile (Formats/nvLAS), as the
  // wheel's read_las reads it; this only hands its columns to VTK.
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  nv::las::Header header;
  nv::las::Points read;
  std::string error;
  const nv::las::ReadResult result = nv::las::ReadFile(this->FileName, header, read, error, [this](double done) {
    this->UpdateProgress(done);
    return !this->GetAbortExecute();
  });
  if (result == nv::las::ReadResult::Failed)
  {
    vtkErrorMacro(<< error);
    return nv::ReadFailed(output);
  }
  if (result == nv::las::ReadResult::Stopped)
  {
    output->Initialize();
    return 1;
  }
  const vtkIdType n = static_cast<vtkIdType>(header.NumberOfPoints);
  vtkNew<vtkPoints> points;
  points->SetData(Adopt<vtkDoubleArray>("Points", read.XYZ, 3));
  output->SetPoints(points);
  output->SetVerts(nv::VertexCells(n));
  vtkPointData* pd = output->GetPointData();
  nv::las::ForEachArray(header.PointFormat, read, [pd](const char* name, auto& column, int components) {
    using ArrayT = typename ArrayOf<typename std::decay_t<decltype(column)>::Value>::Type;
    auto array = Adopt<ArrayT>(name, column, components);
    if (std::strcmp(name, "Colors") == 0)
    {
      pd->SetScalars(array);
    }
    else
    {
      pd->AddArray(array);
    }
  });
  return 1;
}

void vtkLASPointCloudReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
}
