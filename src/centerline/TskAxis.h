/// \file
/// TskAxis: phase II of the TSK centerline paper (WSCG 2008, section 3, "Axis computation"). Over the total
/// order of phase I, with t the voxel's rank scaled to [0, 1], three one-dimensional Takagi-Sugeno-Kang
/// models x(t), y(t), z(t), one per physical coordinate:
///   - antecedents: one Gaussian per cluster j, centred on the mean t of its voxels, of standard deviation
///     `antecedentWidth` times the cluster's span in t (our reading of "a Gaussian membership function to
///     each one of the clusters ... responsible of conducting smooth transitions");
///   - consequents: per cluster, the least-squares line a_j t + b_j through its voxels' coordinates;
///   - model: f(t) = sum_j w_j(t) (a_j t + b_j) / sum_j w_j(t).
/// The width is the paper's open constant, a trade between accuracy and smoothness. Measured on a U tube
/// (radius 6, bend radius 20) and a straight tube (90 + 2 caps of 6 = 102 long):
///   width         0.2    0.3    0.4    0.5    1.0
///   U mean error  0.33   0.34   0.43   0.59   1.69 voxels
///   straight      108.7  106.0  104.6  103.8  -    length (narrow Gaussians leave small steps: wiggles)
/// 0.3 is the default.
/// The three models integrated over t, from the centre of the first cluster whose chosen point is not near
/// the wall to the last such one (the end clusters at the caps are lopsided and would hook the axis), give
/// the 3-D axis, resampled at uniform arc length; Radius comes
/// from the Euclidean distance map of the structure (distance to the nearest outside voxel centre minus half
/// a voxel, trilinear at the axis point).
#pragma once

#include "centerline/BinaryVolume.h"
#include "centerline/TubularClusters.h"

#include <cstdint>
#include <vector>

namespace medial {

/// The parameters of phase II (the TSK models; see the file's description).
struct TskParameters {
  double antecedentWidth = 0.3;  ///< sigma_j as a fraction of cluster j's span in t (see the header)
  double sampleSpacing = 0;      ///< mm between output points; 0: the smallest voxel spacing
  /// Passes of centerInSections (TubeSections.h) over the TSK curve; 0 keeps the paper's curve. 2 by
  /// default: on the tube phantoms the mean distance to the true axis drops from 0.28-0.54 mm to 0.05-0.10.
  int centeringIterations = 2;
};

/// A centerline: points along the structure's axis with the local radius.
struct Centerline {
  std::vector<Eigen::Vector3d> points;  ///< physical (mm)
  std::vector<double> radius;           ///< mm
  std::vector<double> arcLength;        ///< mm from the first point
  std::vector<uint8_t> bridged;         ///< per point, 1 on a bridge across a gap (GapBridges.h); empty: none
  /// The length in mm.
  double length() const { return arcLength.empty() ? 0 : arcLength.back(); }
};

/// The paper's Figs. 9-10: the three TSK models sampled densely over the order parameter t between the
/// first and the last kept cluster's centre; the points are the curve before the centring passes (the
/// paper's own output).
struct TskModelSamples {
  std::vector<double> t;               ///< order parameter t in [0, 1]
  std::vector<Eigen::Vector3d> point;  ///< (x(t), y(t), z(t)), mm
};

/// Phase II: the axis of the structure from phase I's clusters (see the file's description).
/// \param volume the structure (the followed part)
/// \param clusters phase I's result on it
/// \param parameters the antecedent width, the sample spacing, the centring passes
/// \param model when not null, receives the TSK models sampled over t (Figs. 9-10)
/// \return the axis with radii and arc length; empty when fewer than two clusters are usable
Centerline tskAxis(const BinaryVolume& volume, const TubularClusters& clusters,
                   const TskParameters& parameters = {}, TskModelSamples* model = nullptr);

/// Euclidean distance (mm) from every voxel centre to the nearest voxel centre outside the structure (0
/// outside), exact, separable (Felzenszwalb and Huttenlocher), anisotropic spacing honoured.
std::vector<float> distanceToOutside(const BinaryVolume& volume);

/// The distance to the outside (mm) at each point, trilinear between the voxels around it, computed in small
/// boxes around the points only.
std::vector<double> distanceAtPoints(const BinaryVolume& volume, const std::vector<Eigen::Vector3d>& points);

}  // namespace medial
