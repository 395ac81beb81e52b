// SqmRefinement: stage 8 of the SQM issue, the CPU counterpart of the CESCG 2014 paper's GPU tessellation
// (section 5, "Tessellation"): K levels of Catmull-Clark subdivision (OpenMesh), each followed by the
// projection of every vertex onto the truncated cone of the skeleton edge nearest to it - the cone whose
// radius runs linearly from the parent's sphere to the child's along the edge (with ellipsoid nodes, whose
// cross-section interpolates the two ends' ellipsoid matrices). Chosen here: the projection is radial from
// the edge's axis (the paper translates along the vertex normal; radial is the same on a straight tube and
// never misses the cone), and where the projection lies inside another cone whose surface is about as
// near (the inner side of a bend, tubes crowding a branch node) the point goes to a blend of the two
// projections, a rounded crease, instead of snapping to one cone or the other and folding.
//
// Radius scaling at sharp vertices (the paper's last paragraph of section 5): projecting onto the cones
// makes the mesh gain volume, and where two tubes leave a branch node at a narrow angle the refined faces
// of one tube cut into the other. A vertex of the base mesh is sharp where two of its faces form an acute
// angle (their normals more than 90 degrees apart, a fold). Each refined vertex then gets the cone radius
// times B(t), a cubic Bézier curve with control values (s, s, 1, 1), s = minimumScale, at
// t = (distance to the nearest sharp base vertex) / (cone radius there), clamped to [0, 1]: s at the sharp
// vertex, 1 one radius away. The paper's curve is likewise constant (not tuned per vertex).
// Fold repair (beyond the paper): after each level's projection, the vertices of faces that cut other
// faces (CGAL's exact test) move back halfway towards their plain Catmull-Clark points, repeatedly, until
// no face cuts another (at most six halvings, then all the way): the plain Catmull-Clark surface of a
// base mesh that does not cut itself did not cut itself on any test skeleton.
// After refinement every face is a quad (Catmull-Clark), and the mesh stays closed and manifold.
#pragma once

#include "skeleton/Skeleton.h"
#include "sqm/SqmMesher.h"

namespace medial {

// Refines `mesh` in place; `skeleton` is the skeleton it was made from (nodes, radii, edges). With
// `foldRepair`, vertices of faces that cut others go back towards their Catmull-Clark points until none
// do (counted in *repairedVertices). Returns the number of sharp base vertices found (0 when scaling is off).
int refineSqmMesh(SqmMesh& mesh, const Skeleton& skeleton, int levels, const SharpScaling& scaling = {},
                  bool foldRepair = true, int* repairedVertices = nullptr);

// B(t) of the scaling: the cubic Bézier curve with control values (s, s, 1, 1), t clamped to [0, 1].
double sharpScaleFactor(double t, double minimumScale);

}  // namespace medial
