/// \class vtkMedialSQM
/// \brief Skeleton to quad-dominant mesh (SQM of Bærentzen, Misztal and Wełnicka 2012, with the extensions of
/// Piovarči, CESCG 2014): a skeleton with `Radius` per node becomes a closed manifold mesh of quads,
/// triangles only in the leaf fans.
///
/// Input: a skeleton (docs/ARCHITECTURE.md §4: nodes, 2-point lines, `Radius`, optional `EllipsoidAxes` and
/// `Root`). Output: a polygonal mesh of quads and triangles (not triangulated), outward oriented, with point
/// data `SkeletonNode` (int: the input node each vertex belongs to). Several components are meshed each.
/// Cycles are meshed (a genus-g surface for g independent cycles). Repairs: self-loop edges are dropped,
/// repeated edges merged, and a node whose centre lies inside the sphere of a neighbouring branch node is
/// merged into it, the branch node keeping the larger radius (its tube would run backwards out of that
/// sphere; e.g. finger nodes inside a palm's ball, a sketch's wing joint inside its body's next sphere);
/// two neighbouring branch nodes merge once their spheres overlap by more than half the smaller radius.
/// Errors (empty output): no nodes, no Radius, a radius <= 0 or NaN coordinates, coincident joined nodes,
/// two edges leaving a node in the same direction.
/// Implements medial::sqmMesh (src/sqm/SqmMesher.h).
#pragma once

#include "MedialFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h"

#include <map>

#include <string>
#include <vector>

namespace medial {
struct SqmParameters;
}

class MEDIALFILTERS_EXPORT vtkMedialSQM : public vtkPolyDataAlgorithm {
 public:
  ///@{
  /// VTK's object protocol: New() makes an instance with the defaults, PrintSelf() prints every property.
  static vtkMedialSQM* New();
  vtkTypeMacro(vtkMedialSQM, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}
#ifndef __VTK_WRAP__
  /// The properties as the algorithm's parameters (the constructor does the reverse with the defaults).
  medial::SqmParameters MakeParameters() const;
#endif

  ///@{
  /// LIE smoothing after each split, one of GetSmoothingNames(): quaternion (default), averaging,
  /// area-laplacian, valency-laplacian. An unknown name is an error and leaves the smoothing as it was.
  void SetSmoothing(const std::string& name);
  std::string GetSmoothing() const { return this->Smoothing; }
  static std::string GetSmoothingNames();
  ///@}
  ///@{
  /// Pairing of a tube's last ring with a polyhedron, one of GetPairingNames(): total-distance
  /// (default), distance, angle.
  void SetPairing(const std::string& name);
  std::string GetPairing() const { return this->Pairing; }
  static std::string GetPairingNames();
  ///@}
  ///@{
  /// N: vertices of the ring of a skeleton without branch nodes (default 8).
  vtkSetClampMacro(LinearRingVertices, int, 3, 1024);
  vtkGetMacro(LinearRingVertices, int);
  ///@}
  ///@{
  /// Join neighbouring triangles of the leaf fans and cycle bands into quads where they make a fair quad
  /// (default on; off gives the papers' triangle fans and bands).
  vtkSetMacro(PairTriangles, bool);
  vtkGetMacro(PairTriangles, bool);
  vtkBooleanMacro(PairTriangles, bool);
  ///@}
  ///@{
  /// Close leaves with capsules (hemispheres) instead of triangle fans (default off).
  vtkSetMacro(Capsules, bool);
  vtkGetMacro(Capsules, bool);
  vtkBooleanMacro(Capsules, bool);
  ///@}
  ///@{
  /// With capsules: the rings added beyond each leaf to close it (default 4; CESCG 2014, Capsule Ending).
  vtkSetClampMacro(CapsuleSteps, int, 1, 64);
  vtkGetMacro(CapsuleSteps, int);
  ///@}
  ///@{
  /// Tessellation levels (bilinear, OpenSubdiv), each followed by projection onto the spheres swept along
  /// the skeleton's edges (default 0).
  vtkSetClampMacro(SubdivisionLevels, int, 0, 6);
  vtkGetMacro(SubdivisionLevels, int);
  ///@}
  ///@{
  /// With subdivision: shrink the cone radius near sharp vertices (the paper's Bézier radius scaling,
  /// default off: it has not reduced self-intersections on the test skeletons, issue 4 notes) down to
  /// SharpMinimumScale at the sharp vertex (default 0.8).
  vtkSetMacro(SharpScaling, bool);
  vtkGetMacro(SharpScaling, bool);
  vtkBooleanMacro(SharpScaling, bool);
  vtkSetClampMacro(SharpMinimumScale, double, 0.05, 1.0);
  vtkGetMacro(SharpMinimumScale, double);
  ///@}
  ///@{
  /// With subdivision: where the cone projection makes faces cut each other, their vertices go back
  /// towards the base mesh until none do (default on; SqmRefinement.h).
  vtkSetMacro(FoldRepair, bool);
  vtkGetMacro(FoldRepair, bool);
  vtkBooleanMacro(FoldRepair, bool);
  ///@}

