// SqmRefinement: stage 8 of the SQM issue, the CPU counterpart of the CESCG 2014 paper's GPU tessellation
// (section 5, "Tessellation"): K levels of Catmull-Clark subdivision (OpenMesh), each followed by the
// projection of every vertex onto the truncated cone of the skeleton edge nearest to it - the cone whose
// radius runs linearly from the parent's sphere to the child's along the edge. Chosen here: the projection
// is radial from the edge's axis (the paper translates along the vertex normal; radial is the same on a
// straight tube and never misses the cone); the paper's Bézier radius scaling at sharp vertices is not done.
// After refinement every face is a quad (Catmull-Clark), and the mesh stays closed and manifold.
#pragma once

#include "skeleton/Skeleton.h"
#include "sqm/SqmMesher.h"

namespace medial {

// Refines `mesh` in place; `skeleton` is the skeleton it was made from (nodes, radii, edges).
void refineSqmMesh(SqmMesh& mesh, const Skeleton& skeleton, int levels);

}  // namespace medial
