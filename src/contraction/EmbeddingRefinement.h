// EmbeddingRefinement: section III.C of the contraction paper. Each node moves by d_k of eq. (11), to the
// centroid of the original positions of the mesh vertices it absorbed, but only when that centroid lies
// inside the mesh (the paper's correction of Au et al., whose centroids could leave thin bent parts).
#pragma once

#include "contraction/ConnectivitySurgery.h"
#include "mesh/InsideTest.h"

namespace medial {

// Returns the number of nodes moved.
int refineEmbedding(CurveSkeleton& skeleton, const Vertices& originalVertices, const InsideTest& inside);

}  // namespace medial
