#include "mesh/InsideTest.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <cmath>
#include <iterator>
#include <vector>

namespace medial {

namespace {
using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Triangle = Kernel::Triangle_3;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle>::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Point toPoint(const Eigen::Vector3d& p) { return Point(p.x(), p.y(), p.z()); }
}  // namespace

struct InsideTest::Tree {
  std::vector<Triangle> triangles;
  medial::Tree tree;
};

InsideTest::InsideTest(const TriangleMesh& mesh) : tree_(std::make_unique<Tree>()) {
  tree_->triangles.reserve(size_t(mesh.faces.rows()));
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f) {
    const Triangle t(toPoint(mesh.vertices.row(mesh.faces(f, 0)).transpose()),
                     toPoint(mesh.vertices.row(mesh.faces(f, 1)).transpose()),
                     toPoint(mesh.vertices.row(mesh.faces(f, 2)).transpose()));
    if (!t.is_degenerate()) tree_->triangles.push_back(t);
  }
  tree_->tree.insert(tree_->triangles.begin(), tree_->triangles.end());
  tree_->tree.build();
  // Distance queries build CGAL's search tree on first use (thread-safe): most users of the test never ask.
}

InsideTest::~InsideTest() = default;

namespace {
const Kernel::Vector_3 kDirections[3] = {
    {0.5773, 0.5821, 0.5727}, {-0.7071, 0.1013, 0.6998}, {0.2113, -0.9349, 0.2851}};
}  // namespace

bool InsideTest::contains(const Eigen::Vector3d& point) const {
  if (tree_->triangles.empty()) return false;
  int insideVotes = 0, outsideVotes = 0;
  for (const auto& direction : kDirections) {  // two votes of three decide: the third ray is skipped then
    const Kernel::Ray_3 ray(toPoint(point), direction);
    ++(tree_->tree.number_of_intersected_primitives(ray) % 2 == 1 ? insideVotes : outsideVotes);
    if (insideVotes == 2 || outsideVotes == 2) break;
  }
  return insideVotes >= 2;
}

bool InsideTest::wrapped(const Eigen::Vector3d& point) const {
  if (tree_->triangles.empty()) return false;
  int insideVotes = 0, outsideVotes = 0;
  std::vector<Primitive::Id> hits;
  for (const auto& direction : kDirections) {  // two votes of three decide, as in contains()
    if (insideVotes == 2 || outsideVotes == 2) break;
    hits.clear();
    tree_->tree.all_intersected_primitives(Kernel::Ray_3(toPoint(point), direction),
                                           std::back_inserter(hits));
    int winding = 0;
    for (const auto& t : hits)
      winding += CGAL::cross_product(t->vertex(1) - t->vertex(0), t->vertex(2) - t->vertex(0)) * direction > 0
                     ? 1
                     : -1;
    ++(winding >= 1 ? insideVotes : outsideVotes);
  }
  return insideVotes >= 2;
}

bool InsideTest::segmentIsClear(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
  // A point sees itself (a mesh vertex lying on a bone: CGAL's segment test refuses a degenerate segment).
  if (!((b - a).squaredNorm() > 0)) return true;
  // Shrink the segment a little at both ends so that touching the surface at an end point is allowed.
  const Eigen::Vector3d shrink = 1e-6 * (b - a);
  return !tree_->tree.do_intersect(Kernel::Segment_3(toPoint(a + shrink), toPoint(b - shrink)));
}

double InsideTest::squaredDistanceToSurface(const Eigen::Vector3d& point) const {
  if (tree_->triangles.empty()) return INFINITY;
  return tree_->tree.squared_distance(toPoint(point));
}

double InsideTest::distanceAlongRay(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction) const {
  if (tree_->triangles.empty()) return INFINITY;
  const Kernel::Ray_3 ray(toPoint(origin), Kernel::Vector_3(direction.x(), direction.y(), direction.z()));
  const auto hit = tree_->tree.first_intersection(ray);
  if (!hit) return INFINITY;
  Point first = toPoint(origin);
  if (const Point* point = boost::get<Point>(&hit->first))
    first = *point;
  else if (const Kernel::Segment_3* segment = boost::get<Kernel::Segment_3>(&hit->first))  // in the plane
    first = CGAL::squared_distance(ray.source(), segment->source()) <
                    CGAL::squared_distance(ray.source(), segment->target())
                ? segment->source()
                : segment->target();
  return std::sqrt(CGAL::squared_distance(ray.source(), first));
}

Eigen::Vector3d InsideTest::closestSurfacePoint(const Eigen::Vector3d& point) const {
  if (tree_->triangles.empty()) return point;
  const Point q = tree_->tree.closest_point(toPoint(point));
  return {q.x(), q.y(), q.z()};
}

}  // namespace medial
