#include "rig/SkinBinding.h"

#include "mesh/InsideTest.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <queue>
#include <utility>
#include <vector>

namespace medial {

namespace {

bool boxesOverlap(const TriangleMesh& mesh, const Skeleton& skeleton) {
  Eigen::Vector3d skeletonMin = Eigen::Vector3d::Constant(INFINITY), skeletonMax = -skeletonMin;
  for (const Eigen::Vector3d& p : skeleton.nodes) {
    skeletonMin = skeletonMin.cwiseMin(p);
    skeletonMax = skeletonMax.cwiseMax(p);
  }
  const Eigen::Vector3d meshMin = mesh.vertices.colwise().minCoeff().transpose();
  const Eigen::Vector3d meshMax = mesh.vertices.colwise().maxCoeff().transpose();
  return (skeletonMin.array() <= meshMax.array()).all() && (meshMin.array() <= skeletonMax.array()).all();
}

}  // namespace

SkinBindingResult bindSkin(const TriangleMesh& mesh, const Skeleton& skeleton,
                           const HeatWeightParameters& parameters,
                           const std::function<bool(double)>& progress) {
  SkinBindingResult result;
  if (mesh.faces.rows() == 0) {
    result.error = "the mesh has no faces to bind";
    return result;
  }
  if (skeleton.edgeCount() == 0) {
    result.error = "the skeleton has no edges (bones)";
    return result;
  }
  if (!boxesOverlap(mesh, skeleton)) {
    result.error = "the skeleton lies outside the mesh's bounding box (another unit or coordinate frame?)";
    return result;
  }
  result.root = skeleton.root >= 0 ? skeleton.root : bodyCentreNode(skeleton, mesh);
  const InsideTest inside(mesh);
  for (const Eigen::Vector3d& p : skeleton.nodes)
    if (!inside.contains(p)) ++result.nodesOutside;
  HeatWeightResult heat = heatWeights(mesh, skeleton, inside, parameters, progress);
  if (!heat.ok()) {
    result.error = heat.error;
    return result;
  }
  result.weights = std::move(heat.weights);
  result.invisibleVertices = heat.invisibleVertices;
  return result;
}

}  // namespace medial
