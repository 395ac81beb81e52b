/// \class vtkMedialContractionSkeleton
/// \brief Curve skeleton of a surface mesh by mesh contraction (Au, Tai, Chu, Cohen-Or and Lee, SIGGRAPH
/// 2008, section III, stages 1-4, with the node selection and weights of Berenguer Gómez and Moreno Alvarez).
///
/// Input: a polygonal mesh (polygons and strips are triangulated; lines and vertices are ignored).
/// Output port 0: the skeleton of docs/ARCHITECTURE.md §4 (nodes, 2-point lines, `Radius`, field data
/// `Root`). Output port 1: the triangulated input mesh with point data `SkeletonNode` (int: the node that
/// absorbed each vertex, -1 for vertices no face uses), the skeleton-mesh mapping and segmentation, and
/// `ContractedPosition` (double x 3: where the contraction took the vertex, the paper's Fig. 5); with
/// ComputeWeights on, also `SkinWeights` (double, one component per bone: component i is the weight of the
/// bone on line cell i of port 0; each tuple sums to 1), the heat-diffusion weights of section III.E. A dense
/// array was chosen over a sparse pair: 30 bones cost 240 bytes per vertex, and VTK's colouring, probing and
/// Python's numpy view work on it directly. vtkMedialRigWriter turns both outputs into a rig file.
///
/// Parameters carry the paper's defaults, taken from medial::SkeletonByContractionParameters: W_L0 factor
/// 1e-3, s_L = 2, W_L <= 2048, W_H <= 10000, w_a = 1, w_b = 0.1, 30 nodes. Bad input (no triangles, NaN
/// coordinates) gives an error and empty outputs. Implements medial::skeletonByContraction
/// (src/contraction/SkeletonByContraction.h).
#pragma once

#include "MedialFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h"

#include <string>
#include <vector>

namespace medial {
struct SkeletonByContractionParameters;
struct SkeletonByContractionResult;
}  // namespace medial

class MEDIALFILTERS_EXPORT vtkMedialContractionSkeleton : public vtkPolyDataAlgorithm {
 public:
  ///@{
  /// VTK's object protocol: New() makes an instance with the defaults, PrintSelf() prints every property.
  static vtkMedialContractionSkeleton* New();
  vtkTypeMacro(vtkMedialContractionSkeleton, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}
#ifndef __VTK_WRAP__
  /// The properties as the algorithm's parameters (the constructor does the reverse with the defaults).
  medial::SkeletonByContractionParameters MakeParameters() const;
#endif

