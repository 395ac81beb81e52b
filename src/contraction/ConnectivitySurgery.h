/// \file
/// ConnectivitySurgery: section III.B of the contraction paper (Au et al. 2008, section 4.2): turns the
/// contracted, degenerate mesh into a 1-D curve skeleton by edge collapses, keeping the record of which
/// mesh vertices each skeleton node absorbed (the skeleton-mesh mapping of Fig. 8).
///
/// 1. The paper's pre-pass: all edges shorter than delta go into a length priority queue and are collapsed,
///    shortest first, until none is left.
/// 2. Edge collapses ranked by the total cost (10), F = w_a F_a + w_b F_b: the shape cost (8) from the
///    edge-based quadrics (6)-(7) (K_ij built from the unit edge vector a and b = a x v_i; Q_j <- Q_i + Q_j
///    after a collapse), and the sampling cost (9), |v_i - v_j| times the summed length of i's edges.
///    A collapse i -> j keeps v_j (F_a is evaluated at the kept position, as in Au et al.).
///
/// Only an edge that still belongs to a triangle is collapsed; edges without triangles are skeleton
/// edges and stay, so the loops of a genus-g mesh survive as g cycles of the skeleton. The collapses stop
/// when no triangle is left.
#pragma once

#include "mesh/TriangleMesh.h"

#include <functional>
#include <utility>
#include <vector>

namespace medial {

/// The connectivity surgery's weights (paper §III.B: the shape cost w_a, the sampling cost w_b).
struct SurgeryParameters {
  double shapeWeight = 1.0;     ///< w_a
  double samplingWeight = 0.1;  ///< w_b
  /// Pre-pass length delta, as a fraction of the bounding-box diagonal of the contracted mesh.
  double deltaFraction = 1e-3;
};

/// The surgery's result: the curve skeleton and which mesh vertex each node absorbed.
struct CurveSkeleton {
  Vertices nodes;                          ///< node positions
  std::vector<std::pair<int, int>> edges;  ///< node index pairs
  std::vector<int> vertexToNode;           ///< for every mesh vertex, the node that absorbed it (-1: unused)
  std::vector<int> collapseOrder;  ///< for every mesh vertex, when it was collapsed (1: first; 0: a node)
  int prePassCollapses = 0;        ///< edges shorter than the pre-pass delta, collapsed first
  int costCollapses = 0;           ///< collapses in order of the shape and sampling cost
  int remainingFaces = 0;          ///< triangles no loop-preserving collapse could remove
};

/// progress(fraction) may return false to abort; the result then has no nodes.
CurveSkeleton collapseToCurveSkeleton(const Vertices& contracted, const Faces& faces,
                                      const SurgeryParameters& parameters = {},
                                      const std::function<bool(double)>& progress = {});

}  // namespace medial
