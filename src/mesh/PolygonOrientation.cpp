#include "mesh/PolygonOrientation.h"

#include "common/UnionFind.h"

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Simple_cartesian.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cstdint>
#include <numeric>

namespace medial {

namespace {

// The connected component of each face (vertices joined by faces).
std::vector<int> faceComponents(size_t vertexCount, const std::vector<std::vector<int>>& faces) {
  UnionFind sets(vertexCount);
  for (const auto& f : faces)
    for (size_t k = 1; k < f.size(); ++k) sets.join(f[k], f[0]);
  std::vector<int> component;
  for (const auto& f : faces) component.push_back(f.empty() ? -1 : sets.find(f[0]));
  return component;
}

// True when no directed edge is used twice (the cheap test that spares CGAL's orientation on most meshes).
bool consistentlyOriented(const std::vector<std::vector<int>>& faces) {
  std::vector<uint64_t> directed;
  for (const auto& f : faces)
    for (size_t k = 0; k < f.size(); ++k)
      directed.push_back(uint64_t(uint32_t(f[k])) << 32 | uint32_t(f[(k + 1) % f.size()]));
  std::sort(directed.begin(), directed.end());
  return std::adjacent_find(directed.begin(), directed.end()) == directed.end();
}

}  // namespace

int orientPolygonsOutward(const std::vector<Eigen::Vector3d>& vertices,
                          std::vector<std::vector<int>>& faces) {
  std::vector<std::vector<std::size_t>> polygons;
  for (const auto& f : faces) polygons.emplace_back(f.begin(), f.end());
  if (!consistentlyOriented(faces)) {
    using Point = CGAL::Simple_cartesian<double>::Point_3;
    std::vector<Point> points;
    for (const auto& v : vertices) points.emplace_back(v.x(), v.y(), v.z());
    if (!CGAL::Polygon_mesh_processing::orient_polygon_soup(points, polygons)) return -1;
  }

  // Outward: a component whose signed volume is negative is turned over as a whole.
  const std::vector<int> component = faceComponents(vertices.size(), faces);
  std::vector<double> volume(vertices.size(), 0.0);
  for (size_t f = 0; f < polygons.size(); ++f)
    for (size_t k = 1; k + 1 < polygons[f].size(); ++k)
      volume[size_t(component[f])] +=
          vertices[polygons[f][0]].dot(vertices[polygons[f][k]].cross(vertices[polygons[f][k + 1]]));
  int reversed = 0;
  for (size_t f = 0; f < faces.size(); ++f) {
    if (volume[size_t(component[f])] < 0) std::reverse(polygons[f].begin(), polygons[f].end());
    const bool changed = !std::equal(polygons[f].begin(), polygons[f].end(), faces[f].begin(),
                                     [](std::size_t a, int b) { return a == std::size_t(b); });
    if (changed) {
      reversed += 1;
      faces[f].assign(polygons[f].begin(), polygons[f].end());
    }
  }
  return reversed;
}

}  // namespace medial
