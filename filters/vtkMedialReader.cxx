#include "vtkMedialReader.h"

#include "MedialErrorCollector.h"
#include "MedialFileNames.h"
#include "MedialMeshData.h"
#include "MedialSkeletonData.h"
#include "MedialSketchData.h"
#include "vtkMedialINRReader.h"
#include "vtkMedialITKImageReader.h"
#include "vtkMedialInVesaliusReader.h"
#include "vtkMedialOFFReader.h"
#include "vtkMedialSWCReader.h"
#include "vtkMedialSketchReader.h"

#include <vtkBYUReader.h>
#include <vtkCompositeDataGeometryFilter.h>
#include <vtkDataObject.h>
#include <vtkGLTFReader.h>
#include <vtkGenericDataObjectReader.h>
#include <vtkGeometryFilter.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMatrix3x3.h>
#include <vtkOBJReader.h>
#include <vtkObjectFactory.h>
#include <vtkPLYReader.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include "rig/RigImport.h"

#include <sys/stat.h>

#include <set>

vtkStandardNewMacro(vtkMedialReader);

namespace {

const std::set<std::string> kMeshExtensions = {".vtp", ".vtk", ".vtu",  ".obj", ".ply", ".stl", ".off",
                                               ".g",   ".byu", ".gltf", ".glb", ".fbx", ".swc", ".txt"};
const std::set<std::string> kVolumeExtensions = {".nii",  ".nii.gz", ".mha", ".mhd",    ".nrrd", ".nhdr",
                                                 ".gipl", ".dcm",    ".inr", ".inr.gz", ".vti",  ".inv3"};

bool isDirectory(const std::string& path) {
  struct stat status;
  return ::stat(path.c_str(), &status) == 0 && S_ISDIR(status.st_mode);
}

bool exists(const std::string& path) {
  struct stat status;
  return ::stat(path.c_str(), &status) == 0;
}

// A legacy .vtk file holds an image when its header says so.
bool legacyFileIsImage(const std::string& path) {
  auto reader = vtkSmartPointer<vtkGenericDataObjectReader>::New();
  auto quiet = medial::ErrorCollector::Watch(reader);
  reader->SetFileName(path.c_str());
  const int type = reader->ReadOutputType();
  return type == VTK_IMAGE_DATA || type == VTK_STRUCTURED_POINTS;
}

// Runs `reader`, returns its output or null with `error` set from what it reported.
vtkSmartPointer<vtkDataObject> runReader(vtkAlgorithm* reader, std::string& error) {
  auto errors = medial::ErrorCollector::Watch(reader);
  reader->Update();
  if (errors->HasErrors()) {
    error = errors->Joined();
    return nullptr;
  }
  return reader->GetOutputDataObject(0);
}

}  // namespace

vtkMedialReader::vtkMedialReader() { this->SetNumberOfInputPorts(0); }

vtkMedialReader::~vtkMedialReader() = default;

void vtkMedialReader::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
  os << indent << "RigSkeleton: " << this->RigSkeleton << "\n";
}

bool vtkMedialReader::IsVolumeFile(const char* fileName) {
  if (!fileName) return false;
  const std::string extension = medial::fileExtension(fileName);
  if (extension == ".vtk") return legacyFileIsImage(fileName);
  return kVolumeExtensions.count(extension) > 0 || isDirectory(fileName);
}

bool vtkMedialReader::CanReadFile(const char* fileName) {
  if (!fileName) return false;
  const std::string extension = medial::fileExtension(fileName);
  return kMeshExtensions.count(extension) || kVolumeExtensions.count(extension) || isDirectory(fileName);
}

const char* vtkMedialReader::GetMeshExtensions() {
  return "*.vtp *.vtk *.vtu *.obj *.ply *.stl *.off *.g *.byu *.gltf *.glb *.fbx *.swc";
}

const char* vtkMedialReader::GetSketchExtensions() { return "*.txt"; }

const char* vtkMedialReader::GetVolumeExtensions() {
  return "*.nii *.nii.gz *.mha *.mhd *.nrrd *.nhdr *.gipl *.dcm *.inr *.inr.gz *.vti *.inv3";
}

int vtkMedialReader::FillOutputPortInformation(int, vtkInformation* info) {
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkDataObject");
  return 1;
}

