/// \file
/// TskCenterline: the whole TSK centerline of a tubular structure in a volume (WSCG 2008), from the voxels
/// to the finished polylines: the structure selected (a label, a threshold window or the non-zero voxels),
/// cleaned (parts touching the volume's border dropped, the largest 26-component kept - or every part above
/// a volume, chained across the gaps between them by GapBridges - holes filled on request) and cropped to
/// its box; then phase I (TubularClusters) and phase II (TskAxis) along one tube,
/// or along every branch of a tree (Branches, beyond the paper); and on request the perpendicular sections
/// of paper §4 (TubeSections) along the first polyline.
#pragma once

#include "common/Error.h"
#include "centerline/BinaryVolume.h"
#include "centerline/TskAxis.h"
#include "centerline/TubeSections.h"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace medial {

/// A volume's voxels as they are in memory (no copy), with the volume's physical frame.
struct ScalarVolume {
  /// The voxels' type.
  enum class Type { Int8, UInt8, Int16, UInt16, Int32, UInt32, Int64, UInt64, Float32, Float64 };
  std::array<int, 3> size{0, 0, 0};                         ///< voxels along i, j, k
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();         ///< physical position of voxel (0, 0, 0), mm
  Eigen::Vector3d spacing = Eigen::Vector3d::Ones();        ///< mm between voxel centres along i, j, k
  Eigen::Matrix3d direction = Eigen::Matrix3d::Identity();  ///< the index axes' physical directions (columns)
  const void* voxels = nullptr;  ///< x fastest; `components` values per voxel, the first one used
  Type type = Type::UInt8;       ///< the type of `voxels`
  int components = 1;            ///< values per voxel
};

/// Which voxels make the structure. Automatic (the default) looks at the volume: a CT in Hounsfield
/// units (signed or floating-point voxels reaching below -200) takes its air, every voxel up to the
/// threshold window's top (-600 HU: below -1024 too, where a noisy CT stored unclipped puts some), and says
/// so in a note - or, with no voxel in the window, is an error that asks for a threshold
/// or a label; any other volume takes its non-zero voxels, unless they fill most of it (then an error
/// too: a body, not a tube).
enum class VoxelSelection { NonZero, Label, Threshold, Automatic };

/// What happens to parts of the selection that touch the volume's border. Automatic drops them for a
/// threshold selection (the air around the body of a CT) and keeps them for labels and non-zero voxels.
enum class BorderParts { Automatic, Drop, Keep };

/// The parameters of tskCenterline(), with the paper's defaults and Medial's own (selection,
/// clean-up, gaps, branches, sections).
struct TskCenterlineParameters {
  VoxelSelection selection = VoxelSelection::Automatic;  ///< which voxels make the structure
  double label = 1;                                      ///< with VoxelSelection::Label
  ///@{
  /// With VoxelSelection::Threshold, inclusive; by default the air in the colon on CT (the paper's use).
  double thresholdLow = -1024, thresholdHigh = -600;
  ///@}
  BorderParts borderParts = BorderParts::Automatic;  ///< parts touching the volume's border: dropped or kept
  bool fillHoles = false;                            ///< cavities of the structure filled before phase I
  std::optional<Eigen::Vector3d> seed;               ///< P0 in physical coordinates; else the lowest end
  TskParameters tsk;                                 ///< phase II and the centring passes
  ///@{
  /// A structure in several parts (a colon split by collapsed or fluid-filled segments): parts of at least
  /// `minimumPartVolume` mm^3 are followed and chained across gaps of up to `maxGap` mm (GapBridges.h);
  /// a longer gap starts another polyline. maxGap 0: the largest part only (the paper's input).
  double maxGap = 40;
  double minimumPartVolume = 1000;
  ///@}
  bool detectBranches = false;     ///< one polyline per branch (Branches.h; the largest part only)
  double minimumBranchLength = 0;  ///< mm; 0: twice the largest inscribed radius
  bool computeSections = false;    ///< sections along the first polyline (TubeSections.h)
  SectionParameters sections;      ///< with computeSections: where and how densely
  /// The paper's intermediate results (TskCenterlineResult::stages), along one tube (not with branches).
  bool recordStages = false;
  /// The followed structure's voxels (TskCenterlineResult::structure), e.g. for the lumen's surface.
  bool keepStructure = false;
};

