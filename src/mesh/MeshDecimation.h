/// \file
/// MeshDecimation: quadric-error edge-collapse decimation (Garland & Heckbert 1997, CGAL's
/// Surface_mesh_simplification with its Garland-Heckbert plane policies) down to a vertex budget, with the
/// record of which coarse vertex absorbed each input vertex.
///
/// The skeleton pipeline contracts this coarse mesh instead of the input when the input has more vertices
/// than the budget (SkeletonByContractionParameters::contractionVertices): the cost of the contraction
/// grows with the vertex count (each iteration factorizes an n x n matrix with the two-ring pattern),
/// while the skeleton only needs the mesh's shape. The input vertices come back afterwards through
/// `representative`: refinement (III.C), radii, the segmentation and the weights use the input mesh.
///
/// CGAL refuses collapses that break the link condition, so the topology (components, genus, boundaries)
/// is kept. Above 16 x the budget, a linear first pass (EdgeCoarsening: short edges collapsed to their
/// midpoints in sweeps, link condition kept) brings the mesh to 10 x the budget and CGAL goes on from
/// there, several times faster on the largest meshes. CGAL was chosen over OpenMesh's Decimater
/// (ModQuadric), which is slower with a normal-flip module (docs/measurements.md). A mesh a halfedge
/// structure cannot hold (faces oriented against their neighbours, non-manifold edges or vertices) is
/// decimated from a copy that CGAL's soup orientation made orientable and manifold (faces flipped, vertices
/// duplicated where needed). Faces that repeat a vertex are left out; a vertex only they use gets no
/// representative.
#pragma once

#include "mesh/TriangleMesh.h"

#include <string>
#include <vector>

namespace medial {

/// The result of decimateMesh().
struct DecimatedMesh {
  TriangleMesh mesh;  ///< the decimated mesh (the input when nothing was done)
  /// For every input vertex, the vertex of `mesh` that absorbed it (itself when it survived); -1 for input
  /// vertices no face uses.
  std::vector<int> representative;
  bool decimated = false;     ///< false: the input was small enough or could not be decimated (see note)
  int coarsenedVertices = 0;  ///< vertices after the fast first pass (0: none: EdgeCoarsening.h)
  /// The mesh after that pass (10 x the budget; empty without it): a lighter stand-in for the input's shape.
  TriangleMesh coarsened;
  std::string note;  ///< why the mesh was left as it was
};

/// The mesh decimated to about `targetVertices` vertices by the quadric error metric, topology kept
/// (OpenMesh), after a fast edge-coarsening pass for large meshes.
DecimatedMesh decimateMesh(const TriangleMesh& mesh, int targetVertices);

}  // namespace medial
