#include "mesh/MeshGeometry.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace medial {

namespace {

Eigen::Vector3d row(const Vertices& vertices, int i) { return vertices.row(i).transpose(); }

// cot of the angle between u and v, clamped to the cot of [minAngle, pi - minAngle].
double clampedCotangent(const Eigen::Vector3d& u, const Eigen::Vector3d& v, double cotLimit) {
  const double cross = u.cross(v).norm();
  const double dot = u.dot(v);
  if (cross <= std::abs(dot) / cotLimit) return dot >= 0 ? cotLimit : -cotLimit;  // also covers cross = 0
  return dot / cross;
}

}  // namespace

Eigen::MatrixX3d faceCotangents(const Vertices& vertices, const Faces& faces, double minAngle) {
  const double cotLimit = 1.0 / std::tan(minAngle);
  Eigen::MatrixX3d cotangents(faces.rows(), 3);
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int corner = 0; corner < 3; ++corner) {
      const int o = faces(f, corner), i = faces(f, (corner + 1) % 3), j = faces(f, (corner + 2) % 3);
      cotangents(f, corner) = clampedCotangent(row(vertices, i) - row(vertices, o),
                                               row(vertices, j) - row(vertices, o), cotLimit);
    }
  return cotangents;
}

Eigen::SparseMatrix<double> laplacianFromCotangents(const Faces& faces, const Eigen::MatrixX3d& cotangents,
                                                    Eigen::Index vertexCount) {
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(static_cast<size_t>(faces.rows()) * 12);
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int corner = 0; corner < 3; ++corner) {
      const int i = faces(f, (corner + 1) % 3), j = faces(f, (corner + 2) % 3);
      const double w = cotangents(f, corner);  // the angle at `corner` weighs the opposite edge (i, j)
      triplets.emplace_back(i, j, w);
      triplets.emplace_back(j, i, w);
      triplets.emplace_back(i, i, -w);
      triplets.emplace_back(j, j, -w);
    }
  Eigen::SparseMatrix<double> laplacian(vertexCount, vertexCount);
  laplacian.setFromTriplets(triplets.begin(), triplets.end());  // sums the two faces of each edge
  return laplacian;
}

Eigen::SparseMatrix<double> cotangentLaplacian(const Vertices& vertices, const Faces& faces,
                                               double minAngle) {
  return laplacianFromCotangents(faces, faceCotangents(vertices, faces, minAngle), vertices.rows());
}

Eigen::VectorXd faceAreas(const Vertices& vertices, const Faces& faces) {
  Eigen::VectorXd areas(faces.rows());
  for (Eigen::Index f = 0; f < faces.rows(); ++f) {
    const Eigen::Vector3d a = row(vertices, faces(f, 0));
    areas[f] = 0.5 * (row(vertices, faces(f, 1)) - a).cross(row(vertices, faces(f, 2)) - a).norm();
  }
  return areas;
}

Eigen::VectorXd oneRingAreas(const Faces& faces, const Eigen::VectorXd& faceAreas, Eigen::Index vertexCount) {
  Eigen::VectorXd ring = Eigen::VectorXd::Zero(vertexCount);
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int c = 0; c < 3; ++c) ring[faces(f, c)] += faceAreas[f];
  return ring;
}

double enclosedVolume(const Vertices& vertices, const Faces& faces) {
  double volume = 0;
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    volume += row(vertices, faces(f, 0)).dot(row(vertices, faces(f, 1)).cross(row(vertices, faces(f, 2))));
  return volume / 6.0;
}

double boundingBoxDiagonal(const Vertices& vertices) {
  if (vertices.rows() == 0) return 0;
  return (vertices.colwise().maxCoeff() - vertices.colwise().minCoeff()).norm();
}

}  // namespace medial
