/// \file
/// SqmUnion: where the tubes of parts of a skeleton that are not neighbours overlap (a dense tree whose
/// branches pass through each other, a sketch whose fingers touch), SQM's mesh is closed and manifold but
/// its faces cut each other, so that it bounds no volume. The union replaces it by the surface of the
/// volume its tubes enclose together: one closed 2-manifold without self-intersection (issue 27, beyond
/// the papers, which assume tubes that do not meet).
///
/// How (the outer-hull idea of Zhou et al., "Mesh arrangements for solid geometry", 2016): the faces are
/// split into triangles (fanned from their first vertex, as VTK draws them); CGAL's autorefinement
/// (Polygon_mesh_processing::experimental::autorefine, exact constructions) cuts them along every
/// intersection curve, which splits the surface into patches; a patch is kept where the winding number of
/// the whole mesh (crossings counted along rays) is >= 1 (solid) on one side of it and 0 on the other, and
/// turned over if the solid lies in front of it (a fold's pocket). So a tube inside another disappears, a
/// cavity enclosed by tubes stays (facing into it), and folds of the refinement are resolved with the
/// overlaps; closed components that enclose no volume (sheets that only touch) or less than a given
/// volume (a cavity where three tubes meet, a bubble of a fold) are dropped. A polygon none of whose
/// triangles was cut or dropped comes back whole, so quads stay quads away from the intersection curves; the
/// cut ones' triangles are cleaned along the curves (CurveCleanup), kept where the mesh stays a closed
/// manifold that cuts itself no more than before. A vertex keeps its skeleton node; a vertex created on an
/// intersection curve takes the smallest node among its neighbours. Coordinates are rounded to doubles once
/// (CGAL's are exact), and the result is tested again for faces cutting each other.
#pragma once

#include "sqm/CurveCleanup.h"
#include "sqm/SqmMesh.h"

#include <string>
#include <utility>
#include <vector>

namespace medial {

/// Where the tubes of an SQM mesh overlap: the counts of sqmOverlaps().
struct SqmOverlaps {
  int facePairs = 0;     ///< pairs of polygons that cut each other
  int nodePairs = 0;     ///< distinct pairs of skeleton nodes whose faces cut each other
  bool complete = true;  ///< false: counting stopped at kOverlapCountLimit face pairs ("at least")
};

/// Counting overlaps stops after this many pairs of faces: a note needs no more, and a skeleton whose
/// tubes cross everywhere would spend longer counting than meshing.
constexpr int kOverlapCountLimit = 100000;

/// Where the tubes of an SQM mesh overlap: pairs of polygons of different skeleton nodes, not neighbours
/// on the surface, that cut each other (GroupIntersections), and the pairs of nodes they belong to.
SqmOverlaps sqmOverlaps(const SqmMesh& mesh);
/// The same from pairs of polygons already known to cut each other (the refinement's last fold test).
SqmOverlaps sqmOverlaps(const SqmMesh& mesh, const std::vector<std::pair<int, int>>& facePairs);

/// What unionSqmMesh() did.
struct SqmUnionResult {
  SqmOverlaps before;       ///< what the mesh had
  int cutPolygons = 0;      ///< polygons cut along an intersection curve or removed in part
  int removedPolygons = 0;  ///< polygons wholly inside the volume, removed
  int turnedPolygons = 0;   ///< polygons turned over (the solid lay in front of them)
  int droppedPockets = 0;   ///< closed components enclosing no volume or less than the smallest part, dropped
  double autorefineSeconds = 0;  ///< CGAL's cutting along the intersection curves
  double selectionSeconds = 0;   ///< the winding numbers that select the union's faces
  CurveCleanup cleanup;          ///< the cut triangles along the curves (CurveCleanup)
  int intersectingAfter = 0;     ///< face pairs still cutting each other after rounding (0 expected)
  std::string error;             ///< when the union is not a closed manifold (tubes touching along a line)
  /// True when the union succeeded (no error).
  bool ok() const { return error.empty(); }
};

/// Replaces `mesh` by the boundary of the union of the volumes its overlapping parts enclose. A mesh
/// without self-intersections is left as it is. An open mesh (no volume to unite) and a union that is not a
/// closed manifold (sheets touching along a line) are errors; on error `mesh` is left as it was.
/// \param mesh the SQM mesh, replaced by the union
/// \param smallestPart a closed component (cavity or bubble) of less volume than this is dropped (SqmMesher
///        passes a tenth of the ball of the smallest input radius)
/// \param known the mesh's overlaps when already counted (else they are counted here)
SqmUnionResult unionSqmMesh(SqmMesh& mesh, double smallestPart = 0, const SqmOverlaps* known = nullptr);

}  // namespace medial
