/// \file
/// SkeletonByContraction: the whole skeleton pipeline of the contraction paper (section III, stages 1-4)
/// plus node radii: optional decimation to a vertex budget, contraction (III.A), connectivity surgery
/// (III.B), embedding refinement (III.C), node selection (III.D), radii, and on request the heat-diffusion
/// skinning weights (III.E). Input: a triangle mesh (any number of components, open or closed). Output: a
/// Skeleton (docs/ARCHITECTURE.md §4) with radii and a root, and the skeleton-mesh mapping (vertex -> node).
#pragma once

#include "common/Error.h"
#include "contraction/ConnectivitySurgery.h"
#include "contraction/CrossSections.h"
#include "contraction/CycleRepair.h"
#include "rig/HeatWeights.h"
#include "contraction/MeshContraction.h"
#include "skeleton/Skeleton.h"

#include <functional>
#include <string>
#include <vector>

namespace medial {

/// The parameters of skeletonByContraction(), with the papers' defaults \cite au2008 \cite berenguer.
struct SkeletonByContractionParameters {
  /// Meshes with more vertices are first decimated to this many (quadric error metric, topology kept;
  /// src/mesh/MeshDecimation.h) and the coarse mesh is contracted and collapsed; refinement, radii, the
  /// segmentation and the weights use the input mesh. 0 contracts the input itself.
  int contractionVertices = 4000;
  ContractionParameters contraction;  ///< III.A: the contraction's weights and stopping tests
  SurgeryParameters surgery;          ///< III.B: the connectivity surgery's cost weights
  bool refineEmbedding = true;        ///< III.C: move nodes to the centres of the mesh parts they absorbed
  /// Beyond the paper: nodes move to the centroid of the mesh's cross-section through them
  /// (src/contraction/NodeCentring.h): the selected nodes after the selection, branch nodes included, cut
  /// across the unselected skeleton's direction where each came from, or
  /// without a selection every node of one or two edges after the refinement, and edges whose middle is
  /// still off-centre are split at their sections' centroids.
  bool centerNodes = true;
  /// Beyond the paper: put back the cycles surgery lost, so that the skeleton has as many independent
  /// cycles as the closed mesh has genus (src/contraction/CycleRepair.h).
  bool restoreCycles = true;
  /// III.D node selection: the skeleton gets exactly this many nodes, unless fewer would take a bone out of
  /// the mesh or the curve skeleton has fewer (selectionNote says so; no nodes are invented in the middle
  /// of its edges). 0 keeps every node of the refined curve skeleton.
  int targetNodes = 30;
  bool computeWeights = false;   ///< III.E: one weight per vertex and bone (skeleton edge)
  HeatWeightParameters weights;  ///< III.E: the heat-diffusion weights
  /// The intermediate results the paper draws: the contraction's steps (contraction.recordSteps, Figs. 5
  /// and 7) and the curve skeleton straight after the surgery and before the selection.
  bool recordStages = false;
};

/// What skeletonByContraction() made: the skeleton, the maps back to the mesh, the weights and the
/// stage figures.
struct SkeletonByContractionResult {
  Skeleton skeleton;              ///< the curve skeleton with radii (rooted for rigs)
  std::vector<int> vertexToNode;  ///< per input vertex: its node, -1 for vertices no face uses
  Vertices contracted;            ///< the contracted mesh positions (same faces as the input)
  Eigen::MatrixXd weights;        ///< with computeWeights: (vertices x bones), rows summing to 1
  int invisibleVertices = 0;      ///< vertices no nearest bone sees (HeatWeightResult)
  int contractedVertices = 0;  ///< vertices of the mesh that was contracted (the coarse mesh, if decimated)
  int contractionIterations = 0;        ///< III.A iterations run
  double contractionVolumeRatio = 1.0;  ///< enclosed volume after / before the contraction
  std::string contractionStop;          ///< which stopping test ended the contraction
  int curveSkeletonNodes = 0;           ///< before selection
  int refinedNodes = 0;                 ///< nodes the refinement moved
  int pushedNodes = 0;                  ///< nodes moved from outside into the mesh (pushNodesInside)
  CycleRepairResult cycleRepair;        ///< genus, cycles after surgery, cycles restored
  int splitEdges = 0;      ///< nodes added inside edges that left the mesh (splitEdgesLeavingTheMesh)
  int centredNodes = 0;    ///< node moves to their cross-section's centroid (centerNodes)
  int centringSplits = 0;  ///< nodes added in off-centre edges (splitOffCentreEdges, without selection)
  /// With recordStages: the contraction's steps on the contracted mesh (its faces: contractedFaces), the
  /// curve skeleton after the surgery (III.B, unrefined) and before the selection (after III.C).
  std::vector<ContractionStep> contractionSteps;
  std::vector<int>
      collapseOrder;         ///< per contracted vertex: when the surgery collapsed it (1: first; 0: a node)
  Faces contractedFaces;     ///< the faces of the contracted mesh (the coarse mesh's, if decimated)
  Skeleton surgerySkeleton;  ///< with recordStages: after the surgery (III.B, unrefined)
  Skeleton unselectedSkeleton;    ///< with recordStages: before the selection (after III.C)
  std::vector<int> selectedFrom;  ///< with a selection: per node of `skeleton`, the node it came from
  /// With a selection that could not give targetNodes nodes: why, with the count kept (empty otherwise).
  std::string selectionNote;
  ///@{
  /// Seconds per stage, and the share of the contraction spent factorizing.
  double decimationSeconds = 0, contractionSeconds = 0, factorizationSeconds = 0, surgerySeconds = 0,
         refinementSeconds = 0, selectionSeconds = 0, radiiSeconds = 0, weightsSeconds = 0;
  ///@}
  Error error;  ///< why the work failed; empty on success
  /// True when the work succeeded (no error).
  bool ok() const { return error.empty(); }
};

/// The curve skeleton's nodes and edges as a Skeleton (no radii, no root).
Skeleton skeletonOf(const CurveSkeleton& curve);

/// A Skeleton's nodes and edges as a curve skeleton (no vertex map).
CurveSkeleton curveSkeletonOf(const Skeleton& skeleton);

/// Issue 26's goal for the selection: every selected node as centred as the node it came from. Each node
/// of a run's selected skeleton (recordStages: unselectedSkeleton and selectedFrom) is compared with its
/// source in the unselected skeleton, that one centred as the unselected path centres it (centerNodes,
/// without the splits): the off-centre ratio at the node itself (nodeOffCentre).
/// Empty without recordStages.
struct SelectionCentring {
  OffCentreSummary selected;  ///< the selected nodes' ratios, of the pairs where both have a cross-section
  OffCentreSummary source;    ///< their source nodes' ratios, in the same order
  int worse = 0;              ///< pairs whose selected node is more than `tolerance` further off
};
/// The measure of SelectionCentring on a result made with recordStages; nodes count as worse when
/// more than `tolerance` (off-centre ratio) further off than their source.
SelectionCentring measureSelectionCentring(const SkeletonByContractionResult& result,
                                           const TriangleMesh& mesh, double tolerance = 0.1);

/// Checks what the algorithm needs: at least one triangle, finite coordinates, valid vertex ids. The
/// message names the first problem; empty when the mesh is usable.
std::string checkContractionInput(const TriangleMesh& mesh);

/// The curve skeleton of `mesh` by contraction, surgery, refinement and selection (paper §III.A-D), with
/// radii, and on request the heat-diffusion skinning weights (§III.E) \cite au2008 \cite berenguer.
/// \param mesh a triangle mesh: any number of components, open or closed
/// \param parameters the paper's defaults (SkeletonByContractionParameters)
/// \param progress called with the fraction done; returning false stops the work (error: Error::cancelled())
/// \return the skeleton, the vertex-to-node map, the weights and the stage figures, or an error naming
///         the problem (checkContractionInput's, a failed factorization)
SkeletonByContractionResult skeletonByContraction(const TriangleMesh& mesh,
                                                  const SkeletonByContractionParameters& parameters = {},
                                                  const std::function<bool(double)>& progress = {});

}  // namespace medial
