// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkPCDPointCloudReader
 * @brief   Reads PCD point clouds (the Point Cloud Library's format): ascii,
 *          binary and binary_compressed (LZF) data.
 *
 * The x, y, z fields become the points (double precision). Every other
 * field of the header's FIELDS becomes a point data array of the same name,
 * with the type its SIZE and TYPE give (I1 signed char ... F8 double) and
 * COUNT components, except:
 * - "rgb" and "rgba" (a 32-bit value packing 0xAARRGGBB, stored as a float
 *   or an unsigned int by PCL) become "Colors", unsigned char RGB (RGBA for
 *   "rgba"), the active scalars;
 * - normal_x, normal_y, normal_z become "Normals", the active normals;
 * - "_" fields are padding and are skipped.
 * Points whose x, y or z is not finite (PCL marks the holes of organized
 * clouds with NaN) are left out unless SkipInvalidPoints is off. The output
 * has one vertex cell per point.
 *
 * The header is checked against the file before anything is allocated: a
 * point count beyond what the data can hold, sizes that disagree, a damaged
 * LZF stream or a truncated file give an error that says which, and an
 * empty output.
 *
 * @sa vtkLASPointCloudReader vtkPointCloudTextReader
 */
#ifndef vtkPCDPointCloudReader_h
#define vtkPCDPointCloudReader_h

#include "NarrowVolumeReadersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <string> // for the file name

class NARROWVOLUMEREADERS_EXPORT vtkPCDPointCloudReader : public vtkPolyDataAlgorithm
{
public:
  static vtkPCDPointCloudReader* New();
  vtkTypeMacro(vtkPCDPointCloudReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The .pcd file to read.
  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);
  ///@}

  ///@{
  /// Leave out the points whose x, y or z is NaN or infinite. Default on.
  vtkSetMacro(SkipInvalidPoints, bool);
  vtkGetMacro(SkipInvalidPoints, bool);
  vtkBooleanMacro(SkipInvalidPoints, bool);
  ///@}

  /// 1 if the file starts like a PCD header (ParaView's reader factory asks).
  int CanReadFile(const char* fileName);

protected:
  vtkPCDPointCloudReader();
  ~vtkPCDPointCloudReader() override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  std::string FileName;
  bool SkipInvalidPoints = true;

private:
  vtkPCDPointCloudReader(const vtkPCDPointCloudReader&) = delete;
  void operator=(const vtkPCDPointCloudReader&) = delete;
};

#endif
