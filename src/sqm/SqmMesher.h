/// \file
/// SqmMesher: Skeleton to Quad-dominant Mesh (Bærentzen et al. 2012) with the extensions of the CESCG 2014
/// paper and the thesis chapter: a skeleton with a radius per node becomes a closed manifold mesh of quads,
/// with triangles only in the fans that close leaves and the bands that close cycles; these are joined
/// in pairs into quads by default (TrianglePairing), leaving a triangle only where a ring is odd.
///
/// Steps per connected component (section numbers of the CESCG paper): the tree and its root (ext. 1),
/// straightening into the bind pose (4), branch node polyhedra (BNPs) generated and refined in
/// depth-first order from the root (4, see BranchNodePolyhedron), joining: each intersection vertex of a
/// BNP is removed and its former one-ring is carried along the path to the next branch node or leaf, one
/// ring per connection node (translated onto the plane through the node across the path, then projected
/// onto its sphere), closed by a triangle fan at a leaf, or paired with the one-ring of the next BNP's
/// intersection vertex. Finally every vertex goes back from the bind pose to the input pose by linear blend
/// skinning with the straightening rotations (a connection node's ring blends its incoming and outgoing
/// rotations half and half, so that it bisects the bend, and is put back on its sphere).
/// A skeleton without branch nodes gets an N-vertex ring at its first connection node (ext. 2); a lone node
/// becomes a sphere of six quads (a cube projected on it); leaves end in capsules on request (ext. 4,
/// radius sqrt(r^2 (1 - step^2)) at distance step * r beyond the leaf); ellipsoid nodes map their vertices
/// by their `EllipsoidAxes` (ext. 3); cycles are cut and closed again after placement (ext. 5, see
/// CycleClosing).
/// Then, on request, K levels of the paper's tessellation projected onto the swept spheres (SqmRefinement).
#pragma once

#include "common/Error.h"
#include "skeleton/Skeleton.h"
#include "sqm/BranchNodePolyhedron.h"
#include "sqm/SqmMesh.h"
#include "sqm/SqmUnion.h"

#include <Eigen/Core>

#include <functional>
#include <string>
#include <vector>

