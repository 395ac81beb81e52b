/// \file
/// GapBridges: one centerline across a colon split into parts by collapsed or fluid-filled segments (the
/// TSK paper claims robustness to such discontinuities; its method follows one connected structure).
/// Each part kept gets its own TSK centerline. The parts are chained from the lowest end (the rectum, the
/// paper's P0) or from the seed: from the chain's last point, the nearest end of a part not used yet is
/// taken if it lies within the maximum gap, and the gap is bridged by the least-cost path through the CT
/// (A*, 26-connected, the cost per mm of a voxel growing with its value above the selection window, so
/// that the bridge keeps to low densities and stays nearly straight), smoothed and resampled at the
/// centerline's spacing; where it runs through lumen (a TSK line stops short of its part's caps) it is
/// centred and measured like the rest, and where there is no lumen its points have `bridged` = 1 and
/// radius 0. A gap longer than the
/// maximum starts another chain: several polylines.
#pragma once

#include "centerline/TskAxis.h"

#include <Eigen/Core>

#include <array>
#include <functional>
#include <limits>
#include <vector>

namespace medial {

/// Cost per mm of every voxel of a box of the volume (voxel indices `first` .. `first + size - 1`).
struct CostBox {
  std::array<int, 3> first{};  ///< the box's first voxel in the whole volume
  std::array<int, 3> size{};   ///< voxels of the box along i, j, k
  std::vector<float> cost;     ///< x fastest, >= 1
};

/// The least-cost 26-connected path from voxel `from` to voxel `to` (indices of the whole volume, both in
/// the box), a step costing its length in mm times the mean cost of its two voxels; A* with the
/// Euclidean distance (cost >= 1 per mm) as the heuristic. Empty when `to` cannot be reached.
std::vector<std::array<int, 3>> leastCostPath(const CostBox& box, const Eigen::Vector3d& spacing,
                                              const std::array<int, 3>& from, const std::array<int, 3>& to);

/// A bridge across a gap: its points (ends excluded) and the gap's length, the mm of its path that lie
/// outside the structure (infinite when no path was found).
struct Bridge {
  std::vector<Eigen::Vector3d> points;                   ///< mm, the ends excluded
  double gap = std::numeric_limits<double>::infinity();  ///< mm outside the structure; infinite: no path
};
/// The two ends a bridge joins: the chain's last point and the direction it leaves in, the next part's end
/// and the direction the line arrives at it in (unit vectors, along the line's way).
struct BridgeEnds {
  Eigen::Vector3d from;           ///< the chain's last point (mm)
  Eigen::Vector3d fromDirection;  ///< the direction the chain leaves it in
  Eigen::Vector3d to;             ///< the next part's end (mm)
  Eigen::Vector3d toDirection;    ///< the direction the line arrives at it in
};
/// Makes the bridge between two ends (the least-cost path, a Hermite curve, or the one of both that
/// fits the CT better).
using BridgeFunction = std::function<Bridge(const BridgeEnds& ends)>;

/// The cubic Hermite curve from `from` to `to` leaving along `fromDirection` and arriving along
/// `toDirection` (unit; scaled by `tangentScale` times the chord), sampled every `spacing` mm, both ends
/// left out: where the CT holds no evidence of the tube's course, the curve that continues both ends'
/// directions.
std::vector<Eigen::Vector3d> hermiteCurve(const Eigen::Vector3d& from, const Eigen::Vector3d& fromDirection,
                                          const Eigen::Vector3d& to, const Eigen::Vector3d& toDirection,
                                          double spacing, double tangentScale = 1.0);

/// The tangent scale of a bridge's Hermite curve. The ends' directions come from 3 mm of each line and are
/// 8 to 34 degrees off the true axis's at a gap's faces; shorter tangents give them less say. The worst
/// distance to the true axis over seven gaps of 12 and 20 mm in the tube phantoms, by scale: 0.4: 3.23 mm,
/// 0.6: 2.84, 0.8: 3.26, 1.0: 3.72, 1.2: 4.20 (the least-cost path alone: 5.06).
constexpr double kBridgeTangentScale = 0.6;

/// A part's centerline in a chain: which, whether it runs backwards, and the bridge that leads to it.
struct ChainLink {
  int part = 0;           ///< the part (index into the parts' centerlines)
  bool reversed = false;  ///< true: the part's centerline runs backwards in the chain
  Bridge bridge;          ///< from the chain's previous part (none for the first)
};

/// The parts' centerlines linked into chains across the gaps between them.
struct PartChains {
  std::vector<std::vector<ChainLink>> chains;  ///< the first starts at `start` (or the lowest end)
  std::vector<double> brokenGaps;  ///< mm: per chain after the first, the gap that ended the one before
};

/// Orders the parts' centerlines into chains (see the header). `startPart` >= 0: the first chain starts at
/// that part's first point (the seed's); else at the lowest end (smallest physical z) of any part, as
/// every later chain does among the parts left. From a chain's last point the nearest end of a part left
/// is bridged when it is near enough to hold a gap of `maxGap` (the ends of a TSK line stand back from the
/// caps by about a radius), and joined when the bridge's gap is at most `maxGap`. The ends' directions
/// come from the last 3 mm of each line.
PartChains chainParts(const std::vector<Centerline>& parts, int startPart, double maxGap,
                      const BridgeFunction& bridge);

/// The points of a bridge from `from` to `to` (exclusive) through `path` (voxel centres, physical),
/// smoothed and resampled every `spacing` mm.
std::vector<Eigen::Vector3d> bridgePoints(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                                          std::vector<Eigen::Vector3d> path, double spacing);

/// One centerline along `chain`, the parts joined by their bridges; arc lengths recomputed, `bridged` set
/// (radius 0 on the bridges).
Centerline joinChain(const std::vector<Centerline>& parts, const std::vector<ChainLink>& chain);

/// The bridges of `line` (its points with `bridged` = 1, from joinChain) refined in `volume`, the
/// structure: a TSK line stops about a radius before its part's cap, so a bridge first runs through lumen;
/// those stretches are centred in their sections and get their radius, and `bridged` stays 1 only where
/// there is no lumen (the point's voxel outside the structure; radius 0 there).
void refineBridges(const BinaryVolume& volume, Centerline& line);

}  // namespace medial
