#include "sqm/SqmRefinement.h"

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

// Projects p onto the nearest truncated cone of the skeleton's edges (radially from its axis).
Eigen::Vector3d projectOnCones(const Eigen::Vector3d& p, const Skeleton& s) {
  double best = INFINITY;
  Eigen::Vector3d projected = p;
  for (const auto& e : s.edges) {
    const Eigen::Vector3d a = s.nodes[size_t(e[0])], b = s.nodes[size_t(e[1])];
    const Eigen::Vector3d ab = b - a;
    const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
    const Eigen::Vector3d axis = a + t * ab;
    const double radius = (1 - t) * s.radii[size_t(e[0])] + t * s.radii[size_t(e[1])];
    const Eigen::Vector3d radial = p - axis;
    const double distance = radial.norm();
    const double gap = std::abs(distance - radius);
    if (gap < best && distance > 1e-12 * radius) {
      best = gap;
      projected = axis + radius * radial / distance;
    }
  }
  return projected;
}

}  // namespace

void refineSqmMesh(SqmMesh& mesh, const Skeleton& skeleton, int levels) {
  if (levels <= 0 || mesh.faces.empty()) return;
  PolyMesh poly;
  std::vector<PolyMesh::VertexHandle> handles;
  for (const auto& v : mesh.vertices) handles.push_back(poly.add_vertex(PolyMesh::Point(v.x(), v.y(), v.z())));
  for (const auto& f : mesh.faces) {
    std::vector<PolyMesh::VertexHandle> face;
    for (int v : f) face.push_back(handles[size_t(v)]);
    poly.add_face(face);
  }
  OpenMesh::Subdivider::Uniform::CatmullClarkT<PolyMesh> catmullClark;
  for (int level = 0; level < levels; ++level) {
    catmullClark.attach(poly);
    catmullClark(1);
    catmullClark.detach();
    for (auto v : poly.vertices()) {
      const auto& p = poly.point(v);
      const Eigen::Vector3d q = projectOnCones(Eigen::Vector3d(p[0], p[1], p[2]), skeleton);
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
}

}  // namespace medial