/// What the paper draws on the way (WSCG 2008 Figs. 3-10), in physical coordinates (mm).
struct TskStages {
  std::vector<Eigen::Vector3d> voxels;  ///< the followed structure's voxel centres, in phase I's total order
  std::vector<int> layer;               ///< Manhattan layer from P0 of each (Fig. 3)
  std::vector<int> cluster;             ///< cluster (primitive point) of each (Figs. 7-8)
  std::vector<Eigen::Vector3d> primitive;      ///< phase I's chosen points P_0 ... P_n (Figs. 4-6)
  std::vector<int> primitiveLayer;             ///< Manhattan layer of each chosen point
  std::vector<float> primitiveBorderDistance;  ///< mm, six directions
  TskModelSamples model;  ///< x(t), y(t), z(t) (Figs. 9-10); a voxel's t is its rank / (voxels - 1)
  ///@{
  /// The same layers and clusters as label volumes over the followed part's box (-1 outside the structure
  /// or unreached), for the slice views: voxel (i, j, k) at origin + direction * (spacing .* (i, j, k)).
  std::array<int, 3> boxSize{0, 0, 0};
  Eigen::Vector3d boxOrigin = Eigen::Vector3d::Zero(), boxSpacing = Eigen::Vector3d::Ones();
  Eigen::Matrix3d boxDirection = Eigen::Matrix3d::Identity();
  std::vector<int> layerVolume, clusterVolume;
  ///@}
};

/// What tskCenterline() found: the branches' centerlines, their sections and the stages.
struct TskCenterlineResult {
  std::vector<Centerline> branches;   ///< the first is the root (the only one without detectBranches)
  std::vector<int> parent;            ///< per branch: the branch it leaves (-1: the root)
  std::vector<int> junction;          ///< per branch: the point of its parent where it starts (-1: the root)
  TubeSections sections;              ///< with computeSections
  int64_t structureVoxels = 0;        ///< after selection and clean-up
  int primitiveCenterlinePoints = 0;  ///< phase I's chosen points, over all branches
  int partsFollowed = 0;              ///< parts of the structure followed (more than 1: gaps bridged)
  std::vector<double> bridgedGaps;    ///< mm, the length of each bridge outside the structure
  std::vector<std::string> notes;     ///< what a user should know: parts left out, gaps too long
  TskStages stages;                   ///< with recordStages, along one tube
  /// With keepStructure: the followed part(s) after clean-up and hole filling, in their box grown by one
  /// voxel (its outer layer is background unless the structure touches the volume's border).
  BinaryVolume structure;
  /// Seconds of each stage, in order: selection (runs of selected voxels), cleanup (the part to follow in
  /// its box, holes), axis (phases I and II, and the branches), sections.
  std::vector<std::pair<std::string, double>> stageSeconds;
  Error error;  ///< why the work failed; empty on success
  /// True when the work succeeded (no error).
  bool ok() const { return error.empty(); }
};

/// The TSK centerline of the structure in `volume` \cite tsk2008.
/// \param volume a 3-D volume, at least 2 voxels along each axis
/// \param parameters selection, clean-up, seed, the TSK parameters, branches and sections
/// \param progress called with the fraction done; returning false stops the work (error: Error::cancelled())
/// \return polylines in physical coordinates (mm) with radii and arc lengths, or an error naming the
///         problem: no voxel selected, nothing left after the clean-up, a seed outside the structure
TskCenterlineResult tskCenterline(const ScalarVolume& volume, const TskCenterlineParameters& parameters = {},
                                  const std::function<bool(double)>& progress = {});

}  // namespace medial
