/// \file
/// CycleRepair: beyond the paper. Connectivity surgery can lose a tunnel whose cross-section is small next
/// to the contraction (a bolt hole in a plate, a handle of a few triangles in a scanned bone): the skeleton
/// then has fewer independent cycles than the mesh has genus. This step puts the missing ones back.
///
/// 1. A homology basis of the surface: 2g loops of mesh edges (HomologyLoops).
/// 2. Each loop is pushed out of the solid (a little, along the vertex normals) and into it (to half the
///    thickness along the inward normal, the middle of the material).
/// 3. Which class a closed curve inside the solid has is told by its linking numbers with the pushed-out
///    loops (Alexander duality: linking pairs the first homology of the solid with that of its complement
///    perfectly). The skeleton's own cycles get their rows of linking numbers first; then the pushed-in
///    loops, shortest first, each kept when its row is independent of the rows so far, until the rank is g
///    or the skeleton has g cycles (never more: a skeleton cycle that leaves the mesh links unreliably).
/// 4. A kept loop becomes a cycle of nodes (its pushed-in points), tied to the nearest skeleton node it sees
///    from inside the mesh by one edge. Selection (III.D) then thins it like any other part.
#pragma once

#include "contraction/ConnectivitySurgery.h"
#include "mesh/InsideTest.h"

#include <Eigen/Core>

#include <vector>

namespace medial {

/// What restoreMissingCycles() found and added.
struct CycleRepairResult {
  int genus = 0;         ///< of the closed 2-manifold components
  int cyclesBefore = 0;  ///< independent cycles of the skeleton graph
  int cyclesAdded = 0;   ///< cycles put back
};

/// Adds to `skeleton` the cycles it lacks to match the genus of `mesh` (see the file's steps);
/// `inside` tests points against `mesh`.
CycleRepairResult restoreMissingCycles(CurveSkeleton& skeleton, const TriangleMesh& mesh,
                                       const InsideTest& inside);

/// Linking number of two disjoint closed polygons (the last point joins the first): half the signed
/// crossings of their projections, which equals Gauss's linking integral.
double linkingNumber(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b);

}  // namespace medial
