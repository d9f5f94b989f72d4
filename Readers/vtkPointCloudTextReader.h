// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkPointCloudTextReader
 * @brief   Reads plain-text point clouds (.xyz, .pts, .txt) into vtkPolyData.
 *
 * One point per line: x y z, separated by spaces, tabs or commas, optionally
 * followed by more columns, read by their count:
 * - 1 extra column: "Intensity";
 * - 3: "Colors" (unsigned char RGB) when all three are integers in [0, 255]
 *   on the first point, else "Normals";
 * - 4: "Intensity" then "Colors" (the common .pts layout);
 * - 6: "Normals" then "Colors", or "Colors" then "Normals" (told apart the
 *   same way);
 * - any other count: "Column4", "Column5", ... as scalars.
 * A first line of column names (CSV), a first line holding a single integer
 * (the point count of .pts files) and lines starting with # or // are
 * skipped. The output has one vertex cell per point, so ParaView shows the
 * cloud at once. A malformed line is a clear error naming the line, with an
 * empty output.
 *
 * @sa vtkLASPointCloudReader vtkPCDPointCloudReader
 */
#ifndef vtkPointCloudTextReader_h
#define vtkPointCloudTextReader_h

#include "NarrowVolumeReadersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <string> // for the file name

class NARROWVOLUMEREADERS_EXPORT vtkPointCloudTextReader : public vtkPolyDataAlgorithm
{
public:
  static vtkPointCloudTextReader* New();
  vtkTypeMacro(vtkPointCloudTextReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The file to read.
  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);
  ///@}

  /// 1 if the file looks like a text point cloud: its first line of data is
  /// numbers (ParaView's reader factory asks).
  int CanReadFile(const char* fileName);

protected:
  vtkPointCloudTextReader();
  ~vtkPointCloudTextReader() override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  std::string FileName;

private:
  vtkPointCloudTextReader(const vtkPointCloudTextReader&) = delete;
  void operator=(const vtkPointCloudTextReader&) = delete;
};

#endif
