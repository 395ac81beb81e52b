#include "contraction/SkeletonByContraction.h"

#include "common/Stopwatch.h"

#include "contraction/CrossSections.h"
#include "contraction/EmbeddingRefinement.h"
#include "contraction/NodeCentring.h"
#include "contraction/NodeRadii.h"
#include "contraction/NodeSelection.h"
#include "mesh/InsideTest.h"
#include "mesh/MeshDecimation.h"
#include "rig/RigRoot.h"

#include <cmath>
#include <memory>

namespace medial {

Skeleton skeletonOf(const CurveSkeleton& curve) {
  Skeleton skeleton;
  for (Eigen::Index k = 0; k < curve.nodes.rows(); ++k)
    skeleton.nodes.push_back(curve.nodes.row(k).transpose());
  for (const auto& [a, b] : curve.edges) skeleton.edges.push_back({a, b});
  return skeleton;
}

CurveSkeleton curveSkeletonOf(const Skeleton& skeleton) {
  CurveSkeleton curve;
  curve.nodes.resize(Eigen::Index(skeleton.nodes.size()), 3);
  for (size_t k = 0; k < skeleton.nodes.size(); ++k)
    curve.nodes.row(Eigen::Index(k)) = skeleton.nodes[k].transpose();
  for (const auto& e : skeleton.edges) curve.edges.emplace_back(e[0], e[1]);
  return curve;
}

SelectionCentring measureSelectionCentring(const SkeletonByContractionResult& result,
                                           const TriangleMesh& mesh, double tolerance) {
  SelectionCentring out;
  const int sources = int(result.unselectedSkeleton.nodes.size());
  for (int from : result.selectedFrom)
    if (from < 0 || from >= sources) return out;  // no recorded stages, or not this run's
  const CrossSections sections(mesh);
  const InsideTest inside(mesh);
  CurveSkeleton source = curveSkeletonOf(result.unselectedSkeleton);
  const std::vector<Eigen::Vector3d> directions = nodeDirections(source);
  centreNodes(source, sections, inside);
  // Both cut across the unselected skeleton's direction at the source (before its centring, as the
  // pipeline centres the selected nodes): a selected node's own edges are chords of a bent axis, and a
  // cut across a chord would measure the direction as well as the position.
  const std::vector<double> sourceRatios = nodeOffCentre(source.nodes, directions, sections);
  std::vector<Eigen::Vector3d> selectedDirections;
  for (int from : result.selectedFrom) selectedDirections.push_back(directions[size_t(from)]);
  const std::vector<double> selectedRatios =
      nodeOffCentre(curveSkeletonOf(result.skeleton).nodes, selectedDirections, sections);
  for (size_t k = 0; k < selectedRatios.size() && k < result.selectedFrom.size(); ++k) {
    const double from = sourceRatios[size_t(result.selectedFrom[k])];
    if (std::isnan(selectedRatios[k]) || std::isnan(from)) continue;
    out.selected.ratios.push_back(selectedRatios[k]);
    out.source.ratios.push_back(from);
    out.worse += selectedRatios[k] > from + tolerance ? 1 : 0;
  }
  return out;
}

namespace {}  // namespace

std::string checkContractionInput(const TriangleMesh& mesh) {
  if (mesh.faces.rows() == 0) return "the mesh has no triangles";
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v)
    if (!mesh.vertices.row(v).allFinite())
      return "vertex " + std::to_string(v) + " has a non-finite coordinate (NaN or infinity)";
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f)
    for (int c = 0; c < 3; ++c)
      if (mesh.faces(f, c) < 0 || mesh.faces(f, c) >= mesh.vertices.rows())
        return "triangle " + std::to_string(f) + " refers to vertex " + std::to_string(mesh.faces(f, c)) +
               ", which does not exist";
  return {};
}

