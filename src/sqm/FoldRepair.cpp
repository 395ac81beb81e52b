#include "sqm/FoldRepair.h"

#include "mesh/FaceIntersections.h"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <set>

namespace medial {

namespace {

constexpr int kFoldRepairSteps = 6;
constexpr int kFoldSmoothingSteps = 10;
constexpr int kStepsWithoutProgress = 3;
constexpr int kLocalRings = 2;

using FacePairs = std::vector<std::pair<int, int>>;

// Finds the vertices of faces that fold over others; only pairs that are folds are tested (a refined level
// of a dense tree has 100,000 faces and tens of thousands of pairs of overlapping tubes). After the first
// test over every candidate face, only the pairs with a face that moved in the last step are tested,
// among the faces within kLocalRings rings of those; when none is left there, a confirming test covers the
// pairs of every face with a face moved since the last full test - pairs of faces that did not move are as
// they were.
class FoldFinder {
 public:
  FoldFinder(const std::vector<std::vector<int>>& faces, size_t vertices, IsFold isFold,
             std::vector<int> candidates)
      : faces_(faces),
        isFold_(std::move(isFold)),
        everyFace_(std::move(candidates)),
        facesOf_(vertices),
        touched_(faces.size(), 0),
        movingNow_(faces.size(), 0),
        inRegion_(faces.size(), 0) {
    for (size_t f = 0; f < faces_.size(); ++f)
      for (int v : faces_[f]) facesOf_[size_t(v)].push_back(int(f));
  }

  // The first test, over every candidate face: the vertices of faces that fold (empty when none do).
  std::vector<bool> first(const std::vector<Eigen::Vector3d>& points) {
    const Found found = test(points, everyFace_, isFold_);
    folds_ = found.folds;
    return found.vertices;
  }
  // From now on the confirming tests cover every face: once folds are found, the repair moves vertices,
  // and the moved faces may cut faces that could not fold before (the figure refined four times kept one
  // pair).
  void testEveryFace() {
    everyFace_.resize(faces_.size());
    std::iota(everyFace_.begin(), everyFace_.end(), 0);
  }
  // After the vertices `moved` moved: the vertices of faces that still fold. Only the pairs with a face
  // that moved now can have changed; they are tested against the faces within kLocalRings rings of the
  // moved faces (a fold's two faces lie close on the mesh; the confirming test finds any other).
  std::vector<bool> again(const std::vector<Eigen::Vector3d>& points, const std::vector<bool>& moved) {
    std::vector<int> movedNow;
    for (size_t v = 0; v < moved.size(); ++v)
      if (moved[v])
        for (int f : facesOf_[v]) {
          if (!movingNow_[size_t(f)]) movedNow.push_back(f);
          movingNow_[size_t(f)] = 1;
          touch(f);
        }
    std::vector<int> region = movedNow;
    for (int f : region) inRegion_[size_t(f)] = 1;
    for (int ring = 0, first = 0; ring < kLocalRings; ++ring) {
      const int last = int(region.size());
      for (int k = first; k < last; ++k)
        for (int w : faces_[size_t(region[size_t(k)])])
          for (int g : facesOf_[size_t(w)])
            if (!inRegion_[size_t(g)]) {
              inRegion_[size_t(g)] = 1;
              region.push_back(g);
            }
      first = last;
    }
    const Found found = test(points, region, [&](int f, int g) {
      return (movingNow_[size_t(f)] || movingNow_[size_t(g)]) && isFold_(f, g);
    });
    for (int f : movedNow) movingNow_[size_t(f)] = 0;
    for (int f : region) inRegion_[size_t(f)] = 0;
    return found.vertices.empty() ? confirm(points) : found.vertices;
  }
  // The vertices sharing an edge with v (of its faces, the corners before and after it), sorted.
  std::vector<int> neighbours(int v) const {
    std::vector<int> around;
    for (int f : facesOf_[size_t(v)]) {
      const auto& face = faces_[size_t(f)];
      const size_t k = size_t(std::find(face.begin(), face.end(), v) - face.begin());
      around.push_back(face[(k + 1) % face.size()]);
      around.push_back(face[(k + face.size() - 1) % face.size()]);
    }
    std::sort(around.begin(), around.end());  // each edge is seen from both of its faces
    around.erase(std::unique(around.begin(), around.end()), around.end());
    return around;
  }
  // The folds as the mesh is now.
  const FacePairs& folds(const std::vector<Eigen::Vector3d>& points) {
    if (!touchedList_.empty()) confirm(points);
    return folds_;
  }

