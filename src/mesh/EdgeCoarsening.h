/// \file
/// EdgeCoarsening: a fast, topology-keeping first pass of the decimation of large meshes, where CGAL's
/// quadric edge collapse alone takes minutes (docs/measurements.md).
///
/// Passes over the edges collapse each edge shorter than 1.5 x the mean edge length into its midpoint,
/// at most one collapse per surviving vertex per pass (an independent-set sweep, no priority queue), only
/// where OpenMesh's link condition holds (`is_collapse_ok`: components, genus and borders are kept) and no
/// triangle around the edge turns by more than about 78 degrees. Each pass recomputes the mean length, so
/// the mesh coarsens evenly until it has the vertex count asked for. Shape error is not minimized here:
/// the quadric decimation that follows (MeshDecimation) does that on a mesh a tenth of the size or less.
#pragma once

#include "mesh/TriangleMesh.h"

#include <vector>

namespace medial {

/// The result of coarsenEdges().
struct CoarsenedMesh {
  bool ok = false;    ///< false: the input is not an oriented 2-manifold OpenMesh can hold (nothing done)
  TriangleMesh mesh;  ///< the coarser mesh
  std::vector<int> representative;  ///< per input vertex, its vertex in `mesh`; -1 for vertices no face uses
};

/// A fast first decimation pass: the shortest edges collapsed until about `targetVertices` are left
/// (topology kept), before the quadric decimation (MeshDecimation.h) finishes the job.
CoarsenedMesh coarsenEdges(const TriangleMesh& mesh, Eigen::Index targetVertices);

}  // namespace medial
