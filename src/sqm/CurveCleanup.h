/// \file
/// CurveCleanup: the last stage of SqmUnion (issue 27: "quads kept away from the intersection curves and a
/// clean triangulation along them"). The polygons the union cut come out as CGAL's triangulation of each cut
/// triangle; an intersection curve has a vertex wherever it crosses an edge of either sheet, often a few
/// hundredths of an edge apart, and the triangles fanning into such vertices are slivers. Along each curve,
/// an edge much shorter than the edges around it is collapsed into its neighbour on the curve (never at a
/// junction of curves or a corner of one, never where OpenMesh's link condition fails or a triangle would
/// turn over); then
/// edges between cut triangles are flipped where the Delaunay criterion asks for it. Vertices of whole
/// polygons never move, so quads stay quads; the curves keep their vertices but the collapsed ones.
/// (CGAL 5.5's isotropic remeshing did this too but looped forever on some inputs.)
#pragma once

#include "sqm/SqmMesh.h"

#include <utility>
#include <vector>

namespace medial {

/// What the clean-up of the cut triangles along the union's intersection curves did.
struct CurveCleanup {
  int collapsed = 0;      ///< curve vertices removed
  int flipped = 0;        ///< edges flipped
  int snapped = 0;        ///< polygon corners moved onto a curve vertex beside them
  int sliversBefore = 0;  ///< cut triangles with an angle below kSliverDegrees, before
  int sliversAfter = 0;   ///< and after the clean-up
  bool applied = false;   ///< false: not a manifold OpenMesh takes, the mesh is unchanged
};

/// A triangle with an angle below this is a sliver.
constexpr double kSliverDegrees = 10;

/// The smallest angle of polygon `face` of `mesh`, in degrees.
double smallestAngle(const SqmMesh& mesh, size_t face);

/// Cleans the triangles flagged in `band` along the curve edges `curves` (pairs of vertex indices). Vertices
/// flagged in `frozen` (may be empty) are neither removed nor is an edge flipped next to them. `original`,
/// when given, receives the input index of each vertex of the cleaned mesh.
CurveCleanup cleanCurveBands(SqmMesh& mesh, const std::vector<char>& band,
                             const std::vector<std::pair<int, int>>& curves,
                             const std::vector<char>& frozen = {}, std::vector<int>* original = nullptr);

}  // namespace medial
