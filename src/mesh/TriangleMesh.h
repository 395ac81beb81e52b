/// \file
/// TriangleMesh: the plain triangle mesh the geometric algorithms work on (vertex rows, face rows).
#pragma once

#include <Eigen/Core>

namespace medial {

/// One vertex per row (x, y, z).
using Vertices = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
/// One triangle per row (three vertex indices, counter-clockwise seen from outside).
using Faces = Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor>;

/// A triangle mesh: vertex positions and triangles.
struct TriangleMesh {
  Vertices vertices;  ///< positions
  Faces faces;        ///< triangles
};

}  // namespace medial
