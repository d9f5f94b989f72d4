// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The readers in C++, so that the sanitizer build runs them too: the LZF
// decoder on hand-made streams (literal runs, overlapping and maximal back
// references, and streams that must be refused without writing out of
// bounds); LAS 1.0-1.4 in every point format and PCD in its three encodings
// read back; and every file cut at many lengths, which must give either an
// error and an empty output or a consistent cloud, never a crash.
#include "nvLZF.h"
#include "nvTextCloud.h"
#include "nvTestPointFiles.h"
#include "nvTestUtilities.h"

#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkExecutive.h>
#include <vtkLASPointCloudReader.h>
#include <vtkNew.h>
#include <vtkPCDPointCloudReader.h>
#include <vtkPointCloudTextReader.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <vtksys/SystemTools.hxx>

#include <string>
#include <unistd.h>

namespace
{
/// Counts the errors a reader reports, and keeps them from printing.
class ErrorCounter : public vtkCommand
{
public:
  static ErrorCounter* New() { return new ErrorCounter; }
  void Execute(vtkObject*, unsigned long, void*) override { ++this->Errors; }
  int Errors = 0;
};

template <typename Reader>
vtkSmartPointer<vtkPolyData> Read(const std::string& path, int& errors)
{
  vtkNew<Reader> reader;
  vtkNew<ErrorCounter> counter;
  reader->AddObserver(vtkCommand::ErrorEvent, counter);
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, counter);
  reader->SetFileName(path.c_str());
  reader->Update();
  errors = counter->Errors;
  return reader->GetOutput();
}

bool Decodes(const std::string& stream, const std::string& expected)
{
  std::vector<std::uint8_t> out(expected.size());
  const bool ok = nv::LZFDecompress(
    reinterpret_cast<const std::uint8_t*>(stream.data()), stream.size(), out.data(), out.size());
  return ok && std::string(out.begin(), out.end()) == expected;
}

bool Refuses(const std::string& stream, std::size_t outputSize)
{
  // An exact-size buffer: AddressSanitizer catches any write beyond it.
  std::vector<std::uint8_t> out(outputSize);
  return !nv::LZFDecompress(
    reinterpret_cast<const std::uint8_t*>(stream.data()), stream.size(), out.data(), out.size());
}

void TestLZF()
{
  using namespace std::string_literals;
  NV_CHECK(Decodes("\x02"s "abc", "abc"));
  // "ab", then 3 bytes from 2 back: the copy reads what it writes.
  NV_CHECK(Decodes("\x01"s "ab" "\x20\x01"s, "ababa"));
  // "x", then the longest reference: 7 + 255 + 2 = 264 bytes from 1 back.
  NV_CHECK(Decodes("\x00"s "x" "\xe0\xff\x00"s, std::string(265, 'x')));
  // A reference 8192 bytes back (the farthest LZF reaches).
  std::string far(8192, 'a');
  far[0] = 'b';
  std::string stream;
  for (std::size_t at = 0; at < far.size(); at += 32)
  {
    stream += static_cast<char>(31);
    stream += far.substr(at, 32);
  }
  stream += "\x3f\xff"s; // length 1 + 2 = 3, distance 0x1fff + 1 = 8192
  NV_CHECK(Decodes(stream, far + "baa"));
  NV_CHECK(Decodes("", ""));

  NV_CHECK(Refuses("\x20\x00"s, 3));          // a reference before the start
  NV_CHECK(Refuses("\x01"s "ab" "\x20\x02"s, 5)); // 3 back from position 2
  NV_CHECK(Refuses("\x05"s "ab", 6));          // a literal run past the input
  NV_CHECK(Refuses("\x02"s "abc", 4));         // output shorter than announced
  NV_CHECK(Refuses("\x02"s "abc", 2));         // output longer than the buffer
  NV_CHECK(Refuses("\x00"s "x" "\xe0"s, 265)); // a long reference cut short
  NV_CHECK(Refuses("\x00"s "x" "\x20"s, 4));   // a reference without its distance
}

/// The points of a text cloud (nv::text::ReadCloudPoints), or {-1, line} for
/// the line it names (0: no line is a point).
std::vector<double> TextPoints(const std::string& text)
{
  std::vector<double> xyz;
  nv::text::CloudProblem problem;
  if (!nv::text::ReadCloudPoints(text.data(), text.size(), xyz, problem))
  {
    return { -1, static_cast<double>(problem.Line) };
  }
  return xyz;
}

