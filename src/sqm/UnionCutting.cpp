#include "sqm/UnionCutting.h"

#include "common/Parallel.h"
#include "common/UnionFind.h"

#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <map>
#include <numeric>

namespace medial {

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Face = ExactMesh::Face_index;
using Vertex = ExactMesh::Vertex_index;

// CGAL 5.5's autorefine() builds its intersection functor with a constructor that leaves the member
// `const_mesh_ptr` uninitialised (the two-mesh constructor sets it to nullptr). Whatever the stack held
// there decides whether degenerate faces are filtered out of the box intersections and how coplanar
// degenerate pairs are handled: the same mesh gave 42709 or 42701 faces from run to run (the dense tree
// refined twice), and valgrind reported the jump on it. This is autorefine() (corefinement.h) with the member
// set to nullptr before the run, reached through the explicit-instantiation access rule ([temp.spec]:
// access checking does not apply to the names in an explicit instantiation).
using PointMap = boost::property_map<ExactMesh, boost::vertex_point_t>::type;
using CurveMap = ExactMesh::Property_map<ExactMesh::Edge_index, bool>;
using NoOutput = PMP::Corefinement::No_extra_output_from_corefinement<ExactMesh>;
using AutorefineVisitor =
    PMP::Corefinement::Surface_intersection_visitor_for_corefinement<ExactMesh, PointMap, PointMap, NoOutput,
                                                                     CurveMap, CutTracker, true>;
using Autorefinement =
    PMP::Corefinement::Intersection_of_triangle_meshes<ExactMesh, PointMap, PointMap, AutorefineVisitor>;

struct MeshPointerMember {
  using Type = const ExactMesh* Autorefinement::*;
  friend Type memberOf(MeshPointerMember);
};
template <class Tag, typename Tag::Type Member>
struct PrivateMember {
  friend typename Tag::Type memberOf(Tag) { return Member; }
};
template struct PrivateMember<MeshPointerMember, &Autorefinement::const_mesh_ptr>;

void autorefine(ExactSurface& exact) {
  NoOutput noOutput;
  const PointMap points = get(boost::vertex_point, exact.surface);  // the functor keeps a reference to it
  Autorefinement functor(exact.surface, points, AutorefineVisitor(exact.tracker, noOutput, exact.curve));
  functor.*memberOf(MeshPointerMember{}) = nullptr;
  functor(CGAL::Emptyset_iterator(), true);
}

void addProperties(ExactSurface& exact) {
  exact.source = exact.surface.add_property_map<Vertex, int>("v:source", -1).first;
  exact.tracker.polygon = exact.surface.add_property_map<Face, int>("f:polygon", -1).first;
  exact.tracker.cut = exact.surface.add_property_map<Face, bool>("f:cut", false).first;
  exact.curve = exact.surface.add_property_map<ExactMesh::Edge_index, bool>("e:curve", false).first;
}

// Adds polygon `p`'s fan of triangles on the vertices `handles`; false where the surface refuses one (not
// a manifold).
bool addPolygon(const SqmMesh& mesh, size_t p, const std::vector<Vertex>& handles, ExactSurface& exact) {
  const auto& face = mesh.faces[p];
  for (size_t k = 1; k + 1 < face.size(); ++k) {
    const Face t = exact.surface.add_face(handles[size_t(face[0])], handles[size_t(face[k])],
                                          handles[size_t(face[k + 1])]);
    if (t == ExactMesh::null_face()) return false;
    exact.tracker.polygon[t] = int(p);
  }
  return true;
}

const char* const kNotManifold = "the mesh is not a manifold (polygon ";

// The polygons `polygons` of `mesh` as a surface of their own (vertices only those they use).
bool buildPart(const SqmMesh& mesh, const std::vector<int>& polygons, ExactSurface& part,
               std::string& error) {
  addProperties(part);
  part.handles.assign(mesh.vertices.size(), ExactMesh::null_vertex());
  for (const int p : polygons)
    for (const int v : mesh.faces[size_t(p)]) {
      Vertex& handle = part.handles[size_t(v)];
      if (handle != ExactMesh::null_vertex()) continue;
      const Eigen::Vector3d& x = mesh.vertices[size_t(v)];
      handle = part.surface.add_vertex(ExactKernel::Point_3(x.x(), x.y(), x.z()));
      part.source[handle] = v;
    }
  for (const int p : polygons)
    if (!addPolygon(mesh, size_t(p), part.handles, part)) {
      error = kNotManifold + std::to_string(p) + "): no union";
      return false;
    }
  return true;
}

size_t borderHalfedges(const ExactSurface& part) {
  size_t border = 0;
  for (const auto h : part.surface.halfedges()) border += part.surface.is_border(h);
  return border;
}

// True when no cut reached the part's border: as many border halfedges as before, on SQM vertices only.
bool borderUntouched(const ExactSurface& part, size_t borderBefore) {
  if (borderHalfedges(part) != borderBefore) return false;
  for (const auto h : part.surface.halfedges())
    if (part.surface.is_border(h) && part.source[part.surface.target(h)] < 0) return false;
  return true;
}

// The clusters of the cutting region: the polygons of the pairs, grouped by the pairs (each cluster's
// polygons ascending, the clusters by their first polygon). A cluster's border edge cannot be cut: a face
// cutting it would cut the polygon outside the cluster on its other side too, making that a pair of the
// cluster. (Where the rule for faces that share a vertex decides otherwise, the border test catches it.)
std::vector<std::vector<int>> cuttingClusters(const SqmMesh& mesh,
                                              const std::vector<std::pair<int, int>>& cutting) {
  UnionFind sets(mesh.faces.size());
  std::vector<char> inRegion(mesh.faces.size(), 0);
  for (const auto& [a, b] : cutting) {
    sets.join(a, b);
    inRegion[size_t(a)] = inRegion[size_t(b)] = 1;
  }
  std::map<int, size_t> clusterOf;
  std::vector<std::vector<int>> clusters;
  for (size_t p = 0; p < mesh.faces.size(); ++p) {
    if (!inRegion[p]) continue;
    const auto [it, added] = clusterOf.emplace(sets.find(int(p)), clusters.size());
    if (added) clusters.emplace_back();
    clusters[it->second].push_back(int(p));
  }
  return clusters;
}

// Adds a cut part to `whole`: its SQM vertices are whole's, its curve vertices new; false where the
// surface refuses a triangle.
bool addPart(const ExactSurface& part, ExactSurface& whole) {
  std::vector<Vertex> to(part.surface.number_of_vertices() + part.surface.number_of_removed_vertices());
  for (const Vertex v : part.surface.vertices()) {
    const int source = part.source[v];
    if (source >= 0) {
      to[size_t(v)] = whole.handles[size_t(source)];
    } else {
      to[size_t(v)] = whole.surface.add_vertex(part.surface.point(v));
      whole.source[to[size_t(v)]] = -1;
    }
  }
  for (const Face f : part.surface.faces()) {
    std::array<Vertex, 3> corners;
    size_t k = 0;
    for (const Vertex v : CGAL::vertices_around_face(part.surface.halfedge(f), part.surface))
      corners[k++] = to[size_t(v)];
    const Face t = whole.surface.add_face(corners[0], corners[1], corners[2]);
    if (t == ExactMesh::null_face()) return false;
    whole.tracker.polygon[t] = part.tracker.polygon[f];
    whole.tracker.cut[t] = part.tracker.cut[f];
  }
  for (const auto e : part.surface.edges())
    if (part.curve[e]) {
      const auto [h, found] = CGAL::halfedge(to[size_t(part.surface.vertex(e, 0))],
                                             to[size_t(part.surface.vertex(e, 1))], whole.surface);
      if (found) whole.curve[whole.surface.edge(h)] = true;
    }
  return true;
}

bool closedOrError(const ExactSurface& exact, std::string& error) {
  // Winding numbers mean something only for a closed surface.
  if (CGAL::is_closed(exact.surface)) return true;
  error = "the mesh has open edges (no volume to unite): no union";
  return false;
}

// The whole mesh in one surface, every SQM vertex at its handle.
bool buildWhole(const SqmMesh& mesh, const std::vector<char>& skip, ExactSurface& exact, std::string& error) {
  addProperties(exact);
  exact.handles.clear();
  exact.handles.reserve(mesh.vertices.size());
  for (size_t v = 0; v < mesh.vertices.size(); ++v) {
    const Eigen::Vector3d& p = mesh.vertices[v];
    exact.handles.push_back(exact.surface.add_vertex(ExactKernel::Point_3(p.x(), p.y(), p.z())));
    exact.source[exact.handles.back()] = int(v);
  }
  for (size_t p = 0; p < mesh.faces.size(); ++p)
    if ((skip.empty() || !skip[p]) && !addPolygon(mesh, p, exact.handles, exact)) {
      error = kNotManifold + std::to_string(p) + "): no union";
      return false;
    }
  return true;
}

}  // namespace