int vtkMedialReader::RequestDataObject(vtkInformation*, vtkInformationVector**,
                                       vtkInformationVector* outputVector) {
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  // Decided once per update: for a legacy .vtk file it means reading the header.
  const bool volume = this->ReadsVolume = IsVolumeFile(this->FileName.c_str());
  vtkDataObject* current = outInfo->Get(vtkDataObject::DATA_OBJECT());
  if (volume && !vtkImageData::SafeDownCast(current)) {
    outInfo->Set(vtkDataObject::DATA_OBJECT(), vtkSmartPointer<vtkImageData>::New());
  } else if (!volume && !vtkPolyData::SafeDownCast(current)) {
    outInfo->Set(vtkDataObject::DATA_OBJECT(), vtkSmartPointer<vtkPolyData>::New());
  }
  return 1;
}

int vtkMedialReader::RequestInformation(vtkInformation*, vtkInformationVector**,
                                        vtkInformationVector* outputVector) {
  // The whole file is read here, once per file name: volumes need their extent, spacing, origin and
  // direction known now, and most of Medial's volume formats only tell them by being read.
  if (!this->Result || this->ResultFileName != this->FileName || this->ResultTime != this->GetMTime()) {
    this->ResultFileName = this->FileName;
    this->ResultTime = this->GetMTime();
    this->ReadFile();
  }
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  if (auto* image = vtkImageData::SafeDownCast(this->Result)) {
    outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), image->GetExtent(), 6);
    outInfo->Set(vtkDataObject::SPACING(), image->GetSpacing(), 3);
    outInfo->Set(vtkDataObject::ORIGIN(), image->GetOrigin(), 3);
    outInfo->Set(vtkDataObject::DIRECTION(), image->GetDirectionMatrix()->GetData(), 9);
    if (vtkDataArray* scalars = image->GetPointData()->GetScalars())
      vtkDataObject::SetPointDataActiveScalarInfo(outInfo, scalars->GetDataType(),
                                                  scalars->GetNumberOfComponents());
  } else if (this->ReadsVolume) {
    const int empty[6] = {0, -1, 0, -1, 0, -1};
    outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), empty, 6);
  }
  return 1;
}

