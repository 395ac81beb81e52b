#include "vtkMedialImageFileReader.h"

#include <vtkDataArray.h>
#include <vtkDataObject.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMatrix3x3.h>
#include <vtkPointData.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include <sys/stat.h>

vtkMedialImageFileReader::vtkMedialImageFileReader() { this->SetNumberOfInputPorts(0); }

vtkMedialImageFileReader::~vtkMedialImageFileReader() = default;

void vtkMedialImageFileReader::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
}

int vtkMedialImageFileReader::RequestInformation(vtkInformation*, vtkInformationVector**,
                                                 vtkInformationVector* outputVector) {
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  // Read once per file name and parameter change: headers of several formats (DICOM series, .inv3
  // archives, .inr.gz) can only be known by reading most of the file anyway.
  if (!this->Cache || this->CachedFileName != this->FileName || this->CachedTime != this->GetMTime()) {
    this->Cache = vtkSmartPointer<vtkImageData>::New();
    this->CachedFileName = this->FileName;
    this->CachedTime = this->GetMTime();
    this->CachedError.clear();
    struct stat status;
    if (this->FileName.empty())
      this->CachedError = "no file name given";
    else if (::stat(this->FileName.c_str(), &status) != 0)
      this->CachedError = this->FileName + ": no such file or directory";
    else if (!this->ReadImage(this->FileName, this->Cache, this->CachedError))
      this->CachedError = this->FileName + ": " + this->CachedError;
    else if (this->Cache->GetNumberOfPoints() == 0 || !this->Cache->GetPointData()->GetScalars())
      this->CachedError = this->FileName + ": the image holds no voxels";
    if (!this->CachedError.empty()) this->Cache = vtkSmartPointer<vtkImageData>::New();
  }
  if (!this->CachedError.empty()) {
    const int empty[6] = {0, -1, 0, -1, 0, -1};
    outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), empty, 6);
    return 1;  // the error is reported once, by RequestData
  }
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), this->Cache->GetExtent(), 6);
  outInfo->Set(vtkDataObject::SPACING(), this->Cache->GetSpacing(), 3);
  outInfo->Set(vtkDataObject::ORIGIN(), this->Cache->GetOrigin(), 3);
  outInfo->Set(vtkDataObject::DIRECTION(), this->Cache->GetDirectionMatrix()->GetData(), 9);
  vtkDataArray* scalars = this->Cache->GetPointData()->GetScalars();
  vtkDataObject::SetPointDataActiveScalarInfo(outInfo, scalars->GetDataType(),
                                              scalars->GetNumberOfComponents());
  return 1;
}

int vtkMedialImageFileReader::RequestData(vtkInformation*, vtkInformationVector**,
                                          vtkInformationVector* outputVector) {
  vtkImageData* output = vtkImageData::GetData(outputVector);
  if (!this->CachedError.empty()) {
    vtkErrorMacro(<< this->CachedError);
    return 0;
  }
  output->ShallowCopy(this->Cache);
  this->UpdateProgress(1.0);
  return 1;
}
