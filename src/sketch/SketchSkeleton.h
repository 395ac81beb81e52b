/// \file
/// SketchSkeleton: real-time skeletonization for sketch-based modelling (Ma, Wang, Li, Zhang 2021), the
/// whole chain from closed strokes to one animatable skeleton with radii (docs/ARCHITECTURE.md §4, ready for
/// SQM) and an inflated mesh per stroke.
///
/// Per part (§3.1): stroke -> simple counter-clockwise polygon (SketchStroke) -> CGAL straight skeleton
/// without peripheral edges, short edges collapsed (StraightSkeletonGraph) -> every branch of three or more
/// nodes simplified by BoundedDP with epsilon_s (BoundedDP) -> nodes placed in 3-D by the part's placement
/// matrix, each with the radius of its inscribed ball (distance to the resampled outline). Parts are then
/// connected in modelling order (§3.2, PartConnection) and refined (§3.3, SkeletonRefinement): short
/// JT-branches pruned (epsilon_t; first, so that the base of a spur is not merged as a junction), junctions
/// merged (epsilon_m), short internal bones collapsed (epsilon_c).
/// Stage 4 inflates each part's outline (SketchInflation).
///
/// Units. The paper's thresholds are in pixels of its drawing canvas. Here every length parameter is in
/// "sketch pixels": `unitLength` stroke units each. By default unitLength is 1/1000 of the bounding-box
/// diagonal of all strokes, so a drawing 1000 px across behaves as in the paper whatever its units
/// (metres, millimetres, screen pixels). Set unitLength = 1 to use the stroke's own units as pixels.
#pragma once

#include "common/Error.h"
#include "mesh/TriangleMesh.h"
#include "sketch/PartConnection.h"
#include "sketch/SketchGraph.h"
#include "sketch/SketchStroke.h"

#include <Eigen/Core>

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace medial {

/// The four refinement thresholds of §3.3 with the paper's defaults (sketch pixels).
struct RefinementThresholds {
  double simplification = 5;  ///< epsilon_s: BoundedDP, branch level
  double merging = 30;        ///< epsilon_m: junction clusters
  double pruning = 30;        ///< epsilon_t: JT-branches
  double collapsing = 10;     ///< epsilon_c: internal bones
};

/// One sketched part: its closed stroke, where it lies in 3-D, and its own thresholds.
struct SketchPart {
  Polygon2 stroke;                                          ///< closed; the last point may repeat the first
  Eigen::Matrix4d placement = Eigen::Matrix4d::Identity();  ///< maps (x, y, 0, 1) of the stroke into 3-D
  std::optional<RefinementThresholds> thresholds;           ///< part level; the global ones when empty
  std::map<int, double> branchSimplification;  ///< branch level: epsilon_s per branch id of the part
};

/// The parameters of sketchSkeleton() with the paper's defaults \cite ma2021.
struct SketchParameters {
  double unitLength = 0;            ///< stroke units per sketch pixel; 0: diagonal of all strokes / 1000
  double resampleStep = 10;         ///< uniform resampling of the stroke (the paper's Fig. 19)
  double polygonTolerance = 2;      ///< Douglas-Peucker tolerance of the polygon
  double collapseRatio = 0.5;       ///< straight-skeleton edges shorter than this x their mean are collapsed
  double shapeWeight = 1;           ///< alpha_s of eq. (1)
  double sliceStep = 2;             ///< spacing of BoundedDP's slices
  double tuningRatio = 0.8;         ///< Algorithm 2
  RefinementThresholds thresholds;  ///< the global thresholds of §3.3
  bool inflate = true;              ///< stage 4
  double thickness = 2;             ///< c of the inflation (2: round tubes)
  double meshEdgeLength = 10;       ///< largest edge of the inflation's triangulation
  bool mergeParts = true;           ///< one watertight mesh, the union of the parts (else one component each)
  bool recordStages = false;        ///< SketchResult::stages: the skeleton after each step
};

/// What the local stage did with one part.
struct SketchPartResult {
  PreparedStroke stroke;          ///< resampled and simplified outlines (stroke units, 2-D)
  int straightSkeletonNodes = 0;  ///< after peripheral removal and collapsing
  int branches = 0;               ///< long branches simplified by BoundedDP
  PartAttachment attachment;      ///< to the earlier part it hangs from (parent -1: a root)
};

/// What sketchSkeleton() made: the skeleton, the inflated mesh and the figures per part.
struct SketchResult {
  SketchGraph graph;  ///< the skeleton (docs/ARCHITECTURE.md §4: Radius, Root) with part and branch labels
  TriangleMesh mesh;  ///< the inflated parts: their union, or one closed component per part
  std::vector<int> meshVertexPart;      ///< one per mesh vertex
  std::vector<SketchPartResult> parts;  ///< one per input part
  double unitLength = 1;                ///< the unit used
  ///@{
  /// Seconds per stage: local (straight skeletons, BoundedDP), connection, refinement, inflation.
  double localSeconds = 0, connectionSeconds = 0, refinementSeconds = 0, inflationSeconds = 0;
  ///@}
  /// With recordStages, in order (the paper's Figs. 3-9): "straight-skeleton" (each part's, peripheral
  /// edges removed and short edges collapsed), "bounded-dp" (each branch simplified), "connected" (the parts
  /// joined by eq. 3), "pruned", "merged" (the refinement's first two operations; the collapse gives graph).
  std::vector<std::pair<std::string, SketchGraph>> stages;
  Error error;  ///< names the part ("stroke 2: ...") when one is bad
  /// True when the work succeeded (no error).
  bool ok() const { return error.empty(); }
};

/// The skeleton of sketched parts (§3.1-3.3) and their inflated meshes (§4.1) \cite ma2021.
/// \param parts closed strokes in modelling order, each with its placement and optional local thresholds
/// \param parameters the paper's defaults in sketch pixels (SketchParameters)
/// \param progress called with the fraction done; returning false stops the work (error: Error::cancelled())
/// \return the skeleton with part and branch labels, the inflated meshes and stage times, or an error that
///         names the stroke ("stroke 2: ...")
SketchResult sketchSkeleton(const std::vector<SketchPart>& parts, const SketchParameters& parameters = {},
                            const std::function<bool(double)>& progress = {});

}  // namespace medial