int vtkMedialReader::RequestData(vtkInformation*, vtkInformationVector**,
                                 vtkInformationVector* outputVector) {
  vtkDataObject* output = vtkDataObject::GetData(outputVector);
  if (!this->ErrorMessage.empty() || !this->Result) {
    vtkErrorMacro(<< (this->ErrorMessage.empty() ? "nothing was read" : this->ErrorMessage));
    return 0;
  }
  if (output->GetDataObjectType() != this->Result->GetDataObjectType()) {
    vtkErrorMacro(<< this->FileName << ": read a " << this->Result->GetClassName() << " where a "
                  << output->GetClassName() << " was expected");
    return 0;
  }
  output->ShallowCopy(this->Result);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkMedialReader::ReadFile() {
  this->ErrorMessage.clear();
  this->Result = nullptr;
  const std::string& path = this->FileName;
  if (path.empty()) {
    this->ErrorMessage = "no file name given";
    return;
  }
  if (!exists(path)) {
    this->ErrorMessage = path + ": no such file or directory";
    return;
  }
  const std::string extension = medial::fileExtension(path);
  if (!CanReadFile(path.c_str())) {
    this->ErrorMessage = path + ": unsupported file type '" + extension +
                         "' (meshes: " + GetMeshExtensions() + "; volumes: " + GetVolumeExtensions() +
                         "; sketches: " + GetSketchExtensions() + ")";
    return;
  }
  this->UpdateProgress(0.05);
  vtkSmartPointer<vtkDataObject> data =
      this->ReadsVolume ? this->ReadVolume(extension) : this->ReadPolyData(extension);
  if (!data) return;  // ErrorMessage set
  this->Result = data;
}

vtkSmartPointer<vtkDataObject> vtkMedialReader::ReadRig() {
  const std::string& path = this->FileName;
  const medial::ImportedRig rig = medial::importRig(path);
  if (!rig.error.empty()) {
    this->ErrorMessage = path + ": " + rig.error;
    return nullptr;
  }
  if (!this->RigSkeleton) return medial::polyDataFromMesh(rig.mesh);
  if (rig.skeleton.edgeCount() == 0) {
    this->ErrorMessage = path + ": the file holds no joints (not a rig)";
    return nullptr;
  }
  return medial::polyDataFromSkeleton(rig.skeleton);
}

vtkSmartPointer<vtkDataObject> vtkMedialReader::ReadPolyData(const std::string& extension) {
  const std::string& path = this->FileName;
  if (extension == ".fbx" || (this->RigSkeleton && (extension == ".glb" || extension == ".gltf")))
    return this->ReadRig();
  vtkSmartPointer<vtkAlgorithm> reader;
  if (extension == ".vtp") {
    auto r = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  } else if (extension == ".vtk") {
    auto r = vtkSmartPointer<vtkGenericDataObjectReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  } else if (extension == ".vtu") {
    auto r = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  } else if (extension == ".obj") {
    auto r = vtkSmartPointer<vtkOBJReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  } else if (extension == ".ply") {
    auto r = vtkSmartPointer<vtkPLYReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  } else if (extension == ".stl") {
    auto r = vtkSmartPointer<vtkSTLReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  } else if (extension == ".off") {
    auto r = vtkSmartPointer<vtkMedialOFFReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  } else if (extension == ".g" || extension == ".byu") {
    auto r = vtkSmartPointer<vtkBYUReader>::New();
    r->SetGeometryFileName(path.c_str());
    reader = r;
  } else if (extension == ".gltf" || extension == ".glb") {
    // A glTF scene (e.g. a rig exported by Medial or Blender): its meshes, node transforms applied, merged.
    auto r = vtkSmartPointer<vtkGLTFReader>::New();
    r->SetFileName(path.c_str());
    auto merge = vtkSmartPointer<vtkCompositeDataGeometryFilter>::New();
    merge->SetInputConnection(r->GetOutputPort());
    reader = merge;
  } else if (extension == ".txt") {  // a sketch: strokes with placements
    auto r = vtkSmartPointer<vtkMedialSketchReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  } else {  // .swc
    auto r = vtkSmartPointer<vtkMedialSWCReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  }

  std::string error;
  vtkSmartPointer<vtkDataObject> data = runReader(reader, error);
  if (!data) {
    this->ErrorMessage = error.rfind(path, 0) == 0 ? error : path + ": " + error;
    return nullptr;
  }
  // Datasets that are not polydata (a .vtu, or a .vtk unstructured grid): their outer surface.
  vtkSmartPointer<vtkPolyData> polyData = vtkPolyData::SafeDownCast(data);
  if (!polyData) {
    auto* dataSet = vtkDataSet::SafeDownCast(data);
    if (!dataSet) {
      this->ErrorMessage = path + ": holds a " + data->GetClassName() + ", not a mesh";
      return nullptr;
    }
    auto surface = vtkSmartPointer<vtkGeometryFilter>::New();
    surface->SetInputData(dataSet);
    surface->Update();
    polyData = surface->GetOutput();
  }
  if (polyData->GetNumberOfPoints() == 0 || polyData->GetNumberOfCells() == 0) {
    this->ErrorMessage = path + ": the file holds no mesh (no points or no cells)";
    return nullptr;
  }
  if (medial::looksLikeSkeleton(polyData) && !medial::isSketch(polyData)) {
    medial::Skeleton skeleton;
    if (!medial::skeletonFromPolyData(polyData, skeleton, error)) {
      this->ErrorMessage = path + ": " + error;
      return nullptr;
    }
    if (const auto problems = medial::validateSkeleton(skeleton); !problems.empty()) {
      this->ErrorMessage = path + ": invalid skeleton: " + medial::describeProblems(problems);
      return nullptr;
    }
  }
  return polyData;
}

vtkSmartPointer<vtkDataObject> vtkMedialReader::ReadVolume(const std::string& extension) {
  const std::string& path = this->FileName;
  vtkSmartPointer<vtkAlgorithm> reader;
  if (extension == ".inr" || extension == ".inr.gz") {
    auto r = vtkSmartPointer<vtkMedialINRReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  } else if (extension == ".inv3") {
    auto r = vtkSmartPointer<vtkMedialInVesaliusReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  } else if (extension == ".vti") {
    auto r = vtkSmartPointer<vtkXMLImageDataReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  } else if (extension == ".vtk") {
    auto r = vtkSmartPointer<vtkGenericDataObjectReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  } else {
    auto r = vtkSmartPointer<vtkMedialITKImageReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  }
  std::string error;
  vtkSmartPointer<vtkDataObject> data = runReader(reader, error);
  auto* image = vtkImageData::SafeDownCast(data);
  if (!image) {
    if (error.empty()) error = "not an image";
    this->ErrorMessage = error.rfind(path, 0) == 0 ? error : path + ": " + error;
    return nullptr;
  }
  if (image->GetNumberOfPoints() == 0 || !image->GetPointData()->GetScalars()) {
    this->ErrorMessage = path + ": the image holds no voxels";
    return nullptr;
  }
  // vtkStructuredPoints (legacy files) is an image too; hand on a plain vtkImageData.
  auto copy = vtkSmartPointer<vtkImageData>::New();
  copy->ShallowCopy(image);
  return copy;
}
