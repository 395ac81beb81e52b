/// \file
/// HeatWeights: skinning weights by heat diffusion, section III.E of the contraction paper (Baran and
/// Popović 2007, "Automatic rigging and animation of 3D characters", eqs. 13-14).
///
/// Each bone i (a skeleton edge) is a heat source; its weight field w_i on the surface is the equilibrium
/// of eq. (13), -Δw_i + H w_i = H p_i, where d(j) is the distance from vertex j to its nearest bone,
/// p_j^i = 1 when bone i is that bone (shared equally among bones tied within 1e-6 of the distance: 1/k each
/// for k tied bones), and H_jj = k c / d(j)^2 (k = 1 without a tie, as Baran and Popović say for
/// equidistant bones: a joint's vertex is held k times as firmly) when the segment from j to the nearest
/// point of that bone lies inside the mesh (the bone "sees" the vertex), 0 otherwise.
///
/// The Laplacian is scaled as in Blender's bone heat (meshlaplacian.c, "Automatic Weights"), so that the
/// heat constant c (--heat, default 1) means what it means there and in the paper: row j of eq. (13) is
///     sum_k w_jk (w_j - w_k) / (4 A_j) + H_jj w_j = H_jj p_j,
/// with w_jk the cotangents of the angles opposite the edge (j, k), each divided by the number of faces at
/// the edge ((cot a + cot b) / 2 on a manifold), and A_j the mixed Voronoi area of Meyer et al. 2003
/// (mesh/MeshGeometry.h). Multiplied by 4 A_j it is the symmetric system
///     (-L_w + 4 A H) w_i = 4 A H p_i                                                        (14)
/// (L_w: the Laplacian of the w_jk, negative diagonal). Until 2026-12 Medial used L_c = cot a + cot b and a
/// third of the one-ring area, which diffused about 8 times more at the same c: weights that reached
/// vertices nearer another bone.
/// The cotangents enter with negative values clamped to 0. Clamped angles (needed for the degenerate
/// triangles of real meshes) can make the true cotangent matrix indefinite (a 0.5/0.5/179 degree triangle
/// clamped to 1/1/179 degrees has weights 57, 57, -57: CHOLMOD refused man.off), while non-negative weights
/// make -L_w + 4 A H a symmetric M-matrix: positive definite, and the weights obey the maximum principle.
/// The matrix is the same for every bone: it is factorized once and solved with one right-hand side per
/// bone. Since sum_i p^i = 1 wherever H > 0 and L_w 1 = 0, the weights of a vertex sum to 1 (the solution
/// of the summed system is the constant 1); they are then clamped to [0, 1], limited as Blender limits
/// them (below `minimumWeight` 0, up to twice it a ramp) and each row is renormalized to sum exactly 1.
///
/// A mesh component that no bone sees anywhere (every H_jj = 0 there: the system would be singular) gets
/// H from its nearest bones regardless of visibility; isolated vertices (in no triangle) take their
/// nearest bone's weight directly.
#pragma once

#include "common/Error.h"
#include "mesh/InsideTest.h"
#include "mesh/SparseSolver.h"
#include "mesh/TriangleMesh.h"
#include "skeleton/Skeleton.h"

#include <functional>
#include <string>

namespace medial {

/// The heat-diffusion weights' parameters (paper §III.E \cite au2008, as bone heat \cite baran2007).
struct HeatWeightParameters {
  double heatConstant = 1.0;     ///< c of H_jj = c / d(j)^2 (Baran and Popović: 1)
  double minimumWeight = 0.025;  ///< Blender's limit: smaller weights are dropped, up to twice it ramped
  double minAngleDegrees = 1.0;  ///< cotangent clamping, as in the contraction
  SparseSolverKind solver = SparseSolverKind::Automatic;  ///< the factorization of (-L + H)
};

/// The weights of heatWeights() and what it met.
struct HeatWeightResult {
  /// weights(j, i): influence of bone i (skeleton edge i) on vertex j; each row sums to 1.
  Eigen::MatrixXd weights;
  int invisibleVertices = 0;       ///< vertices no nearest bone sees (H_jj = 0: weight by diffusion only)
  int componentsWithoutSight = 0;  ///< mesh components handled by the visibility fallback
  Error error;                     ///< non-empty on failure (no bones, solver breakdown, cancelled)
  /// True when the work succeeded (no error).
  bool ok() const { return error.empty(); }
};

/// progress(fraction) is called now and then; returning false aborts.
HeatWeightResult heatWeights(const TriangleMesh& mesh, const Skeleton& skeleton, const InsideTest& inside,
                             const HeatWeightParameters& parameters = {},
                             const std::function<bool(double)>& progress = {});

}  // namespace medial
