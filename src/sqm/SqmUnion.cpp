#include "sqm/SqmUnion.h"

#include "mesh/FaceIntersections.h"
#include "mesh/InsideTest.h"
#include "mesh/MeshTopology.h"
#include "common/Parallel.h"
#include "common/Stopwatch.h"
#include "common/UnionFind.h"

#include "sqm/UnionCutting.h"

#include <CGAL/boost/graph/helpers.h>
#include <Eigen/Geometry>

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

using Surface = ExactMesh;
using Face = Surface::Face_index;
using Vertex = Surface::Vertex_index;

// Drops the closed components that enclose no volume (two sheets kept where tubes just touch) or less
// than `smallestPart`, a cavity or a bubble (pockets left where three tubes meet: 6 cavities of 1e-5 or
// less on the dense tree refined twice, 4 bubbles of 1e-9 from folds refined three times); returns how many.
int dropPockets(std::vector<std::vector<int>>& faces, std::vector<char>& band,
                const std::vector<Eigen::Vector3d>& points, double smallestPart) {
  UnionFind components(points.size());
  for (const auto& f : faces)
    for (size_t k = 1; k < f.size(); ++k) components.join(f[k], f[0]);
  std::map<int, std::pair<double, double>> volumeAndArea;
  for (const auto& f : faces) {
    auto& [volume, area] = volumeAndArea[components.find(f[0])];
    for (size_t k = 1; k + 1 < f.size(); ++k) {
      const Eigen::Vector3d &a = points[size_t(f[0])], &b = points[size_t(f[k])],
                            &c = points[size_t(f[k + 1])];
      volume += a.dot(b.cross(c)) / 6;
      area += (b - a).cross(c - a).norm() / 2;
    }
  }
  std::set<int> flat;
  for (const auto& [root, va] : volumeAndArea)
    if (std::abs(va.first) <= 1e-6 * std::pow(va.second, 1.5) || std::abs(va.first) < smallestPart)
      flat.insert(root);
  size_t kept = 0;
  for (size_t f = 0; f < faces.size(); ++f)
    if (!flat.count(components.find(faces[f][0]))) {
      if (kept != f) faces[kept] = std::move(faces[f]);  // (a vector moved onto itself is emptied)
      band[kept++] = band[f];
    }
  faces.resize(kept);
  band.resize(kept);
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
    if (side != 0)
      edgesOf(t, side, kept);
    else
      dropped[patch[t]].push_back(t);
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

// Stage 3: the cut surface in doubles, rounded once: its points (one per point: the autorefinement leaves
// each intersection curve once in each of the two sheets that cross there), their skeleton nodes and the
// triangles. (Indices of their own: the surface may hold removed elements.)
struct RoundedSurface {
  std::vector<Eigen::Vector3d> points;
  std::vector<int> node;  // per point; -1 a capsule node
  std::vector<std::array<int, 3>> triangles;
  std::vector<Face> faceOf;                     // per triangle
  std::vector<int> vertexIndex, triangleIndex;  // by the surface's vertex and face index
  std::vector<std::pair<int, int>> curves;      // the intersection curves' edges
};

RoundedSurface roundedSurface(const ExactSurface& exact, const SqmMesh& mesh) {
  const Surface& surface = exact.surface;
  RoundedSurface r;
  r.vertexIndex.assign(surface.number_of_vertices() + surface.number_of_removed_vertices(), -1);
  r.triangleIndex.assign(surface.number_of_faces() + surface.number_of_removed_faces(), -1);
  constexpr int kNone = -2;  // a curve vertex before it takes a neighbour's node
  for (const Vertex v : surface.vertices()) {
    r.vertexIndex[size_t(v)] = int(r.points.size());
    const auto& p = surface.point(v);
    r.points.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    r.node.push_back(exact.source[v] >= 0 ? mesh.vertexNode[size_t(exact.source[v])] : kNone);
  }
  // Curve vertices take the smallest node among their neighbours that have one.
  for (bool changed = true; changed;) {
    changed = false;
    for (const Vertex v : surface.vertices()) {
      int& mine = r.node[size_t(r.vertexIndex[size_t(v)])];
      if (mine != kNone) continue;
      for (const Vertex u : CGAL::vertices_around_target(surface.halfedge(v), surface)) {
        const int theirs = r.node[size_t(r.vertexIndex[size_t(u)])];
        if (theirs != kNone && (mine == kNone || theirs < mine)) mine = theirs;
      }
      changed |= mine != kNone;
    }
  }
  for (int& n : r.node) n = std::max(n, -1);
  // Vertices at the same point become one (the exact points round to the same doubles).
  std::map<std::array<double, 3>, int> atPoint;
  std::vector<int> merged(r.points.size());
  for (size_t v = 0; v < r.points.size(); ++v)
    merged[v] =
        atPoint.emplace(std::array<double, 3>{r.points[v].x(), r.points[v].y(), r.points[v].z()}, int(v))
            .first->second;
  for (const Vertex v : surface.vertices())
    r.vertexIndex[size_t(v)] = merged[size_t(r.vertexIndex[size_t(v)])];
  for (const auto e : surface.edges())
    if (exact.curve[e])
      r.curves.emplace_back(r.vertexIndex[size_t(surface.vertex(e, 0))],
                            r.vertexIndex[size_t(surface.vertex(e, 1))]);
  for (const Face f : surface.faces()) {
    r.triangleIndex[size_t(f)] = int(r.triangles.size());
    r.faceOf.push_back(f);
    std::array<int, 3> t;
    int k = 0;
    for (const Vertex v : CGAL::vertices_around_face(surface.halfedge(f), surface))
      t[size_t(k++)] = r.vertexIndex[size_t(v)];
    r.triangles.push_back(t);
  }
  return r;
}

// Stage 4: the side of each triangle: 1 kept, -1 kept turned over, 0 dropped. Patches are triangles joined
// across edges that are not on an intersection curve; a patch bounds the union where the winding number
// is >= 1 on one side of it and 0 on the other (tested just off its largest triangles); it is turned over
// where the solid lies in front of it (a fold's pocket).
std::vector<int> triangleSides(const ExactSurface& exact, const RoundedSurface& r) {
  const Surface& surface = exact.surface;
  const auto& points = r.points;
  const auto& triangles = r.triangles;
  UnionFind patchOf(triangles.size());
  for (const Surface::Edge_index e : surface.edges())
    if (!exact.curve[e] && !surface.is_border(e))
      patchOf.join(r.triangleIndex[size_t(surface.face(surface.halfedge(e)))],
                   r.triangleIndex[size_t(surface.face(surface.opposite(surface.halfedge(e))))]);
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
  std::vector<int> side(patches.size());
  TriangleMesh refined;
  refined.vertices.resize(Eigen::Index(points.size()), 3);
  for (size_t v = 0; v < points.size(); ++v) refined.vertices.row(Eigen::Index(v)) = points[v];
  refined.faces.resize(Eigen::Index(triangles.size()), 3);
  for (size_t t = 0; t < triangles.size(); ++t)
    refined.faces.row(Eigen::Index(t)) << triangles[t][0], triangles[t][1], triangles[t][2];
  const InsideTest winding(refined);
  inParallel(
      patches.size(),
      [&](size_t k) {  // each patch: six rays through the whole mesh
        std::map<int, int> votes;
        for (const int sample : patches[k].second) {
          const size_t t = size_t(sample);
          if (!(area[t] > 0)) continue;
          const Eigen::Vector3d centre = (points[size_t(triangles[t][0])] + points[size_t(triangles[t][1])] +
                                          points[size_t(triangles[t][2])]) /
                                         3;
          const Eigen::Vector3d offset = 1e-3 * std::sqrt(area[t]) * normal[t].normalized();
          const bool solidBehind = winding.wrapped(centre - offset),
                     solidInFront = winding.wrapped(centre + offset);
          // Two of the (at most) three votes agreeing decide: the third is not cast.
          if (++votes[solidBehind == solidInFront ? 0 : solidBehind ? 1 : -1] == 2) break;
        }
        side[k] = votes.empty()
                      ? 0
                      : std::max_element(votes.begin(), votes.end(), [](const auto& x, const auto& y) {
                          return x.second < y.second;
                        })->first;
      },
      2);
  std::map<int, int> sideOf;
  for (size_t k = 0; k < patches.size(); ++k) sideOf[patches[k].first] = side[k];
  std::vector<int> patch(triangles.size());
  for (size_t t = 0; t < triangles.size(); ++t) patch[t] = patchOf.find(int(t));
  closeOpenEdges(triangles, patch, sideOf);
  std::vector<int> triangleSide(triangles.size());
  for (size_t t = 0; t < triangles.size(); ++t) triangleSide[t] = sideOf[patch[t]];
  return triangleSide;
}

// Stage 5: the kept triangles as polygons: a polygon none of whose triangles was cut comes back whole
// where all its triangles are kept the same way round; the others as triangles, flagged in `band`. Counts
// what was cut, removed and turned in `result`.
SqmMesh keptPolygons(const SqmMesh& mesh, const ExactSurface& exact, const RoundedSurface& r,
                     const std::vector<int>& triangleSide, std::vector<char>& band, SqmUnionResult& result) {
  const CutTracker& tracker = exact.tracker;
  std::vector<int> keptTriangles(mesh.faces.size(), 0), turnedTriangles(mesh.faces.size(), 0);
  std::vector<bool> polygonCut(mesh.faces.size(), false);
  for (size_t t = 0; t < r.triangles.size(); ++t) {
    const Face f = r.faceOf[t];
    const size_t p = size_t(tracker.polygon[f]);
    if (tracker.cut[f])
      polygonCut[p] = true;
    else if (triangleSide[t] != 0)
      ++(triangleSide[t] > 0 ? keptTriangles[p] : turnedTriangles[p]);
  }
  const auto whole = [&](size_t p) {
    const int needed = int(mesh.faces[p].size()) - 2;
    return !polygonCut[p] && (keptTriangles[p] == needed || turnedTriangles[p] == needed);
  };
  SqmMesh united;
  united.vertices = r.points;
  united.vertexNode = r.node;
  std::vector<bool> emitted(mesh.faces.size(), false);
  for (size_t t = 0; t < r.triangles.size(); ++t) {
    if (triangleSide[t] == 0) continue;
    const size_t p = size_t(tracker.polygon[r.faceOf[t]]);
    std::vector<int> polygon;
    if (!whole(p)) {
      polygon.assign(r.triangles[t].begin(), r.triangles[t].end());
    } else if (!emitted[p]) {
      emitted[p] = true;
      for (const int v : mesh.faces[p]) polygon.push_back(r.vertexIndex[size_t(exact.handles[size_t(v)])]);
    } else {
      continue;
    }
    if (triangleSide[t] < 0) std::reverse(polygon.begin(), polygon.end());
    band.push_back(polygon.size() == 3 && !whole(p));
    united.faces.push_back(polygon);
  }
  for (size_t p = 0; p < mesh.faces.size(); ++p) {
    if (polygonCut[p])
      ++result.cutPolygons;
    else if (keptTriangles[p] + turnedTriangles[p] == 0)
      ++result.removedPolygons;
    if (!polygonCut[p] && turnedTriangles[p] > 0) ++result.turnedPolygons;
  }
  return united;
}

MeshTopology topologyOf(const SqmMesh& mesh) {
  std::vector<std::vector<int64_t>> faces;
  faces.reserve(mesh.faces.size());
  for (const auto& face : mesh.faces) faces.emplace_back(face.begin(), face.end());
  return computeMeshTopology(int64_t(mesh.vertices.size()), faces);
}

// The mesh without the vertices no face uses (those of removed parts); `used` maps the old indices to
// the new ones (-1: dropped).
SqmMesh withoutUnusedVertices(SqmMesh united, std::vector<int>& used) {
  used.assign(united.vertices.size(), -1);
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
  return compact;
}

// Stage 6: the cut triangles along the curves cleaned (CurveCleanup), kept where the mesh stays a closed
// manifold that cuts itself no more than before. Where the cleaned mesh cuts itself (a collapse or a flip
// folded a triangle through a nearby sheet: 61 pairs on the dense tree refined twice), the vertices of those
// faces and their neighbours are frozen and the cleanup runs again from the uncleaned mesh, at most
// kCleanupRounds times. The mesh before is tested only when the cleaned one cuts itself at all.
constexpr int kCleanupRounds = 4;

void cleanAlongCurves(SqmMesh& mesh, const std::vector<char>& band,
                      const std::vector<std::pair<int, int>>& curves, SqmUnionResult& result) {
  int pairsBefore = -1;  // the uncleaned mesh's, counted when needed
  const auto uncleanedPairs = [&] {
    if (pairsBefore < 0) pairsBefore = int(intersectingFaces(mesh.vertices, mesh.faces).facePairs.size());
    return pairsBefore;
  };
  std::vector<char> frozen;
  for (int round = 0; round < kCleanupRounds; ++round) {
    SqmMesh cleaned = mesh;
    std::vector<int> original;
    const CurveCleanup cleanup = cleanCurveBands(cleaned, band, curves, frozen, &original);
    if (round == 0) result.cleanup = cleanup;
    if (!cleanup.applied || !topologyOf(cleaned).isClosedManifold()) break;
    const auto pairs = intersectingFaces(cleaned.vertices, cleaned.faces).facePairs;
    if (pairs.empty() || int(pairs.size()) <= uncleanedPairs()) {
      result.cleanup = cleanup;
      result.intersectingAfter = int(pairs.size());
      mesh = std::move(cleaned);
      return;
    }
    if (frozen.empty()) frozen.assign(mesh.vertices.size(), 0);
    for (const auto& [f, g] : pairs)
      for (const int face : {f, g})
        for (const int v : cleaned.faces[size_t(face)]) frozen[size_t(original[size_t(v)])] = 1;
    const std::vector<char> seeds = frozen;  // grown by one ring of the uncleaned mesh
    for (const auto& face : mesh.faces)
      if (std::any_of(face.begin(), face.end(), [&](int v) { return seeds[size_t(v)] != 0; }))
        for (const int v : face) frozen[size_t(v)] = 1;
  }
  result.cleanup.applied = false;
  result.cleanup.sliversAfter = result.cleanup.sliversBefore;
  result.intersectingAfter = uncleanedPairs();
}

}  // namespace

