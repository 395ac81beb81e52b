/// \file
/// CycleClosing: extension 5 of the CESCG 2014 SQM paper. A cyclic skeleton is meshed as a tree: each edge
/// closing a cycle is cut and each of its ends gets a pseudo child at the other end's place (so that its
/// ring turns to face the other end), the tubes are built and placed as usual, and the two open rings are
/// then joined. The rings are projected onto one plane across the cut edge, put on concentric circles
/// (radius 1 for the first, 2 for the second) at their angles about their own centres, and triangulated
/// (Delaunay, CGAL); the triangles with vertices from both rings close the gap.
#pragma once

#include <Eigen/Core>

#include <array>
#include <vector>

namespace medial {

/// Triangles joining ringA (around centreA) and ringB (around centreB), both counter-clockwise about
/// their outward direction (towards each other), oriented consistently with the tubes they end.
std::vector<std::array<int, 3>> closeCycleGap(const std::vector<Eigen::Vector3d>& positions,
                                              const std::vector<int>& ringA, const Eigen::Vector3d& centreA,
                                              const std::vector<int>& ringB, const Eigen::Vector3d& centreB);

}  // namespace medial
