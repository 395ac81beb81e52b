#include "mesh/MeshGeometry.h"

#include <algorithm>
#include <cmath>
#include <utility>
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
  // Built column by column: Eigen's setFromTriplets needs 12 triplets per face plus a copy of them all
  // (docs/measurements.md); here each column gathers its off-diagonal entries (6 per face in all), merges
  // the two faces of each edge, and appends the diagonal.
  const size_t n = size_t(vertexCount);
  std::vector<int> start(n + 1, 0);
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int corner = 0; corner < 3; ++corner) {
      const int i = faces(f, (corner + 1) % 3), j = faces(f, (corner + 2) % 3);
      if (i == j) continue;  // a degenerate face's repeated vertex: no edge
      ++start[size_t(i) + 1];
      ++start[size_t(j) + 1];
    }
  for (size_t v = 0; v < n; ++v) start[v + 1] += start[v];
  std::vector<std::pair<int, double>> entries(static_cast<size_t>(start[n]));
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int corner = 0; corner < 3; ++corner) {
      const int i = faces(f, (corner + 1) % 3), j = faces(f, (corner + 2) % 3);
      const double w = cotangents(f, corner);  // the angle at `corner` weighs the opposite edge (i, j)
      if (i == j) continue;
      entries[size_t(fill[size_t(i)]++)] = {j, w};
      entries[size_t(fill[size_t(j)]++)] = {i, w};
    }

  // Each column: its neighbours in order (the two faces of an edge merged), the diagonal in its place.
  Eigen::SparseMatrix<double> laplacian(vertexCount, vertexCount);
  laplacian.resizeNonZeros(Eigen::Index(entries.size() + n));  // an upper bound, shrunk at the end
  int* outer = laplacian.outerIndexPtr();
  int* inner = laplacian.innerIndexPtr();
  double* value = laplacian.valuePtr();
  int size = 0;
  for (size_t v = 0; v < n; ++v) {
    outer[v] = size;
    const auto first = entries.begin() + start[v], last = entries.begin() + start[v + 1];
    if (first == last) continue;  // in no face: an empty column
    std::sort(first, last, [](const auto& a, const auto& b) { return a.first < b.first; });
    int diagonal = -1;
    double rowSum = 0;
    for (auto e = first; e != last; ++e) {
      rowSum += e->second;
      if (diagonal < 0 && e->first > int(v)) {
        diagonal = size;
        inner[size++] = int(v);
      }
      if (size > outer[v] && inner[size - 1] == e->first) {
        value[size - 1] += e->second;  // the edge's other face
      } else {
        inner[size] = e->first;
        value[size++] = e->second;
      }
    }
    if (diagonal < 0) {
      diagonal = size;
      inner[size++] = int(v);
    }
    value[diagonal] = -rowSum;
  }
  outer[n] = size;
  laplacian.resizeNonZeros(size);
  return laplacian;
}

namespace {

// The position of entry (row, column) in a compressed column-major matrix with sorted columns.
int entryAt(const Eigen::SparseMatrix<double>& m, int row, int column) {
  const int* first = m.innerIndexPtr() + m.outerIndexPtr()[column];
  const int* last = m.innerIndexPtr() + m.outerIndexPtr()[column + 1];
  const int* at = std::lower_bound(first, last, row);
  return at != last && *at == row ? int(at - m.innerIndexPtr()) : -1;
}

}  // namespace

LaplacianAssembler::LaplacianAssembler(const Faces& faces, Eigen::Index vertexCount)
    : laplacian_(laplacianFromCotangents(faces, Eigen::MatrixX3d::Ones(faces.rows(), 3), vertexCount)),
      targets_(size_t(faces.rows() * 3)) {
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int corner = 0; corner < 3; ++corner) {
      const int i = faces(f, (corner + 1) % 3), j = faces(f, (corner + 2) % 3);
      auto& target = targets_[size_t(3 * f + corner)];
      if (i == j) {
        target = {-1, -1, -1, -1};
        continue;
      }
      target = {entryAt(laplacian_, j, i), entryAt(laplacian_, i, j), entryAt(laplacian_, i, i),
                entryAt(laplacian_, j, j)};
    }
}

