#include "rig/HeatWeights.h"

#include "common/Parallel.h"
#include "common/UnionFind.h"

#include "mesh/MeshGeometry.h"
#include "skeleton/SegmentDistance.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace medial {

namespace {

// Bones solved together: few at a time reuse their memory, and CHOLMOD's solve is bound by reading the
// factor, not by the columns (docs/measurements.md).
constexpr int kBonesPerSolve = 2;

struct NearestBones {
  std::vector<int> bones;  // the nearest bone, with every bone tied with it
  double distance = INFINITY;
  Eigen::Vector3d closestPoint;  // on the first of those bones
};

NearestBones nearestBones(const Eigen::Vector3d& p, const Skeleton& skeleton) {
  NearestBones nearest;
  for (int i = 0; i < skeleton.edgeCount(); ++i) {
    const auto& e = skeleton.edges[size_t(i)];
    const Eigen::Vector3d q =
        closestPointOnSegment(p, skeleton.nodes[size_t(e[0])], skeleton.nodes[size_t(e[1])]);
    const double d = (q - p).norm();
    if (d < nearest.distance * (1 - 1e-6)) {
      nearest.bones.assign(1, i);
      nearest.distance = d;
      nearest.closestPoint = q;
    } else if (d <= nearest.distance * (1 + 1e-6)) {
      nearest.bones.push_back(i);
    }
  }
  return nearest;
}

// L_w of the header: the clamped cotangents (>= 0) of each face, divided by the number of faces at the edge
// they weigh (halved on a manifold edge), as Blender's meshlaplacian.c. The face counts come from the same
// assembly with every cotangent 1, so both matrices share one sparsity pattern.
Eigen::SparseMatrix<double> boneHeatLaplacian(const TriangleMesh& mesh, double minAngle) {
  const Eigen::Index n = mesh.vertices.rows();
  const Eigen::MatrixX3d cotangents = faceCotangents(mesh.vertices, mesh.faces, minAngle).cwiseMax(0.0);
  Eigen::SparseMatrix<double> laplacian = laplacianFromCotangents(mesh.faces, cotangents, n);
  const Eigen::SparseMatrix<double> faceCount =
      laplacianFromCotangents(mesh.faces, Eigen::MatrixX3d::Ones(mesh.faces.rows(), 3), n);
  for (Eigen::Index column = 0; column < n; ++column) {
    double diagonal = 0;
    Eigen::SparseMatrix<double>::InnerIterator entry(laplacian, column), count(faceCount, column);
    double* diagonalEntry = nullptr;
    for (; entry; ++entry, ++count) {
      if (entry.row() == column) {
        diagonalEntry = &entry.valueRef();
        continue;
      }
      entry.valueRef() /= std::max(1.0, count.value());
      diagonal -= entry.value();
    }
    if (diagonalEntry) *diagonalEntry = diagonal;
  }
  return laplacian;
}

// Component id of every vertex through the faces; -1 for vertices in no face.
std::vector<int> vertexComponents(const Faces& faces, Eigen::Index vertexCount, int& componentCount) {
  UnionFind sets{static_cast<size_t>(vertexCount)};
  std::vector<bool> used(static_cast<size_t>(vertexCount), false);
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int c = 0; c < 3; ++c) {
      used[size_t(faces(f, c))] = true;
      sets.join(faces(f, c), faces(f, (c + 1) % 3));
    }
  std::vector<int> id(size_t(vertexCount), -1), rootId(size_t(vertexCount), -1);
  componentCount = 0;
  for (Eigen::Index v = 0; v < vertexCount; ++v) {
    if (!used[size_t(v)]) continue;
    int& r = rootId[size_t(sets.find(int(v)))];
    if (r < 0) r = componentCount++;
    id[size_t(v)] = r;
  }
  return id;
}

// Blender's heat_limit_weight, then rows renormalized to sum 1 (column by column: the matrix is stored so).
void limitAndNormalize(Eigen::MatrixXd& weights, const std::vector<NearestBones>& nearest, double low) {
  // Below the minimum 0, then a ramp that meets the weight at twice the minimum, so that the weights stay
  // continuous over the surface where a bone's influence ends.
  weights = weights.unaryExpr([low](double w) { return w < low ? 0.0 : w < 2 * low ? 2 * (w - low) : w; });
  const Eigen::VectorXd sums = weights.rowwise().sum();
  for (Eigen::Index j = 0; j < weights.rows(); ++j) {
    if (sums[j] > 0) continue;
    // Only when every weight fell below the limit (more than 1 / low bones sharing a vertex evenly).
    for (int bone : nearest[size_t(j)].bones)
      weights(j, bone) = 1.0 / double(nearest[size_t(j)].bones.size());
  }
  const Eigen::VectorXd divide = (sums.array() > 0).select(sums, 1.0);
  weights.array().colwise() /= divide.array();
}

}  // namespace