  ///@{
  /// The skeleton's node count (default 30; 0 keeps the full curve skeleton): exactly this many, or more
  /// where fewer would take a bone out of the mesh, or fewer where the curve skeleton has fewer
  /// (GetSelectionNote).
  vtkSetClampMacro(TargetNodes, int, 0, VTK_INT_MAX);
  vtkGetMacro(TargetNodes, int);
  ///@}
  ///@{
  /// Meshes with more vertices are decimated to this many (quadric error, topology kept) before the
  /// contraction; the segmentation, radii and weights still use every input vertex (default 4000; 0
  /// contracts the input itself).
  vtkSetClampMacro(ContractionVertices, int, 0, VTK_INT_MAX);
  vtkGetMacro(ContractionVertices, int);
  ///@}
  ///@{
  /// A mesh contracted with more vertices than this starts with W_L0 x (n / ReferenceVertices)^1.5, so
  /// that its first iterations contract as a mesh of this size does (default 4000; 0: the paper's W_L0
  /// at every resolution).
  vtkSetClampMacro(ReferenceVertices, int, 0, VTK_INT_MAX);
  vtkGetMacro(ReferenceVertices, int);
  ///@}
  ///@{
  /// W_L0 = factor * sqrt(mean face area) in the normalized frame (default 1e-3).
  vtkSetClampMacro(InitialContractionFactor, double, 1e-6, 10.0);
  vtkGetMacro(InitialContractionFactor, double);
  ///@}
  ///@{
  /// s_L, the growth of W_L per iteration (default 2).
  vtkSetClampMacro(ContractionScale, double, 1.01, 10.0);
  vtkGetMacro(ContractionScale, double);
  ///@}
  ///@{
  /// W_H0, the initial attraction weight (default 1).
  vtkSetClampMacro(InitialAttractionWeight, double, 1e-6, 1e6);
  vtkGetMacro(InitialAttractionWeight, double);
  ///@}
  ///@{
  /// Upper bounds of W_L and W_H (defaults 2048 and 10000).
  vtkSetClampMacro(MaxContractionWeight, double, 1.0, 1e6);
  vtkGetMacro(MaxContractionWeight, double);
  vtkSetClampMacro(MaxAttractionWeight, double, 1.0, 1e7);
  vtkGetMacro(MaxAttractionWeight, double);
  ///@}
  ///@{
  /// Contraction iterations at most (default 40).
  vtkSetClampMacro(MaxIterations, int, 1, 1000);
  vtkGetMacro(MaxIterations, int);
  ///@}
  ///@{
  /// w_a and w_b of the surgery cost (10) (defaults 1 and 0.1).
  vtkSetClampMacro(ShapeWeight, double, 0.0, 100.0);
  vtkGetMacro(ShapeWeight, double);
  vtkSetClampMacro(SamplingWeight, double, 0.0, 100.0);
  vtkGetMacro(SamplingWeight, double);
  ///@}
  ///@{
  /// delta of the surgery's pre-pass (edges shorter collapse first), as a fraction of the contracted
  /// mesh's bounding-box diagonal (default 0.001).
  vtkSetClampMacro(CollapseLengthFraction, double, 0.0, 0.5);
  vtkGetMacro(CollapseLengthFraction, double);
  ///@}
  ///@{
  /// Move nodes to the centroid of their absorbed vertices where it lies inside (default on).
  vtkSetMacro(RefineEmbedding, bool);
  vtkGetMacro(RefineEmbedding, bool);
  vtkBooleanMacro(RefineEmbedding, bool);
  ///@}
  ///@{
  /// Put back the cycles connectivity surgery lost, so that the skeleton has as many independent cycles
  /// as the closed mesh has genus (default on; src/contraction/CycleRepair.h).
  vtkSetMacro(RestoreCycles, bool);
  vtkGetMacro(RestoreCycles, bool);
  vtkBooleanMacro(RestoreCycles, bool);
  ///@}
  ///@{
  /// Move nodes of one or two edges to the centroid of the mesh's cross-section through them: the selected
  /// ones, or every node without a selection (default on; src/contraction/NodeCentring.h).
  vtkSetMacro(CenterNodes, bool);
  vtkGetMacro(CenterNodes, bool);
  vtkBooleanMacro(CenterNodes, bool);
  ///@}
  ///@{
  /// Deprecated, removed in the next release: the British spelling of SetCenterNodes and its kin.
  void SetCentreNodes(bool on) { this->SetCenterNodes(on); }
  bool GetCentreNodes() { return this->GetCenterNodes(); }
  void CentreNodesOn() { this->CenterNodesOn(); }
  void CentreNodesOff() { this->CenterNodesOff(); }
  ///@}
  ///@{
  /// Compute the skinning weights of section III.E (default off: they cost one more factorization).
  vtkSetMacro(ComputeWeights, bool);
  vtkGetMacro(ComputeWeights, bool);
  vtkBooleanMacro(ComputeWeights, bool);
  ///@}
  ///@{
  /// c of H_jj = c / d(j)^2 in the heat equilibrium (default 1, Baran and Popović).
  vtkSetClampMacro(HeatConstant, double, 1e-3, 100.0);
  vtkGetMacro(HeatConstant, double);
  ///@}
  ///@{
  /// Sparse solver, one of GetSolverNames() (default auto: Eigen's simplicial LLT with AMD below 30,000
  /// vertices, CHOLMOD supernodal with METIS above); an unknown name is an error and leaves the solver as
  /// it was.
  void SetSolver(const std::string& name);
  std::string GetSolver() const { return this->Solver; }
  ///@}
  /// The solvers' names, comma-separated: auto, cholmod-metis, cholmod-amd, llt-amd, ldlt-amd, llt-metis,
  /// ldlt-metis, lu-colamd, lu-amd, lu-metis, qr-colamd, cg.
  static std::string GetSolverNames();