const Eigen::SparseMatrix<double>& LaplacianAssembler::update(const Eigen::MatrixX3d& cotangents) {
  double* value = laplacian_.valuePtr();
  std::fill(value, value + laplacian_.nonZeros(), 0.0);
  for (Eigen::Index f = 0; f < cotangents.rows(); ++f)
    for (int corner = 0; corner < 3; ++corner) {
      const auto& target = targets_[size_t(3 * f + corner)];
      if (target[0] < 0) continue;
      const double w = cotangents(f, corner);
      value[target[0]] += w;
      value[target[1]] += w;
      value[target[2]] -= w;
      value[target[3]] -= w;
    }
  return laplacian_;
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

Eigen::VectorXd mixedVoronoiAreas(const Vertices& vertices, const Faces& faces) {
  Eigen::VectorXd area = Eigen::VectorXd::Zero(vertices.rows());
  for (Eigen::Index f = 0; f < faces.rows(); ++f) {
    const Eigen::Vector3d p[3] = {row(vertices, faces(f, 0)), row(vertices, faces(f, 1)),
                                  row(vertices, faces(f, 2))};
    const double twiceArea = (p[1] - p[0]).cross(p[2] - p[0]).norm();
    if (!(twiceArea > 0)) continue;
    double cotangent[3];
    int obtuse = -1;
    for (int c = 0; c < 3; ++c) {
      const Eigen::Vector3d u = p[(c + 1) % 3] - p[c], v = p[(c + 2) % 3] - p[c];
      cotangent[c] = u.dot(v) / twiceArea;  // cot = cos / sin = (u . v) / |u x v|
      if (u.dot(v) < 0) obtuse = c;
    }
    for (int c = 0; c < 3; ++c) {
      double share;
      if (obtuse >= 0) {
        share = (c == obtuse ? 0.25 : 0.125) * twiceArea;  // area / 2 or area / 4
      } else {  // (|e_ab|^2 cot C + |e_ac|^2 cot B) / 8 for the corner A
        const int b = (c + 1) % 3, d = (c + 2) % 3;
        share = ((p[b] - p[c]).squaredNorm() * cotangent[d] + (p[d] - p[c]).squaredNorm() * cotangent[b]) / 8;
      }
      area[faces(f, c)] += share;
    }
  }
  return area;
}

Eigen::Vector3d volumeCentroid(const Vertices& vertices, const Faces& faces) {
  Eigen::Vector3d areaMoment = Eigen::Vector3d::Zero();
  double area = 0;
  for (Eigen::Index f = 0; f < faces.rows(); ++f) {
    const Eigen::Vector3d a = row(vertices, faces(f, 0)), b = row(vertices, faces(f, 1)),
                          c = row(vertices, faces(f, 2));
    const double triangle = 0.5 * (b - a).cross(c - a).norm();
    area += triangle;
    areaMoment += triangle * (a + b + c) / 3.0;
  }
  if (!(area > 0))
    return vertices.rows() > 0 ? Eigen::Vector3d(vertices.colwise().mean().transpose())
                               : Eigen::Vector3d::Zero();
  // Tetrahedra from the faces' centre: for a closed mesh any apex gives the same centroid; for an open one
  // the faces' centre closes it as a cone would, which keeps the answer independent of the mesh's place.
  const Eigen::Vector3d apex = areaMoment / area;
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  double volume = 0;
  for (Eigen::Index f = 0; f < faces.rows(); ++f) {
    const Eigen::Vector3d a = row(vertices, faces(f, 0)) - apex, b = row(vertices, faces(f, 1)) - apex,
                          c = row(vertices, faces(f, 2)) - apex;
    const double tetra = a.dot(b.cross(c)) / 6.0;
    volume += tetra;
    moment += tetra * (a + b + c) / 4.0;
  }
  if (std::abs(volume) > 1e-9 * std::pow(area, 1.5)) return apex + moment / volume;
  return apex;
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
