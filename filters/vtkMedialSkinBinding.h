/// \class vtkMedialSkinBinding
/// \brief Binds any mesh to any skeleton with heat-diffusion skinning weights (Au, Tai, Chu, Cohen-Or and Lee
/// 2008, §III.E; bone heat as Baran and Popović 2007), so that vtkMedialRigWriter can write a rig: a sketch's
/// mesh and its skeleton, an SQM mesh and the skeleton it was made from, a mesh and a skeleton drawn by hand.
///
/// Input port 0: a surface mesh (polygons of any size, or strips; triangulated for the solve only).
/// Input port 1: a skeleton (docs/ARCHITECTURE.md §4; bone i is its 2-point line i after polylines are
/// split). Output port 0: the input mesh, its cells as they are, with point data `SkinWeights` (one component
/// per bone, each tuple summing to 1) and `Bone` (int: the bone of largest weight, for colouring). Output
/// port 1: the skeleton with field data `Root`: Root when set (>= 0), else the skeleton's own, else its body
/// centre (the branch node nearest the mesh's volume centroid among the nodes central along the skeleton: a
/// figure's hips; src/rig/RigRoot.h).
///
/// Errors (empty outputs): a mesh without polygons, a skeleton without edges or with invalid values, a
/// skeleton outside the mesh's bounding box, a Root out of range, solver failure or abort. Nodes outside the
/// mesh are a warning: their bones still get the vertices nearest them, by diffusion.
/// Implements medial::bindSkin (src/rig/SkinBinding.h).
#pragma once

#include "MedialFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

class MEDIALFILTERS_EXPORT vtkMedialSkinBinding : public vtkPolyDataAlgorithm {
 public:
  ///@{
  /// VTK's object protocol: New() makes an instance with the defaults, PrintSelf() prints every property.
  static vtkMedialSkinBinding* New();
  vtkTypeMacro(vtkMedialSkinBinding, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

  ///@{
  /// The skeleton (input port 1).
  void SetSkeletonData(vtkPolyData* skeleton);
  void SetSkeletonConnection(vtkAlgorithmOutput* output);
  ///@}

  ///@{
  /// c of the heat equation's H = c / d^2 (Baran and Popović: 1). Larger binds vertices more to their
  /// nearest bone, smaller blends more across joints.
  vtkSetClampMacro(HeatConstant, double, 1e-3, 100.0);
  vtkGetMacro(HeatConstant, double);
  ///@}
  ///@{
  /// The rig's root node; -1 (default): the skeleton's `Root`, else its body centre (src/rig/RigRoot.h).
  vtkSetClampMacro(Root, int, -1, VTK_INT_MAX);
  vtkGetMacro(Root, int);
  ///@}

  ///@{
  /// After an update: the root used, the skeleton nodes outside the mesh, the vertices no nearest bone
  /// sees (weighted by diffusion alone).
  vtkGetMacro(ChosenRoot, int);
  vtkGetMacro(NodesOutside, int);
  vtkGetMacro(InvisibleVertices, int);
  ///@}

 protected:
  ///@{
  /// VTK's pipeline: the constructor sets the defaults; the overrides of vtkAlgorithm check the input, run
  /// the algorithm and fill the outputs (errors leave them empty).
  vtkMedialSkinBinding();
  ~vtkMedialSkinBinding() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
                  vtkInformationVector* outputVector) override;
  ///@}

 private:
  vtkMedialSkinBinding(const vtkMedialSkinBinding&) = delete;
  void operator=(const vtkMedialSkinBinding&) = delete;

  double HeatConstant = 1.0;
  int Root = -1;
  int ChosenRoot = -1;
  int NodesOutside = 0;
  int InvisibleVertices = 0;
};
