/// \file
/// BinaryVolume: a segmented 3-D image on plain arrays - which voxels belong to the structure - with its
/// physical frame (origin, spacing, direction: physical = origin + direction * (spacing .* index), the ITK
/// and VTK 9 convention), and the clean-up the TSK centerline needs before it starts.
#pragma once

#include <Eigen/Core>
#include <Eigen/LU>

#include <array>
#include <cstdint>
#include <vector>

namespace medial {

/// A segmented structure: a voxel mask in the volume's physical frame (ITK's convention:
/// physical = origin + direction * (spacing .* index)).
struct BinaryVolume {
  std::array<int, 3> size{0, 0, 0};                         ///< voxels along i, j, k
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();         ///< physical position of voxel (0, 0, 0), mm
  Eigen::Vector3d spacing = Eigen::Vector3d::Ones();        ///< mm between voxel centres along i, j, k
  Eigen::Matrix3d direction = Eigen::Matrix3d::Identity();  ///< the index axes' physical directions (columns)
  std::vector<uint8_t> inside;                              ///< 1 for voxels of the structure, x fastest

  /// The number of voxels.
  int64_t voxelCount() const { return int64_t(size[0]) * size[1] * size[2]; }
  /// The linear index of voxel (i, j, k), x fastest.
  int64_t index(int i, int j, int k) const { return i + int64_t(size[0]) * (j + int64_t(size[1]) * k); }
  /// The (i, j, k) of a linear index.
  std::array<int, 3> coordinates(int64_t index) const {
    return {int(index % size[0]), int((index / size[0]) % size[1]),
            int(index / (int64_t(size[0]) * size[1]))};
  }
  /// Whether (i, j, k) lies inside the volume.
  bool contains(int i, int j, int k) const {
    return i >= 0 && j >= 0 && k >= 0 && i < size[0] && j < size[1] && k < size[2];
  }
  /// The physical point (mm) of a continuous index.
  Eigen::Vector3d physical(const Eigen::Vector3d& continuousIndex) const {
    return origin + direction * spacing.cwiseProduct(continuousIndex);
  }
  /// The physical centre (mm) of a voxel.
  Eigen::Vector3d physical(int64_t index) const {
    const auto c = coordinates(index);
    return physical(Eigen::Vector3d(c[0], c[1], c[2]));
  }
  /// The continuous index of a physical point (the inverse of physical()).
  Eigen::Vector3d continuousIndex(const Eigen::Vector3d& point) const {
    return (direction.inverse() * (point - origin)).cwiseQuotient(spacing);
  }
};

// Whole-volume clean-up. tskCenterline does the same from runs (StructureRuns.h), without full-volume
// arrays; these stay as the reference its test compares against, and for callers holding a mask already.

/// Keeps the largest 26-connected component of the structure; returns how many components there were.
int keepLargestComponent(BinaryVolume& volume);

/// Removes the parts of the structure that touch the volume's border (air outside the body when the
/// structure is a threshold of air on a CT); returns the number of voxels removed.
int64_t dropBorderTouchingParts(BinaryVolume& volume);

/// Fills the cavities of the structure: background voxels not 6-connected to the volume's border.
int64_t fillHoles(BinaryVolume& volume);

/// Crops the volume to the structure's bounding box grown by `margin` voxels (kept within the volume),
/// moving the origin so that every voxel keeps its physical position; returns the index of the new first
/// voxel in the old volume. With margin >= 1 the box's outer layer is background, so distances to the
/// background, layers and sections inside are the same as in the whole volume; a CT's colon fills a
/// tenth of it.
std::array<int, 3> cropToStructure(BinaryVolume& volume, int margin = 1);

}  // namespace medial