/// The wheel's text clouds: every layout gives the same two points, and a
/// line that is not a point is named.
void TestTextCloud()
{
  using namespace std::string_literals;
  const std::vector<double> two = { 1, 2, 3, 4, 5, 6 };
  for (const std::string& text : { "1 2 3\n4 5 6\n"s, "x y z\n1,2,3\n4,5,6"s, "2\n1 2 3 0.5\n4 5 6 0.5\n"s,
         "1\t2\t3\r\n4\t5\t6\r\n\n"s, "1 2 3\n# a comment\n4 5 6\n"s, "1 2 3\n\n4 5 6 7\n"s,
         "1 2 3 red\n4 5 6 blue\n"s, "// c\n1_0e-1 2 3\r4 5 6"s })
  {
    NV_CHECK(TextPoints(text) == two);
  }
  NV_CHECK((TextPoints("1 2 3\n4 5 six\n") == std::vector<double>{ -1, 2 }));
  NV_CHECK((TextPoints("1 2\n3 4\n") == std::vector<double>{ -1, 1 }));
  NV_CHECK((TextPoints("1 2 3\n7\n") == std::vector<double>{ -1, 2 }));
  NV_CHECK((TextPoints("0x1 2 3\n") == std::vector<double>{ -1, 0 }));
  NV_CHECK((TextPoints("") == std::vector<double>{ -1, 0 }));
  std::vector<double> xyz;
  nv::text::CloudProblem problem;
  NV_CHECK(!nv::text::ReadCloudPoints("a\0b\nc\n", 6, xyz, problem) && problem.Binary && problem.Lines == 2);
  NV_CHECK(!nv::text::ReadCloudPoints("x y z\n", 6, xyz, problem) && !problem.Binary && problem.Lines == 1);
  double value = 0;
  NV_CHECK(nv::text::ParseNumber("nan", value) && value != value);
  NV_CHECK(nv::text::ParseNumber("-1.5e3", value) && value == -1500);
  NV_CHECK(!nv::text::ParseNumber("1__0", value) && !nv::text::ParseNumber("_1", value));
}

void TestLAS(const std::string& folder, const std::vector<double>& xyz)
{
  const double offset[3] = { 500000.0, 4000000.0, 0.0 };
  for (int minor = 0; minor <= 4; ++minor)
  {
    const int formats = minor <= 1 ? 2 : minor == 2 ? 4 : minor == 3 ? 6 : 11;
    for (int format = 0; format < formats; ++format)
    {
      const std::string path = folder + "/v" + std::to_string(minor) + "f" + std::to_string(format) + ".las";
      NV_CHECK(nvtest::WriteFile(path, nvtest::LASFile(minor, format, xyz, offset)));
      int errors = 0;
      vtkSmartPointer<vtkPolyData> cloud = Read<vtkLASPointCloudReader>(path, errors);
      const vtkIdType n = static_cast<vtkIdType>(xyz.size() / 3);
      NV_CHECK(errors == 0);
      NV_CHECK(cloud->GetNumberOfPoints() == n && cloud->GetNumberOfVerts() == n);
      if (cloud->GetNumberOfPoints() != n)
      {
        continue;
      }
      NV_CHECK(cloud->GetPoints()->GetDataType() == VTK_DOUBLE);
      const int last = static_cast<int>(n - 1);
      double p[3];
      cloud->GetPoint(last, p);
      for (int a = 0; a < 3; ++a)
      {
        NV_CHECK_NEAR(p[a], std::lround((xyz[3 * last + a] - offset[a]) / 0.001) * 0.001 + offset[a], 1e-9);
      }
      vtkPointData* pd = cloud->GetPointData();
      NV_CHECK(pd->GetArray("Intensity")->GetTuple1(last) == nvtest::LASIntensity(last));
      NV_CHECK(pd->GetArray("Classification")->GetTuple1(last) == nvtest::LASClass(last));
      NV_CHECK(pd->GetArray("ReturnNumber")->GetTuple1(last) == 1);
      NV_CHECK(pd->GetArray("NumberOfReturns")->GetTuple1(last) == 1);
      const bool time = format == 1 || format >= 3;
      NV_CHECK((pd->GetArray("GpsTime") != nullptr) == time);
      if (time && pd->GetArray("GpsTime"))
      {
        NV_CHECK(pd->GetArray("GpsTime")->GetTuple1(last) == nvtest::LASGpsTime(last));
      }
      const bool color = format == 2 || format == 3 || format == 5 || format == 7 || format == 8 || format == 10;
      NV_CHECK((pd->GetScalars() != nullptr) == color);
      if (color && pd->GetScalars())
      {
        NV_CHECK(pd->GetScalars()->GetComponent(last, 0) == nvtest::LASRed(last) / 256);
      }
    }
  }
}

