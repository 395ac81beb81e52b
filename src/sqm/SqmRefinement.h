/// \file
/// SqmRefinement: stage 8 of the SQM issue, the CPU counterpart of the CESCG 2014 paper's GPU tessellation
/// (section 5, "Tessellation"): each face of the base mesh is tessellated (K levels of bilinear splitting,
/// OpenSubdiv's Far with its bilinear scheme: an n-gon becomes n quads, a quad four) and every new vertex
/// is projected onto the union of the spheres swept along the skeleton's edges (SweptSpheres: the end
/// spheres joined by their tangent cone), level by level. Catmull-Clark was used before: on a cycle without
/// nodes between its corners it pulled each corner inward by a sixth of the edge, and the projection
/// (perpendicular to the edges) could not bring it back, leaving the corner nodes outside the mesh.
/// Where a point lies near two edges' surfaces and the projection onto the nearest lies inside the other
/// (the inner side of a bend, tubes crowding a branch node) it goes to a blend of the projections, a
/// rounded crease, and is blended again twice from there (each pass halves its depth below the crease).
///
/// Radius scaling at sharp vertices (the paper's last paragraph of section 5): projecting onto the swept
/// surfaces makes the mesh gain volume, and where two tubes leave a branch node at a narrow angle the
/// refined faces of one tube cut into the other. A vertex of the base mesh is sharp where two of its faces
/// form an acute angle (their normals more than 90 degrees apart, a fold). Each refined vertex then gets
/// the surface's radius times B(t), a cubic Bézier curve with control values (s, s, 1, 1), s =
/// minimumScale, at t = (distance to the nearest sharp base vertex) / (radius there), clamped to [0, 1]:
/// s at the sharp vertex, 1 one radius away. The paper's curve is likewise constant (not tuned per vertex).
/// Fold repair (beyond the paper, FoldRepair): after the last level's projection, the vertices of faces
/// that fold over others move back towards the base mesh's own tessellation until none do; when folds are
/// left that repairing the coarser levels could undo, every level is refined again with the repair.
/// After refinement every face is a quad, and the mesh stays closed and manifold.
#pragma once

#include "skeleton/Skeleton.h"
#include "sqm/SqmMesher.h"

#include <utility>
#include <vector>

namespace medial {

/// What the refinement's fold repair found, beside the refined mesh.
struct RefinementReport {
  int repairedVertices = 0;  ///< vertices moved back towards the base mesh
};

/// Refines `mesh` in place; `skeleton` is the skeleton it was made from (nodes, radii, edges). With
/// `foldRepair`, vertices of faces that fold over others go back towards the base mesh until none do.
/// Returns the number of sharp base vertices found (0 when scaling is off).
int refineSqmMesh(SqmMesh& mesh, const Skeleton& skeleton, int levels, const SharpScaling& scaling = {},
                  bool foldRepair = true, RefinementReport* report = nullptr);

/// B(t) of the scaling: the cubic Bézier curve with control values (s, s, 1, 1), t clamped to [0, 1].
double sharpScaleFactor(double t, double minimumScale);

}  // namespace medial
