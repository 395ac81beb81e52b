/// \class vtkMedialTskCenterline
/// \brief Centerline of a tubular structure in a CT or label image by the TSK method (WSCG 2008).
///
/// Input: a 3-D vtkImageData (origin, spacing and direction honoured). The structure is the voxels equal to
/// Label (label images), or within [ThresholdLow, ThresholdHigh] (e.g. colon air -1024..-600 HU), or else
/// the non-zero voxels; parts touching the volume's border go (BorderParts: automatically for a threshold,
/// the air outside the body; or always, or never); then the largest 26-connected component is kept and,
/// with FillHoles, its cavities are filled.
/// Output: one polyline from P0 (the seed, or the lowest end of the structure) along the structure, in
/// physical coordinates (mm), with point data `Radius` and `ArcLength` (mm).
/// With DetectBranches, one polyline per branch of a tree (see below). With ComputeSections (along the
/// first polyline), the virtual-colonoscopy measurements of the paper's section 4 (Figs. 14-15):
/// output port 1, a vtkTable with one row per perpendicular section every SectionSpacing mm (columns
/// `ArcLength`, `MinDiameter`, `MaxDiameter`, `Perimeter` in mm, `Area` in mm^2; NaN where a ray found no
/// wall); output port 2, the unfolded wall ("terrain"): a 2-D vtkImageData of SectionRays x sections with
/// point data `WallDistance` (mm from the axis), x = angle (spacing 360/rays degrees), y = arc length
/// (spacing SectionSpacing mm). Implements medial::tubeSections (src/centerline/TubeSections.h). With
/// ComputeSurface: output port 3, the closed surface of the followed structure (the lumen: the kept part(s)
/// after hole filling), smoothed and decimated to at most SurfaceTriangles triangles, in mm, with the
/// centerline inside it (filters/MedialLumenSurface.h), for the fly-through and the ghost view. Errors (empty
/// output): not a 3-D image, a label that no voxel has, nothing left after the clean-up, a seed outside the
/// structure. Implements medial::tskCenterline (src/centerline/TskCenterline.h), whose
/// TskCenterlineParameters give every default.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "MedialFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h"

namespace medial {
struct TskCenterlineParameters;
struct TskStages;
}  // namespace medial

class vtkImageData;

class MEDIALFILTERS_EXPORT vtkMedialTskCenterline : public vtkPolyDataAlgorithm {
 public:
  ///@{
  /// VTK's object protocol: New() makes an instance with the defaults, PrintSelf() prints every property.
  static vtkMedialTskCenterline* New();
  vtkTypeMacro(vtkMedialTskCenterline, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}
#ifndef __VTK_WRAP__
  /// The properties as the algorithm's parameters (the constructor does the reverse with the defaults).
  medial::TskCenterlineParameters MakeParameters() const;
#endif

  /// Select the voxels equal to a label (disables the threshold).
  void SetLabel(int label);
  /// Select the voxels in [low, high] (disables the label).
  void SetThreshold(double low, double high);
  /// Use the non-zero voxels.
  void SelectNonZero();
  /// Choose from the volume (the default): on a CT in Hounsfield units its air, every voxel up to the
  /// window's top (-600 HU; with a note; an error when it holds no air), the non-zero voxels on any other
  /// volume (an error when they fill most of it). src/centerline/TskCenterline.h says how.
  void SelectAutomatically();
  ///@{
  /// The selection: "automatic", "label", "threshold" or "non-zero", and its values (the window defaults
  /// to colon air on CT, -1024..-600 HU).
  const char* GetSelectionName() const;
  vtkGetMacro(Label, int);
  vtkGetMacro(ThresholdLow, double);
  vtkGetMacro(ThresholdHigh, double);
  ///@}

  ///@{
  /// Parts of the selection touching the volume's border: BORDER_PARTS_AUTOMATIC (the default: dropped
  /// for a threshold selection, kept for a label or the non-zero voxels), BORDER_PARTS_DROP or
  /// BORDER_PARTS_KEEP.
  enum { BORDER_PARTS_AUTOMATIC = 0, BORDER_PARTS_DROP = 1, BORDER_PARTS_KEEP = 2 };
  vtkSetClampMacro(BorderParts, int, BORDER_PARTS_AUTOMATIC, BORDER_PARTS_KEEP);
  vtkGetMacro(BorderParts, int);
  ///@}
  /// Whether the next update drops parts touching the border (BorderParts resolved for the selection).
  bool GetDropBorderParts() const;
  ///@{
  /// Fill the cavities of the kept structure before phase I (default off).
  vtkSetMacro(FillHoles, bool);
  vtkGetMacro(FillHoles, bool);
  vtkBooleanMacro(FillHoles, bool);
  ///@}