 private:
  struct Found {
    std::vector<bool> vertices;  // of the folds; empty when there are none
    FacePairs folds;
  };
  void touch(int f) {
    if (!touched_[size_t(f)]) touchedList_.push_back(f);
    touched_[size_t(f)] = 1;
  }
  std::vector<bool> confirm(const std::vector<Eigen::Vector3d>& points) {
    const Found found = test(points, everyFace_, isFold_, &touched_);
    folds_ = found.folds;
    for (int f : touchedList_) touched_[size_t(f)] = 0;
    touchedList_.clear();
    return found.vertices;
  }
  // Tests the faces `tested`, the pairs of faces for which `consider` holds (folds only).
  // With `selected` (a flag per face of the level), only the pairs with a selected face.
  Found test(const std::vector<Eigen::Vector3d>& points, const std::vector<int>& tested,
             const IsFold& consider, const std::vector<char>* selected = nullptr) const {
    Found found;
    const auto pairs =
        intersectingFaces(points, faces_, std::numeric_limits<size_t>::max(), consider, selected, &tested);
    for (const auto& [f, g] : pairs.facePairs) {
      found.folds.emplace_back(f, g);
      found.vertices.resize(points.size(), false);
      for (int h : {f, g})
        for (int v : faces_[size_t(h)]) found.vertices[size_t(v)] = true;
    }
    return found;
  }

  const std::vector<std::vector<int>>& faces_;
  IsFold isFold_;
  std::vector<int> everyFace_;             // the faces of full tests
  std::vector<std::vector<int>> facesOf_;  // the faces of each vertex
  std::vector<char> touched_;              // faces moved since the last full test
  std::vector<int> touchedList_;
  std::vector<char> movingNow_;  // faces moved in this step (again)
  std::vector<char> inRegion_;   // in the region of a local test
  FacePairs folds_;              // in the last full test
};

// Whether some of `folds` do not cut each other on the flat tessellation.
bool someCutOnlyWhenProjected(const std::vector<std::vector<int>>& faces,
                              const std::vector<Eigen::Vector3d>& flat, const FacePairs& folds) {
  std::vector<int> involved;
  for (const auto& [f, g] : folds) involved.insert(involved.end(), {f, g});
  std::sort(involved.begin(), involved.end());
  involved.erase(std::unique(involved.begin(), involved.end()), involved.end());
  const std::set<std::pair<int, int>> wanted(folds.begin(), folds.end());
  const auto flatCuts = intersectingFaces(
      flat, faces, std::numeric_limits<size_t>::max(),
      [&](int f, int g) { return wanted.count(std::minmax(f, g)) > 0; }, nullptr, &involved);
  return flatCuts.facePairs.size() < folds.size();
}

}  // namespace

FoldRepairResult repairFolds(const std::vector<std::vector<int>>& faces,
                             const std::vector<Eigen::Vector3d>& flat, std::vector<Eigen::Vector3d>& points,
                             const IsFold& isFold, std::vector<int> candidates) {
  FoldRepairResult result;
  const std::vector<Eigen::Vector3d> projected = points;
  std::vector<double>& weight = result.shares;
  weight.assign(points.size(), 1.0);
  FoldFinder finder(faces, points.size(), isFold, std::move(candidates));
  std::vector<bool> folded = finder.first(points);
  if (!folded.empty()) finder.testEveryFace();
  for (int step = 0; step <= kFoldRepairSteps && !folded.empty(); ++step) {
    for (size_t v = 0; v < points.size(); ++v) {
      if (!folded[v]) continue;
      result.movedVertices += weight[v] == 1.0;
      weight[v] = step < kFoldRepairSteps ? 0.5 * weight[v] : 0.0;
      points[v] = flat[v] + weight[v] * (projected[v] - flat[v]);
    }
    folded = finder.again(points, folded);
  }
  // Vertices of folds that appeared since the halvings go to the base mesh first; those already there are
  // smoothed, until kStepsWithoutProgress steps in a row leave as many folded vertices.
  size_t fewest = SIZE_MAX;
  for (int step = 0, stalled = 0;
       step < kFoldSmoothingSteps && !folded.empty() && stalled < kStepsWithoutProgress; ++step) {
    std::vector<std::pair<size_t, Eigen::Vector3d>> moves;  // applied after: all from the points before
    for (size_t v = 0; v < points.size(); ++v) {
      if (!folded[v]) continue;
      const std::vector<int> around = finder.neighbours(int(v));
      if (around.empty()) continue;
      if (weight[v] > 0) {
        result.movedVertices += weight[v] == 1.0;
        weight[v] = 0;
        moves.emplace_back(v, flat[v]);
        continue;
      }
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      for (int n : around) sum += points[size_t(n)];
      moves.emplace_back(v, sum / double(around.size()));
    }
    for (const auto& [v, p] : moves) points[v] = p;
    folded = finder.again(points, folded);
    const size_t count = size_t(std::count(folded.begin(), folded.end(), true));
    stalled = count < fewest ? 0 : stalled + 1;
    fewest = std::min(fewest, count);
  }
  result.settled = folded.empty();
  if (!result.settled) {
    result.foldsLeft = finder.folds(points);
    result.repairable = someCutOnlyWhenProjected(faces, flat, result.foldsLeft);
  }
  return result;
}

}  // namespace medial