namespace medial {

/// How the last ring of a tube is paired with the one-ring of the BNP it reaches (thesis, "Branch node
/// termination"): the rotation minimizing the total Euclidean distance (default), the first vertex's
/// nearest vertex, or the vertex whose direction is closest to the path's direction.
enum class RingPairing { MinimalTotalDistance, MinimalDistance, MinimalAngle };
/// The pairing's name as the command line spells it ("total-distance", "distance", "angle").
const char* ringPairingName(RingPairing pairing);
/// The pairing named `name`; false, leaving `pairing` alone, for an unknown name.
bool parseRingPairing(const std::string& name, RingPairing& pairing);
/// Every pairing's name (the one list the filter, the command line and the GUI offer).
std::vector<std::string> ringPairingNames();

/// Stage 8's radius scaling near sharp vertices (SqmRefinement.h tells how). Off by default: on the test
/// skeletons refined twice it did not lower the self-intersections (docs/measurements.md).
struct SharpScaling {
  bool enabled = false;       ///< scale the radii near sharp vertices
  double minimumScale = 0.8;  ///< s: B(0), the radius factor at a sharp vertex
};

/// SQM's parameters with the papers' defaults (the filter vtkMedialSQM and `medial sqm` expose each).
struct SqmParameters {
  LieSmoothing smoothing = LieSmoothing::Quaternion;        ///< the smoothing after each LIE split
  RingPairing pairing = RingPairing::MinimalTotalDistance;  ///< how a tube's last ring meets its polyhedron
  int linearRingVertices = 8;                               ///< N of extension 2
  bool capsules = false;                                    ///< extension 4
  int capsuleSteps = 4;  ///< with capsules: rings added beyond each leaf to close it
  /// Neighbouring triangles of the leaf fans and cycle bands joined into quads where the quad is fair
  /// (TrianglePairing): beyond the papers, whose fans stay triangles; off gives the paper's mesh.
  bool pairTriangles = true;
  int subdivisionLevels =
      0;  ///< stage 8: tessellation levels projected onto the swept spheres (SqmRefinement)
  SharpScaling sharpScaling;  ///< stage 8: Bézier radius scaling near sharp vertices (SqmRefinement)
  bool foldRepair = true;  ///< stage 8: refined vertices of faces that cut others back towards the base mesh
  /// The repair that merges a node lying inside a neighbouring branch node's sphere into it (off: such a
  /// skeleton is an error naming the node).
  bool mergeNodes = true;
  ///@{
  /// Where tubes of parts that are not neighbours overlap, their faces cut each other: count the pairs
  /// (SqmResult::overlaps), and with `unite` replace the mesh by the boundary of the union of its volumes
  /// (SqmUnion; beyond the papers). `unite` implies counting.
  bool countOverlaps = false;
  bool unite = false;
  ///@}
  /// The papers' intermediate results (SqmResult's polyhedra, refinedPolyhedra, baseMesh).
  bool recordStages = false;
};

/// The mesh of sqmMesh() and the figures of its stages.
struct SqmResult {
  SqmMesh mesh;             ///< the output: closed, manifold, outward oriented
  int branchNodes = 0;      ///< nodes with three or more edges
  int connectionNodes = 0;  ///< nodes with two edges
  int leafNodes = 0;        ///< nodes with one edge
  int reorientedFaces = 0;  ///< faces turned over by the final orientation repair (-1: not orientable)
  int mergedNodes = 0;      ///< nodes inside a neighbouring branch node's sphere, merged into it (a repair)
  int pairedTriangles = 0;  ///< quads made of two fan or band triangles (SqmParameters::pairTriangles)
  int foldRepairedVertices = 0;  ///< refined vertices moved off their cones by the fold repair
  int irregularVertices = 0;     ///< vertices of the output where other than four edges meet
  SqmOverlaps overlaps;  ///< with countOverlaps or unite: the faces cutting each other (before the union)
  SqmUnionResult unionResult;  ///< with unite: what the union cut and removed
  double unionSeconds = 0;     ///< counting the overlaps and the union
  ///@{
  /// The paper's Table 1 stages: straightening, BNP generation and refinement, joining, skinning
  /// (placement), subdivision, and Medial's repairs (orientation, triangle pairing).
  double straighteningSeconds = 0, generationSeconds = 0, refinementSeconds = 0, joiningSeconds = 0,
         placementSeconds = 0, subdivisionSeconds = 0, repairSeconds = 0;
  ///@}
  ///@{
  /// With recordStages: every branch node polyhedron as generated (the hull, 1-to-6 split and projected:
  /// CESCG Fig. 3) and after the LIE refinement (Fig. 4), in the bind pose (the straightened skeleton), a
  /// vertex's node the branch node; and the joined base mesh before the subdivision, in the input pose.
  SqmMesh polyhedra, refinedPolyhedra, baseMesh;
  ///@}
  Error error;  ///< why the work failed; empty on success
  /// True when the work succeeded (no error).
  bool ok() const { return error.empty(); }
};

/// The SQM mesh of `skeleton`: one closed quad-dominant manifold per connected component \cite baerentzen2012
/// \cite piovarci2014. \param skeleton nodes, edges and a positive radius per node (optional EllipsoidAxes
/// and root) \param parameters the papers' defaults and Medial's extensions (SqmParameters) \param progress
/// called with the fraction done; returning false stops the work (error: Error::cancelled()) \return the mesh
/// with each vertex's node, node counts, repairs and stage times, or an error naming the
///         problem (no radius, coincident joined nodes, two edges leaving a node in one direction)
SqmResult sqmMesh(const Skeleton& skeleton, const SqmParameters& parameters = {},
                  const std::function<bool(double)>& progress = {});

}  // namespace medial
