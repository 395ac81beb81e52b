#include "sketch/SketchSkeleton.h"

#include "common/Stopwatch.h"

#include "mesh/MeshUnion.h"
#include "sketch/BoundedDP.h"
#include "sketch/SketchInflation.h"
#include "sketch/SkeletonRefinement.h"
#include "sketch/StraightSkeletonGraph.h"

#include <cmath>

namespace medial {
namespace {

Eigen::Vector3d place(const Eigen::Matrix4d& placement, const Eigen::Vector2d& p, double z = 0) {
  return (placement * Eigen::Vector4d(p.x(), p.y(), z, 1)).head<3>();
}

// How much the placement scales lengths in the stroke's plane.
double planeScale(const Eigen::Matrix4d& placement) {
  return std::sqrt(placement.block<3, 1>(0, 0).cross(placement.block<3, 1>(0, 1)).norm());
}

// Stage 1-3 for one part: its skeleton nodes and bones, added to `graph` with label `part`.
// The inflated piece (in its stroke's plane) moved by the part's placement; a mirroring placement turns
// the faces back outward.
TriangleMesh placedPiece(const TriangleMesh& piece, const Eigen::Matrix4d& placement) {
  TriangleMesh placed = piece;
  for (Eigen::Index v = 0; v < piece.vertices.rows(); ++v) {
    const Eigen::Vector3d q = piece.vertices.row(v).transpose();
    placed.vertices.row(v) = place(placement, q.head<2>(), q.z()).transpose();
  }
  if (placement.block<3, 3>(0, 0).determinant() < 0) placed.faces.col(1).swap(placed.faces.col(2));
  return placed;
}

// The pieces side by side in one mesh, each vertex labelled with its part.
void appendPieces(const std::vector<TriangleMesh>& pieces, SketchResult& result) {
  Eigen::Index vertices = 0, faces = 0;
  for (const TriangleMesh& piece : pieces) {
    vertices += piece.vertices.rows();
    faces += piece.faces.rows();
  }
  result.mesh.vertices.resize(vertices, 3);
  result.mesh.faces.resize(faces, 3);
  vertices = faces = 0;
  for (size_t k = 0; k < pieces.size(); ++k) {
    result.mesh.vertices.middleRows(vertices, pieces[k].vertices.rows()) = pieces[k].vertices;
    result.mesh.faces.middleRows(faces, pieces[k].faces.rows()) = pieces[k].faces.array() + int(vertices);
    result.meshVertexPart.insert(result.meshVertexPart.end(), size_t(pieces[k].vertices.rows()), int(k));
    vertices += pieces[k].vertices.rows();
    faces += pieces[k].faces.rows();
  }
}

bool extractPart(const SketchPart& part, int partIndex, const SketchParameters& p, double unit,
                 SketchGraph& graph, SketchPartResult& out, std::string& error, SketchGraph* straight) {
  out.stroke = prepareStroke(part.stroke, {p.resampleStep * unit, p.polygonTolerance * unit});
  if (!out.stroke.ok()) {
    error = out.stroke.error;
    return false;
  }
  SkeletonGraph2 local;
  if (!straightSkeletonGraph(out.stroke.polygon, p.collapseRatio, local, error)) return false;
  out.straightSkeletonNodes = local.nodeCount();
  const double scale = planeScale(part.placement);
  const RefinementThresholds& thresholds = part.thresholds ? *part.thresholds : p.thresholds;
  std::vector<int> nodeOf(local.nodeCount(), -1);
  auto addNode = [&](const Eigen::Vector2d& q) {
    return graph.addNode(place(part.placement, q), scale * distanceToBoundary(out.stroke.resampled, q),
                         partIndex);
  };
  auto jointNode = [&](int v) {
    if (nodeOf[v] < 0) nodeOf[v] = addNode(local.nodes[v]);
    return nodeOf[v];
  };
  if (straight) {  // recordStages: the straight skeleton as it is, before BoundedDP
    const int first = straight->skeleton.nodeCount();
    for (const Eigen::Vector2d& q : local.nodes)
      straight->addNode(place(part.placement, q), scale * distanceToBoundary(out.stroke.resampled, q),
                        partIndex);
    for (const auto& e : local.edges) straight->addEdge(first + e[0], first + e[1], partIndex, -1);
  }
  if (local.edges.empty()) {  // e.g. a triangle: one inscribed ball
    jointNode(0);
    return true;
  }
  const auto branches = findBranches(local.nodeCount(), local.edges);
  for (int b = 0; b < int(branches.size()); ++b) {
    const auto& branch = branches[b];
    std::vector<Eigen::Vector2d> points;
    for (int v : branch) points.push_back(local.nodes[v]);
    if (branch.size() >= 3) {
      BoundedDPParameters dp;
      const auto custom = part.branchSimplification.find(b);
      dp.threshold =
          (custom != part.branchSimplification.end() ? custom->second : thresholds.simplification) * unit;
      dp.shapeWeight = p.shapeWeight;
      dp.sliceStep = p.sliceStep * unit;
      dp.tuningRatio = p.tuningRatio;
      dp.ladderUnit = unit;
      points = boundedDP(points, out.stroke.polygon, dp).points;
      ++out.branches;
    }
    int previous = jointNode(branch.front());
    for (size_t k = 1; k + 1 < points.size(); ++k) {
      const int node = addNode(points[k]);
      graph.addEdge(previous, node, partIndex, b);
      previous = node;
    }
    graph.addEdge(previous, jointNode(branch.back()), partIndex, b);
  }
  return true;
}

std::vector<double> nodeThresholds(const SketchGraph& graph, const std::vector<SketchPart>& parts,
                                   const SketchParameters& p, double unit,
                                   double RefinementThresholds::*which) {
  std::vector<double> result(graph.skeleton.nodeCount());
  for (int v = 0; v < graph.skeleton.nodeCount(); ++v) {
    const auto& part = parts[graph.nodePart[v]];
    result[v] = unit * (part.thresholds ? *part.thresholds : p.thresholds).*which;
  }
  return result;
}

bool validPlacement(const Eigen::Matrix4d& m) {
  return m.allFinite() && planeScale(m) > 0 && m.row(3).isApprox(Eigen::RowVector4d(0, 0, 0, 1));
}

}  // namespace

SketchResult sketchSkeleton(const std::vector<SketchPart>& parts, const SketchParameters& p,
                            const std::function<bool(double)>& progress) {
  SketchResult result;
  if (parts.empty()) {
    result.error = "no stroke";
    return result;
  }
  auto aborted = [&](double fraction) {
    if (progress && !progress(fraction)) {
      result.error = Error::cancelled();
      return true;
    }
    return false;
  };
  // The unit: a thousandth of the drawing's diagonal unless given.
  Eigen::AlignedBox2d box;
  for (const auto& part : parts)
    for (const auto& q : part.stroke)
      if (q.allFinite()) box.extend(q);
  result.unitLength = p.unitLength > 0 ? p.unitLength : (box.isEmpty() ? 0.0 : box.diagonal().norm() / 1000);
  const double unit = result.unitLength;
  if (!(unit > 0)) {
    result.error = "the strokes have no extent (all points coincide or are not finite)";
    return result;
  }
  Stopwatch localStart;
  result.parts.resize(parts.size());
  SketchGraph straight;
  for (int k = 0; k < int(parts.size()); ++k) {
    std::string error;
    if (!validPlacement(parts[k].placement))
      error = "the placement matrix must be finite, with last row 0 0 0 1 and a non-degenerate plane";
    else
      extractPart(parts[k], k, p, unit, result.graph, result.parts[k], error,
                  p.recordStages ? &straight : nullptr);
    if (!error.empty()) {
      result.error = "stroke " + std::to_string(k + 1) + ": " + error;
      return result;
    }
    if (aborted(0.6 * (k + 1) / parts.size())) return result;
  }
  result.localSeconds = localStart.seconds();

  const auto record = [&](const char* name) {
    if (p.recordStages) result.stages.emplace_back(name, result.graph);
  };
  if (p.recordStages) result.stages.emplace_back("straight-skeleton", straight);
  record("bounded-dp");
  Stopwatch connectionStart;
  const auto attachments = connectParts(result.graph, int(parts.size()));
  for (size_t k = 0; k < parts.size(); ++k) result.parts[k].attachment = attachments[k];
  result.connectionSeconds = connectionStart.seconds();

  Stopwatch refinementStart;
  SketchGraph& g = result.graph;
  // Pruning first: the junctions at the base of spurs and twigs are not real junctions to merge.
  record("connected");
  pruneBranches(g, nodeThresholds(g, parts, p, unit, &RefinementThresholds::pruning));
  record("pruned");
  mergeJunctions(g, nodeThresholds(g, parts, p, unit, &RefinementThresholds::merging));
  record("merged");
  collapseEdges(g, nodeThresholds(g, parts, p, unit, &RefinementThresholds::collapsing));
  // The root: the widest joint of the first part (the torso of a character drawn torso first).
  for (int v = 0; v < g.skeleton.nodeCount(); ++v)
    if (g.nodePart[v] == 0 &&
        (g.skeleton.root < 0 || g.skeleton.radii[v] > g.skeleton.radii[g.skeleton.root]))
      g.skeleton.root = v;
  result.refinementSeconds = refinementStart.seconds();
  if (aborted(0.7)) return result;

  if (p.inflate) {
    Stopwatch inflationStart;
    std::vector<TriangleMesh> pieces(parts.size());
    for (int k = 0; k < int(parts.size()); ++k) {
      TriangleMesh piece;
      std::string error;
      if (!inflatePolygon(result.parts[k].stroke.resampled, {p.thickness, p.meshEdgeLength * unit}, piece,
                          error)) {
        result.error = "stroke " + std::to_string(k + 1) + ": " + error;
        return result;
      }
      pieces[size_t(k)] = placedPiece(piece, parts[k].placement);
      if (aborted(0.7 + 0.1 * (k + 1) / parts.size())) return result;
    }
    if (p.mergeParts && pieces.size() > 1) {
      // One watertight mesh (the paper's Fig. 12: a model to animate), the parts' volumes joined.
      MeshUnionResult merged = meshUnion(pieces, [&](double f) { return !aborted(0.8 + 0.2 * f); });
      if (!merged.ok()) {
        result.error = merged.error.within("joining the inflated parts");
        return result;
      }
      result.mesh = std::move(merged.mesh);
      result.meshVertexPart = std::move(merged.vertexLabel);
    } else {
      appendPieces(pieces, result);
    }
    result.inflationSeconds = inflationStart.seconds();
  }
  return result;
}

}  // namespace medial
