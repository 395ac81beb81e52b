#include "sqm/SqmUnion.h"

#include "mesh/InsideTest.h"
#include "mesh/MeshTopology.h"
#include "mesh/SelfIntersections.h"
#include "common/Parallel.h"
#include "common/Stopwatch.h"
#include "common/UnionFind.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <Eigen/Geometry>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <numeric>
#include <set>

namespace medial {

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Exact = CGAL::Exact_predicates_exact_constructions_kernel;
using Surface = CGAL::Surface_mesh<Exact::Point_3>;
using Face = Surface::Face_index;
using Vertex = Surface::Vertex_index;

// Marks every triangle the autorefinement cuts, and gives each piece the polygon of the triangle it came
// from. CGAL copies the visitor: the state is shared.
struct CutTracker : PMP::Corefinement::Default_visitor<Surface> {
  Surface::Property_map<Face, int> polygon;
  Surface::Property_map<Face, bool> cut;
  std::shared_ptr<int> current = std::make_shared<int>(-1);
  void before_subface_creations(Face old, Surface&) {
    *current = polygon[old];
    cut[old] = true;
  }
  void after_subface_created(Face piece, Surface&) {
    polygon[piece] = *current;
    cut[piece] = true;
  }
};

// Drops the closed components that enclose no volume (two sheets kept where tubes just touch) or less
// than `smallestPart`, a cavity or a bubble (pockets left where three tubes meet: 6 cavities of 1e-5 or
// less on the dense tree refined twice, 4 bubbles of 1e-9 from folds refined three times); returns how many.
int dropPockets(std::vector<std::vector<int>>& faces, const std::vector<Eigen::Vector3d>& points, double smallestPart) {
  UnionFind components(points.size());
  for (const auto& f : faces)
    for (size_t k = 1; k < f.size(); ++k) components.join(f[k], f[0]);
  std::map<int, std::pair<double, double>> volumeAndArea;
  for (const auto& f : faces) {
    auto& [volume, area] = volumeAndArea[components.find(f[0])];
    for (size_t k = 1; k + 1 < f.size(); ++k) {
      const Eigen::Vector3d &a = points[size_t(f[0])], &b = points[size_t(f[k])], &c = points[size_t(f[k + 1])];
      volume += a.dot(b.cross(c)) / 6;
      area += (b - a).cross(c - a).norm() / 2;
    }
  }
  std::set<int> flat;
  for (const auto& [root, va] : volumeAndArea)
    if (std::abs(va.first) <= 1e-6 * std::pow(va.second, 1.5) || std::abs(va.first) < smallestPart)
      flat.insert(root);
  faces.erase(std::remove_if(faces.begin(), faces.end(), [&](const auto& f) { return flat.count(components.find(f[0])) > 0; }),
              faces.end());
  return int(flat.size());
}

// Where the chosen patches leave edges open (a patch of one tiny triangle between three curves whose test
// points saw the same side, or whose triangles rounded flat: once on the dense tree refined three times), a
// dropped patch all of whose open boundary edges it would close, and no others open, is kept, turned the
// way that closes them.
void closeOpenEdges(const std::vector<std::array<int, 3>>& triangles, const std::vector<int>& patch,
                    std::map<int, int>& sideOf) {
  // Each triangle's edges as (low << 32 | high, +1 for low->high, -1 against), of the kept triangles summed.
  auto edgesOf = [&](size_t t, int sign, std::vector<std::pair<uint64_t, int>>& out) {
    for (int k = 0; k < 3; ++k) {
      const uint64_t a = uint64_t(triangles[t][size_t(k)]), b = uint64_t(triangles[t][size_t((k + 1) % 3)]);
      out.emplace_back(std::min(a, b) << 32 | std::max(a, b), a < b ? sign : -sign);
    }
  };
  std::vector<std::pair<uint64_t, int>> kept;
  std::map<int, std::vector<size_t>> dropped;
  for (size_t t = 0; t < triangles.size(); ++t) {
    const int side = sideOf[patch[t]];
    if (side != 0) edgesOf(t, side, kept);
    else dropped[patch[t]].push_back(t);
  }
  std::sort(kept.begin(), kept.end());
  std::map<uint64_t, int> open;  // edge -> net direction of the kept triangles, where it is not 0
  for (size_t i = 0; i < kept.size();) {
    size_t j = i;
    int net = 0;
    for (; j < kept.size() && kept[j].first == kept[i].first; ++j) net += kept[j].second;
    if (net != 0) open[kept[i].first] = net;
    i = j;
  }
  for (auto& [root, members] : dropped) {
    std::vector<std::pair<uint64_t, int>> edges;
    for (size_t t : members) edgesOf(t, 1, edges);
    std::map<uint64_t, int> own;  // the patch's boundary, as it is (its inner edges cancel)
    for (const auto& [e, c] : edges) own[e] += c;
    bool touchesOpen = false;
    for (const auto& [e, c] : own) touchesOpen |= c != 0 && open.count(e) > 0;
    if (!touchesOpen) continue;
    for (const int sign : {1, -1}) {
      bool closes = true;
      for (const auto& [e, c] : own) {
        const auto found = open.find(e);
        if (c != 0) closes &= (found != open.end() ? found->second : 0) + sign * c == 0;
      }
      if (!closes) continue;
      sideOf[root] = sign;
      for (const auto& [e, c] : own)
        if (c != 0) open.erase(e);
      break;
    }
  }
}

}  // namespace

