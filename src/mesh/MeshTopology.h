/// \file
/// MeshTopology: counts that tell whether a polygon mesh is a closed 2-manifold and of which genus.
///
/// Input: vertex count and faces as lists of vertex ids (any polygon size). Output: edge classes (border:
/// one face, manifold: two, non-manifold: more), connected components (of the vertices faces use), boundary
/// loops, Euler characteristic V - E + F, and the genus by chi = 2 - 2g - b summed over components.
/// These are the invariants the contraction and SQM tests check (closedness, manifoldness, genus).
#pragma once

#include <cstdint>
#include <vector>

namespace medial {

/// Counts that say whether a mesh is a closed 2-manifold, and its genus (computeMeshTopology()).
struct MeshTopology {
  int64_t vertices = 0;             ///< vertices used by at least one face
  int64_t unusedVertices = 0;       ///< vertices no face uses
  int64_t faces = 0;                ///< faces, degenerate ones included
  int64_t degenerateFaces = 0;      ///< fewer than 3 distinct vertex ids
  int64_t edges = 0;                ///< distinct undirected edges
  int64_t borderEdges = 0;          ///< edges with exactly one incident face
  int64_t nonManifoldEdges = 0;     ///< edges with three or more incident faces
  int64_t components = 0;           ///< connected through shared vertices
  int64_t boundaryLoops = 0;        ///< connected pieces of the border-edge graph
  int64_t eulerCharacteristic = 0;  ///< V - E + F over the used vertices
  int64_t genus = 0;  ///< sum over components of (2 - chi_c - b_c) / 2; meaningful for manifolds

  /// No border edges.
  bool isClosed() const { return borderEdges == 0; }
  /// No edge with three or more faces.
  bool isEdgeManifold() const { return nonManifoldEdges == 0; }
  /// Closed, edge-manifold and not empty.
  bool isClosedManifold() const { return isClosed() && isEdgeManifold() && faces > 0; }
};

/// The topology of a polygon mesh: edges, border and non-manifold edges, components, boundary loops,
/// Euler characteristic and genus.
/// \param vertexCount the number of vertices (unused ones are counted as such)
/// \param faces polygons as vertex indices; faces with fewer than three distinct vertices count as degenerate
MeshTopology computeMeshTopology(int64_t vertexCount, const std::vector<std::vector<int64_t>>& faces);

}  // namespace medial
