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

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <fstream>
#include <vector>

vtkStandardNewMacro(vtkLASPointCloudReader);

namespace
{
/// Points decoded per read: large enough to read fast, small enough to keep
/// the buffer at a few megabytes whatever the file's size.
constexpr vtkIdType PointsPerChunk = 1 << 16;

template <typename ArrayT>
vtkSmartPointer<ArrayT> NewArray(const char* name, vtkIdType count, int components = 1)
{
  auto array = vtkSmartPointer<ArrayT>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(count);
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
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  std::ifstream in(this->FileName, std::ios::binary);
  if (this->FileName.empty() || !in)
  {
    vtkErrorMacro("Cannot open the LAS file \"" << this->FileName << "\".");
    return nv::ReadFailed(output);
  }
  const std::uint64_t fileSize = vtksys::SystemTools::FileLength(this->FileName);
  std::vector<std::uint8_t> headerBytes(
    static_cast<std::size_t>(std::min<std::uint64_t>(fileSize, nv::las::MaximumHeaderSize)));
  in.read(reinterpret_cast<char*>(headerBytes.data()), static_cast<std::streamsize>(headerBytes.size()));
  nv::las::Header header;
  std::string error;
  if (!in || !nv::las::ParseHeader(headerBytes.data(), headerBytes.size(), fileSize, header, error))
  {
    vtkErrorMacro(<< this->FileName << ": " << (error.empty() ? "cannot read the header" : error) << ".");
    return nv::ReadFailed(output);
  }

  // ParseHeader checked that the file holds every announced point, so these
  // arrays are at most a small multiple of the file's size.
  const vtkIdType n = static_cast<vtkIdType>(header.NumberOfPoints);
  const int format = header.PointFormat;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n);
  double* xyz = vtkDoubleArray::SafeDownCast(points->GetData())->GetPointer(0);
  auto intensity = NewArray<vtkUnsignedShortArray>("Intensity", n);
  auto classification = NewArray<vtkUnsignedCharArray>("Classification", n);
  auto returnNumber = NewArray<vtkUnsignedCharArray>("ReturnNumber", n);
  auto numberOfReturns = NewArray<vtkUnsignedCharArray>("NumberOfReturns", n);
  auto flags = NewArray<vtkUnsignedCharArray>("ClassificationFlags", n);
  auto scanDirection = NewArray<vtkUnsignedCharArray>("ScanDirectionFlag", n);
  auto edge = NewArray<vtkUnsignedCharArray>("EdgeOfFlightLine", n);
  auto userData = NewArray<vtkUnsignedCharArray>("UserData", n);
  auto scanAngle = NewArray<vtkFloatArray>("ScanAngle", n);
  auto source = NewArray<vtkUnsignedShortArray>("PointSourceId", n);
  const bool extended = nv::las::IsExtendedFormat(format);
  const bool hasTime = nv::las::HasGpsTime(format);
  const bool hasColor = nv::las::HasColor(format);
  const bool hasInfrared = nv::las::HasNearInfrared(format);
  auto channel = NewArray<vtkUnsignedCharArray>("ScannerChannel", extended ? n : 0);
  auto gpsTime = NewArray<vtkDoubleArray>("GpsTime", hasTime ? n : 0);
  auto infrared = NewArray<vtkUnsignedShortArray>("NearInfrared", hasInfrared ? n : 0);
  std::vector<std::uint16_t> rgb(hasColor ? 3 * static_cast<std::size_t>(n) : 0);

  in.seekg(static_cast<std::streamoff>(header.PointDataOffset));
  const std::size_t length = header.PointRecordLength;
  std::vector<std::uint8_t> chunk(static_cast<std::size_t>(std::min(n, PointsPerChunk)) * length);
  nv::las::Point p;
  for (vtkIdType first = 0; first < n; first += PointsPerChunk)
  {
    const vtkIdType count = std::min(PointsPerChunk, n - first);
    in.read(reinterpret_cast<char*>(chunk.data()), static_cast<std::streamsize>(count * length));
    if (!in)
    {
      vtkErrorMacro(<< this->FileName << ": the file ends in point " << first + in.gcount() / length
                    << " of " << n << " (it changed while being read?).");
      output->Initialize();
      return nv::ReadFailed(output);
    }
    for (vtkIdType k = 0; k < count; ++k)
    {
      const vtkIdType i = first + k;
      nv::las::DecodePoint(chunk.data() + k * length, format, p);
      // The coordinate is the integer times the scale plus the offset, in double.
      xyz[3 * i] = p.X * header.Scale[0] + header.Offset[0];
      xyz[3 * i + 1] = p.Y * header.Scale[1] + header.Offset[1];
      xyz[3 * i + 2] = p.Z * header.Scale[2] + header.Offset[2];
      intensity->SetValue(i, p.Intensity);
      classification->SetValue(i, p.Classification);
      returnNumber->SetValue(i, p.ReturnNumber);
      numberOfReturns->SetValue(i, p.NumberOfReturns);
      flags->SetValue(i, p.ClassificationFlags);
      scanDirection->SetValue(i, p.ScanDirectionFlag);
      edge->SetValue(i, p.EdgeOfFlightLine);
      userData->SetValue(i, p.UserData);
      scanAngle->SetValue(i, p.ScanAngle);
      source->SetValue(i, p.PointSourceId);
      if (extended)
      {
        channel->SetValue(i, p.ScannerChannel);
      }
      if (hasTime)
      {
        gpsTime->SetValue(i, p.GpsTime);
      }
      if (hasColor)
      {
        rgb[3 * i] = p.Red;
        rgb[3 * i + 1] = p.Green;
        rgb[3 * i + 2] = p.Blue;
      }
      if (hasInfrared)
      {
        infrared->SetValue(i, p.NearInfrared);
      }
    }
    this->UpdateProgress(static_cast<double>(first + count) / n);
    if (this->GetAbortExecute())
    {
      output->Initialize();
      return 1;
    }
  }

  output->SetPoints(points);
  output->SetVerts(nv::VertexCells(n));
  vtkPointData* pd = output->GetPointData();
  for (vtkDataArray* array : { static_cast<vtkDataArray*>(intensity), static_cast<vtkDataArray*>(classification),
         static_cast<vtkDataArray*>(returnNumber), static_cast<vtkDataArray*>(numberOfReturns),
         static_cast<vtkDataArray*>(flags), static_cast<vtkDataArray*>(scanDirection),
         static_cast<vtkDataArray*>(edge), static_cast<vtkDataArray*>(userData),
         static_cast<vtkDataArray*>(scanAngle), static_cast<vtkDataArray*>(source) })
  {
    pd->AddArray(array);
  }
  if (extended)
  {
    pd->AddArray(channel);
  }
  if (hasTime)
  {
    pd->AddArray(gpsTime);
  }
  if (hasInfrared)
  {
    pd->AddArray(infrared);
  }
  if (hasColor)
  {
    // 16-bit colours to 8 bits, unless the file stores 8-bit values already.
    const bool sixteenBit = std::any_of(rgb.begin(), rgb.end(), [](std::uint16_t c) { return c > 255; });
    auto colors = NewArray<vtkUnsignedCharArray>("Colors", n, 3);
    unsigned char* c = colors->GetPointer(0);
    for (std::size_t k = 0; k < rgb.size(); ++k)
    {
      c[k] = static_cast<unsigned char>(sixteenBit ? rgb[k] >> 8 : rgb[k]);
    }
    pd->SetScalars(colors);
  }
  return 1;
}

void vtkLASPointCloudReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
}
