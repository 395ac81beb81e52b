/// \class vtkMedialReader
/// \brief The one place that opens any input Medial supports, chosen by extension.
///
/// Meshes and skeletons (output vtkPolyData): .vtp .vtk .vtu (its surface) .obj .ply .stl .g/.byu and
/// .gltf/.glb (the scene's meshes merged, node transforms applied) through VTK's readers, .fbx (and
/// a rig's skeleton with RigSkeleton) through Assimp (src/rig/RigImport.h), .off
/// (OFF/COFF/NOFF...) through OpenMesh (vtkMedialOFFReader), .swc (vtkMedialSWCReader).
/// Sketches (output vtkPolyData of strokes with cell data `Placement`): .txt (vtkMedialSketchReader).
/// Volumes (output vtkImageData, physical coordinates kept): .nii .nii.gz .mha .mhd .nrrd .nhdr .gipl .dcm
/// and DICOM series directories through ITK (vtkMedialITKImageReader), .inr .inr.gz through CGAL
/// (vtkMedialINRReader), .vti through VTK, .inv3 InVesalius projects (vtkMedialInVesaliusReader).
///
/// A polydata with lines and no polygons (not a sketch) is a skeleton and is validated
/// (docs/ARCHITECTURE.md §4). Errors (missing file,
/// unknown extension, unreadable content, empty mesh, invalid skeleton) are reported with vtkErrorMacro
/// naming the file, and the output is empty.
#pragma once

#include "MedialFiltersModule.h"
#include "vtkDataObjectAlgorithm.h"
#include "vtkSmartPointer.h"

#include <string>

class MEDIALFILTERS_EXPORT vtkMedialReader : public vtkDataObjectAlgorithm {
 public:
  ///@{
  /// VTK's object protocol: New() makes an instance with the defaults, PrintSelf() prints every property.
  static vtkMedialReader* New();
  vtkTypeMacro(vtkMedialReader, vtkDataObjectAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

  ///@{
  /// The file to read.
  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);
  ///@}

  /// Whether the output is (or will be) a volume, judged from the file name (and a .vtk header).
  static bool IsVolumeFile(const char* fileName);
  /// Whether the extension (or a directory, read as a DICOM series) is supported.
  static bool CanReadFile(const char* fileName);
  ///@{
  /// Space-separated supported extensions, e.g. for file dialogs: "*.vtp *.obj ...".
  static const char* GetMeshExtensions();
  static const char* GetVolumeExtensions();
  ///@}
  /// "*.txt": sketches, strokes with their placements.
  static const char* GetSketchExtensions();

  ///@{
  /// For a rig (.fbx, .glb, .gltf with joints): output its skeleton (joints as nodes, Radius from the
  /// weights' spread; src/rig/RigImport.h) instead of its mesh. Default off.
  vtkSetMacro(RigSkeleton, bool);
  vtkGetMacro(RigSkeleton, bool);
  vtkBooleanMacro(RigSkeleton, bool);
  ///@}

  /// The last error in one line (empty after a successful read), without VTK's file/line prefix.
  const char* GetErrorMessage() const { return this->ErrorMessage.c_str(); }

 protected:
  ///@{
  /// VTK's pipeline: the constructor sets the defaults; the overrides of vtkAlgorithm check the input, run
  /// the algorithm and fill the outputs (errors leave them empty).
  vtkMedialReader();
  ~vtkMedialReader() override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestDataObject(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  ///@}

 private:
  vtkMedialReader(const vtkMedialReader&) = delete;
  void operator=(const vtkMedialReader&) = delete;

  ///@{
  /// Reads FileName into Result, or sets ErrorMessage.
  void ReadFile();
  vtkSmartPointer<vtkDataObject> ReadPolyData(const std::string& extension);
  vtkSmartPointer<vtkDataObject> ReadVolume(const std::string& extension);
  vtkSmartPointer<vtkDataObject> ReadRig();  ///< .fbx, or a rig's skeleton
  ///@}

  std::string FileName;
  bool ReadsVolume = false;  ///< set by RequestDataObject from the file name
  std::string ErrorMessage;
  bool RigSkeleton = false;
  std::string ResultFileName;
  vtkMTimeType ResultTime = 0;
  vtkSmartPointer<vtkDataObject> Result;
};