HeatWeightResult heatWeights(const TriangleMesh& mesh, const Skeleton& skeleton, const InsideTest& inside,
                             const HeatWeightParameters& p, const std::function<bool(double)>& progress) {
  HeatWeightResult result;
  const Eigen::Index n = mesh.vertices.rows();
  const int bones = skeleton.edgeCount();
  if (bones == 0) {
    result.error = "the skeleton has no bones (edges) to weight";
    return result;
  }
  if (n == 0) {
    result.error = "the mesh has no vertices";
    return result;
  }
  auto aborted = [&](double f) { return progress && !progress(f); };

  // Nearest bones, their distance and whether they see the vertex (H_jj and p_j of eq. 13).
  std::vector<NearestBones> nearest(static_cast<size_t>(n));
  std::vector<bool> visible(static_cast<size_t>(n), false);
  // On every core, in blocks between which progress is reported and an abort is heard (on this thread).
  std::vector<unsigned char> sees(static_cast<size_t>(n), 0);
  constexpr Eigen::Index kBlock = 65536;
  for (Eigen::Index first = 0; first < n; first += kBlock) {
    const Eigen::Index count = std::min(kBlock, n - first);
    inParallel(size_t(count), [&](size_t k) {
      const size_t j = size_t(first) + k;
      const Eigen::Vector3d v = mesh.vertices.row(Eigen::Index(j)).transpose();
      nearest[j] = nearestBones(v, skeleton);
      sees[j] = inside.segmentIsClear(v, nearest[j].closestPoint);
    });
    if (aborted(0.4 * double(first + count) / double(n))) {
      result.error = Error::cancelled();
      return result;
    }
  }
  for (Eigen::Index j = 0; j < n; ++j) visible[size_t(j)] = sees[size_t(j)] != 0;
  int componentCount = 0;
  const std::vector<int> component = vertexComponents(mesh.faces, n, componentCount);
  std::vector<bool> componentSeen(size_t(componentCount), false);
  for (Eigen::Index j = 0; j < n; ++j)
    if (component[size_t(j)] >= 0 && visible[size_t(j)]) componentSeen[size_t(component[size_t(j)])] = true;
  for (Eigen::Index j = 0; j < n; ++j) {
    const int c = component[size_t(j)];
    if (c >= 0 && !componentSeen[size_t(c)]) visible[size_t(j)] = true;  // fallback: see the header
    if (c >= 0 && !visible[size_t(j)]) ++result.invisibleVertices;
  }
  result.componentsWithoutSight = int(std::count(componentSeen.begin(), componentSeen.end(), false));

  // System (14) in Blender's scaling (see the header): A = -L_w + 4 A_mixed H, B = 4 A_mixed H P.
  Eigen::SparseMatrix<double> matrix = -boneHeatLaplacian(mesh, p.minAngleDegrees * M_PI / 180.0);
  const Eigen::VectorXd mass = 4.0 * mixedVoronoiAreas(mesh.vertices, mesh.faces);
  // Row j of B is source[j] / k on each of its k nearest bones (M_jj H_jj, or 1 for an identity row).
  std::vector<double> source(static_cast<size_t>(n), 0.0);
  // A vertex on a bone (d = 0) would make H infinite: d is bounded below by a millionth of the mesh size.
  const double smallest = 1e-6 * boundingBoxDiagonal(mesh.vertices);
  for (Eigen::Index j = 0; j < n; ++j) {
    const NearestBones& near = nearest[size_t(j)];
    if (component[size_t(j)] < 0) {  // in no triangle: a row of the identity, its nearest bone's weight
      matrix.coeffRef(j, j) = 1.0;
      source[size_t(j)] = 1.0;
      continue;
    }
    if (!visible[size_t(j)]) continue;
    const double d = std::max(near.distance, smallest);
    const double ties = double(near.bones.size());  // H_jj = k c / d^2 for k equidistant bones
    const double heat = ties * mass[j] * p.heatConstant / (d * d);
    matrix.coeffRef(j, j) += heat;
    source[size_t(j)] = heat;
  }
  matrix.makeCompressed();
  if (aborted(0.5)) {
    result.error = Error::cancelled();
    return result;
  }

  SparseSolver solver(p.solver);
  solver.analyze(matrix);
  if (!solver.factorize(matrix)) {
    result.error = "heat diffusion: " + solver.error();
    return result;
  }
  // A few bones per solve (kBonesPerSolve): the right-hand sides and solutions of all bones at once were
  // 400 MB each at 1.66M vertices, fresh memory every time; blocks reuse theirs, and an abort is heard
  // between them.
  result.weights.resize(n, bones);
  for (int first = 0; first < bones; first += kBonesPerSolve) {
    const int count = std::min(kBonesPerSolve, bones - first);
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n, count);
    for (Eigen::Index j = 0; j < n; ++j)
      for (int bone : nearest[size_t(j)].bones)
        if (bone >= first && bone < first + count)
          rhs(j, bone - first) = source[size_t(j)] / double(nearest[size_t(j)].bones.size());
    Eigen::MatrixXd solution;
    if (!solver.solve(rhs, solution)) {
      result.error = "heat diffusion: " + solver.error();
      return result;
    }
    result.weights.middleCols(first, count) = solution.cwiseMax(0.0).cwiseMin(1.0);
    if (aborted(0.5 + 0.4 * double(first + count) / double(bones))) {
      result.error = Error::cancelled();
      return result;
    }
  }

  limitAndNormalize(result.weights, nearest, p.minimumWeight);
  if (aborted(1.0)) result.error = Error::cancelled();
  return result;
}

}  // namespace medial
