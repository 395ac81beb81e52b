/// \file
/// MeshContraction: geometry contraction by constrained Laplacian smoothing, section III.A of the
/// contraction paper (Au et al. 2008 with the paper's solver choice).
///
/// Each iteration solves system (2), [W_L L; W_H] V' = [0; W_H V], in least squares through the normal
/// equations (5): (W_L^2 L^T L + W_H^2) V' = W_H^2 V, with L the cotangent Laplacian of eq. (1) of the
/// current positions (angles clamped). Then W_L <- s_L W_L (capped) and W_H,i <- W_H,i0 sqrt(A_i0 / A_i^t)
/// (capped). The pattern of the normal matrix is the two-ring of the mesh and never changes: the sparse
/// Cholesky's symbolic analysis runs once, each iteration refactorizes numerically.
///
/// Scale: W_L0 = 1e-3 sqrt(mean face area) has the unit of a length, so the result would depend on the
/// mesh's units. The mesh is therefore contracted in a normalized frame (bounding-box centre at the origin,
/// diagonal `frameDiagonal`) and mapped back: the result is the same for a mesh in metres or millimetres.
/// The frame size is the one constant the paper leaves implicit. With diagonal 1, W_L0 is so small that
/// the first ~12 iterations barely move the mesh and W_L reaches its cap before thick parts have contracted
/// (armadillo: 27 iterations, final volume ratio 0.22); with 10^4 contraction starts at once (armadillo:
/// 16 iterations, volume ratio 0.019).
///
/// Resolution: in the normal matrix, W_L^2 L^T L acts on a smooth field like W_L^2 a^2 times its
/// bi-Laplacian (a the mean face area: the cotangent Laplacian's entries have no unit), so the paper's
/// W_L0 ~ sqrt(a) makes each iteration's smoothing step W_L0^2 a^2 ~ a^3: four times the vertices, 64 times
/// smaller a step, three more iterations in which nothing moves (docs/measurements.md). A mesh with more
/// vertices than `referenceVertices` (the default decimation budget) therefore starts with W_L0 x
/// (n / referenceVertices)^1.5, the step it would have at the reference resolution.
///
/// Degenerate faces: as a face collapses, its angles head for 0 and 180 degrees and its cotangents, even
/// clamped, swing between +-57 (1 degree); the signed weights then push vertices outwards (spikes) and the
/// area grows again. A face whose area falls below `degenerateFaceFraction` of its initial area therefore
/// keeps the cotangents it had then, for the rest of the contraction: the contraction then converges
/// instead of being stopped by the area-growth guard, and the curve skeleton loses its one-edge hairs
/// (docs/measurements.md, with the other fractions tried).
#pragma once

#include "common/Error.h"
#include "mesh/SparseSolver.h"
#include "mesh/TriangleMesh.h"

#include <functional>
#include <string>
#include <vector>

namespace medial {

/// The parameters of the contraction (paper §III.A) with its defaults.
struct ContractionParameters {
  double initialContractionFactor = 1e-3;  ///< W_L0 = factor * sqrt(mean face area), in the normalized frame
  double frameDiagonal = 1e4;              ///< bounding-box diagonal of the normalized frame
  /// A mesh with more vertices than this starts with W_L0 x (n / referenceVertices)^1.5 (see the header;
  /// 0: the paper's W_L0 at every resolution).
  int referenceVertices = 4000;
  double initialAttraction = 1.0;        ///< W_H0
  double contractionScale = 2.0;         ///< s_L
  double maxContractionWeight = 2048.0;  ///< cap on W_L
  double maxAttractionWeight = 10000.0;  ///< cap on W_H
  double minAngleDegrees = 1.0;          ///< cotangent clamping (III.A detail 1)
  /// A face whose area falls below this fraction of its initial area keeps the cotangents it had then.
  double degenerateFaceFraction = 0.2;
  int maxIterations = 40;  ///< the contraction stops after this many iterations at the latest
  /// Stop when the surface area (or the enclosed volume) has shrunk below this fraction of the original
  /// (the degenerate, almost zero-volume mesh of Au et al.), or, once W_L is capped, when an iteration
  /// shrinks the area by less than stallFraction of the original area (the test CGAL's skeletonization
  /// uses, there with 1e-4; relative to the current area, elephant ran 30 iterations instead of 15 for the
  /// same skeleton).
  double areaRatioStop = 1e-4;
  double volumeRatioStop = 1e-6;  ///< Au et al.'s zero-volume test (closed meshes)
  double stallFraction = 0.01;    ///< see areaRatioStop
  /// When an iteration makes the area grow by this factor, the Laplacian of the degenerate triangles has
  /// become unreliable (spikes): the previous iterate is kept and the contraction stops.
  double areaGrowthGuard = 1.1;
  SparseSolverKind solver =
      SparseSolverKind::Automatic;  ///< the factorization of the normal equations (SparseSolver.h)
  /// The paper's Fig. 5 and 7: keep the mesh after every iteration with the weights that made it
  /// (ContractionResult::steps). Memory: one copy of the vertices per iteration.
  bool recordSteps = false;
};

/// One contraction iteration as the paper draws it (Fig. 5: the mesh; Fig. 7: the weights): step 0 is the
/// input with the initial weights, step t the mesh after iteration t with the weights that iteration used.
struct ContractionStep {
  Vertices positions;            ///< in the input's frame
  Eigen::VectorXd laplacian;     ///< |L V| per vertex, in the input's units: the curvature-flow pull left
  double contractionWeight = 0;  ///< W_L (one value for every vertex, eq. 5), in the normalized frame
  Eigen::VectorXd attraction;    ///< W_H,i per vertex (III.A step 3: W_H0 sqrt(A_0 / A_t))
  double areaRatio = 1;          ///< area / initial area
  double volumeRatio = 1;        ///< enclosed volume / initial volume
};

/// The contracted mesh and how the contraction went.
struct ContractionResult {
  Vertices contracted;                 ///< same vertex order and faces as the input
  int iterations = 0;                  ///< iterations run
  double areaRatio = 1.0;              ///< final area / initial area
  double volumeRatio = 1.0;            ///< final enclosed volume / initial volume
  std::string stopReason;              ///< which test stopped it ("area", "volume", "stall", ...)
  std::vector<ContractionStep> steps;  ///< with recordSteps: step 0 (the input), then one per iteration
  ///@{
  /// Seconds spent in the stages of the iterations.
  double assembleSeconds = 0, analyzeSeconds = 0, factorizeSeconds = 0, solveSeconds = 0;
  ///@}
  Error error;  ///< non-empty when the contraction failed (solver breakdown, cancelled)
  /// True when the work succeeded (no error).
  bool ok() const { return error.empty(); }
};

/// progress(fraction) is called after each iteration; returning false aborts the contraction.
using ProgressCallback = std::function<bool(double)>;

/// III.A: the mesh contracted by implicit Laplacian smoothing with attraction weights (eq. 5),
/// W_L scaled by s_L and W_H raised with the area loss each iteration, until the area or the volume is
/// gone or the iterations stall.
/// \param mesh a triangle mesh (normalized into a frame of frameDiagonal internally)
/// \param parameters the weights and stopping tests
/// \param progress called after each iteration; false stops the work
/// \return the contracted positions (same faces), or an error (solver breakdown, cancelled)
ContractionResult contractMesh(const TriangleMesh& mesh, const ContractionParameters& parameters = {},
                               const ProgressCallback& progress = {});

}  // namespace medial
