/// \file
/// MeshUnion: one closed 2-manifold mesh bounding the union of the volumes of several closed meshes (the
/// sketch's inflated parts; SQM's overlapping tubes). CGAL's corefinement (Polygon_mesh_processing::
/// corefine_and_compute_union), run with exact constructions (Epeck) so that the intersection curves are
/// computed exactly, one part after another; the result is rounded to doubles once, at the end.
///
/// Each output vertex keeps the label of its part: a vertex of an input keeps that input's label, a vertex
/// created on an intersection curve gets the smaller label of the two parts that meet there (the earlier
/// part, to which a later one is attached). A part entirely inside the others adds nothing.
#pragma once

#include "common/Error.h"
#include "mesh/TriangleMesh.h"

#include <functional>
#include <string>
#include <vector>

namespace medial {

/// The result of the union of closed meshes.
struct MeshUnionResult {
  TriangleMesh mesh;             ///< the boundary of the union
  std::vector<int> vertexLabel;  ///< one per output vertex
  Error error;                   ///< non-empty when a part is not closed or cuts itself, or cancelled
  /// True when the work succeeded (no error).
  bool ok() const { return error.empty(); }
};

/// The union of `parts` (each closed, manifold and free of self-intersections; one oriented inward is
/// turned outward), labelled 0, 1, ... in their order. progress(fraction) after each part; returning false
/// aborts.
MeshUnionResult meshUnion(const std::vector<TriangleMesh>& parts,
                          const std::function<bool(double)>& progress = {});

}  // namespace medial