bool cutAlongIntersections(const SqmMesh& mesh, const std::vector<std::pair<int, int>>& cutting,
                           ExactSurface& exact, std::string& error) {
  const std::vector<std::vector<int>> clusters = cuttingClusters(mesh, cutting);
  std::vector<ExactSurface> parts(clusters.size());
  std::vector<std::string> errors(clusters.size());
  std::vector<char> cutInside(clusters.size(), 0);
  // Largest first, one cluster at a time to whichever core is free; each part's cut depends only on it.
  std::vector<size_t> order(clusters.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return clusters[a].size() > clusters[b].size(); });
  inParallelEach(order.size(), [&](size_t k) {
    const size_t c = order[k];
    if (!buildPart(mesh, clusters[c], parts[c], errors[c])) return;
    const size_t border = borderHalfedges(parts[c]);
    autorefine(parts[c]);
    cutInside[c] = borderUntouched(parts[c], border);
  });
  for (const std::string& e : errors)
    if (!e.empty()) {
      error = e;
      return false;
    }
  if (std::all_of(cutInside.begin(), cutInside.end(), [](char inside) { return inside != 0; })) {
    std::vector<char> inCluster(mesh.faces.size(), 0);
    for (const auto& cluster : clusters)
      for (const int p : cluster) inCluster[size_t(p)] = 1;
    if (!buildWhole(mesh, inCluster, exact, error)) return false;
    for (const ExactSurface& part : parts)
      if (!addPart(part, exact)) {
        error = "the cut mesh is not a manifold: no union";
        return false;
      }
    return closedOrError(exact, error);
  }
  // A cut reached a cluster's border: the whole mesh at once.
  if (!buildWhole(mesh, {}, exact, error) || !closedOrError(exact, error)) return false;
  autorefine(exact);
  return true;
}

}  // namespace medial
