/// \file
/// TrianglePairing: joins neighbouring triangles of a strip into quads, so that the leaf fans and the cycle
/// bands of SQM (the only places the paper puts triangles) become quads too where the pair makes a fair
/// quad. A strip is a cycle of triangles each sharing an edge with the next: a fan around a leaf's apex, or
/// the band closing a cut cycle edge. On each cycle the most pairs are taken (a cycle of even length pairs
/// up completely when every pair is fair), then the flattest pairs; what is left stays a triangle.
///
/// A pair is fair when the quad folds by less than `maxFoldDegrees` about either diagonal: a fan of 8
/// around a cone's tip gives quads folded by about 50 degrees, a fan of 4 would give two quads folded by 90
/// degrees over one diagonal they share, and stays triangles.
#pragma once

#include <Eigen/Core>

#include <vector>

namespace medial {

/// Replaces pairs of triangles of each strip (indices into `faces`, consistently oriented, in any order) by
/// quads whose 0-2 diagonal is the shared edge, so that splitting a quad along it gives back the two
/// triangles. A strip whose triangles do not form one path or cycle is left alone. No vertex is left on
/// fewer than three faces. Faces keep their order; a quad takes the place of its first triangle.
/// Returns the number of quads made.
int pairStripTriangles(const std::vector<Eigen::Vector3d>& vertices, std::vector<std::vector<int>>& faces,
                       const std::vector<std::vector<size_t>>& strips, double maxFoldDegrees = 75.0);

}  // namespace medial
