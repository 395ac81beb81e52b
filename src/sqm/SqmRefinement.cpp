#include "sqm/SqmRefinement.h"

#include <Eigen/LU>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/CatmullClarkT.hh>

#include <algorithm>
#include <cmath>

namespace medial {

namespace {

struct Traits : public OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<Traits>;

Eigen::Vector3d toEigen(const PolyMesh::Point& p) { return {p[0], p[1], p[2]}; }

// The point of the nearest truncated cone: its axis point and radius there (radial projection).
struct ConePoint {
  Eigen::Vector3d axis, radial;  // radial: unit vector from the axis towards p
  double radius = 0;             // along `radial`
  bool found = false;
};

// With ellipsoid nodes (extension 3) the cone is a generalized one: its cross-sections interpolate the
// two ends' ellipsoid matrices, and the radius along a direction u is 1 / |M(t)^-1 u| (r for M = r I).
ConePoint nearestCone(const Eigen::Vector3d& p, const Skeleton& s) {
  ConePoint cone;
  double best = INFINITY;
  const bool ellipsoids = !s.ellipsoidAxes.empty();
  for (const auto& e : s.edges) {
    const Eigen::Vector3d a = s.nodes[size_t(e[0])], b = s.nodes[size_t(e[1])];
    const Eigen::Vector3d ab = b - a;
    const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
    const Eigen::Vector3d axis = a + t * ab;
    const Eigen::Vector3d radial = p - axis;
    const double distance = radial.norm();
    double radius = (1 - t) * s.radii[size_t(e[0])] + t * s.radii[size_t(e[1])];
    if (distance <= 1e-12 * radius) continue;
    if (ellipsoids) {
      const Eigen::Matrix3d m = (1 - t) * s.ellipsoidAxes[size_t(e[0])] + t * s.ellipsoidAxes[size_t(e[1])];
      const Eigen::Vector3d local = m.fullPivLu().solve(radial / distance);
      if (local.norm() > 0) radius = 1 / local.norm();
    }
    const double gap = std::abs(distance - radius);
    if (gap < best) {
      best = gap;
      cone = {axis, radial / distance, radius, true};
    }
  }
  return cone;
}

// Base vertices where two faces sharing an edge fold to an acute angle (normals > 90 degrees apart).
std::vector<Eigen::Vector3d> sharpVertices(PolyMesh& poly) {
  poly.request_face_normals();
  poly.update_face_normals();
  std::vector<bool> sharp(poly.n_vertices(), false);
  for (auto e : poly.edges()) {
    if (poly.is_boundary(e)) continue;
    const auto h = poly.halfedge_handle(e, 0);
    const auto n0 = poly.normal(poly.face_handle(h)), n1 = poly.normal(poly.face_handle(poly.opposite_halfedge_handle(h)));
    if (OpenMesh::dot(n0, n1) < 0) sharp[size_t(poly.to_vertex_handle(h).idx())] = sharp[size_t(poly.from_vertex_handle(h).idx())] = true;
  }
  poly.release_face_normals();
  std::vector<Eigen::Vector3d> points;
  for (auto v : poly.vertices())
    if (sharp[size_t(v.idx())]) points.push_back(toEigen(poly.point(v)));
  return points;
}

double distanceToNearest(const Eigen::Vector3d& p, const std::vector<Eigen::Vector3d>& points) {
  double best = INFINITY;
  for (const auto& q : points) best = std::min(best, (q - p).squaredNorm());
  return std::sqrt(best);
}

}  // namespace

double sharpScaleFactor(double t, double s) {
  t = std::clamp(t, 0.0, 1.0);
  const double u = 1 - t;
  return s * u * u * u + 3 * s * t * u * u + 3 * t * t * u + t * t * t;
}

int refineSqmMesh(SqmMesh& mesh, const Skeleton& skeleton, int levels, const SharpScaling& scaling) {
  if (levels <= 0 || mesh.faces.empty()) return 0;
  PolyMesh poly;
  std::vector<PolyMesh::VertexHandle> handles;
  for (const auto& v : mesh.vertices) handles.push_back(poly.add_vertex(PolyMesh::Point(v.x(), v.y(), v.z())));
  for (const auto& f : mesh.faces) {
    std::vector<PolyMesh::VertexHandle> face;
    for (int v : f) face.push_back(handles[size_t(v)]);
    poly.add_face(face);
  }
  const std::vector<Eigen::Vector3d> sharp = scaling.enabled ? sharpVertices(poly) : std::vector<Eigen::Vector3d>{};
  OpenMesh::Subdivider::Uniform::CatmullClarkT<PolyMesh> catmullClark;
  for (int level = 0; level < levels; ++level) {
    catmullClark.attach(poly);
    catmullClark(1);
    catmullClark.detach();
    for (auto v : poly.vertices()) {
      const Eigen::Vector3d p = toEigen(poly.point(v));
      const ConePoint cone = nearestCone(p, skeleton);
      if (!cone.found) continue;
      double radius = cone.radius;
      if (!sharp.empty()) radius *= sharpScaleFactor(distanceToNearest(p, sharp) / cone.radius, scaling.minimumScale);
      const Eigen::Vector3d q = cone.axis + radius * cone.radial;
      poly.set_point(v, PolyMesh::Point(q.x(), q.y(), q.z()));
    }
  }
  // Back to plain arrays; a vertex belongs to the node nearest to it.
  mesh.vertices.clear();
  mesh.faces.clear();
  mesh.vertexNode.clear();
  for (auto v : poly.vertices()) {
    const auto& p = poly.point(v);
    mesh.vertices.emplace_back(p[0], p[1], p[2]);
    int nearest = 0;
    for (int k = 1; k < skeleton.nodeCount(); ++k)
      if ((skeleton.nodes[size_t(k)] - mesh.vertices.back()).squaredNorm() <
          (skeleton.nodes[size_t(nearest)] - mesh.vertices.back()).squaredNorm())
        nearest = k;
    mesh.vertexNode.push_back(nearest);
  }
  for (auto f : poly.faces()) {
    std::vector<int> face;
    for (auto v : poly.fv_range(f)) face.push_back(v.idx());
    mesh.faces.push_back(face);
  }
  return int(sharp.size());
}

}  // namespace medial
