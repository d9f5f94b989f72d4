// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkPLYPointCloudReader.h"

#include "nvPLY.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include <vtksys/SystemTools.hxx>

#include <sstream>
#include <string>

vtkStandardNewMacro(vtkPLYPointCloudReader);

vtkPLYPointCloudReader::vtkPLYPointCloudReader() = default;

vtkPLYPointCloudReader::~vtkPLYPointCloudReader() = default;

int vtkPLYPointCloudReader::CanReadFile(const char* fileName)
{
  return fileName && vtksys::SystemTools::FileExists(fileName, /*isFile=*/true) ? 1 : 0;
}

int vtkPLYPointCloudReader::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  std::string error;
  const bool valid = this->ReadFromInputString
    ? nv::ply::CheckText(this->InputString, error)
    : nv::ply::CheckFile(this->FileName ? this->FileName : "", error);
  if (!valid)
  {
    vtkPolyData::GetData(outputVector, 0)->Initialize();
    vtkErrorMacro(<< (this->ReadFromInputString ? std::string("the input string")
                                                  : std::string(this->FileName ? this->FileName : ""))
                  << ": " << error << ".");
    // 1, not 0: the error says it all, where a failed request would add the
    // executive's dump of the pipeline's state after it.
    return 1;
  }
  return this->Superclass::RequestData(request, inputVector, outputVector);
}

void vtkPLYPointCloudReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
