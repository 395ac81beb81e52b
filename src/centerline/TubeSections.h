/// \file
/// TubeSections: perpendicular sections of a segmented tube along its centerline, the measurements of the
/// TSK paper's section 4 (Fig. 14: sections along the axis, diameter and perimeter evolution) and its
/// "terrain" view of the inner wall (Fig. 15): at every k mm of arc length, rays in the plane
/// perpendicular to the axis find the wall (where the structure's mask, trilinearly interpolated, drops
/// below 1/2); each section gives min/max diameter, perimeter and area, and the wall distances over arc
/// length x angle form the unfolded wall image.
#pragma once

#include "BinaryVolume.h"

#include <Eigen/Core>

#include <cstdint>
#include <functional>
#include <vector>

namespace medial {

/// Where and how densely sections are cast (paper §4).
struct SectionParameters {
  double spacing = 1.0;  ///< k: mm of arc length between sections
  int rays = 72;         ///< angles per section (even; every 5 degrees by default)
  double maxRadius = 0;  ///< farthest wall searched (mm); 0: 100 x the smallest voxel spacing
};

/// Sections of a tube across its centerline (paper §4: rays from the axis to the wall), for the
/// diameter profile (Fig. 14) and the unfolded wall (Fig. 15).
struct TubeSections {
  int rays = 0;                           ///< rays per section
  std::vector<double> arcLength;          ///< mm, per section
  std::vector<Eigen::Vector3d> center;    ///< on the axis
  std::vector<Eigen::Vector3d> tangent;   ///< unit, along the axis
  std::vector<Eigen::Vector3d> normal;    ///< unit, angle 0 of the rays (transported along the axis)
  std::vector<std::vector<double>> wall;  ///< per section, per ray: distance axis-wall (mm); NaN: none
  std::vector<double> minDiameter;        ///< per section, mm (NaN if a ray failed)
  std::vector<double> maxDiameter;        ///< per section, mm (NaN if a ray failed)
  std::vector<double> perimeter;          ///< per section, mm (NaN if a ray failed)
  std::vector<double> area;               ///< per section, mm^2 (NaN if a ray failed)
  std::vector<uint8_t> bridged;  ///< per section: 1 on a bridge across a gap (walls NaN: no lumen there)
};

/// Sections of `volume`'s structure along the polyline `axis` (physical mm, at least two distinct points).
/// `keepGoing(fraction)` reports progress and returns false to abort (the result is then empty).
TubeSections tubeSections(const BinaryVolume& volume, const std::vector<Eigen::Vector3d>& axis,
                          const SectionParameters& parameters = {},
                          const std::function<bool(double)>& keepGoing = nullptr);

/// Centricity (the paper's §2: in the section perpendicular to the axis, the axis point should be as far
/// as possible from the wall): moves every point of `axis` towards the centroid of its section's wall
/// polygon (`rays` rays), the moves smoothed along the axis over +-`smoothing` mm so that the line stays
/// smooth, `iterations` times. Points whose section has no closed wall stay. Returns the moved points.
std::vector<Eigen::Vector3d> centerInSections(const BinaryVolume& volume, std::vector<Eigen::Vector3d> axis,
                                              int rays = 36, int iterations = 3, double smoothing = 2.0);

/// The axis grown at both ends towards the caps of its tube, as far as one local radius before each (the TSK
/// curve stops where its end clusters turn lopsided, up to 3 radii short on a wide colon): a point a voxel
/// ahead along the end's direction, moved to the centroid of its perpendicular section (three times), taken
/// while the wall straight ahead lies farther than the section's median radius; the direction follows the
/// new points. Ends at the volume's border stop there. Returns the longer axis.
std::vector<Eigen::Vector3d> extendToCaps(const BinaryVolume& volume, std::vector<Eigen::Vector3d> axis,
                                          int rays = 36);

}  // namespace medial
