#include "contraction/MeshContraction.h"

#include "common/Stopwatch.h"

#include "contraction/NormalMatrix.h"
#include "mesh/MeshGeometry.h"

#include <algorithm>
#include <cmath>
#include <memory>

namespace medial {

namespace {

// W_L0 (III.A): the paper's factor times the square root of the mean face area, scaled up above
// `referenceVertices` (see the header) and never above the cap.
double firstContractionWeight(const ContractionParameters& p, double area, Eigen::Index faces,
                              Eigen::Index n) {
  double weight = p.initialContractionFactor * std::sqrt(area / double(faces));
  if (p.referenceVertices > 0 && n > p.referenceVertices)
    weight *= std::pow(double(n) / p.referenceVertices, 1.5);
  return std::min(weight, p.maxContractionWeight);  // a small reference: capped
}

// The cotangents at the new positions, but for faces that have collapsed below a fraction of their first
// area: those keep their last value from then on (see the header).
void refreshCotangents(const Vertices& positions, const Faces& faces, const ContractionParameters& p,
                       const Eigen::VectorXd& areas, const Eigen::VectorXd& initialFaceAreas,
                       Eigen::MatrixX3d& cotangents, std::vector<bool>& frozen) {
  const Eigen::MatrixX3d current = faceCotangents(positions, faces, p.minAngleDegrees * M_PI / 180.0);
  for (Eigen::Index f = 0; f < faces.rows(); ++f) {
    if (!frozen[size_t(f)] && areas[f] < p.degenerateFaceFraction * initialFaceAreas[f])
      frozen[size_t(f)] = true;
    if (!frozen[size_t(f)]) cotangents.row(f) = current.row(f);
  }
}

// III.A, step 3: W_H,i = W_H0 sqrt(A_i^0 / A_i^t), capped.
void updateAttraction(const ContractionParameters& p, const Eigen::VectorXd& initialRingAreas,
                      const Eigen::VectorXd& ringAreas, Eigen::VectorXd& attraction) {
  for (Eigen::Index i = 0; i < attraction.size(); ++i) {
    const double ratio = ringAreas[i] > 0 ? initialRingAreas[i] / ringAreas[i] : INFINITY;
    attraction[i] = std::min(p.initialAttraction * std::sqrt(ratio), p.maxAttractionWeight);
  }
}

enum class Stop { No, Here, KeepPrevious };

// Whether the iterations end after one that left the surface area `area` (the previous one's
// `previousArea`), and why.
Stop shouldStop(const ContractionParameters& p, const ContractionResult& result, double area,
                double previousArea, double initialArea, double initialVolume, double contractionWeight,
                std::string& reason) {
  if (result.areaRatio < p.areaRatioStop) {
    reason = "area ratio below threshold";
    return Stop::Here;
  }
  if (initialVolume > 0 && result.volumeRatio < p.volumeRatioStop) {
    reason = "volume ratio below threshold";
    return Stop::Here;
  }
  if (area > previousArea * p.areaGrowthGuard) {
    // The Laplacian of a nearly degenerate mesh grows unreliable: keep the last shrinking iterate.
    reason = "area grew: kept the previous iterate";
    return Stop::KeepPrevious;
  }
  if (previousArea - area < p.stallFraction * initialArea && contractionWeight >= p.maxContractionWeight) {
    reason = "converged (area no longer shrinks)";
    return Stop::Here;
  }
  return Stop::No;
}

}  // namespace

ContractionResult contractMesh(const TriangleMesh& mesh, const ContractionParameters& p,
                               const ProgressCallback& progress) {
  ContractionResult result;
  const Eigen::Index n = mesh.vertices.rows();
  if (n == 0 || mesh.faces.rows() == 0) {
    result.error = "the mesh has no triangles";
    return result;
  }

  // Normalized frame (see the header): centre of the bounding box at the origin, diagonal frameDiagonal.
  const Eigen::RowVector3d centre =
      0.5 * (mesh.vertices.colwise().maxCoeff() + mesh.vertices.colwise().minCoeff());
  const double diagonal = boundingBoxDiagonal(mesh.vertices) / p.frameDiagonal;
  if (!(diagonal > 0) || !std::isfinite(diagonal)) {
    result.error = "the mesh has no extent (all vertices coincide) or non-finite coordinates";
    return result;
  }
  Vertices positions = (mesh.vertices.rowwise() - centre) / diagonal;

  const double minAngle = p.minAngleDegrees * M_PI / 180.0;
  const Eigen::VectorXd initialFaceAreas = faceAreas(positions, mesh.faces);
  const Eigen::VectorXd initialRingAreas = oneRingAreas(mesh.faces, initialFaceAreas, n);
  const double initialArea = initialFaceAreas.sum();
  const double initialVolume = std::abs(enclosedVolume(positions, mesh.faces));
  double contractionWeight = firstContractionWeight(p, initialArea, mesh.faces.rows(), n);
  Eigen::VectorXd attraction = Eigen::VectorXd::Constant(n, p.initialAttraction);

  // Cotangents of faces that have collapsed are frozen at their last value (see the header).
  Eigen::MatrixX3d cotangents = faceCotangents(positions, mesh.faces, minAngle);
  std::vector<bool> frozen(size_t(mesh.faces.rows()), false);
  Eigen::VectorXd areas = initialFaceAreas;

  // The paper's figures: the mesh and the weights at each step, in the input's frame.
  const auto record = [&](const Vertices& at, const Eigen::SparseMatrix<double>& laplacian, double weight,
                          const Eigen::VectorXd& attractionUsed) {
    ContractionStep step;
    step.positions = (at * diagonal).rowwise() + centre;
    step.laplacian = (laplacian * at).rowwise().norm() * diagonal;
    step.contractionWeight = weight;
    step.attraction = attractionUsed;
    step.areaRatio = result.areaRatio;
    step.volumeRatio = result.volumeRatio;
    result.steps.push_back(std::move(step));
  };

  LaplacianAssembler assembler(mesh.faces, n);
  SparseSolver solver(p.solver);
  std::unique_ptr<NormalMatrix> normal;  // its pattern from the first Laplacian
  double previousArea = initialArea;
  Vertices best = positions;
  result.stopReason = "maximum iterations";
  for (int iteration = 0; iteration < p.maxIterations; ++iteration) {
    Stopwatch start;
    if (iteration > 0)
      refreshCotangents(positions, mesh.faces, p, areas, initialFaceAreas, cotangents, frozen);
    const Eigen::SparseMatrix<double>& laplacian = assembler.update(cotangents);
    if (p.recordSteps && iteration == 0) record(positions, laplacian, contractionWeight, attraction);
    const double weightUsed = contractionWeight;
    const Eigen::VectorXd attractionUsed = p.recordSteps ? attraction : Eigen::VectorXd();
    if (!normal) normal = std::make_unique<NormalMatrix>(laplacian);
    const Eigen::SparseMatrix<double>& matrix = normal->update(laplacian, contractionWeight, attraction);
    const Eigen::MatrixXd rhs = attraction.array().square().matrix().asDiagonal() * positions;
    result.assembleSeconds += start.seconds();

    if (iteration == 0) {
      start.restart();
      solver.analyze(matrix);
      result.analyzeSeconds += start.seconds();
    }
    start.restart();
    const bool factorized = solver.factorize(matrix);
    result.factorizeSeconds += start.seconds();
    Eigen::MatrixXd solution;
    start.restart();
    if (!factorized || !solver.solve(rhs, solution)) {
      result.error = "contraction iteration " + std::to_string(iteration + 1) + ": " + solver.error();
      return result;
    }
    result.solveSeconds += start.seconds();
    positions = solution;
    result.iterations = iteration + 1;

    // Weight updates of III.A, steps 2 and 3.
    contractionWeight = std::min(contractionWeight * p.contractionScale, p.maxContractionWeight);
    areas = faceAreas(positions, mesh.faces);
    updateAttraction(p, initialRingAreas, oneRingAreas(mesh.faces, areas, n), attraction);

    const double area = areas.sum();
    result.areaRatio = area / initialArea;
    result.volumeRatio =
        initialVolume > 0 ? std::abs(enclosedVolume(positions, mesh.faces)) / initialVolume : 0;
    if (p.recordSteps) record(positions, laplacian, weightUsed, attractionUsed);
    if (progress && !progress(double(result.iterations) / p.maxIterations)) {
      result.error = Error::cancelled();
      return result;
    }
    const Stop stop = shouldStop(p, result, area, previousArea, initialArea, initialVolume, contractionWeight,
                                 result.stopReason);
    if (stop == Stop::KeepPrevious) {
      positions = best;
      result.areaRatio = previousArea / initialArea;
    }
    if (stop != Stop::No) break;
    previousArea = area;
    best = positions;
  }
  result.contracted = (positions * diagonal).rowwise() + centre;
  return result;
}

}  // namespace medial
