#include "mesh/FaceIntersections.h"

#include "common/Parallel.h"
#include "mesh/BoxPairs.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <array>

namespace medial {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Triangle = std::array<int, 3>;

Box3 boxOf(const std::vector<Eigen::Vector3d>& vertices, const std::vector<int>& face) {
  Box3 box{vertices[size_t(face[0])], vertices[size_t(face[0])]};
  for (int v : face) {
    box.low = box.low.cwiseMin(vertices[size_t(v)]);
    box.high = box.high.cwiseMax(vertices[size_t(v)]);
  }
  return box;
}

// Whether triangles a and b cut each other beyond what they share, by the rule of CGAL's
// self_intersections: sharing an edge, only when coplanar and folded onto each other; sharing a vertex,
// when the edge opposite it in either cuts the other triangle.
bool trianglesCut(const std::vector<Point>& p, const Triangle& a, const Triangle& b) {
  int sharedA[3], sharedB[3], shared = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (a[size_t(i)] == b[size_t(j)]) {
        sharedA[shared] = i;
        sharedB[shared++] = j;
      }
  const auto at = [&](const Triangle& t, int i) -> const Point& { return p[size_t(t[size_t(i)])]; };
  if (shared == 3) return true;  // the same triangle twice (either way round) covers itself, as in CGAL's
  if (shared == 2) {
    const Point &e0 = at(a, sharedA[0]), &e1 = at(a, sharedA[1]);
    const Point& thirdA = at(a, 3 - sharedA[0] - sharedA[1]);
    const Point& thirdB = at(b, 3 - sharedB[0] - sharedB[1]);
    return CGAL::coplanar(e0, e1, thirdA, thirdB) &&
           CGAL::coplanar_orientation(e0, e1, thirdA, thirdB) == CGAL::POSITIVE;
  }
  const Kernel::Triangle_3 ta(at(a, 0), at(a, 1), at(a, 2)), tb(at(b, 0), at(b, 1), at(b, 2));
  if (shared == 1) {
    const int i = sharedA[0], j = sharedB[0];
    return CGAL::do_intersect(ta, Kernel::Segment_3(at(b, (j + 1) % 3), at(b, (j + 2) % 3))) ||
           CGAL::do_intersect(tb, Kernel::Segment_3(at(a, (i + 1) % 3), at(a, (i + 2) % 3)));
  }
  return CGAL::do_intersect(ta, tb);
}

bool degenerate(const Triangle& t) { return t[0] == t[1] || t[1] == t[2] || t[0] == t[2]; }

bool polygonsCut(const std::vector<Point>& points, const std::vector<int>& f, const std::vector<int>& g) {
  for (size_t i = 1; i + 1 < f.size(); ++i) {
    const Triangle a{f[0], f[i], f[i + 1]};
    if (degenerate(a)) continue;
    for (size_t j = 1; j + 1 < g.size(); ++j) {
      const Triangle b{g[0], g[j], g[j + 1]};
      if (!degenerate(b) && trianglesCut(points, a, b)) return true;
    }
  }
  return false;
}

}  // namespace

FaceIntersections intersectingFaces(const std::vector<Eigen::Vector3d>& vertices,
                                    const std::vector<std::vector<int>>& faces, size_t limit,
                                    const FacePairFilter& consider, const std::vector<char>* selected) {
  FaceIntersections result;
  std::vector<Point> points;
  points.reserve(vertices.size());
  for (const auto& v : vertices) points.emplace_back(v.x(), v.y(), v.z());
  // Pairs of polygons (of three vertices or more) whose boxes overlap.
  std::vector<int> polygon;
  std::vector<Box3> tested;
  std::vector<char> testedSelected;
  for (size_t f = 0; f < faces.size(); ++f)
    if (faces[f].size() >= 3) {
      tested.push_back(boxOf(vertices, faces[f]));
      polygon.push_back(int(f));
      if (selected) testedSelected.push_back((*selected)[f]);
    }
  std::vector<std::pair<int, int>> candidates =
      overlappingBoxPairs(tested, selected ? &testedSelected : nullptr);  // a fixed order
  for (auto& [a, b] : candidates) {
    a = polygon[size_t(a)];
    b = polygon[size_t(b)];
  }
  // Blocks of candidates, each tested in parallel; the search stops after the block that reaches the limit.
  constexpr size_t block = size_t(1) << 16;
  std::vector<char> cut;
  for (size_t first = 0; first < candidates.size() && result.complete; first += block) {
    const size_t count = std::min(block, candidates.size() - first);
    cut.assign(count, 0);
    inParallel(
        count,
        [&](size_t i) {
          const auto [f, g] = candidates[first + i];
          cut[i] = (!consider || consider(f, g)) && polygonsCut(points, faces[size_t(f)], faces[size_t(g)]);
        },
        1024);
    for (size_t i = 0; i < count; ++i)
      if (cut[i]) {
        if (result.facePairs.size() == limit) {
          result.complete = false;
          break;
        }
        result.facePairs.push_back(candidates[first + i]);
      }
  }
  std::sort(result.facePairs.begin(), result.facePairs.end());
  return result;
}

}  // namespace medial