  ///@{
  /// Keep the intermediate results the paper draws (default off): the contracted mesh after every
  /// iteration (Fig. 5) with its weights (Fig. 7), the curve skeleton after the surgery and before the
  /// selection. Costs a copy of the contracted mesh's vertices per iteration.
  vtkSetMacro(RecordStages, bool);
  vtkGetMacro(RecordStages, bool);
  vtkBooleanMacro(RecordStages, bool);
  ///@}
  ///@{
  /// With RecordStages, after an update: step 0 is the contracted mesh as it started (the input, or its
  /// decimation), step t the mesh after iteration t: triangles with point data `Laplacian` (|L V|, the
  /// curvature-flow pull left) and `AttractionWeight` (W_H,i), field data `ContractionWeight` (W_L),
  /// `Iteration`, `AreaRatio`, `VolumeRatio`; the last step also `CollapseOrder` (int: when the surgery
  /// collapsed each vertex, 1 first, 0 for the vertices that became nodes). Null out of range.
  int GetNumberOfContractionSteps() const { return static_cast<int>(this->Steps.size()); }
  vtkPolyData* GetContractionStep(int step) const;
  ///@}
  ///@{
  /// With RecordStages: the curve skeleton straight after the connectivity surgery (III.B), and after the
  /// refinement before the selection (III.C); null otherwise.
  vtkPolyData* GetSurgerySkeleton() const { return this->SurgerySkeleton; }
  vtkPolyData* GetUnselectedSkeleton() const { return this->UnselectedSkeleton; }
  ///@}

  ///@{
  /// Figures of the last update.
  vtkGetMacro(ContractionIterations, int);
  vtkGetMacro(CurveSkeletonNodes, int);
  ///@}
  /// Vertices of the mesh that was contracted (fewer than the input's when it was decimated).
  vtkGetMacro(ContractedVertices, int);
  ///@{
  /// Genus of the mesh's closed components, and the cycles put back (RestoreCycles).
  vtkGetMacro(Genus, int);
  vtkGetMacro(RestoredCycles, int);
  ///@}
  /// Why the skeleton does not have TargetNodes nodes (merging more would take a bone out of the mesh, or
  /// the curve skeleton has fewer), with the count kept; empty when it has them. Also the skeleton's field
  /// data `SelectionNote`, and a warning.
  std::string GetSelectionNote() const { return this->SelectionNote; }
  /// Seconds of a stage of the last update: decimation, contraction, factorization (part of the
  /// contraction), surgery, refinement, selection, radii, weights.
  double GetStageSeconds(const std::string& stage) const;
#ifndef __VTK_WRAP__
  /// The stages' names, in order (for C++ callers; Python names them itself).
  static std::vector<std::string> GetStageNames();
#endif

 protected:
  ///@{
  /// VTK's pipeline: the constructor sets the defaults; the overrides of vtkAlgorithm check the input, run
  /// the algorithm and fill the outputs (errors leave them empty).
  vtkMedialContractionSkeleton();
  ~vtkMedialContractionSkeleton() override = default;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  ///@}

 private:
  vtkMedialContractionSkeleton(const vtkMedialContractionSkeleton&) = delete;
  void operator=(const vtkMedialContractionSkeleton&) = delete;
  /// Keeps the recorded intermediate results as polydata (RecordStages).
  void KeepStages(const medial::SkeletonByContractionResult& result);

  ///@{
  /// Parameters: defaults from medial::SkeletonByContractionParameters (the constructor).
  int TargetNodes;
  int ContractionVertices;
  int ReferenceVertices;
  double InitialContractionFactor;
  double ContractionScale;
  double MaxContractionWeight;
  double MaxAttractionWeight;
  int MaxIterations;
  double ShapeWeight;
  double SamplingWeight;
  double CollapseLengthFraction;
  double InitialAttractionWeight;
  bool RefineEmbedding;
  bool RestoreCycles;
  bool CenterNodes;
  bool ComputeWeights;
  double HeatConstant;
  std::string Solver;
  bool RecordStages = false;
  std::vector<vtkSmartPointer<vtkPolyData>> Steps;
  vtkSmartPointer<vtkPolyData> SurgerySkeleton, UnselectedSkeleton;
  ///@}
  ///@{
  /// Figures of the last update.
  int ContractionIterations = 0;
  int CurveSkeletonNodes = 0;
  int ContractedVertices = 0;
  int Genus = 0;
  int RestoredCycles = 0;
  std::string SelectionNote;
  double Seconds[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  ///@}
};