SqmOverlaps sqmOverlaps(const SqmMesh& mesh) {
  const FaceIntersections found = intersectingFaces(mesh.vertices, mesh.faces, size_t(kOverlapCountLimit));
  SqmOverlaps overlaps = sqmOverlaps(mesh, found.facePairs);
  overlaps.complete = found.complete;
  return overlaps;
}

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
  if (known && known->facePairs == 0) {
    result.before = *known;
    return result;
  }
  const std::vector<std::pair<int, int>> cutting = intersectingFaces(mesh.vertices, mesh.faces).facePairs;
  result.before = known ? *known : sqmOverlaps(mesh, cutting);
  if (cutting.empty()) return result;

  // Stages 1 and 2 (UnionCutting): every intersection curve becomes edges (marked), no two triangles cut
  // each other any more.
  Stopwatch clock;
  ExactSurface exact;
  if (!cutAlongIntersections(mesh, cutting, exact, result.error)) return result;
  result.autorefineSeconds = clock.seconds();
  const RoundedSurface rounded = roundedSurface(exact, mesh);
  const std::vector<int> sides = triangleSides(exact, rounded);
  result.selectionSeconds = clock.seconds() - result.autorefineSeconds;

  std::vector<char> band;
  SqmMesh united = keptPolygons(mesh, exact, rounded, sides, band, result);
  result.droppedPockets = dropPockets(united.faces, band, united.vertices, smallestPart);
  std::vector<int> used;
  SqmMesh compact = withoutUnusedVertices(std::move(united), used);
  const MeshTopology topology = topologyOf(compact);
  if (!topology.isClosedManifold()) {
    result.error = "the union is not a closed manifold (" + std::to_string(topology.borderEdges) +
                   " border and " + std::to_string(topology.nonManifoldEdges) +
                   " non-manifold edges): no union";
    return result;
  }
  std::vector<std::pair<int, int>> curves;
  for (const auto& [a, b] : rounded.curves)
    if (used[size_t(a)] >= 0 && used[size_t(b)] >= 0) curves.emplace_back(used[size_t(a)], used[size_t(b)]);
  cleanAlongCurves(compact, band, curves, result);
  mesh = std::move(compact);
  return result;
}

}  // namespace medial
