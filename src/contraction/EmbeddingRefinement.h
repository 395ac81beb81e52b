/// \file
/// EmbeddingRefinement: section III.C of the contraction paper. Each node moves by d_k of eq. (11), to the
/// centroid of the original positions of the mesh vertices it absorbed, but only when that centroid lies
/// inside the mesh (the paper's correction of Au et al., whose centroids could leave thin bent parts).
#pragma once

#include "contraction/ConnectivitySurgery.h"
#include "mesh/InsideTest.h"

#include <functional>
#include <vector>

namespace medial {

/// Returns the number of nodes moved.
int refineEmbedding(CurveSkeleton& skeleton, const Vertices& originalVertices, const InsideTest& inside);

/// Beyond the paper: a node still outside the mesh after the refinement (its centroid and its contracted
/// position both outside: a thin part, a finger, that the contraction pushed through the surface) moves to
/// the most central point on the way from it through its nearest surface point into the material: the
/// farthest from the surface among points stepped inward until that distance stops growing. Such a node
/// would otherwise make every edge it has leave the mesh. Returns the number of nodes moved.
int pushNodesInside(CurveSkeleton& skeleton, const InsideTest& inside);

/// Beyond the paper: an edge of the curve skeleton whose segment leaves the mesh (the surgery joined two
/// nodes across a bend: elephant, hand) gets a node in between, at the centroid of the input vertices its
/// two ends absorbed that project onto the middle half of the edge, when that centroid lies inside; those
/// vertices move to the new node. The halves are split again while they still leave the mesh, up to
/// `maxDepth` times. Returns the number of nodes added.
int splitEdgesLeavingTheMesh(CurveSkeleton& skeleton, const Vertices& originalVertices,
                             const InsideTest& inside, int maxDepth = 5);

///@{
/// The splitting that splitEdgesLeavingTheMesh and NodeCentring's splitOffCentreEdges share: each edge (a, b)
/// is offered to `splitPoint` with the input vertices its ends absorbed that project onto its middle half;
/// when it returns true, a node at `point` joins the halves, takes those vertices, and each half is offered
/// again, up to `maxDepth` times. Returns the number of nodes added.
using SplitPoint = std::function<bool(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                      const std::vector<int>& middleVertices, Eigen::Vector3d& point)>;
int splitSkeletonEdges(CurveSkeleton& skeleton, const Vertices& originalVertices, int maxDepth,
                       const SplitPoint& splitPoint);
///@}

}  // namespace medial
