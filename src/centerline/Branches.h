/// \file
/// Branches: the structure of a branching tube (vessels, airways) cut into unbranched tubes, for the TSK
/// centerline to follow one at a time (issue 5, beyond the paper). The Manhattan layers grown from P0 (the
/// paper's phase I) are cross-sections of the tube; where a layer falls apart into several 26-connected
/// pieces, the tube branches. Pieces are linked to the piece of the previous layer they touch, giving a tree;
/// chains of single pieces are branches. A side branch shorter than `minimumLength` layers (a bump, noise,
/// a short stub) stays part of the branch it leaves.
#pragma once

#include "centerline/BinaryVolume.h"

#include <cstdint>
#include <string>
#include <vector>

namespace medial {

/// A branching structure split into branches (a root and the branches leaving it).
struct BranchVolumes {
  std::vector<std::vector<int64_t>> voxels;  ///< per branch, its voxels
  std::vector<int> parent;                   ///< per branch, the branch it leaves (-1: the root)
  std::vector<int64_t> start;                ///< per branch, a voxel of its first layer (its P0)
  std::string error;                         ///< why the split failed; empty on success
  /// True when the split succeeded.
  bool ok() const { return error.empty(); }
};

/// `seed`: P0 (a voxel inside), or -1 for the structure's lowest voxel. `centrality` (optional, per voxel,
/// e.g. the distance to the outside): a branch starts at the voxel of its first layer that maximizes it, so
/// that its layers grow from the middle of the junction and not from its wall.
BranchVolumes splitBranches(const BinaryVolume& volume, int64_t seed, int minimumLength,
                            const std::vector<float>* centrality = nullptr);

}  // namespace medial