namespace {

// The coarse mesh's vertex map and contracted positions carried back to the input's vertices: each one
// goes with the coarse vertex that absorbed it.
void toInputVertices(const DecimatedMesh& coarse, const Vertices& contracted, CurveSkeleton& curve,
                     SkeletonByContractionResult& result) {
  std::vector<int> vertexToNode(coarse.representative.size(), -1);
  for (size_t v = 0; v < coarse.representative.size(); ++v) {
    const int r = coarse.representative[v];
    if (r < 0) continue;
    vertexToNode[v] = curve.vertexToNode[size_t(r)];
    result.contracted.row(Eigen::Index(v)) = contracted.row(r);
  }
  curve.vertexToNode = std::move(vertexToNode);
}

// III.C refinement (with the cycles surgery lost put back before edges leaving the mesh are split) and,
// without a selection, the centring of every node; returns the cross-sections the centring uses (none
// without it).
std::unique_ptr<CrossSections> refineCurve(const TriangleMesh& mesh, const DecimatedMesh& coarse,
                                           const InsideTest& inside, const SkeletonByContractionParameters& p,
                                           CurveSkeleton& curve, SkeletonByContractionResult& result) {
  if (p.refineEmbedding) {
    result.refinedNodes = refineEmbedding(curve, mesh.vertices, inside);
    result.pushedNodes = pushNodesInside(curve, inside);
  }
  if (p.restoreCycles) result.cycleRepair = restoreMissingCycles(curve, mesh, inside);
  if (p.refineEmbedding) result.splitEdges = splitEdgesLeavingTheMesh(curve, mesh.vertices, inside);
  if (!p.centerNodes) return nullptr;
  // Above 64,000 vertices the sections are cut from the decimation's 40,000-vertex first pass: centroids
  // within a small fraction of a radius of the input's, at a fraction of the cost.
  auto sections =
      std::make_unique<CrossSections>(coarse.coarsened.faces.rows() > 0 ? coarse.coarsened : mesh);
  // With a selection only the selected nodes are centred (selectCurve): as centred, at a fifth of the
  // cost. Without one, edges still off-centre after the centring are split at their sections' centroids
  // and the new nodes centred in turn. (Branch nodes of the whole curve skeleton stay: moved, those of
  // small side branches - the cow's udder - tangled the skeleton.)
  if (p.targetNodes <= 0) {
    result.centredNodes = centreNodes(curve, *sections, inside);
    result.centringSplits = splitOffCentreEdges(curve, mesh.vertices, *sections, inside);
    result.centredNodes += centreNodes(curve, *sections, inside);
  }
  return sections;
}

// III.D selection. The selected nodes are centred across the unselected skeleton's direction where they
// came from: their own edges are chords of bent parts, and a cut across a chord is oblique to the part (a
// node centred in it lands off the axis; docs/measurements.md).
void selectCurve(const InsideTest& inside, const CrossSections* sections, int targetNodes,
                 CurveSkeleton& curve, SkeletonByContractionResult& result) {
  const std::vector<Eigen::Vector3d> unselectedDirections = nodeDirections(curve);
  selectNodes(curve, targetNodes, &inside, &result.selectedFrom);
  std::vector<Eigen::Vector3d> directions;
  for (int from : result.selectedFrom) directions.push_back(unselectedDirections[size_t(from)]);
  if (sections)
    result.centredNodes += centreNodes(curve, *sections, inside, /*branchNodes=*/true, 2, &directions);
  const int kept = int(curve.nodes.rows());
  if (kept != targetNodes)
    result.selectionNote = std::to_string(kept) + " nodes kept of the " + std::to_string(targetNodes) +
                           " asked for: " +
                           (kept > targetNodes ? "merging any more would take a bone out of the mesh"
                                               : "the curve skeleton has no more");
}

}  // namespace

