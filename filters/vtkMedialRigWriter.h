/// \class vtkMedialRigWriter
/// \brief Writes a skinned mesh and its skeleton as a rig (contraction paper, III.F): glTF 2.0 binary
/// (.glb, TinyGLTF) or FBX (.fbx, Medial's writer), for Blender, Maya, 3ds Max or a game engine.
///
/// Input port 0: the mesh with point data `SkinWeights` (one component per bone), as port 1 of
/// vtkMedialContractionSkeleton gives it with ComputeWeights on; polygons are triangulated.
/// Input port 1: the skeleton (docs/ARCHITECTURE.md §4); bone i is its line cell i, rooted at field data
/// `Root`. The rig: one bone per skeleton edge, head at the end nearer the root, Y along the bone, hierarchy
/// from the root, an end joint at each leaf, the root joint on the ground, at most 4 influences per vertex,
/// turned so that UpAxis points up and scaled by Scale (see src/rig/RigExport.h and src/rig/RigBones.h).
/// Errors: an unknown UpAxis, a Scale that is not positive.
///
/// Atomic like vtkMedialPolyDataWriter: nothing is left behind on failure. Errors name the file; Write()
/// returns 0 on failure.
#pragma once

#include "MedialFiltersModule.h"
#include "vtkWriter.h"

#include <string>

class vtkPolyData;

class MEDIALFILTERS_EXPORT vtkMedialRigWriter : public vtkWriter {
 public:
  ///@{
  /// VTK's object protocol: New() makes an instance with the defaults, PrintSelf() prints every property.
  static vtkMedialRigWriter* New();
  vtkTypeMacro(vtkMedialRigWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

  ///@{
  /// The file to write.
  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);
  ///@}

  /// The skeleton (input port 1).
  void SetSkeletonData(vtkPolyData* skeleton);

  ///@{
  /// Most bones influencing one vertex (default 4).
  vtkSetClampMacro(MaxInfluences, int, 1, 64);
  vtkGetMacro(MaxInfluences, int);
  ///@}

  ///@{
  /// The mesh's up axis: "x", "y" (default, glTF's), "z" (most scans and CAD), "-x", "-y" or "-z". The rig is
  /// turned so that this axis points up in the file, and the character stands in Blender.
  vtkSetStdStringFromCharMacro(UpAxis);
  vtkGetCharFromStdStringMacro(UpAxis);
  ///@}

  ///@{
  /// Mesh units to the file's metres (default 1; 0.01 for a mesh in centimetres).
  vtkSetMacro(Scale, double);
  vtkGetMacro(Scale, double);
  ///@}

  /// Whether the file name has an extension the writer knows (.glb, .gltf, .fbx).
  static bool CanWriteFile(const char* fileName);
  /// The extensions, as a file dialog's filter.
  static const char* GetExtensions() { return "*.glb *.fbx"; }

 protected:
  ///@{
  /// VTK's pipeline: the constructor sets the defaults; the overrides of vtkAlgorithm check the input, run
  /// the algorithm and fill the outputs (errors leave them empty).
  vtkMedialRigWriter();
  ~vtkMedialRigWriter() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  void WriteData() override;
  ///@}

 private:
  vtkMedialRigWriter(const vtkMedialRigWriter&) = delete;
  void operator=(const vtkMedialRigWriter&) = delete;
  void Fail(unsigned long code);

  std::string FileName;
  int MaxInfluences = 4;
  std::string UpAxis = "y";
  double Scale = 1.0;
};
