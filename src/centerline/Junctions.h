/// \file
/// Junctions: where the branches of a tree meet (beyond the paper, with Branches.h). A parent branch's TSK
/// line runs on past the true junction up the middle of the blob where its children part (its last layers
/// are the junction's, not its own tube's), and the children joined it at that overshot end: 1.9 mm (0.4
/// radius) off the axis on the tree phantom. Instead the parent is cut back by as far as its children start
/// from its end, and each child is reached from there by a cubic Hermite curve that leaves along the
/// parent's direction and arrives along the child's own (the true axes curve out of a junction the same
/// way): the tree's worst distance to the true axis 0.58 mm, its mean 0.12 (was 1.91 and 0.17). Of such
/// curves, leaving between the parent's direction and the straight way to the child, the one of the largest
/// mean inscribed radius is taken (the distance map's ridge): 0.42 and 0.095 mm.
#pragma once

#include "centerline/BinaryVolume.h"
#include "centerline/TskAxis.h"

#include <vector>

namespace medial {

/// Cuts back every parent that its children leave at its end (they start within 3 radii of it) and
/// prepends to each child its curve from the new end. `parents[b]`: branch b's parent, -1 for the root.
/// Radii (from the distance map) and arc lengths follow.
void placeJunctions(const BinaryVolume& volume, std::vector<Centerline>& branches,
                    const std::vector<int>& parents);

}  // namespace medial
