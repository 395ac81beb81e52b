#include "contraction/CrossSections.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_slicer.h>
#include <CGAL/Surface_mesh.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <random>

namespace medial {

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Surface = CGAL::Surface_mesh<Kernel::Point_3>;
using Polyline = std::vector<Kernel::Point_3>;

// Twice the signed area and the area centroid of a closed loop in the plane's (u, v) coordinates about
// `origin`, and how often it winds around the origin.
struct PlanarLoop {
  double area = 0;
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  int winding = 0;
};

PlanarLoop planarLoop(const std::vector<Eigen::Vector2d>& points) {
  PlanarLoop loop;
  double twiceArea = 0;
  Eigen::Vector2d weighted = Eigen::Vector2d::Zero();
  for (size_t k = 0; k < points.size(); ++k) {
    const Eigen::Vector2d& a = points[k];
    const Eigen::Vector2d& b = points[(k + 1) % points.size()];
    const double cross = a.x() * b.y() - b.x() * a.y();
    twiceArea += cross;
    weighted += (a + b) * cross;
    // Winding number about the origin (crossings of the positive x axis, signed).
    if (a.y() <= 0 && b.y() > 0 && cross > 0) ++loop.winding;
    if (a.y() > 0 && b.y() <= 0 && cross < 0) --loop.winding;
  }
  loop.area = std::abs(twiceArea) / 2;
  if (twiceArea != 0) loop.centroid = weighted / (3 * twiceArea);
  return loop;
}
}  // namespace

struct CrossSections::Slicer {
  Surface surface;
  std::unique_ptr<CGAL::Polygon_mesh_slicer<Surface, Kernel>> slicer;
};

CrossSections::CrossSections(const TriangleMesh& mesh) : slicer_(std::make_unique<Slicer>()) {
  Surface& s = slicer_->surface;
  std::vector<Surface::Vertex_index> handles;
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v)
    handles.push_back(
        s.add_vertex(Kernel::Point_3(mesh.vertices(v, 0), mesh.vertices(v, 1), mesh.vertices(v, 2))));
  // A face that would break the surface's manifold structure is left out: its cuts stay open.
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f)
    s.add_face(handles[size_t(mesh.faces(f, 0))], handles[size_t(mesh.faces(f, 1))],
               handles[size_t(mesh.faces(f, 2))]);
  slicer_->slicer = std::make_unique<CGAL::Polygon_mesh_slicer<Surface, Kernel>>(s);
}

CrossSections::~CrossSections() = default;

CrossSection CrossSections::around(const Eigen::Vector3d& point, const Eigen::Vector3d& normal) const {
  CrossSection best;
  if (normal.norm() == 0 || slicer_->surface.number_of_faces() == 0) return best;
  const Eigen::Vector3d n = normal.normalized();
  const Eigen::Vector3d u = n.unitOrthogonal(), v = n.cross(u);
  std::vector<Polyline> polylines;
  (*slicer_->slicer)(Kernel::Plane_3(Kernel::Point_3(point.x(), point.y(), point.z()),
                                     Kernel::Vector_3(n.x(), n.y(), n.z())),
                     std::back_inserter(polylines));
  for (const Polyline& line : polylines) {
    if (line.size() < 4 || line.front() != line.back()) continue;  // open: not a loop
    std::vector<Eigen::Vector2d> planar;
    for (size_t k = 0; k + 1 < line.size(); ++k) {
      const Eigen::Vector3d q = Eigen::Vector3d(line[k].x(), line[k].y(), line[k].z()) - point;
      planar.emplace_back(q.dot(u), q.dot(v));
    }
    const PlanarLoop loop = planarLoop(planar);
    if (loop.winding == 0 || loop.area <= 0 || (best.found && loop.area >= best.area)) continue;
    best.found = true;
    best.area = loop.area;
    best.centroid = point + loop.centroid.x() * u + loop.centroid.y() * v;
  }
  return best;
}

double CrossSection::offCentre(const Eigen::Vector3d& point) const {
  return (point - centroid).norm() / std::sqrt(area / M_PI);
}

double OffCentreSummary::median() const {
  if (ratios.empty()) return NAN;
  std::vector<double> sorted = ratios;
  std::sort(sorted.begin(), sorted.end());
  return sorted[sorted.size() / 2];
}

double OffCentreSummary::percentile90() const {
  if (ratios.empty()) return NAN;
  std::vector<double> sorted = ratios;
  std::sort(sorted.begin(), sorted.end());
  return sorted[std::min(sorted.size() - 1, size_t(0.9 * double(sorted.size())))];
}

OffCentreSummary offCentre(const Skeleton& skeleton, const CrossSections& sections, int samples,
                           unsigned seed) {
  OffCentreSummary summary;
  std::vector<double> lengths;
  for (const auto& [a, b] : skeleton.edges)
    lengths.push_back((skeleton.nodes[size_t(b)] - skeleton.nodes[size_t(a)]).norm());
  if (lengths.empty() || *std::max_element(lengths.begin(), lengths.end()) <= 0) return summary;
  std::mt19937 random(seed);
  std::discrete_distribution<size_t> pickEdge(lengths.begin(), lengths.end());
  std::uniform_real_distribution<double> along(0.2, 0.8);
  for (int k = 0; k < samples; ++k) {
    const auto& [a, b] = skeleton.edges[pickEdge(random)];
    const Eigen::Vector3d from = skeleton.nodes[size_t(a)], to = skeleton.nodes[size_t(b)];
    const Eigen::Vector3d s = from + along(random) * (to - from);
    const CrossSection section = sections.around(s, to - from);
    if (section.found) {
      summary.ratios.push_back(section.offCentre(s));
      summary.points.push_back(s);
    } else {
      ++summary.outside;
    }
  }
  return summary;
}

}  // namespace medial