  ///@{
  /// Where tubes of parts that are not neighbours overlap (their faces cut each other, so that the mesh
  /// bounds no volume), replace the mesh by the boundary of the union of the tubes' volumes: one closed
  /// 2-manifold without self-intersection, quads kept away from the intersection curves, triangles along
  /// them, `SkeletonNode` carried over (default off; a mesh without overlaps is left as it is). An overlap
  /// the union cannot resolve (tubes touching along a line) is an error. Implements medial::unionSqmMesh.
  vtkSetMacro(Union, bool);
  vtkGetMacro(Union, bool);
  vtkBooleanMacro(Union, bool);
  ///@}
  ///@{
  /// Count the faces that cut each other (GetOverlappingFacePairs, GetOverlappingNodePairs) without the
  /// union (default off: it costs a self-intersection test; Union counts them anyway).
  vtkSetMacro(CountOverlaps, bool);
  vtkGetMacro(CountOverlaps, bool);
  vtkBooleanMacro(CountOverlaps, bool);
  ///@}

  ///@{
  /// The repair that merges a node lying inside a neighbouring branch node's sphere into it (default on).
  /// Off, such a skeleton is an error naming the node (SQM cannot join its tube to the polyhedron).
  vtkSetMacro(MergeNodes, bool);
  vtkGetMacro(MergeNodes, bool);
  vtkBooleanMacro(MergeNodes, bool);
  ///@}

  ///@{
  /// Keep the papers' intermediate results (default off): GetStageMesh of "polyhedra" (every branch node
  /// polyhedron as generated: hull, 1-to-6 split, projection; CESCG Fig. 3), "refined-polyhedra" (after the
  /// LIE refinement, Fig. 4), both in the bind pose of the straightened skeleton, and "base" (the joined
  /// mesh before subdivision, in the input pose); point data `SkeletonNode` on each.
  vtkSetMacro(RecordStages, bool);
  vtkGetMacro(RecordStages, bool);
  vtkBooleanMacro(RecordStages, bool);
  ///@}
  ///@{
  /// A recorded stage by name (see RecordStages); null when not recorded or unknown.
  vtkPolyData* GetStageMesh(const std::string& name) const;
  static std::vector<std::string> GetStageMeshNames() { return {"polyhedra", "refined-polyhedra", "base"}; }
  ///@}

  /// After an update: how many nodes lay inside a neighbouring branch node's sphere and were merged into it
  /// (the repair above).
  vtkGetMacro(MergedNodes, int);
  /// After an update with subdivision: refined vertices the fold repair moved off the swept spheres.
  vtkGetMacro(FoldRepairedVertices, int);
  ///@{
  /// After an update, the paper's Table 1 counts: branch, connection and leaf nodes meshed (the merged ones
  /// are GetMergedNodes()), the output's vertices where other than four edges meet, its quads and triangles.
  vtkGetMacro(BranchNodes, int);
  vtkGetMacro(ConnectionNodes, int);
  vtkGetMacro(LeafNodes, int);
  vtkGetMacro(IrregularVertices, int);
  vtkGetMacro(Quads, int);
  vtkGetMacro(Triangles, int);
  ///@}
  ///@{
  /// After an update with Union or CountOverlaps: the pairs of polygons that cut each other and the pairs of
  /// skeleton nodes they belong to (before the union); with Union, the polygons cut along the intersection
  /// curves and those removed (inside the union). Counting stops after 100,000 face pairs
  /// (medial::kOverlapCountLimit): then GetOverlapCountComplete() is false and the counts are lower bounds.
  vtkGetMacro(OverlappingFacePairs, int);
  vtkGetMacro(OverlappingNodePairs, int);
  vtkGetMacro(OverlapCountComplete, bool);
  vtkGetMacro(UnionCutPolygons, int);
  vtkGetMacro(UnionRemovedPolygons, int);
  ///@}
  ///@{
  /// After an update: the seconds of a stage of GetStageNames() (the paper's Table 1: straightening,
  /// generation and refinement of the branch node polyhedra, joining, skinning, subdivision; and repairs,
  /// and the union with the counting of overlaps).
  double GetStageSeconds(const std::string& stage) const;
  static std::vector<std::string> GetStageNames();
  ///@}

 protected:
  ///@{
  /// VTK's pipeline: the constructor sets the defaults; the overrides of vtkAlgorithm check the input, run
  /// the algorithm and fill the outputs (errors leave them empty).
  vtkMedialSQM();
  ~vtkMedialSQM() override = default;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  ///@}

 private:
  vtkMedialSQM(const vtkMedialSQM&) = delete;
  void operator=(const vtkMedialSQM&) = delete;

  ///@{
  /// Parameters: defaults from medial::SqmParameters (the constructor).
  std::string Smoothing;
  std::string Pairing;
  int LinearRingVertices;
  bool Capsules;
  int CapsuleSteps;
  bool PairTriangles;
  int SubdivisionLevels;
  bool SharpScaling;
  double SharpMinimumScale;
  bool FoldRepair;
  bool MergeNodes;
  bool Union;
  bool CountOverlaps;
  bool RecordStages = false;
  std::map<std::string, vtkSmartPointer<vtkPolyData>> Stages;
  ///@}
  ///@{
  /// Figures of the last update.
  int MergedNodes = 0;
  int FoldRepairedVertices = 0;
  int BranchNodes = 0, ConnectionNodes = 0, LeafNodes = 0, IrregularVertices = 0, Quads = 0, Triangles = 0;
  bool OverlapCountComplete = true;
  int OverlappingFacePairs = 0, OverlappingNodePairs = 0, UnionCutPolygons = 0, UnionRemovedPolygons = 0;
  std::vector<double> Seconds;  ///< per stage of GetStageNames()
  ///@}
};
