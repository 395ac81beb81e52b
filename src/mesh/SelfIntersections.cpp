#include "mesh/SelfIntersections.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <iterator>

namespace medial {

template <class Index>
std::vector<std::pair<int, int>> selfIntersectingFaces(const std::vector<Eigen::Vector3d>& vertices,
                                                       const std::vector<std::vector<Index>>& faces) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Surface = CGAL::Surface_mesh<Kernel::Point_3>;
  Surface surface;
  size_t triangleCount = 0;
  for (const auto& f : faces) triangleCount += f.size() >= 2 ? f.size() - 2 : 0;
  surface.reserve(Surface::size_type(std::min(vertices.size(), 3 * triangleCount)),
                  Surface::size_type(3 * triangleCount), Surface::size_type(triangleCount));
  // Only the vertices the faces use (a few faces of a large mesh are tested again and again).
  std::vector<Surface::Vertex_index> handles(vertices.size(), Surface::null_vertex());
  for (const auto& f : faces)
    for (const auto v : f)
      if (handles[size_t(v)] == Surface::null_vertex()) {
        const Eigen::Vector3d& p = vertices[size_t(v)];
        handles[size_t(v)] = surface.add_vertex(Kernel::Point_3(p.x(), p.y(), p.z()));
      }
  // Each triangle remembers its polygon. add_face refuses a triangle that would break the surface's
  // manifold structure (a repeated vertex, an edge used twice in one direction): it is left out.
  auto polygon = surface.add_property_map<Surface::Face_index, int>("f:polygon", -1).first;
  for (size_t f = 0; f < faces.size(); ++f)
    for (size_t k = 1; k + 1 < faces[f].size(); ++k) {
      const auto t = surface.add_face(handles[size_t(faces[f][0])], handles[size_t(faces[f][k])],
                                      handles[size_t(faces[f][k + 1])]);
      if (t != Surface::null_face()) polygon[t] = int(f);
    }
  std::vector<std::pair<Surface::Face_index, Surface::Face_index>> triangles;
  CGAL::Polygon_mesh_processing::self_intersections(surface, std::back_inserter(triangles));
  std::vector<std::pair<int, int>> pairs;
  for (const auto& [a, b] : triangles) {
    const int p = polygon[a], q = polygon[b];
    if (p != q) pairs.emplace_back(std::min(p, q), std::max(p, q));
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

template std::vector<std::pair<int, int>> selfIntersectingFaces(const std::vector<Eigen::Vector3d>&,
                                                                const std::vector<std::vector<int>>&);
template std::vector<std::pair<int, int>> selfIntersectingFaces(const std::vector<Eigen::Vector3d>&,
                                                                const std::vector<std::vector<int64_t>>&);

}  // namespace medial
