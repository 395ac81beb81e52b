#include "mesh/MeshUnion.h"

#include "mesh/StableBoxIds.h"  // before CGAL's Polygon_mesh_processing headers

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <map>

namespace medial {

namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Surface = CGAL::Surface_mesh<Kernel::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

using Key = std::array<double, 3>;

bool toSurface(const TriangleMesh& mesh, Surface& surface) {
  std::vector<Surface::Vertex_index> handles;
  handles.reserve(size_t(mesh.vertices.rows()));
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v)
    handles.push_back(
        surface.add_vertex(Kernel::Point_3(mesh.vertices(v, 0), mesh.vertices(v, 1), mesh.vertices(v, 2))));
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f)
    if (surface.add_face(handles[size_t(mesh.faces(f, 0))], handles[size_t(mesh.faces(f, 1))],
                         handles[size_t(mesh.faces(f, 2))]) == Surface::null_face())
      return false;
  return CGAL::is_closed(surface);
}

Key keyOf(const Kernel::Point_3& p) {
  return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
}

}  // namespace

MeshUnionResult meshUnion(const std::vector<TriangleMesh>& parts,
                          const std::function<bool(double)>& progress) {
  MeshUnionResult result;
  // Where each input vertex came from; intersection vertices are found in none.
  std::map<Key, int> labelAt;
  Surface whole;
  for (size_t k = 0; k < parts.size(); ++k) {
    Surface part;
    const std::string name = "part " + std::to_string(k + 1);
    if (!toSurface(parts[k], part)) {
      result.error = name + " is not a closed manifold mesh";
      return result;
    }
    // does_bound_a_volume assumes no self-intersection: test that first.
    if (PMP::does_self_intersect(part) || !PMP::does_bound_a_volume(part)) {
      result.error = name + " bounds no volume (it cuts itself)";
      return result;
    }
    if (!PMP::is_outward_oriented(part)) PMP::reverse_face_orientations(part);
    for (Eigen::Index v = 0; v < parts[k].vertices.rows(); ++v)
      labelAt.emplace(Key{parts[k].vertices(v, 0), parts[k].vertices(v, 1), parts[k].vertices(v, 2)}, int(k));
    if (k == 0) {
      whole = std::move(part);
    } else {
      Surface joined;
      if (!PMP::corefine_and_compute_union(whole, part, joined)) {
        result.error =
            name + " touches the earlier parts along an edge or at a point only: the union is not a manifold";
        return result;
      }
      whole = std::move(joined);
    }
    if (progress && !progress(double(k + 1) / double(parts.size()))) {
      result.error = Error::cancelled();
      return result;
    }
  }

  whole.collect_garbage();
  result.mesh.vertices.resize(Eigen::Index(whole.number_of_vertices()), 3);
  result.vertexLabel.resize(whole.number_of_vertices());
  for (const Surface::Vertex_index v : whole.vertices()) {
    const Key key = keyOf(whole.point(v));
    result.mesh.vertices.row(Eigen::Index(v)) << key[0], key[1], key[2];
    const auto found = labelAt.find(key);
    result.vertexLabel[size_t(v)] = found != labelAt.end() ? found->second : -1;
  }
  // A vertex on an intersection curve: the smallest label among its neighbours from the inputs.
  for (const Surface::Vertex_index v : whole.vertices()) {
    if (result.vertexLabel[size_t(v)] >= 0) continue;
    int label = int(parts.size());
    for (const Surface::Vertex_index u : CGAL::vertices_around_target(whole.halfedge(v), whole))
      if (result.vertexLabel[size_t(u)] >= 0) label = std::min(label, result.vertexLabel[size_t(u)]);
    result.vertexLabel[size_t(v)] = label < int(parts.size()) ? label : 0;
  }
  result.mesh.faces.resize(Eigen::Index(whole.number_of_faces()), 3);
  Eigen::Index row = 0;
  for (const Surface::Face_index f : whole.faces()) {
    int c = 0;
    for (const Surface::Vertex_index v : CGAL::vertices_around_face(whole.halfedge(f), whole))
      result.mesh.faces(row, c++) = int(v);
    ++row;
  }
  return result;
}

}  // namespace medial
