/// \file
/// MeshGeometry: the per-face and per-vertex measures the contraction and weight solvers share:
/// the cotangent Laplacian of eq. (1) of the contraction paper (Desbrun et al. 1999) with clamped angles,
/// face areas, one-ring areas, enclosed volume, and the bounding-box diagonal; LaplacianAssembler refills the
/// Laplacian of a mesh whose connectivity stays.
#pragma once

#include "mesh/TriangleMesh.h"

#include <Eigen/Geometry>
#include <Eigen/SparseCore>

#include <array>
#include <vector>

namespace medial {

/// L of eq. (1): L_ij = cot(alpha_ij) + cot(beta_ij) for an edge (i,j), L_ii = -sum_k L_ik, 0 elsewhere.
/// Angles are clamped to [minAngle, pi - minAngle] (radians) so that the cotangents stay finite on the
/// degenerate triangles of a contracted mesh (paper, III.A detail 1). Every mesh edge is a structural
/// entry even when its weight is zero, so the sparsity pattern depends on the connectivity alone.
Eigen::SparseMatrix<double> cotangentLaplacian(const Vertices& vertices, const Faces& faces, double minAngle);

///@{
/// The two halves of cotangentLaplacian: the clamped cotangent of each face's angle at each corner
/// (row f, column c: the angle at faces(f, c)), and the Laplacian assembled from such cotangents.
Eigen::MatrixX3d faceCotangents(const Vertices& vertices, const Faces& faces, double minAngle);
Eigen::SparseMatrix<double> laplacianFromCotangents(const Faces& faces, const Eigen::MatrixX3d& cotangents,
                                                    Eigen::Index vertexCount);
///@}

/// laplacianFromCotangents for a mesh whose connectivity stays while its cotangents change (the contraction's
/// iterations): the pattern and, per face corner, the four entries its cotangent goes to are found once;
/// each update only adds the cotangents into the values (no sorting, no allocation).
class LaplacianAssembler {
 public:
  /// Finds the pattern and the targets of every face corner of `faces`.
  LaplacianAssembler(const Faces& faces, Eigen::Index vertexCount);
  /// The Laplacian of `cotangents` (faceCotangents()), valid until the next update.
  const Eigen::SparseMatrix<double>& update(const Eigen::MatrixX3d& cotangents);

 private:
  Eigen::SparseMatrix<double> laplacian_;
  std::vector<std::array<int, 4>>
      targets_;  ///< per face corner: entries (i, j), (j, i), (i, i), (j, j); -1: none
};

/// The area of each face.
Eigen::VectorXd faceAreas(const Vertices& vertices, const Faces& faces);

/// Sum of the areas of the faces around each vertex (A_i of the attraction-weight update in III.A), from
/// the areas faceAreas() gave.
Eigen::VectorXd oneRingAreas(const Faces& faces, const Eigen::VectorXd& faceAreas, Eigen::Index vertexCount);

/// The mixed Voronoi area of each vertex (Meyer, Desbrun, Schroeder and Barr 2003, "Discrete
/// differential-geometry operators", fig. 4): in a non-obtuse triangle the vertex's Voronoi region, in an
/// obtuse one half the area at the obtuse corner and a quarter at the others. The areas sum to the mesh's.
Eigen::VectorXd mixedVoronoiAreas(const Vertices& vertices, const Faces& faces);

/// Centre of the volume the faces enclose (divergence theorem, tetrahedra from the faces' centre); an open
/// mesh is closed by the cone from that centre; a flat one (no volume) gets the faces' area-weighted centre.
Eigen::Vector3d volumeCentroid(const Vertices& vertices, const Faces& faces);

/// Signed volume enclosed by the faces (divergence theorem); meaningful for closed, oriented meshes.
double enclosedVolume(const Vertices& vertices, const Faces& faces);

/// The length of the vertices' bounding-box diagonal (0 for none).
double boundingBoxDiagonal(const Vertices& vertices);

}  // namespace medial
