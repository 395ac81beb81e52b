// TriangleMesh: the plain triangle mesh the geometric algorithms work on (vertex rows, face rows).
#pragma once

#include <Eigen/Core>

namespace medial {

using Vertices = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
using Faces = Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor>;

struct TriangleMesh {
  Vertices vertices;
  Faces faces;
};

}  // namespace medial