SqmOverlaps sqmOverlaps(const SqmMesh& mesh) { return sqmOverlaps(mesh, selfIntersectingFaces(mesh.vertices, mesh.faces)); }

SqmOverlaps sqmOverlaps(const SqmMesh& mesh, const std::vector<std::pair<int, int>>& facePairs) {
  SqmOverlaps overlaps;
  overlaps.facePairs = int(facePairs.size());
  std::set<std::pair<int, int>> nodes;
  for (const auto& [a, b] : facePairs) {
    const int p = mesh.faceNode(size_t(a)), q = mesh.faceNode(size_t(b));
    nodes.emplace(std::min(p, q), std::max(p, q));
  }
  overlaps.nodePairs = int(nodes.size());
  return overlaps;
}

SqmUnionResult unionSqmMesh(SqmMesh& mesh, double smallestPart, const SqmOverlaps* known) {
  SqmUnionResult result;
  result.before = known ? *known : sqmOverlaps(mesh);
  if (result.before.facePairs == 0) return result;

  // The polygons as triangles fanned from their first vertex, each knowing its polygon.
  Surface surface;
  auto source = surface.add_property_map<Vertex, int>("v:source", -1).first;
  std::vector<Vertex> handles;
  handles.reserve(mesh.vertices.size());
  for (size_t v = 0; v < mesh.vertices.size(); ++v) {
    const Eigen::Vector3d& p = mesh.vertices[v];
    handles.push_back(surface.add_vertex(Exact::Point_3(p.x(), p.y(), p.z())));
    source[handles.back()] = int(v);
  }
  CutTracker tracker;
  tracker.polygon = surface.add_property_map<Face, int>("f:polygon", -1).first;
  tracker.cut = surface.add_property_map<Face, bool>("f:cut", false).first;
  for (size_t f = 0; f < mesh.faces.size(); ++f)
    for (size_t k = 1; k + 1 < mesh.faces[f].size(); ++k) {
      const Face t = surface.add_face(handles[size_t(mesh.faces[f][0])], handles[size_t(mesh.faces[f][k])],
                                      handles[size_t(mesh.faces[f][k + 1])]);
      if (t == Surface::null_face()) {
        result.error = "the mesh is not a manifold (polygon " + std::to_string(f) + "): no union";
        return result;
      }
      tracker.polygon[t] = int(f);
    }
  // Every intersection curve becomes edges (marked), no two triangles cut each other any more.
  auto curve = surface.add_property_map<Surface::Edge_index, bool>("e:curve", false).first;
  Stopwatch clock;
  PMP::experimental::autorefine(surface, CGAL::parameters::visitor(tracker).edge_is_constrained_map(curve));
  result.autorefineSeconds = clock.seconds();

  // Doubles, once; a vertex on an intersection curve has no source.
  // (Indices of their own: the surface may hold removed elements.)
  std::vector<int> vertexIndex(surface.number_of_vertices() + surface.number_of_removed_vertices(), -1);
  std::vector<int> triangleIndex(surface.number_of_faces() + surface.number_of_removed_faces(), -1);
  std::vector<Eigen::Vector3d> points;
  std::vector<int> node;
  for (const Vertex v : surface.vertices()) {
    vertexIndex[size_t(v)] = int(points.size());
    const auto& p = surface.point(v);
    points.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    node.push_back(source[v] >= 0 ? mesh.vertexNode[size_t(source[v])] : -2);
  }
  // Curve vertices take the smallest node among their neighbours that have one.
  for (bool changed = true; changed;) {
    changed = false;
    for (const Vertex v : surface.vertices()) {
      int& mine = node[size_t(vertexIndex[size_t(v)])];
      if (mine != -2) continue;
      for (const Vertex u : CGAL::vertices_around_target(surface.halfedge(v), surface)) {
        const int theirs = node[size_t(vertexIndex[size_t(u)])];
        if (theirs != -2 && (mine == -2 || theirs < mine)) mine = theirs;
      }
      changed |= mine != -2;
    }
  }
  // The autorefinement leaves each intersection curve once in each of the two sheets that cross there:
  // vertices at the same point become one (the exact points round to the same doubles).
  std::map<std::array<double, 3>, int> atPoint;
  std::vector<int> merged(points.size());
  for (size_t v = 0; v < points.size(); ++v)
    merged[v] = atPoint.emplace(std::array<double, 3>{points[v].x(), points[v].y(), points[v].z()}, int(v)).first->second;
  for (const Vertex v : surface.vertices()) vertexIndex[size_t(v)] = merged[size_t(vertexIndex[size_t(v)])];
  std::vector<std::array<int, 3>> triangles;
  std::vector<Face> faceOf;
  for (const Face f : surface.faces()) {
    triangleIndex[size_t(f)] = int(triangles.size());
    faceOf.push_back(f);
    std::array<int, 3> t;
    int k = 0;
    for (const Vertex v : CGAL::vertices_around_face(surface.halfedge(f), surface))
      t[size_t(k++)] = vertexIndex[size_t(v)];
    triangles.push_back(t);
  }

  // Patches: triangles joined across edges that are not on an intersection curve. A patch bounds the
  // union where the winding number is >= 1 on one side of it and 0 on the other (tested just off its
  // largest triangle); it is turned over where the solid lies in front of it (a fold's pocket).
  UnionFind patchOf(triangles.size());
  for (const Surface::Edge_index e : surface.edges())
    if (!curve[e])
      patchOf.join(triangleIndex[size_t(surface.face(surface.halfedge(e)))],
                   triangleIndex[size_t(surface.face(surface.opposite(surface.halfedge(e))))]);
  // Each patch votes with its three largest triangles (a sample point next to another sheet may see the
  // wrong side).
  std::map<int, std::vector<int>> largest;  // patch root -> its largest triangles, largest first
  std::vector<double> area(triangles.size());
  std::vector<Eigen::Vector3d> normal(triangles.size());
  for (size_t t = 0; t < triangles.size(); ++t) {
    const auto& [a, b, c] = triangles[t];
    normal[t] = (points[size_t(b)] - points[size_t(a)]).cross(points[size_t(c)] - points[size_t(a)]);
    area[t] = normal[t].norm();
    std::vector<int>& samples = largest[patchOf.find(int(t))];
    samples.insert(std::upper_bound(samples.begin(), samples.end(), int(t),
                                    [&](int x, int y) { return area[size_t(x)] > area[size_t(y)]; }),
                   int(t));
    if (samples.size() > 3) samples.pop_back();
  }
  std::vector<std::pair<int, std::vector<int>>> patches(largest.begin(), largest.end());
  std::vector<int> side(patches.size());  // 1: keep, -1: keep turned over, 0: drop
  TriangleMesh refined;
  refined.vertices.resize(Eigen::Index(points.size()), 3);
  for (size_t v = 0; v < points.size(); ++v) refined.vertices.row(Eigen::Index(v)) = points[v];
  refined.faces.resize(Eigen::Index(triangles.size()), 3);
  for (size_t t = 0; t < triangles.size(); ++t)
    refined.faces.row(Eigen::Index(t)) << triangles[t][0], triangles[t][1], triangles[t][2];
  const InsideTest winding(refined);
  inParallel(patches.size(), [&](size_t k) {  // each patch: six rays through the whole mesh
    std::map<int, int> votes;
    for (const int sample : patches[k].second) {
      const size_t t = size_t(sample);
      if (!(area[t] > 0)) continue;
      const Eigen::Vector3d centre = (points[size_t(triangles[t][0])] + points[size_t(triangles[t][1])] +
                                      points[size_t(triangles[t][2])]) / 3;
      const Eigen::Vector3d offset = 1e-3 * std::sqrt(area[t]) * normal[t].normalized();
      const bool solidBehind = winding.wrapped(centre - offset), solidInFront = winding.wrapped(centre + offset);
      ++votes[solidBehind == solidInFront ? 0 : solidBehind ? 1 : -1];
    }
    side[k] = votes.empty() ? 0
                            : std::max_element(votes.begin(), votes.end(), [](const auto& x, const auto& y) {
                                return x.second < y.second;
                              })->first;
  }, 2);
  std::map<int, int> sideOf;
  for (size_t k = 0; k < patches.size(); ++k) sideOf[patches[k].first] = side[k];
  std::vector<int> patch(triangles.size());
  for (size_t t = 0; t < triangles.size(); ++t) patch[t] = patchOf.find(int(t));
  closeOpenEdges(triangles, patch, sideOf);
  result.selectionSeconds = clock.seconds() - result.autorefineSeconds;

  // Whole polygons back where all their triangles are kept, uncut and the same way round.
  std::vector<int> keptTriangles(mesh.faces.size(), 0), turnedTriangles(mesh.faces.size(), 0);
  std::vector<bool> polygonCut(mesh.faces.size(), false);
  std::vector<int> triangleSide(triangles.size());
  for (size_t t = 0; t < triangles.size(); ++t) {
    const Face f = faceOf[t];
    const size_t p = size_t(tracker.polygon[f]);
    triangleSide[t] = sideOf[patchOf.find(int(t))];
    if (tracker.cut[f]) polygonCut[p] = true;
    else if (triangleSide[t] != 0) ++(triangleSide[t] > 0 ? keptTriangles[p] : turnedTriangles[p]);
  }
  const auto whole = [&](size_t p) {
    const int needed = int(mesh.faces[p].size()) - 2;
    return !polygonCut[p] && (keptTriangles[p] == needed || turnedTriangles[p] == needed);
  };
  SqmMesh united;
  united.vertices = points;
  united.vertexNode.assign(node.begin(), node.end());
  for (int& n : united.vertexNode) n = std::max(n, -1);
  std::vector<bool> emitted(mesh.faces.size(), false);
  for (size_t t = 0; t < triangles.size(); ++t) {
    if (triangleSide[t] == 0) continue;
    const size_t p = size_t(tracker.polygon[faceOf[t]]);
    std::vector<int> polygon;
    if (!whole(p)) {
      polygon.assign(triangles[t].begin(), triangles[t].end());
    } else if (!emitted[p]) {
      emitted[p] = true;
      for (const int v : mesh.faces[p]) polygon.push_back(vertexIndex[size_t(handles[size_t(v)])]);
    } else {
      continue;
    }
    if (triangleSide[t] < 0) std::reverse(polygon.begin(), polygon.end());
    united.faces.push_back(polygon);
  }
  for (size_t p = 0; p < mesh.faces.size(); ++p) {
    if (polygonCut[p]) ++result.cutPolygons;
    else if (keptTriangles[p] + turnedTriangles[p] == 0) ++result.removedPolygons;
    if (!polygonCut[p] && turnedTriangles[p] > 0) ++result.turnedPolygons;
  }

  result.droppedPockets = dropPockets(united.faces, united.vertices, smallestPart);

  // Drop the vertices of removed parts.
  std::vector<int> used(united.vertices.size(), -1);
  SqmMesh compact;
  for (auto& face : united.faces)
    for (int& v : face) {
      if (used[size_t(v)] < 0) {
        used[size_t(v)] = int(compact.vertices.size());
        compact.vertices.push_back(united.vertices[size_t(v)]);
        compact.vertexNode.push_back(united.vertexNode[size_t(v)]);
      }
      v = used[size_t(v)];
    }
  compact.faces = std::move(united.faces);

  std::vector<std::vector<int64_t>> faces64;
  for (const auto& face : compact.faces) faces64.emplace_back(face.begin(), face.end());
  const MeshTopology topology = computeMeshTopology(int64_t(compact.vertices.size()), faces64);
  if (!topology.isClosedManifold()) {
    result.error = "the union is not a closed manifold (" + std::to_string(topology.borderEdges) + " border and " +
                   std::to_string(topology.nonManifoldEdges) + " non-manifold edges): no union";
    return result;
  }
  result.intersectingAfter = int(selfIntersectingFaces(compact.vertices, compact.faces).size());
  mesh = std::move(compact);
  return result;
}

}  // namespace medial
