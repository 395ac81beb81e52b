/// \class vtkMedialSketchSkeleton
/// \brief Real-time skeletonization of sketched closed strokes (Ma, Wang, Li and Zhang 2021): straight
/// skeleton, BoundedDP, connection of parts, global refinement; and the inflated mesh of each stroke.
///
/// Input: a polydata whose line cells are closed 2-D strokes (x, y; z ignored), one per part in modelling
/// order, optionally with cell data `Placement` (16 doubles, row-major 4x4 matrix placing the stroke's plane
/// in 3-D), as vtkMedialSketchReader produces.
/// Output port 0: the skeleton (docs/ARCHITECTURE.md §4: `Radius` from the inscribed balls, `NodeType`, field
/// `Root`), with point data `Part` (int) and cell data `Part` and `Branch` (int: the branch of the part's
/// local skeleton, -1 for the bones joining parts). Ready for vtkMedialSQM. Output port 1: the inflated parts
/// as one watertight triangle mesh, the union of their volumes (CGAL corefinement with exact constructions:
/// closed, manifold, no face cutting another), point data `Part` (a vertex on a seam has the earlier part's);
/// with MergeParts off, one closed component per part. Ready for vtkMedialSkinBinding with the skeleton.
///
/// Lengths are in sketch pixels, UnitLength stroke units each (0, the default: a thousandth of the
/// drawing's bounding-box diagonal), so the paper's defaults work at any scale.
/// Errors (empty outputs): no stroke, fewer than 3 distinct points, NaN, zero area, a stroke that crosses
/// itself, a degenerate placement matrix; each names the stroke.
/// Implements medial::sketchSkeleton (src/sketch/SketchSkeleton.h).
#pragma once

#include "MedialFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h"

#include <array>
#include <map>
#include <utility>

namespace medial {
struct SketchParameters;
}

class MEDIALFILTERS_EXPORT vtkMedialSketchSkeleton : public vtkPolyDataAlgorithm {
 public:
  ///@{
  /// VTK's object protocol: New() makes an instance with the defaults, PrintSelf() prints every property.
  static vtkMedialSketchSkeleton* New();
  vtkTypeMacro(vtkMedialSketchSkeleton, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}
#ifndef __VTK_WRAP__
  /// The properties as the algorithm's parameters (the constructor does the reverse with the defaults).
  medial::SketchParameters MakeParameters() const;
#endif

  ///@{
  /// Global thresholds of §3.3 in sketch pixels: branch simplification epsilon_s (5), joint merging
  /// epsilon_m (30), branch pruning epsilon_t (30), edge collapsing epsilon_c (10).
  vtkSetClampMacro(SimplificationThreshold, double, 0.0, 1e12);
  vtkGetMacro(SimplificationThreshold, double);
  vtkSetClampMacro(MergingThreshold, double, 0.0, 1e12);
  vtkGetMacro(MergingThreshold, double);
  vtkSetClampMacro(PruningThreshold, double, 0.0, 1e12);
  vtkGetMacro(PruningThreshold, double);
  vtkSetClampMacro(CollapsingThreshold, double, 0.0, 1e12);
  vtkGetMacro(CollapsingThreshold, double);
  ///@}
  /// Part level: the four thresholds for one part (0-based, modelling order); the global ones elsewhere.
  void SetPartThresholds(int part, double simplification, double merging, double pruning, double collapsing);
  /// Branch level: epsilon_s for one branch (the `Branch` cell value) of one part.
  void SetBranchSimplification(int part, int branch, double simplification);
  /// Forgets all part- and branch-level thresholds.
  void ClearLocalThresholds();

  ///@{
  /// Stroke units per sketch pixel; 0 (default): bounding-box diagonal of all strokes / 1000.
  vtkSetClampMacro(UnitLength, double, 0.0, 1e300);
  vtkGetMacro(UnitLength, double);
  ///@}
  ///@{
  /// Uniform resampling step of the stroke (10 px, the paper's Fig. 19).
  vtkSetClampMacro(ResampleStep, double, 1e-6, 1e12);
  vtkGetMacro(ResampleStep, double);
  ///@}
  ///@{
  /// Douglas-Peucker tolerance of the polygon (2 px).
  vtkSetClampMacro(PolygonTolerance, double, 0.0, 1e12);
  vtkGetMacro(PolygonTolerance, double);
  ///@}
  ///@{
  /// alpha_s of BoundedDP's error (eq. 1; 1).
  vtkSetClampMacro(ShapeWeight, double, 0.0, 1e6);
  vtkGetMacro(ShapeWeight, double);
  ///@}
  ///@{
  /// Inflation thickness c of the Poisson height field (2: round tubes).
  vtkSetClampMacro(Thickness, double, 1e-6, 1e6);
  vtkGetMacro(Thickness, double);
  ///@}
  ///@{
  /// Largest triangle edge of the inflated mesh (10 px).
  vtkSetClampMacro(MeshEdgeLength, double, 1e-3, 1e12);
  vtkGetMacro(MeshEdgeLength, double);
  ///@}
  ///@{
  /// Whether port 1 gets the inflated meshes (default on).
  vtkSetMacro(Inflate, bool);
  vtkGetMacro(Inflate, bool);
  vtkBooleanMacro(Inflate, bool);
  ///@}
  ///@{
  /// Whether the inflated parts are joined into one watertight mesh (default on) or left overlapping.
  vtkSetMacro(MergeParts, bool);
  vtkGetMacro(MergeParts, bool);
  vtkBooleanMacro(MergeParts, bool);
  ///@}
  ///@{
  /// Keep the skeleton after each step (default off; the paper's Figs. 3-9), then GetStageSkeleton of
  /// GetStageSkeletonNames(): "straight-skeleton" (each part's, peripheral edges removed), "bounded-dp"
  /// (its branches simplified), "connected" (the parts joined, eq. 3), "pruned", "merged" (the refinement's
  /// first two operations; the third, collapsing, gives port 0). Each with Part and Branch like port 0.
  vtkSetMacro(RecordStages, bool);
  vtkGetMacro(RecordStages, bool);
  vtkBooleanMacro(RecordStages, bool);
  vtkPolyData* GetStageSkeleton(const std::string& name) const;
  static std::vector<std::string> GetStageSkeletonNames() {
    return {"straight-skeleton", "bounded-dp", "connected", "pruned", "merged"};
  }
  ///@}

 protected:
  ///@{
  /// VTK's pipeline: the constructor sets the defaults; the overrides of vtkAlgorithm check the input, run
  /// the algorithm and fill the outputs (errors leave them empty).
  vtkMedialSketchSkeleton();
  ~vtkMedialSketchSkeleton() override = default;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  ///@}

 private:
  vtkMedialSketchSkeleton(const vtkMedialSketchSkeleton&) = delete;
  void operator=(const vtkMedialSketchSkeleton&) = delete;

  ///@{
  /// Parameters: defaults from medial::SketchParameters (the constructor).
  double SimplificationThreshold;
  double MergingThreshold;
  double PruningThreshold;
  double CollapsingThreshold;
  double UnitLength;
  double ResampleStep;
  double PolygonTolerance;
  double ShapeWeight;
  double Thickness;
  double MeshEdgeLength;
  bool Inflate;
  bool MergeParts;
  bool RecordStages = false;
  std::map<std::string, vtkSmartPointer<vtkPolyData>> Stages;
  std::map<int, std::array<double, 4>> PartThresholds;
  std::map<std::pair<int, int>, double> BranchThresholds;
  ///@}
};
