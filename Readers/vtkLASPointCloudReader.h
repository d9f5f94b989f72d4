// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLASPointCloudReader
 * @brief   Reads LAS 1.0 to 1.4 point clouds (uncompressed, point formats 0-10).
 *
 * The points come out in double precision, each coordinate the record's
 * integer times the header's scale plus its offset: airborne and mobile
 * LiDAR sits at UTM-sized coordinates (hundreds of kilometres), where single
 * precision loses centimetres. Point data:
 * - "Intensity" (unsigned short), "Classification" (unsigned char: the class
 *   number, 5 bits in formats 0-5, 8 bits in 6-10);
 * - "ReturnNumber", "NumberOfReturns", "ClassificationFlags" (bit 0
 *   synthetic, 1 key-point, 2 withheld, 3 overlap), "ScanDirectionFlag",
 *   "EdgeOfFlightLine", "UserData" (unsigned char), "ScanAngle" (float,
 *   degrees), "PointSourceId" (unsigned short);
 * - "ScannerChannel" (unsigned char) in formats 6-10, "GpsTime" (double) in
 *   formats 1 and 3-10;
 * - "Colors" (unsigned char RGB, the active scalars) in formats 2, 3, 5, 7,
 *   8 and 10: LAS stores 16-bit colours, which are scaled to 8 bits (divided
 *   by 256) unless no value of the file exceeds 255 (files that store 8-bit
 *   colours in the 16-bit fields);
 * - "NearInfrared" (unsigned short) in formats 8 and 10.
 * Extra bytes and waveform packets are skipped. The output has one vertex
 * cell per point.
 *
 * The header is checked against the file before anything is allocated: a
 * truncated file, header sizes or offsets the file cannot hold, a point
 * count beyond the file's size, an unknown point format or LAZ-compressed
 * points give an error that says which, and an empty output.
 *
 * @sa vtkPCDPointCloudReader vtkPointCloudTextReader
 */
#ifndef vtkLASPointCloudReader_h
#define vtkLASPointCloudReader_h

#include "NarrowVolumeReadersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <string> // for the file name

class NARROWVOLUMEREADERS_EXPORT vtkLASPointCloudReader : public vtkPolyDataAlgorithm
{
public:
  static vtkLASPointCloudReader* New();
  vtkTypeMacro(vtkLASPointCloudReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The .las file to read.
  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);
  ///@}

  /// 1 if the file starts like an uncompressed LAS 1.0-1.4 file (ParaView's
  /// reader factory asks).
  int CanReadFile(const char* fileName);

protected:
  vtkLASPointCloudReader();
  ~vtkLASPointCloudReader() override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  std::string FileName;

private:
  vtkLASPointCloudReader(const vtkLASPointCloudReader&) = delete;
  void operator=(const vtkLASPointCloudReader&) = delete;
};

#endif