void TestPCD(const std::string& folder, const std::vector<double>& xyz)
{
  for (const char* encoding : { "ascii", "binary", "binary_compressed" })
  {
    const std::string path = folder + "/" + encoding + ".pcd";
    NV_CHECK(nvtest::WriteFile(path, nvtest::PCDFile(encoding, xyz)));
    int errors = 0;
    vtkSmartPointer<vtkPolyData> cloud = Read<vtkPCDPointCloudReader>(path, errors);
    const vtkIdType n = static_cast<vtkIdType>(xyz.size() / 3);
    NV_CHECK(errors == 0);
    NV_CHECK(cloud->GetNumberOfPoints() == n && cloud->GetNumberOfVerts() == n);
    if (cloud->GetNumberOfPoints() != n)
    {
      continue;
    }
    double p[3];
    cloud->GetPoint(n - 1, p);
    for (int a = 0; a < 3; ++a)
    {
      NV_CHECK(p[a] == static_cast<float>(xyz[3 * (n - 1) + a]));
    }
    vtkDataArray* intensity = cloud->GetPointData()->GetArray("intensity");
    NV_CHECK(intensity && intensity->GetDataType() == VTK_UNSIGNED_SHORT &&
      intensity->GetTuple1(n - 1) == nvtest::PCDIntensity(static_cast<int>(n - 1)));
    vtkDataArray* colors = cloud->GetPointData()->GetScalars();
    NV_CHECK(colors && colors->GetNumberOfComponents() == 3 && colors->GetComponent(0, 0) == 0x10 &&
      colors->GetComponent(0, 1) == 0x20 && colors->GetComponent(0, 2) == 0x30);
  }
}

/// Every file cut at many lengths: an error and an empty output, or a
/// cloud whose vertices and arrays match its points; never a crash.
template <typename Reader>
void TestTruncations(const std::string& path, const nvtest::Bytes& bytes, int& refused)
{
  const std::size_t step = std::max<std::size_t>(1, bytes.size() / 150);
  for (std::size_t length = 0; length < bytes.size(); length += step)
  {
    NV_CHECK(nvtest::WriteFile(path, nvtest::Bytes(bytes.begin(), bytes.begin() + length)));
    int errors = 0;
    vtkSmartPointer<vtkPolyData> cloud = Read<Reader>(path, errors);
    const vtkIdType n = cloud->GetNumberOfPoints();
    if (errors > 0)
    {
      ++refused;
      NV_CHECK(n == 0 && cloud->GetNumberOfCells() == 0);
      continue;
    }
    NV_CHECK(cloud->GetNumberOfVerts() == n);
    for (int a = 0; a < cloud->GetPointData()->GetNumberOfArrays(); ++a)
    {
      NV_CHECK(cloud->GetPointData()->GetArray(a)->GetNumberOfTuples() == n);
    }
  }
}
} // namespace

int main()
{
  TestLZF();
  TestTextCloud();
  const std::string folder = "TestReaders-" + std::to_string(getpid());
  vtksys::SystemTools::MakeDirectory(folder);
  const double center[3] = { 500123.25, 4001234.5, 300.0 };
  const std::vector<double> xyz = nvtest::SpherePoints(64, 25.0, center);
  TestLAS(folder, xyz);
  TestPCD(folder, xyz);

  int refused = 0;
  const double offset[3] = { 500000.0, 4000000.0, 0.0 };
  for (int format : { 0, 3, 6, 10 })
  {
    const nvtest::Bytes file = nvtest::LASFile(4, format, xyz, offset);
    TestTruncations<vtkLASPointCloudReader>(folder + "/cut.las", file, refused);
  }
  for (const char* encoding : { "ascii", "binary", "binary_compressed" })
  {
    TestTruncations<vtkPCDPointCloudReader>(folder + "/cut.pcd", nvtest::PCDFile(encoding, xyz), refused);
  }
  TestTruncations<vtkPointCloudTextReader>(folder + "/cut.xyz", nvtest::TextFile(xyz), refused);
  // Every cut of a LAS or binary PCD file loses points the header announces.
  NV_CHECK(refused > 4 * 140);
  std::printf("truncated files refused with an error: %d\n", refused);
  vtksys::SystemTools::RemoveADirectory(folder);
  return nvtest::Result("TestReaders");
}
