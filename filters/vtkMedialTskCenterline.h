/**
 * @class vtkMedialTskCenterline
 * @brief Centerline of a tubular structure in a CT or label image by the TSK method (WSCG 2008 paper).
 *
 * Input: a 3-D vtkImageData (origin, spacing and direction honoured). The structure is the voxels equal to
 * Label (label images), or within [ThresholdLow, ThresholdHigh] (e.g. colon air -1024..-600 HU), or else
 * the non-zero voxels; with DropBorderParts (default on for thresholds) the parts touching the volume's
 * border go (the air outside the body); then the largest 26-connected component is kept and, with
 * FillHoles, its cavities are filled.
 * Output: one polyline from P0 (the seed, or the lowest end of the structure) along the structure, in
 * physical coordinates (mm), with point data `Radius` and `ArcLength` (mm).
 * With DetectBranches, one polyline per branch of a tree (see below). With ComputeSections (along the
 * first polyline), the virtual-colonoscopy measurements of the paper's section 4 (Figs. 14-15):
 * output port 1, a vtkTable with one row per perpendicular section every SectionSpacing mm (columns
 * `ArcLength`, `MinDiameter`, `MaxDiameter`, `Perimeter` in mm, `Area` in mm^2; NaN where a ray found no
 * wall); output port 2, the unfolded wall ("terrain"): a 2-D vtkImageData of SectionRays x sections with
 * point data `WallDistance` (mm from the axis), x = angle (spacing 360/rays degrees), y = arc length (spacing
 * SectionSpacing mm). Implements medial::tubeSections (src/centerline/TubeSections.h).
 * Errors (empty output): not a 3-D image, a label that no voxel has, nothing left after the clean-up, a
 * seed outside the structure. Implements medial::structureTube and medial::tskAxis (src/centerline).
 */
#pragma once

#include "MedialFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace medial {
struct BinaryVolume;
struct Centerline;
struct TskParameters;
}

class MEDIALFILTERS_EXPORT vtkMedialTskCenterline : public vtkPolyDataAlgorithm {
 public:
  static vtkMedialTskCenterline* New();
  vtkTypeMacro(vtkMedialTskCenterline, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Select the voxels equal to a label (disables the threshold).
  void SetLabel(int label);
  /// Select the voxels in [low, high] (disables the label).
  void SetThreshold(double low, double high);
  /// Use the non-zero voxels (the default).
  void SelectNonZero();

  vtkSetMacro(DropBorderParts, bool);
  vtkGetMacro(DropBorderParts, bool);
  vtkBooleanMacro(DropBorderParts, bool);
  vtkSetMacro(FillHoles, bool);
  vtkGetMacro(FillHoles, bool);
  vtkBooleanMacro(FillHoles, bool);

  /// P0 in physical coordinates (mm); without it, the lowest end of the structure.
  void SetSeed(double x, double y, double z);
  void ClearSeed();

  /// Width of the TSK antecedent Gaussians relative to their cluster (default 0.3).
  vtkSetMacro(AntecedentWidth, double);
  vtkGetMacro(AntecedentWidth, double);
  /// Branching structures (vessels, airways; beyond the paper): the structure is cut where its Manhattan
  /// layers fall apart, each branch is followed by the TSK method, and the output has one polyline per
  /// branch, starting at the junction on its parent, with cell data `Branch` and `ParentBranch` (-1 for the
  /// root). Default off: one polyline, as in the paper.
  vtkSetMacro(DetectBranches, bool);
  vtkGetMacro(DetectBranches, bool);
  vtkBooleanMacro(DetectBranches, bool);
  /// Side branches shorter than this (mm) stay part of the branch they leave (0, the default: twice the
  /// structure's largest inscribed radius).
  vtkSetClampMacro(MinimumBranchLength, double, 0.0, 1e6);
  vtkGetMacro(MinimumBranchLength, double);
  /// Passes that move the TSK curve towards the centre of its perpendicular sections (the paper's
  /// centricity criterion, §2, enforced after its two phases; default 2, 0 = the paper's curve as is).
  vtkSetClampMacro(CenteringIterations, int, 0, 20);
  vtkGetMacro(CenteringIterations, int);
  /// Distance between output points in mm (0: the smallest voxel spacing).
  vtkSetMacro(SampleSpacing, double);
  vtkGetMacro(SampleSpacing, double);

  /// Perpendicular sections and the unfolded wall on output ports 1 and 2 (default off).
  vtkSetMacro(ComputeSections, bool);
  vtkGetMacro(ComputeSections, bool);
  vtkBooleanMacro(ComputeSections, bool);
  /// k, the arc length between sections in mm (default 1).
  vtkSetClampMacro(SectionSpacing, double, 0.01, 1000.0);
  vtkGetMacro(SectionSpacing, double);
  /// Rays (angles) per section, even (default 72: every 5 degrees).
  vtkSetClampMacro(SectionRays, int, 4, 3600);
  vtkGetMacro(SectionRays, int);
  /// Figures of the last update.
  vtkGetMacro(PrimitiveCenterlinePoints, int);
  vtkGetMacro(StructureVoxels, vtkIdType);

 protected:
  vtkMedialTskCenterline();
  ~vtkMedialTskCenterline() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

 private:
  vtkMedialTskCenterline(const vtkMedialTskCenterline&) = delete;
  // The centerline of one tube (the paper), or of every branch of a tree; false after an error.
  bool FollowTube(const medial::BinaryVolume& volume, int64_t seed, const medial::TskParameters& p,
                  std::vector<medial::Centerline>& branches, std::vector<int>& parents);
  bool FollowBranches(const medial::BinaryVolume& volume, int64_t seed, const medial::TskParameters& p,
                      std::vector<medial::Centerline>& branches, std::vector<int>& parents);
  // Fills output ports 1 (profile table) and 2 (unfolded wall); false after an error or an abort.
  bool WriteSections(const medial::BinaryVolume& volume, const std::vector<Eigen::Vector3d>& axis,
                     vtkInformationVector* outputVector);
  void operator=(const vtkMedialTskCenterline&) = delete;

  enum class Selection { NonZero, Label, Threshold };
  Selection Mode = Selection::NonZero;
  int Label = 1;
  double ThresholdLow = 0, ThresholdHigh = 0;
  bool DropBorderParts = false;
  bool FillHoles = false;
  bool HasSeed = false;
  double Seed[3] = {0, 0, 0};
  double AntecedentWidth = 0.3;
  double SampleSpacing = 0;
  int CenteringIterations = 2;
  bool DetectBranches = false;
  double MinimumBranchLength = 0;
  bool ComputeSections = false;
  double SectionSpacing = 1.0;
  int SectionRays = 72;
  int PrimitiveCenterlinePoints = 0;
  vtkIdType StructureVoxels = 0;
};
