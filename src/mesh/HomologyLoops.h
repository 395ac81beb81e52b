/// \file
/// HomologyLoops: a basis of the first homology of a closed triangle mesh: 2g loops of mesh edges for each
/// closed 2-manifold component of genus g. Tree-cotree construction (Eppstein 2003) with the greedy choice
/// of Erickson & Whittlesey (2005): a shortest-path tree T from a base vertex, a maximum spanning tree C of
/// the dual graph over the edges not in T, weighted by the length of each edge's loop, and one loop per edge
/// in neither T nor C. Each loop closes an edge (u, v) by the tree paths from u and v to their lowest common
/// ancestor (the same free homotopy class as the loop through the base vertex, and shorter).
#pragma once

#include "mesh/TriangleMesh.h"

#include <vector>

namespace medial {

/// Loops as vertex ids in order (the last connects back to the first). Components with a border edge or a
/// non-manifold edge are left out.
std::vector<std::vector<int>> homologyBasisLoops(const TriangleMesh& mesh);

/// The closed path through a tree that an extra edge (a, b) makes: from the lowest common ancestor of a
/// and b down to a, then from b back up to the ancestor's child (the edge b-a closes it). `parent` and
/// `depth` describe the tree (the root's parent is never followed).
std::vector<int> loopThroughTree(int a, int b, const std::vector<int>& parent, const std::vector<int>& depth);

/// The genus summed over the same components (half the number of loops above), from their Euler
/// characteristics: cheap enough to ask before building the loops.
int closedGenus(const TriangleMesh& mesh);

}  // namespace medial
