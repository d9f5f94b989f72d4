// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkPLYPointCloudReader
 * @brief   Reads PLY files as vtkPLYReader does, after checking that the
 *          file holds what its header announces.
 *
 * vtkPLYReader trusts a file's header: a PLY without a vertex element or
 * without z, a negative element count or one beyond the file crash it or
 * abort the process, and a truncated binary file reads as all the points
 * its header announces, the missing ones made up. This reader checks the
 * header and walks the data first (nv::ply::CheckFile: a vertex element
 * with x, y and z, counts within the file, list counts and the faces'
 * vertex indices within bounds, ASCII values that are numbers), and refuses
 * a file that fails with one error that names the file and what is wrong,
 * and an empty output; a text file of numbers named .ply is told to be
 * renamed .xyz. A file that passes is read by vtkPLYReader, with the same
 * output.
 *
 * CanReadFile accepts any file, so that ParaView's reader factory picks
 * this reader for .ply and the error explains a file that is not a PLY.
 *
 * @sa vtkPLYReader vtkPointCloudTextReader
 */
#ifndef vtkPLYPointCloudReader_h
#define vtkPLYPointCloudReader_h

#include "NarrowVolumeReadersModule.h" // for export macro
#include "vtkPLYReader.h"

class NARROWVOLUMEREADERS_EXPORT vtkPLYPointCloudReader : public vtkPLYReader
{
public:
  static vtkPLYPointCloudReader* New();
  vtkTypeMacro(vtkPLYPointCloudReader, vtkPLYReader);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// 1 for any file that exists: RequestData says what is wrong with one
  /// that is not a valid PLY (ParaView's reader factory asks).
  static int CanReadFile(VTK_FILEPATH const char* fileName);

protected:
  vtkPLYPointCloudReader();
  ~vtkPLYPointCloudReader() override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkPLYPointCloudReader(const vtkPLYPointCloudReader&) = delete;
  void operator=(const vtkPLYPointCloudReader&) = delete;
};

#endif
