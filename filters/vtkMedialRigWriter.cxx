#include "vtkMedialRigWriter.h"

#include "MedialFileNames.h"
#include "MedialMeshData.h"
#include "MedialSkeletonData.h"
#include "rig/RigExport.h"

#include <vtkDataArray.h>
#include <vtkErrorCode.h>
#include <vtkInformation.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkTriangleFilter.h>

#include <cmath>
#include <cstdio>

vtkStandardNewMacro(vtkMedialRigWriter);

vtkMedialRigWriter::vtkMedialRigWriter() { this->SetNumberOfInputPorts(2); }

void vtkMedialRigWriter::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
  os << indent << "MaxInfluences: " << this->MaxInfluences << "\n";
  os << indent << "UpAxis: " << this->UpAxis << "\n";
  os << indent << "Scale: " << this->Scale << "\n";
}

void vtkMedialRigWriter::SetSkeletonData(vtkPolyData* skeleton) { this->SetInputData(1, skeleton); }

bool vtkMedialRigWriter::CanWriteFile(const char* fileName) {
  const std::string e = medial::fileExtension(fileName);
  return e == ".glb" || e == ".fbx";
}

int vtkMedialRigWriter::FillInputPortInformation(int, vtkInformation* info) {
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

void vtkMedialRigWriter::Fail(unsigned long code) { this->SetErrorCode(code); }

void vtkMedialRigWriter::WriteData() {
  this->SetErrorCode(vtkErrorCode::NoError);
  if (this->FileName.empty()) {
    vtkErrorMacro(<< "no file name given");
    return this->Fail(vtkErrorCode::NoFileNameError);
  }
  if (!CanWriteFile(this->FileName.c_str())) {
    vtkErrorMacro(<< this->FileName << ": a rig is written as " << GetExtensions());
    return this->Fail(vtkErrorCode::UnrecognizedFileTypeError);
  }
  vtkPolyData* mesh = vtkPolyData::SafeDownCast(this->GetInputDataObject(0, 0));
  vtkPolyData* skeletonData = vtkPolyData::SafeDownCast(this->GetInputDataObject(1, 0));
  if (!mesh || !skeletonData) {
    vtkErrorMacro(<< this->FileName << ": a rig needs the mesh (port 0) and the skeleton (port 1)");
    return this->Fail(vtkErrorCode::UnknownError);
  }
  vtkDataArray* weights = mesh->GetPointData()->GetArray("SkinWeights");
  if (!weights) {
    vtkErrorMacro(<< this->FileName
                  << ": the mesh has no SkinWeights point data (compute the weights first)");
    return this->Fail(vtkErrorCode::UnknownError);
  }

  medial::Rig rig;
  std::string error;
  if (!medial::skeletonFromPolyData(skeletonData, rig.skeleton, error)) {
    vtkErrorMacro(<< this->FileName << ": " << error);
    return this->Fail(vtkErrorCode::UnknownError);
  }
  const vtkSmartPointer<vtkPolyData> triangles = medial::triangulated(mesh);
  rig.mesh = medial::toTriangleMesh(triangles);
  vtkDataArray* triangulatedWeights = triangles->GetPointData()->GetArray("SkinWeights");
  rig.weights = medial::matrixFromArray(triangulatedWeights);

  medial::RigExportOptions options;
  options.maxInfluences = this->MaxInfluences;
  options.upAxis = this->UpAxis;
  options.scale = this->Scale;
  Eigen::Matrix3d turn;
  if (!medial::upAxisRotation(options.upAxis, turn)) {
    vtkErrorMacro(<< this->FileName << ": UpAxis is '" << this->UpAxis << "': one of x, y, z, -x, -y, -z");
    return this->Fail(vtkErrorCode::UnknownError);
  }
  if (!(this->Scale > 0) || !std::isfinite(this->Scale)) {
    vtkErrorMacro(<< this->FileName << ": Scale is " << this->Scale << ": a positive number");
    return this->Fail(vtkErrorCode::UnknownError);
  }
  const std::string format = medial::rigFormatForFile(this->FileName);
  const auto write = [&](const std::string& temporary, std::string& why) {
    why = medial::exportRig(rig, temporary, format, options);
    return why.empty();
  };
  if (!medial::writeAtomically(this->FileName, write, error)) {
    vtkErrorMacro(<< this->FileName << ": " << error);
    return this->Fail(vtkErrorCode::CannotOpenFileError);
  }
}