  ///@{
  /// P0 in physical coordinates (mm); without it, the lowest end of the structure.
  void SetSeed(double x, double y, double z);
  void ClearSeed();
  ///@}

  ///@{
  /// A structure in several parts (a colon split by collapsed or fluid-filled segments): parts of at least
  /// MinimumPartVolume mm^3 (default 1000) are followed and chained from the lowest end (or the seed's
  /// part) across gaps of up to MaxGap mm (default 40), each gap bridged by the least-cost path through
  /// the volume; point data `Bridged` is 1 on the bridges (radius 0 there, no lumen). A longer gap starts
  /// another polyline (see GetNote). MaxGap 0: the largest part only, as in the paper. Not with
  /// DetectBranches (the largest part only).
  vtkSetClampMacro(MaxGap, double, 0.0, 1e6);
  vtkGetMacro(MaxGap, double);
  vtkSetClampMacro(MinimumPartVolume, double, 0.0, 1e12);
  vtkGetMacro(MinimumPartVolume, double);
  ///@}

  ///@{
  /// Width of the TSK antecedent Gaussians relative to their cluster (default 0.3).
  vtkSetClampMacro(AntecedentWidth, double, 0.01, 10.0);
  vtkGetMacro(AntecedentWidth, double);
  ///@}
  ///@{
  /// Branching structures (vessels, airways; beyond the paper): the structure is cut where its Manhattan
  /// layers fall apart, each branch is followed by the TSK method, and the output has one polyline per
  /// branch, starting at the junction on its parent, with cell data `Branch` and `ParentBranch` (-1 for the
  /// root). Default off: one polyline, as in the paper.
  vtkSetMacro(DetectBranches, bool);
  vtkGetMacro(DetectBranches, bool);
  vtkBooleanMacro(DetectBranches, bool);
  ///@}
  ///@{
  /// Side branches shorter than this (mm) stay part of the branch they leave (0, the default: twice the
  /// structure's largest inscribed radius).
  vtkSetClampMacro(MinimumBranchLength, double, 0.0, 1e6);
  vtkGetMacro(MinimumBranchLength, double);
  ///@}
  ///@{
  /// Passes that move the TSK curve towards the centre of its perpendicular sections (the paper's
  /// centricity criterion, §2, enforced after its two phases; default 2, 0 = the paper's curve as is).
  vtkSetClampMacro(CenteringIterations, int, 0, 20);
  vtkGetMacro(CenteringIterations, int);
  ///@}
  ///@{
  /// Distance between output points in mm (0: the smallest voxel spacing).
  vtkSetClampMacro(SampleSpacing, double, 0.0, 1e6);
  vtkGetMacro(SampleSpacing, double);
  ///@}

