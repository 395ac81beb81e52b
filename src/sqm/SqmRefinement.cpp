#include "sqm/SqmRefinement.h"

#include "mesh/SelfIntersections.h"

#include <Eigen/LU>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/CatmullClarkT.hh>

#include <algorithm>
#include <cmath>
#include <vector>

namespace medial {

namespace {

struct Traits : public OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<Traits>;

Eigen::Vector3d toEigen(const PolyMesh::Point& p) { return {p[0], p[1], p[2]}; }

// The width of the blend of cone projections (nearestCone), in radii of the nearest cone. Refined twice,
// intersecting pairs of the humanoid / fish / figure / octopus: no blend 490 / 15 / 168 / 24; 0.2: 94 / 22
// / 31 / 0; 0.8: 16 / 24 / 14 / 0. (Blending on the outer side of bends as well cut them further, to 23 /
// 0 / 26 / 0 at 0.2, but grooved every tentacle at its nodes and sharpened the octopus's head.)
constexpr double kConeBlend = 0.8;

struct ConePoint {
  Eigen::Vector3d axis, radial;     // radial: unit vector from the axis towards the point
  double radius = 0, distance = 0;  // the cone's radius along `radial`; the point's distance from the axis
  bool found = false;
  Eigen::Vector3d onSurface() const { return axis + radius * radial; }
};

// A point's radial projection onto the truncated cone of skeleton edge `edge`. With ellipsoid nodes
// (extension 3) the cone is a generalized one: its cross-sections interpolate the two ends' ellipsoid
// matrices, and the radius along a direction u is 1 / |M(t)^-1 u| (r for M = r I).
ConePoint conePoint(const Eigen::Vector3d& p, const Skeleton& s, size_t edge) {
  const auto& e = s.edges[edge];
  const Eigen::Vector3d a = s.nodes[size_t(e[0])], b = s.nodes[size_t(e[1])];
  const Eigen::Vector3d ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
  ConePoint cone;
  cone.axis = a + t * ab;
  const Eigen::Vector3d radial = p - cone.axis;
  cone.distance = radial.norm();
  cone.radius = (1 - t) * s.radii[size_t(e[0])] + t * s.radii[size_t(e[1])];
  if (cone.distance <= 1e-12 * cone.radius) return cone;
  cone.radial = radial / cone.distance;
  if (!s.ellipsoidAxes.empty()) {
    const Eigen::Matrix3d m = (1 - t) * s.ellipsoidAxes[size_t(e[0])] + t * s.ellipsoidAxes[size_t(e[1])];
    const Eigen::Vector3d local = m.fullPivLu().solve(cone.radial);
    if (local.norm() > 0) cone.radius = 1 / local.norm();
  }
  cone.found = true;
  return cone;
}

// The cone whose surface lies nearest to p (radial projection), and in `placed` where p goes: that
// projection, blended where another cone's surface lies about as near and the projection lies inside that
// cone - the inner side of a bend, tubes crowding a branch node, where a point snapped to one cone or the
// other and neighbouring points folded over each other. Weights exp(-(gap - nearest gap) / (kConeBlend r)),
// r the nearest cone's radius: a rounded crease where two cones meet. On the outer side of a bend (the
// projection outside the other cone) nothing is blended: a chord there would groove the tube at every node.
ConePoint nearestCone(const Eigen::Vector3d& p, const Skeleton& s, Eigen::Vector3d& placed) {
  std::vector<ConePoint> cones;
  size_t nearest = 0;
  for (size_t e = 0; e < s.edges.size(); ++e) {
    cones.push_back(conePoint(p, s, e));
    auto gap = [](const ConePoint& c) { return std::abs(c.distance - c.radius); };
    if (cones[e].found && (!cones[nearest].found || gap(cones[e]) < gap(cones[nearest]))) nearest = e;
  }
  if (cones.empty() || !cones[nearest].found) return {};
  const ConePoint& best = cones[nearest];
  const Eigen::Vector3d onBest = best.onSurface();
  const double bestGap = std::abs(best.distance - best.radius), sigma = kConeBlend * best.radius;
  Eigen::Vector3d sum = onBest;
  double weights = 1;
  for (size_t e = 0; e < cones.size(); ++e) {
    if (e == nearest || !cones[e].found) continue;
    const double w = std::exp(-(std::abs(cones[e].distance - cones[e].radius) - bestGap) / sigma);
    if (w < 1e-6) continue;
    const ConePoint around = conePoint(onBest, s, e);
    if (!around.found || around.distance >= around.radius) continue;  // outside it: the outer side
    sum += w * cones[e].onSurface();
    weights += w;
  }
  placed = sum / weights;
  return best;
}

// Base vertices where two faces sharing an edge fold to an acute angle (normals > 90 degrees apart).
std::vector<Eigen::Vector3d> sharpVertices(PolyMesh& poly) {
  poly.request_face_normals();
  poly.update_face_normals();
  std::vector<bool> sharp(poly.n_vertices(), false);
  for (auto e : poly.edges()) {
    if (poly.is_boundary(e)) continue;
    const auto h = poly.halfedge_handle(e, 0);
    const auto n0 = poly.normal(poly.face_handle(h)),
               n1 = poly.normal(poly.face_handle(poly.opposite_halfedge_handle(h)));
    if (OpenMesh::dot(n0, n1) < 0)
      sharp[size_t(poly.to_vertex_handle(h).idx())] = sharp[size_t(poly.from_vertex_handle(h).idx())] = true;
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

namespace {

// Fold repair (beyond the paper): the projection onto the cones can fold the refined surface where
// cones of different edges crowd (a thin tube leaving a flat ellipsoid, a right-angle bend), while the
// plain Catmull-Clark points of a base mesh that does not cut itself hardly ever do. Each vertex of a
// face that cuts another goes back halfway from its projection towards its Catmull-Clark point, as often
// as needed (at most kFoldRepairSteps times, then all the way); every other vertex stays on its cone.
constexpr int kFoldRepairSteps = 6;

int repairFolds(PolyMesh& poly, const std::vector<Eigen::Vector3d>& smooth,
                const std::vector<Eigen::Vector3d>& projected) {
  std::vector<std::vector<int>> faces;
  for (auto f : poly.faces()) {
    faces.emplace_back();
    for (auto v : poly.fv_range(f)) faces.back().push_back(v.idx());
  }
  std::vector<Eigen::Vector3d> points = projected;
  std::vector<double> weight(points.size(), 1.0);  // 1: on the cone, 0: the Catmull-Clark point
  int moved = 0;
  for (int step = 0; step <= kFoldRepairSteps; ++step) {
    const auto pairs = selfIntersectingFaces(points, faces);
    if (pairs.empty()) break;
    std::vector<bool> folded(points.size(), false);
    for (const auto& [a, b] : pairs)
      for (int f : {a, b})
        for (int v : faces[size_t(f)]) folded[size_t(v)] = true;
    for (size_t v = 0; v < points.size(); ++v) {
      if (!folded[v]) continue;
      moved += weight[v] == 1.0;
      weight[v] = step < kFoldRepairSteps ? 0.5 * weight[v] : 0.0;
      points[v] = smooth[v] + weight[v] * (projected[v] - smooth[v]);
    }
  }
  for (auto v : poly.vertices()) {
    const Eigen::Vector3d& p = points[size_t(v.idx())];
    poly.set_point(v, PolyMesh::Point(p.x(), p.y(), p.z()));
  }
  return moved;
}

}  // namespace

int refineSqmMesh(SqmMesh& mesh, const Skeleton& skeleton, int levels, const SharpScaling& scaling,
                  bool foldRepair, int* repairedVertices) {
  if (levels <= 0 || mesh.faces.empty()) return 0;
  PolyMesh poly;
  std::vector<PolyMesh::VertexHandle> handles;
  for (const auto& v : mesh.vertices)
    handles.push_back(poly.add_vertex(PolyMesh::Point(v.x(), v.y(), v.z())));
  for (const auto& f : mesh.faces) {
    std::vector<PolyMesh::VertexHandle> face;
    for (int v : f) face.push_back(handles[size_t(v)]);
    poly.add_face(face);
  }
  const std::vector<Eigen::Vector3d> sharp =
      scaling.enabled ? sharpVertices(poly) : std::vector<Eigen::Vector3d>{};
  OpenMesh::Subdivider::Uniform::CatmullClarkT<PolyMesh> catmullClark;
  for (int level = 0; level < levels; ++level) {
    catmullClark.attach(poly);
    catmullClark(1);
    catmullClark.detach();
    std::vector<Eigen::Vector3d> smooth, projected;
    for (auto v : poly.vertices()) {
      const Eigen::Vector3d p = toEigen(poly.point(v));
      smooth.push_back(p);
      Eigen::Vector3d q;
      const ConePoint cone = nearestCone(p, skeleton, q);
      if (!cone.found)
        q = p;
      else if (!sharp.empty())  // the paper's scaling, on the nearest cone
        q = cone.axis +
            cone.radius * sharpScaleFactor(distanceToNearest(p, sharp) / cone.radius, scaling.minimumScale) *
                cone.radial;
      projected.push_back(q);
      poly.set_point(v, PolyMesh::Point(q.x(), q.y(), q.z()));
    }
    if (foldRepair) {
      const int moved = repairFolds(poly, smooth, projected);
      if (repairedVertices) *repairedVertices += moved;
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