SkeletonByContractionResult skeletonByContraction(const TriangleMesh& mesh,
                                                  const SkeletonByContractionParameters& p,
                                                  const std::function<bool(double)>& progress) {
  SkeletonByContractionResult result;
  result.error = checkContractionInput(mesh);
  if (!result.error.empty()) return result;
  auto report = [&](double from, double to) {
    return [&progress, from, to](double f) { return !progress || progress(from + (to - from) * f); };
  };

  // The mesh that is contracted: the input, or its decimation to the vertex budget.
  Stopwatch start;
  const DecimatedMesh coarse = decimateMesh(mesh, p.contractionVertices);
  result.decimationSeconds = start.seconds();
  result.contractedVertices = int(coarse.mesh.vertices.rows());
  if (progress && !progress(0.02)) {
    result.error = Error::cancelled();
    return result;
  }

  // III.A geometry contraction.
  start.restart();
  const double contractionEnd = p.computeWeights ? 0.6 : 0.75, surgeryEnd = p.computeWeights ? 0.7 : 0.9;
  ContractionParameters contractionParameters = p.contraction;
  contractionParameters.recordSteps = contractionParameters.recordSteps || p.recordStages;
  ContractionResult contraction =
      contractMesh(coarse.mesh, contractionParameters, report(0.02, contractionEnd));
  result.contractionSeconds = start.seconds();
  result.factorizationSeconds = contraction.analyzeSeconds + contraction.factorizeSeconds;
  result.contractionIterations = contraction.iterations;
  result.contractionVolumeRatio = contraction.volumeRatio;
  result.contractionStop = contraction.stopReason;
  if (!contraction.ok()) {
    result.error = contraction.error.within("contraction failed");
    return result;
  }

  // III.B connectivity surgery.
  start.restart();
  CurveSkeleton curve = collapseToCurveSkeleton(contraction.contracted, coarse.mesh.faces, p.surgery,
                                                report(contractionEnd, surgeryEnd));
  result.surgerySeconds = start.seconds();
  if (curve.nodes.rows() == 0) {
    result.error = Error::cancelled();
    return result;
  }
  result.curveSkeletonNodes = int(curve.nodes.rows());
  if (p.recordStages) {
    result.contractionSteps = std::move(contraction.steps);
    result.contractedFaces = coarse.mesh.faces;
    result.surgerySkeleton = skeletonOf(curve);
    result.collapseOrder = curve.collapseOrder;
  }
  result.contracted = mesh.vertices;
  toInputVertices(coarse, contraction.contracted, curve, result);

  start.restart();
  const InsideTest inside(mesh);
  const std::unique_ptr<CrossSections> sections =
      refineCurve(mesh, coarse, inside, p, curve, result);  // III.C
  result.refinementSeconds = start.seconds();
  start.restart();
  if (p.recordStages) result.unselectedSkeleton = skeletonOf(curve);
  if (p.targetNodes > 0) selectCurve(inside, sections.get(), p.targetNodes, curve, result);  // III.D
  result.selectionSeconds = start.seconds();
  start.restart();
  result.skeleton.radii = nodeRadii(curve, mesh.vertices, inside);
  result.radiiSeconds = start.seconds();

  const std::vector<double> radii = std::move(result.skeleton.radii);
  result.skeleton = skeletonOf(curve);
  result.skeleton.radii = radii;
  result.vertexToNode = std::move(curve.vertexToNode);
  result.skeleton.root = bodyCentreNode(result.skeleton, mesh);  // the hips of a figure (rig/RigRoot.h)

  // III.E skinning weights.
  if (p.computeWeights) {
    start.restart();
    HeatWeightResult weights = heatWeights(mesh, result.skeleton, inside, p.weights, report(0.8, 0.99));
    result.weightsSeconds = start.seconds();
    if (!weights.ok()) {
      result.error = weights.error.within("skinning weights");
      return result;
    }
    result.weights = std::move(weights.weights);
    result.invisibleVertices = weights.invisibleVertices;
  }
  if (progress && !progress(1.0)) result.error = Error::cancelled();
  return result;
}

}  // namespace medial
