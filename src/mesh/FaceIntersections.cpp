#include "mesh/FaceIntersections.h"

#include "common/Parallel.h"
#include "mesh/BoxPairs.h"

#include <Eigen/Geometry>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <array>
#include <tuple>

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

// Whether the vertices `others` of polygon b (those it does not share with a) lie on one side of a's plane,
// each farther from it than rounding can account for: then b meets that plane at most in what the two
// share, and the two do not cut. Evaluated in doubles; a margin of about 900 units in the last place of the
// determinant's magnitude (Shewchuk's bound for orient3d is 7) leaves every doubtful case to the exact
// predicates. On a refined SQM mesh most candidate pairs are neighbours on a smooth surface, which this
// settles without CGAL's exact machinery.
template <class Polygon>
bool clearlyOnOneSide(const std::vector<Eigen::Vector3d>& v, const Triangle& a, const Polygon& b,
                      const int* others, int count) {
  constexpr double kRelativeMargin = 1e-13;
  const Eigen::Vector3d& origin = v[size_t(a[0])];
  const Eigen::Vector3d e1 = v[size_t(a[1])] - origin, e2 = v[size_t(a[2])] - origin;
  const Eigen::Vector3d normal = e1.cross(e2);
  const double scale = e1.squaredNorm() * e2.squaredNorm();
  int side = 0;
  for (int k = 0; k < count; ++k) {
    const Eigen::Vector3d w = v[size_t(b[size_t(others[k])])] - origin;
    const double d = normal.dot(w);
    const double margin = kRelativeMargin * kRelativeMargin * scale * w.squaredNorm();
    if (d * d <= margin) return false;
    const int s = d > 0 ? 1 : -1;
    if (side != 0 && s != side) return false;
    side = s;
  }
  return true;
}

// Whether triangles a and b cut each other beyond what they share, by the rule of CGAL's
// self_intersections: sharing an edge, only when coplanar and folded onto each other; sharing a vertex,
// when the edge opposite it in either cuts the other triangle.
bool trianglesCut(const std::vector<Eigen::Vector3d>& v, const Triangle& a, const Triangle& b) {
  int sharedA[3], sharedB[3], shared = 0;
  bool inA[3] = {false, false, false}, inB[3] = {false, false, false};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (a[size_t(i)] == b[size_t(j)]) {
        sharedA[shared] = i;
        sharedB[shared++] = j;
        inA[i] = inB[j] = true;
      }
  if (shared <= 1) {  // the quick answer for most pairs: one triangle clear of the other's plane
    int othersA[3], othersB[3], countA = 0, countB = 0;
    for (int i = 0; i < 3; ++i) {
      if (!inA[i]) othersA[countA++] = i;
      if (!inB[i]) othersB[countB++] = i;
    }
    if (clearlyOnOneSide(v, a, b, othersB, countB) || clearlyOnOneSide(v, b, a, othersA, countA))
      return false;
  }
  const auto at = [&](const Triangle& t, int i) {
    const Eigen::Vector3d& q = v[size_t(t[size_t(i)])];
    return Point(q.x(), q.y(), q.z());
  };
  if (shared == 3) return true;  // the same triangle twice (either way round) covers itself, as in CGAL's
  if (shared == 2) {
    const Point e0 = at(a, sharedA[0]), e1 = at(a, sharedA[1]);
    const Point thirdA = at(a, 3 - sharedA[0] - sharedA[1]);
    const Point thirdB = at(b, 3 - sharedB[0] - sharedB[1]);
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

// Whether, for every triangle of f's fan, the vertices of g it does not hold lie clearly on one side of its
// plane (clearlyOnOneSide): then no triangle of g cuts it. Two normals per quad instead of a test per pair
// of triangles: most candidate pairs of a refined mesh are neighbours that this settles.
bool polygonClearOf(const std::vector<Eigen::Vector3d>& v, const std::vector<int>& f,
                    const std::vector<int>& g) {
  int others[8];
  for (size_t i = 1; i + 1 < f.size(); ++i) {
    const Triangle a{f[0], f[i], f[i + 1]};
    if (degenerate(a)) continue;
    int count = 0;
    for (size_t k = 0; k < g.size(); ++k)
      if (g[k] != a[0] && g[k] != a[1] && g[k] != a[2]) {
        if (count == 8) return false;
        others[count++] = int(k);
      }
    if (count == 0 || !clearlyOnOneSide(v, a, g, others, count)) return false;
  }
  return true;
}

bool polygonsCut(const std::vector<Eigen::Vector3d>& vertices, const std::vector<int>& f,
                 const std::vector<int>& g) {
  if (polygonClearOf(vertices, f, g) || polygonClearOf(vertices, g, f)) return false;
  for (size_t i = 1; i + 1 < f.size(); ++i) {
    const Triangle a{f[0], f[i], f[i + 1]};
    if (degenerate(a)) continue;
    for (size_t j = 1; j + 1 < g.size(); ++j) {
      const Triangle b{g[0], g[j], g[j + 1]};
      if (!degenerate(b) && trianglesCut(vertices, a, b)) return true;
    }
  }
  return false;
}

}  // namespace

FaceIntersections intersectingFaces(const std::vector<Eigen::Vector3d>& vertices,
                                    const std::vector<std::vector<int>>& faces, size_t limit,
                                    const FacePairFilter& consider, const std::vector<char>* selected,
                                    const std::vector<int>* subset) {
  FaceIntersections result;
  // Pairs of polygons (of three vertices or more) whose boxes overlap.
  const size_t listed = subset ? subset->size() : faces.size();
  std::vector<int> polygon;
  std::vector<Box3> tested;
  std::vector<char> testedSelected;
  polygon.reserve(listed);
  tested.reserve(listed);
  for (size_t k = 0; k < listed; ++k) {
    const size_t f = subset ? size_t((*subset)[k]) : k;
    if (faces[f].size() >= 3) {
      tested.push_back(boxOf(vertices, faces[f]));
      polygon.push_back(int(f));
      if (selected) testedSelected.push_back((*selected)[f]);
    }
  }
  std::vector<std::pair<int, int>> candidates =
      overlappingBoxPairs(tested, selected ? &testedSelected : nullptr);  // a fixed order
  for (auto& [a, b] : candidates) std::tie(a, b) = std::minmax(polygon[size_t(a)], polygon[size_t(b)]);
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
          cut[i] = (!consider || consider(f, g)) && polygonsCut(vertices, faces[size_t(f)], faces[size_t(g)]);
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