  ///@{
  /// Perpendicular sections and the unfolded wall on output ports 1 and 2 (default off).
  vtkSetMacro(ComputeSections, bool);
  vtkGetMacro(ComputeSections, bool);
  vtkBooleanMacro(ComputeSections, bool);
  ///@}
  ///@{
  /// k, the arc length between sections in mm (default 1).
  vtkSetClampMacro(SectionSpacing, double, 0.01, 1000.0);
  vtkGetMacro(SectionSpacing, double);
  ///@}
  ///@{
  /// Rays (angles) per section, even (default 72: every 5 degrees).
  vtkSetClampMacro(SectionRays, int, 4, 3600);
  vtkGetMacro(SectionRays, int);
  ///@}
  ///@{
  /// The lumen's closed surface on output port 3 (default off).
  vtkSetMacro(ComputeSurface, bool);
  vtkGetMacro(ComputeSurface, bool);
  vtkBooleanMacro(ComputeSurface, bool);
  ///@}
  ///@{
  /// The surface's triangle budget (default 100,000: about 60 frames per second in software rendering;
  /// 0: not decimated) and its windowed-sinc smoothing passes (default 20, 0: the voxel staircase).
  vtkSetClampMacro(SurfaceTriangles, int, 0, 100000000);
  vtkGetMacro(SurfaceTriangles, int);
  vtkSetClampMacro(SurfaceSmoothing, int, 0, 500);
  vtkGetMacro(SurfaceSmoothing, int);
  ///@}
  ///@{
  /// Keep the paper's intermediate results along the (first) tube (default off; not with DetectBranches),
  /// then GetStageData of: "voxels" (the followed structure's voxel centres in phase I's total order, as
  /// vertices with point data Layer - Fig. 3 -, Cluster - Figs. 7-8 - and T, the order parameter),
  /// "primitive" (the primitive centerline P_0 ... P_n, Figs. 4-6, a polyline with Layer and
  /// BorderDistance), "tsk-model" (x(t), y(t), z(t) sampled, a polyline with point data T: Figs. 9-10, and
  /// the curve before the centring passes, the paper's own output).
  vtkSetMacro(RecordStages, bool);
  vtkGetMacro(RecordStages, bool);
  vtkBooleanMacro(RecordStages, bool);
  vtkPolyData* GetStageData(const std::string& name) const;
  ///@}
  ///@{
  /// With RecordStages: the Manhattan layers (scalars `Layer`, Fig. 3) and the clusters (`Cluster`, Figs.
  /// 7-8) as an int label volume over the followed part's box (-1 outside), for the slice views.
  vtkImageData* GetStageLabels() const;
  ///@}
  /// The names GetStageData takes: "voxels", "primitive", "tsk-model".
  static std::vector<std::string> GetStageDataNames() { return {"voxels", "primitive", "tsk-model"}; }

  ///@{
  /// Figures of the last update.
  vtkGetMacro(PrimitiveCenterlinePoints, int);
  vtkGetMacro(StructureVoxels, vtkIdType);
  ///@}
  ///@{
  /// Parts of the structure followed (more than 1: gaps were bridged) and the gaps bridged.
  vtkGetMacro(PartsFollowed, int);
  int GetNumberOfBridgedGaps() const { return static_cast<int>(this->BridgedGaps.size()); }
  ///@}
  /// The length of a bridged gap (mm): of its bridge, the part outside the structure.
  double GetBridgedGap(int i) const;
  ///@{
  /// Notes of the last update a user should see: parts left out, a gap longer than MaxGap.
  int GetNumberOfNotes() const { return static_cast<int>(this->Notes.size()); }
  const char* GetNote(int i) const;
  ///@}
  /// Seconds of a stage of the last update: selection, cleanup (with the crop), axis, sections (0 when
  /// not run).
  double GetStageSeconds(const std::string& stage) const;
  /// The stages' names, in order (for C++ callers).
  static std::vector<std::string> GetStageNames();

 protected:
  ///@{
  /// VTK's pipeline: the constructor sets the defaults; the overrides of vtkAlgorithm check the input, run
  /// the algorithm and fill the outputs (errors leave them empty).
  vtkMedialTskCenterline();
  ~vtkMedialTskCenterline() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  ///@}

 private:
  vtkMedialTskCenterline(const vtkMedialTskCenterline&) = delete;
  void operator=(const vtkMedialTskCenterline&) = delete;
  /// Keeps the recorded intermediate results as polydata (RecordStages).
  void KeepStages(const medial::TskStages& stages);

  /// Parameters: defaults from medial::TskCenterlineParameters (the constructor).
  enum class Selection { NonZero, Label, Threshold, Automatic };
  Selection Mode;
  int Label;
  double ThresholdLow, ThresholdHigh;
  int BorderParts;
  bool FillHoles;
  bool HasSeed;
  double Seed[3] = {0, 0, 0};
  double MaxGap;
  double MinimumPartVolume;
  double AntecedentWidth;
  double SampleSpacing;
  int CenteringIterations;
  bool DetectBranches;
  double MinimumBranchLength;
  bool ComputeSections;
  double SectionSpacing;
  int SectionRays;
  bool ComputeSurface = false;
  int SurfaceTriangles;
  int SurfaceSmoothing;
  bool RecordStages = false;
  std::map<std::string, vtkSmartPointer<vtkPolyData>> Stages;
  vtkSmartPointer<vtkImageData> StageLabels;
  ///@{
  /// Figures of the last update.
  int PrimitiveCenterlinePoints = 0;
  vtkIdType StructureVoxels = 0;
  int PartsFollowed = 0;
  std::vector<double> BridgedGaps;
  std::vector<std::string> Notes;
  std::vector<std::pair<std::string, double>> StageSeconds;  ///< of the last update
  ///@}
};
