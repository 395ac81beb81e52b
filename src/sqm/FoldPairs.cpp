#include "sqm/FoldPairs.h"

#include "mesh/FaceIntersections.h"

#include <algorithm>

namespace medial {

namespace {

// A fold spans a bend or a branch node: the faces of a node and of its neighbours' neighbours' neighbours
// (a tight zig-zag of short edges folds across three).
constexpr int kFoldHops = 3;

std::pair<int, int> ordered(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

}  // namespace

FoldPairs::FoldPairs(const SqmMesh& base, const Skeleton& skeleton) {
  for (size_t f = 0; f < base.faces.size(); ++f) faceNode_.push_back(base.faceNode(f));
  std::vector<std::vector<int>> neighbours(size_t(skeleton.nodeCount()));
  for (const auto& e : skeleton.edges) {
    neighbours[size_t(e[0])].push_back(e[1]);
    neighbours[size_t(e[1])].push_back(e[0]);
  }
  for (int start = 0; start < skeleton.nodeCount(); ++start) {
    std::vector<int> frontier{start}, seen{start};
    for (int hop = 0; hop < kFoldHops; ++hop) {
      std::vector<int> next;
      for (int n : frontier)
        for (int m : neighbours[size_t(n)])
          if (std::find(seen.begin(), seen.end(), m) == seen.end()) {
            seen.push_back(m);
            next.push_back(m);
          }
      frontier = std::move(next);
    }
    for (int n : seen) near_.insert(ordered(start, n));
  }
  for (const auto& [a, b] : intersectingFaces(base.vertices, base.faces).facePairs)
    baseOverlaps_.insert(ordered(faceNode_[size_t(a)], faceNode_[size_t(b)]));
  foldPartners_.resize(size_t(skeleton.nodeCount()));
  for (const auto& [a, b] : near_)
    if (baseOverlaps_.count({a, b}) == 0) foldPartners_[size_t(a)].push_back(b);  // near_ is sorted
}

bool FoldPairs::isFold(int baseFaceA, int baseFaceB) const {
  const int a = faceNode_[size_t(baseFaceA)], b = faceNode_[size_t(baseFaceB)];
  if (a < 0 || b < 0) return true;  // capsule vertices: no node to tell by
  const auto& partners = foldPartners_[size_t(std::min(a, b))];
  return std::binary_search(partners.begin(), partners.end(), std::max(a, b));
}

}  // namespace medial
