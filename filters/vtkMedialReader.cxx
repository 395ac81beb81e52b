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

#include <string>

vtkStandardNewMacro(vtkMedialReader);

namespace {

// A reader of one file type, given the file's path.
using ReaderFactory = vtkSmartPointer<vtkAlgorithm> (*)(const std::string& path);

template <class Reader>
vtkSmartPointer<vtkAlgorithm> fileReader(const std::string& path) {
  auto reader = vtkSmartPointer<Reader>::New();
  reader->SetFileName(path.c_str());
  return reader;
}

vtkSmartPointer<vtkAlgorithm> byuReader(const std::string& path) {
  auto reader = vtkSmartPointer<vtkBYUReader>::New();
  reader->SetGeometryFileName(path.c_str());
  return reader;
}

// A glTF scene (e.g. a rig exported by Medial or Blender): its meshes, node transforms applied, merged.
vtkSmartPointer<vtkAlgorithm> gltfReader(const std::string& path) {
  auto merge = vtkSmartPointer<vtkCompositeDataGeometryFilter>::New();
  merge->SetInputConnection(fileReader<vtkGLTFReader>(path)->GetOutputPort());
  return merge;
}

struct FileType {
  const char* extension;
  ReaderFactory reader;  // null: read as a rig (ReadRig)
};

// Meshes and skeletons; a legacy .vtk file is a volume instead when its header says it holds an image.
const FileType kMeshTypes[] = {
    {".vtp", fileReader<vtkXMLPolyDataReader>},
    {".vtk", fileReader<vtkGenericDataObjectReader>},
    {".vtu", fileReader<vtkXMLUnstructuredGridReader>},
    {".obj", fileReader<vtkOBJReader>},
    {".ply", fileReader<vtkPLYReader>},
    {".stl", fileReader<vtkSTLReader>},
    {".off", fileReader<vtkMedialOFFReader>},
    {".g", byuReader},
    {".byu", byuReader},
    {".gltf", gltfReader},  // with RigSkeleton: a rig
    {".glb", gltfReader},   // with RigSkeleton: a rig
    {".fbx", nullptr},
    {".swc", fileReader<vtkMedialSWCReader>},
};
const FileType kSketchTypes[] = {{".txt", fileReader<vtkMedialSketchReader>}};  // strokes with placements
const FileType kVolumeTypes[] = {
    {".nii", fileReader<vtkMedialITKImageReader>},    {".nii.gz", fileReader<vtkMedialITKImageReader>},
    {".mha", fileReader<vtkMedialITKImageReader>},    {".mhd", fileReader<vtkMedialITKImageReader>},
    {".nrrd", fileReader<vtkMedialITKImageReader>},   {".nhdr", fileReader<vtkMedialITKImageReader>},
    {".gipl", fileReader<vtkMedialITKImageReader>},   {".dcm", fileReader<vtkMedialITKImageReader>},
    {".inr", fileReader<vtkMedialINRReader>},         {".inr.gz", fileReader<vtkMedialINRReader>},
    {".vti", fileReader<vtkXMLImageDataReader>},      {".inv3", fileReader<vtkMedialInVesaliusReader>},
    {".vtk", fileReader<vtkGenericDataObjectReader>},  // when its header says it holds an image
};

template <size_t N>
const FileType* findType(const FileType (&types)[N], const std::string& extension) {
  for (const FileType& type : types)
    if (extension == type.extension) return &type;
  return nullptr;
}

// "*.a *.b ..." of a table, without `skip`.
template <size_t N>
std::string patterns(const FileType (&types)[N], const std::string& skip = "") {
  std::string text;
  for (const FileType& type : types)
    if (type.extension != skip) text += std::string(text.empty() ? "" : " ") + "*" + type.extension;
  return text;
}

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
  return findType(kVolumeTypes, extension) || isDirectory(fileName);
}

bool vtkMedialReader::CanReadFile(const char* fileName) {
  if (!fileName) return false;
  const std::string extension = medial::fileExtension(fileName);
  return findType(kMeshTypes, extension) || findType(kSketchTypes, extension) ||
         findType(kVolumeTypes, extension) || isDirectory(fileName);
}

const char* vtkMedialReader::GetMeshExtensions() {
  static const std::string text = patterns(kMeshTypes);
  return text.c_str();
}

const char* vtkMedialReader::GetSketchExtensions() {
  static const std::string text = patterns(kSketchTypes);
  return text.c_str();
}

const char* vtkMedialReader::GetVolumeExtensions() {
  static const std::string text = patterns(kVolumeTypes, ".vtk");  // .vtk is listed with the meshes
  return text.c_str();
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
  const FileType* type = findType(kMeshTypes, extension);
  if (!type) type = findType(kSketchTypes, extension);
  if (!type) {  // CanReadFile lets no other type through
    this->ErrorMessage = path + ": not a mesh, skeleton or sketch file";
    return nullptr;
  }
  if (!type->reader || (this->RigSkeleton && (extension == ".glb" || extension == ".gltf")))
    return this->ReadRig();
  vtkSmartPointer<vtkAlgorithm> reader = type->reader(path);
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
  const FileType* type = findType(kVolumeTypes, extension);
  // A DICOM series directory (no extension) goes to ITK.
  vtkSmartPointer<vtkAlgorithm> reader =
      type ? type->reader(path) : fileReader<vtkMedialITKImageReader>(path);
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
