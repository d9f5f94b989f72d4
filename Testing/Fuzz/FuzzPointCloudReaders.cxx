// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target for the native point cloud readers: the input bytes are
// written to a file that vtkLASPointCloudReader, vtkPCDPointCloudReader,
// vtkPLYPointCloudReader and vtkPointCloudTextReader each read. Whatever the
// bytes, a reader must not crash, read out of bounds, leak or allocate
// without bound (run with -rss_limit_mb / -malloc_limit_mb), and its output
// must be consistent: no points after an error, else one vertex per point
// (the PLY reader gives vtkPLYReader's cells instead) and every array as
// long as the points. The seeds (MakeReaderSeeds) are valid files of each
// format. For the PLY reader this fuzzes nv::ply::CheckFile and what
// vtkPLYReader does with every file that check lets through.
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkExecutive.h>
#include <vtkLASPointCloudReader.h>
#include <vtkNew.h>
#include <vtkObject.h>
#include <vtkPCDPointCloudReader.h>
#include <vtkPLYPointCloudReader.h>
#include <vtkPointCloudTextReader.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <unistd.h>

namespace
{
void Require(bool condition)
{
  if (!condition)
  {
    std::abort();
  }
}

class ErrorCounter : public vtkCommand
{
public:
  static ErrorCounter* New() { return new ErrorCounter; }
  void Execute(vtkObject*, unsigned long, void*) override { ++this->Errors; }
  int Errors = 0;
};

template <typename Reader>
void ReadAndCheck(const std::string& path, bool vertexPerPoint = true)
{
  vtkNew<Reader> reader;
  vtkNew<ErrorCounter> counter;
  reader->AddObserver(vtkCommand::ErrorEvent, counter);
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, counter);
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkPolyData* cloud = reader->GetOutput();
  const vtkIdType n = cloud->GetNumberOfPoints();
  if (counter->Errors > 0)
  {
    Require(n == 0 && cloud->GetNumberOfCells() == 0);
    return;
  }
  Require(!vertexPerPoint || cloud->GetNumberOfVerts() == n);
  for (int a = 0; a < cloud->GetPointData()->GetNumberOfArrays(); ++a)
  {
    Require(cloud->GetPointData()->GetArray(a)->GetNumberOfTuples() == n);
  }
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  static const std::string path = "/tmp/nv-fuzz-readers-" + std::to_string(getpid());
  static bool quiet = (vtkObject::GlobalWarningDisplayOff(), true);
  (void)quiet;
  std::FILE* file = std::fopen(path.c_str(), "wb");
  Require(file != nullptr);
  Require(std::fwrite(data, 1, size, file) == size);
  std::fclose(file);
  ReadAndCheck<vtkLASPointCloudReader>(path);
  ReadAndCheck<vtkPCDPointCloudReader>(path);
  ReadAndCheck<vtkPLYPointCloudReader>(path, /*vertexPerPoint=*/false);
  ReadAndCheck<vtkPointCloudTextReader>(path);
  return 0;
}
