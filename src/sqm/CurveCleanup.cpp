#include "sqm/CurveCleanup.h"

#include "sqm/BranchNodePolyhedron.h"  // BnpMesh: OpenMesh's triangle mesh with double points
#include "common/UnionFind.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <unordered_map>

namespace medial {

namespace {

using Mesh = BnpMesh;
using VH = OpenMesh::VertexHandle;
using HH = OpenMesh::HalfedgeHandle;
using EH = OpenMesh::EdgeHandle;
using FH = OpenMesh::FaceHandle;

// A curve edge shorter than this fraction of the median edge around its ends is collapsed.
constexpr double kShortCurveEdge = 0.5;
constexpr int kPasses = 6;
// A polygon's corner nearer than this fraction of the median edge around to a curve vertex is moved onto it.
constexpr double kSnapCorner = 0.3;
// A curve vertex is removed only where its curve turns by less than this (degrees).
constexpr double kStraightCurve = 30;

Eigen::Vector3d at(const Mesh& m, VH v) {
  const auto& p = m.point(v);
  return {p[0], p[1], p[2]};
}

Eigen::Vector3d normalOf(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return (b - a).cross(c - a);
}

struct BandMesh {
  Mesh mesh;
  OpenMesh::FPropHandleT<int> polygon;  // the whole polygon a triangle came from; -1 a cut triangle
  OpenMesh::EPropHandleT<bool> curve;
  OpenMesh::VPropHandleT<bool> fixed;  // a vertex of a whole polygon: moves only onto a curve (snapped)
  OpenMesh::VPropHandleT<bool>
      frozen;                         // never removed, never a collapse's target, no edge flipped next to it
  OpenMesh::VPropHandleT<int> index;  // into points
  std::vector<Eigen::Vector3d> points;  // the input's vertices, then those split onto curve edges
  std::vector<int> nodes, origin;       // their skeleton node; the input vertex they come from
  std::vector<int> mergedInto;          // vertex -> the vertex it was collapsed into, or -1
};

// Moving `from` to `target` keeps every triangle around `from` that does not touch `removed` (they go
// with the collapse) the same way round and not flat.
bool moveKeepsOrientation(const Mesh& m, VH from, const Eigen::Vector3d& target, VH removed) {
  for (const FH f : m.vf_range(from)) {
    Eigen::Vector3d before[3], after[3];
    int k = 0;
    bool touches = false;
    for (const VH v : m.fv_range(f)) {
      before[k] = at(m, v);
      after[k] = v == from ? target : at(m, v);
      touches |= v == removed;
      ++k;
    }
    if (touches) continue;
    const Eigen::Vector3d n0 = normalOf(before[0], before[1], before[2]),
                          n1 = normalOf(after[0], after[1], after[2]);
    if (n0.dot(n1) <= 0.2 * n0.norm() * n1.norm()) return false;
  }
  return true;
}

bool collapseKeepsOrientation(const Mesh& m, VH from, VH to) {
  return moveKeepsOrientation(m, from, at(m, to), to);
}

double medianAround(const Mesh& m, VH a, VH b) {
  std::vector<double> lengths;
  for (const VH v : {a, b})
    for (const HH h : m.voh_range(v))
      if (m.to_vertex_handle(h) != a && m.to_vertex_handle(h) != b) lengths.push_back(m.calc_edge_length(h));
  if (lengths.empty()) return 0;
  std::nth_element(lengths.begin(), lengths.begin() + long(lengths.size() / 2), lengths.end());
  return lengths[lengths.size() / 2];
}

// Collapses h's from-vertex into its to-vertex, remembering where it went (the whole polygons that named it
// name the survivor).
void collapseRecorded(BandMesh& b, HH h) {
  Mesh& m = b.mesh;
  b.mergedInto[size_t(m.property(b.index, m.from_vertex_handle(h)))] =
      m.property(b.index, m.to_vertex_handle(h));
  m.collapse(h);
}

// A polygon's corner (h's from-vertex) moved onto the curve vertex h points to, a polygon corner from then
// on.
void snapInto(BandMesh& b, HH h) {
  const VH to = b.mesh.to_vertex_handle(h);
  collapseRecorded(b, h);
  b.mesh.property(b.fixed, to) = true;
}

int collapseShortCurveEdges(BandMesh& b) {
  Mesh& m = b.mesh;
  int collapsed = 0;
  for (int pass = 0; pass < kPasses; ++pass) {
    int before = collapsed;
    for (const EH e : m.edges()) {
      if (m.status(e).deleted() || !m.property(b.curve, e)) continue;
      const HH h0 = m.halfedge_handle(e, 0);
      if (m.calc_edge_length(e) >=
          kShortCurveEdge * medianAround(m, m.from_vertex_handle(h0), m.to_vertex_handle(h0)))
        continue;
      for (const HH h : {h0, m.halfedge_handle(e, 1)}) {  // remove h's from-vertex into its to-vertex
        const VH from = m.from_vertex_handle(h), to = m.to_vertex_handle(h);
        if (m.property(b.fixed, from) || m.property(b.frozen, from) || m.property(b.frozen, to)) continue;
        VH other;  // the other end of from's second curve edge: a mid-curve vertex has exactly two
        int curveEdges = 0;
        for (const HH out : m.voh_range(from))
          if (m.property(b.curve, m.edge_handle(out))) {
            ++curveEdges;
            if (m.to_vertex_handle(out) != to) other = m.to_vertex_handle(out);
          }
        if (curveEdges != 2 || !other.is_valid() || !m.is_collapse_ok(h) ||
            !collapseKeepsOrientation(m, from, to))
          continue;
        // Only where the curve runs on nearly straight: a corner of it (two boxes meeting) is its shape.
        const Eigen::Vector3d in = (at(m, from) - at(m, other)).normalized(),
                              out = (at(m, to) - at(m, from)).normalized();
        if (in.dot(out) < std::cos(kStraightCurve * M_PI / 180)) continue;
        collapseRecorded(b, h);
        const HH joined = m.find_halfedge(to, other);  // the curve goes on from `to`
        if (joined.is_valid()) m.property(b.curve, m.edge_handle(joined)) = true;
        ++collapsed;
        break;
      }
    }
    if (collapsed == before) break;
  }
  return collapsed;
}

bool onCurve(const BandMesh& b, VH v) {
  for (const HH h : b.mesh.voh_range(v))
    if (b.mesh.property(b.curve, b.mesh.edge_handle(h))) return true;
  return false;
}

// A whole polygon's corner lying just beside a curve vertex (the curve passes near a ring of the tube:
// a needle between them that no flip removes) is moved onto that vertex: the edge between them, with
// cut triangles on both sides, collapses into the curve vertex, which is a polygon corner from then on.
int snapCornersOntoCurves(BandMesh& b) {
  Mesh& m = b.mesh;
  int snapped = 0;
  for (const EH e : m.edges()) {
    if (m.status(e).deleted() || m.property(b.curve, e)) continue;
    for (const HH h : {m.halfedge_handle(e, 0), m.halfedge_handle(e, 1)}) {
      const VH from = m.from_vertex_handle(h), to = m.to_vertex_handle(h);
      if (!m.property(b.fixed, from) || m.property(b.fixed, to) || m.property(b.frozen, from) ||
          m.property(b.frozen, to) || !onCurve(b, to))
        continue;
      const FH left = m.face_handle(h), right = m.face_handle(m.opposite_halfedge_handle(h));
      if (!left.is_valid() || !right.is_valid() || m.property(b.polygon, left) >= 0 ||
          m.property(b.polygon, right) >= 0)
        continue;
      if (m.calc_edge_length(e) >= kSnapCorner * medianAround(m, from, to) || !m.is_collapse_ok(h) ||
          !collapseKeepsOrientation(m, from, to))
        continue;
      snapInto(b, h);
      ++snapped;
      break;
    }
  }
  return snapped;
}

// A whole polygon's corner lying just beside the middle of a curve edge (a cap: the triangle between them
// has an angle near 180 degrees at the corner) is moved onto the curve: the curve edge is split at the
// corner's foot (the new vertex lies on both sheets, so the surface does not change there) and the corner
// collapses into it.
int snapCornersOntoCurveEdges(BandMesh& b) {
  Mesh& m = b.mesh;
  int snapped = 0;
  const size_t faceCount = m.n_faces();
  for (size_t fi = 0; fi < faceCount; ++fi) {
    const FH f = m.face_handle(int(fi));
    if (m.status(f).deleted() || m.property(b.polygon, f) >= 0) continue;
    for (const HH h : m.fh_range(f)) {  // h: the curve edge; the corner opposite it
      const EH e = m.edge_handle(h);
      const VH corner = m.to_vertex_handle(m.next_halfedge_handle(h));
      const VH c1 = m.from_vertex_handle(h), c2 = m.to_vertex_handle(h);
      if (!m.property(b.curve, e) || !m.property(b.fixed, corner) || m.property(b.frozen, corner) ||
          m.property(b.frozen, c1) || m.property(b.frozen, c2) || m.is_boundary(e) ||
          m.property(b.polygon, m.opposite_face_handle(h)) >= 0)
        continue;
      const Eigen::Vector3d a = at(m, c1), d = at(m, c2) - a, p = at(m, corner);
      const double t = (p - a).dot(d) / d.squaredNorm();
      if (t < 0.2 || t > 0.8) continue;  // near an end the other snap applies
      const Eigen::Vector3d foot = a + t * d;
      if ((p - foot).norm() >= kSnapCorner * medianAround(m, c1, c2) ||
          !moveKeepsOrientation(m, corner, foot, c1))
        continue;
      // The faces around the corner that touch c1 or c2 stay with it (the corner moves along); check them
      // too.
      if (!moveKeepsOrientation(m, corner, foot, c2)) continue;
      const VH w = m.add_vertex(Mesh::Point(foot.x(), foot.y(), foot.z()));
      m.property(b.index, w) = int(b.points.size());
      m.property(b.fixed, w) = false;
      m.property(b.frozen, w) = false;
      b.points.push_back(foot);
      b.nodes.push_back(b.nodes[size_t(m.property(b.index, c1))]);
      b.origin.push_back(b.origin[size_t(m.property(b.index, c1))]);
      b.mergedInto.push_back(-1);
      m.split(e, w);
      for (const HH out : m.voh_range(w)) {
        const VH to = m.to_vertex_handle(out);
        m.property(b.curve, m.edge_handle(out)) = to == c1 || to == c2;
        if (m.face_handle(out).is_valid()) m.property(b.polygon, m.face_handle(out)) = -1;
      }
      const HH toW = m.find_halfedge(corner, w);
      if (toW.is_valid() && m.is_collapse_ok(toW)) {
        snapInto(b, toW);
        ++snapped;
      }
      break;
    }
  }
  return snapped;
}

double angleAt(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d u = a - p, v = b - p;
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

bool isSliver(const Mesh& m, FH f) {
  Eigen::Vector3d p[3];
  int k = 0;
  for (const VH v : m.fv_range(f)) p[k++] = at(m, v);
  double smallest = M_PI;
  for (k = 0; k < 3; ++k) smallest = std::min(smallest, angleAt(p[k], p[(k + 1) % 3], p[(k + 2) % 3]));
  return smallest * 180 / M_PI < kSliverDegrees;
}

// Turns the whole polygon that triangle `f` belongs to into cut triangles.
void dissolvePolygon(BandMesh& b, FH f) {
  Mesh& m = b.mesh;
  const int polygon = m.property(b.polygon, f);
  std::vector<FH> todo{f};
  m.property(b.polygon, f) = -1;
  while (!todo.empty()) {
    const FH t = todo.back();
    todo.pop_back();
    for (const FH n : m.ff_range(t))
      if (m.property(b.polygon, n) == polygon) {
        m.property(b.polygon, n) = -1;
        todo.push_back(n);
      }
  }
}

// Flips edges between two cut triangles (not on a curve) whose opposite angles sum above pi, where the
// flip keeps both triangles the same way round as the pair was.
int delaunayFlips(BandMesh& b) {
  Mesh& m = b.mesh;
  int flipped = 0;
  for (int pass = 0; pass < 4 * kPasses; ++pass) {
    int before = flipped;
    for (const EH e : m.edges()) {
      if (m.status(e).deleted() || m.is_boundary(e) || m.property(b.curve, e)) continue;
      const HH h = m.halfedge_handle(e, 0), g = m.halfedge_handle(e, 1);
      const int ph = m.property(b.polygon, m.face_handle(h)), pg = m.property(b.polygon, m.face_handle(g));
      // An edge of a whole polygon flips only to remove a sliver beside it (a curve vertex that comes
      // near the polygon's side): the polygon then becomes cut triangles.
      if ((ph >= 0 && pg >= 0) || ((ph >= 0 || pg >= 0) && !isSliver(m, m.face_handle(ph >= 0 ? g : h))))
        continue;
      const VH a = m.from_vertex_handle(h), c = m.to_vertex_handle(h);
      const VH p = m.to_vertex_handle(m.next_halfedge_handle(h)),
               q = m.to_vertex_handle(m.next_halfedge_handle(g));
      if (m.property(b.frozen, a) || m.property(b.frozen, c) || m.property(b.frozen, p) ||
          m.property(b.frozen, q))
        continue;
      const Eigen::Vector3d A = at(m, a), C = at(m, c), P = at(m, p), Q = at(m, q);
      if (angleAt(P, A, C) + angleAt(Q, A, C) <= M_PI + 1e-9 || !m.is_flip_ok(e)) continue;
      // The pair's orientation: faces (a, c, p) and (c, a, q); after the flip (p, q, c) and (q, p, a).
      const Eigen::Vector3d n = normalOf(A, C, P) + normalOf(C, A, Q);
      const Eigen::Vector3d n1 = normalOf(P, Q, C), n2 = normalOf(Q, P, A);
      if (n1.dot(n) <= 0.2 * n1.norm() * n.norm() || n2.dot(n) <= 0.2 * n2.norm() * n.norm()) continue;
      if (ph >= 0 || pg >= 0) dissolvePolygon(b, m.face_handle(ph >= 0 ? h : g));
      m.flip(e);
      ++flipped;
    }
    if (flipped == before) break;
  }
  return flipped;
}

// For each corner of each face, which fan of faces around its vertex it belongs to (0 for the first; a
// vertex where sheets touch at a point has more than one fan). Corners of faces sharing an edge at the
// vertex are in one fan.
std::vector<std::vector<int>> fansAtCorners(const SqmMesh& mesh) {
  std::vector<size_t> first(mesh.faces.size() + 1, 0);
  for (size_t f = 0; f < mesh.faces.size(); ++f) first[f + 1] = first[f] + mesh.faces[f].size();
  UnionFind corners(first.back());
  std::unordered_map<uint64_t, int> cornerAtEdge;  // (vertex, neighbour) -> a corner of the vertex there
  const uint64_t count = mesh.vertices.size();
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    const auto& face = mesh.faces[f];
    for (size_t k = 0; k < face.size(); ++k) {
      const uint64_t v = uint64_t(face[k]);
      for (const int w : {face[(k + 1) % face.size()], face[(k + face.size() - 1) % face.size()]}) {
        const auto [at, fresh] = cornerAtEdge.emplace(v * count + uint64_t(w), int(first[f] + k));
        if (!fresh) corners.join(int(first[f] + k), at->second);
      }
    }
  }
  std::vector<std::vector<int>> fans(mesh.faces.size());
  std::unordered_map<uint64_t, int> fanOfRoot;  // (vertex, corner root) -> fan number
  std::vector<int> fanCount(mesh.vertices.size(), 0);
  for (size_t f = 0; f < mesh.faces.size(); ++f)
    for (size_t k = 0; k < mesh.faces[f].size(); ++k) {
      const int v = mesh.faces[f][k];
      const uint64_t key = uint64_t(v) * (first.back() + 1) + uint64_t(corners.find(int(first[f] + k)));
      const auto [at, fresh] = fanOfRoot.emplace(key, fanCount[size_t(v)]);
      if (fresh) ++fanCount[size_t(v)];
      fans[f].push_back(at->second);
    }
  return fans;
}

int countSlivers(const SqmMesh& mesh, const std::vector<char>& band) {
  int slivers = 0;
  for (size_t f = 0; f < mesh.faces.size(); ++f)
    slivers += band[f] && smallestAngle(mesh, f) < kSliverDegrees;
  return slivers;
}

}  // namespace

double smallestAngle(const SqmMesh& mesh, size_t face) {
  const auto& f = mesh.faces[face];
  double smallest = M_PI;
  for (size_t k = 0; k < f.size(); ++k)
    smallest =
        std::min(smallest, angleAt(mesh.vertices[size_t(f[k])], mesh.vertices[size_t(f[(k + 1) % f.size()])],
                                   mesh.vertices[size_t(f[(k + f.size() - 1) % f.size()])]));
  return smallest * 180 / M_PI;
}

CurveCleanup cleanCurveBands(SqmMesh& mesh, const std::vector<char>& band,
                             const std::vector<std::pair<int, int>>& curves, const std::vector<char>& frozen,
                             std::vector<int>* original) {
  CurveCleanup report;
  report.sliversBefore = report.sliversAfter = countSlivers(mesh, band);
  if (std::none_of(band.begin(), band.end(), [](char c) { return c != 0; })) return report;

  BandMesh b;
  Mesh& m = b.mesh;
  m.request_vertex_status();
  m.request_edge_status();
  m.request_face_status();
  m.add_property(b.polygon);
  m.add_property(b.curve);
  m.add_property(b.fixed);
  m.add_property(b.frozen);
  m.add_property(b.index);
  // A vertex where sheets touch at a point gets one OpenMesh vertex per fan of faces around it; the copies
  // are frozen and come back as one vertex.
  const std::vector<std::vector<int>> cornerFans = fansAtCorners(mesh);
  std::vector<std::vector<VH>> handles(mesh.vertices.size());
  const auto handleOf = [&](size_t f, size_t k) {
    const size_t v = size_t(mesh.faces[f][k]);
    const size_t fan = size_t(cornerFans[f][k]);
    while (handles[v].size() <= fan) {
      const Eigen::Vector3d& p = mesh.vertices[v];
      handles[v].push_back(m.add_vertex(Mesh::Point(p.x(), p.y(), p.z())));
      m.property(b.fixed, handles[v].back()) = false;
      m.property(b.index, handles[v].back()) = int(v);
      m.property(b.frozen, handles[v].back()) = fan > 0 || (!frozen.empty() && frozen[v]);
    }
    if (fan > 0) m.property(b.frozen, handles[v][0]) = true;
    return handles[v][fan];
  };
  // OpenMesh reports a face it cannot add on its error stream (none expected once fans are split).
  omerr().disable();
  bool added = true;
  for (size_t f = 0; f < mesh.faces.size() && added; ++f) {
    const auto& face = mesh.faces[f];
    for (size_t k = 1; k + 1 < face.size() && added; ++k) {
      const FH t = m.add_face(handleOf(f, 0), handleOf(f, k), handleOf(f, k + 1));
      added = t.is_valid();
      if (added) m.property(b.polygon, t) = band[f] ? -1 : int(f);
    }
    if (!band[f])
      for (size_t k = 0; k < face.size(); ++k) m.property(b.fixed, handleOf(f, k)) = true;
  }
  omerr().enable();
  if (!added) return report;
  for (const EH e : m.edges()) m.property(b.curve, e) = false;
  for (const auto& [x, y] : curves)
    for (const VH hx : handles[size_t(x)])
      for (const VH hy : handles[size_t(y)]) {
        const HH h = m.find_halfedge(hx, hy);
        if (h.is_valid()) m.property(b.curve, m.edge_handle(h)) = true;
      }

  b.points = mesh.vertices;
  b.nodes = mesh.vertexNode;
  b.origin.resize(mesh.vertices.size());
  std::iota(b.origin.begin(), b.origin.end(), 0);
  b.mergedInto.assign(mesh.vertices.size(), -1);
  report.collapsed = collapseShortCurveEdges(b);
  report.snapped = snapCornersOntoCurves(b) + snapCornersOntoCurveEdges(b);
  report.flipped = delaunayFlips(b);

  // Back to polygons: whole ones as they were, cut triangles as they are now.
  std::vector<int> index(b.points.size(), -1), kept;
  SqmMesh cleaned;
  for (const VH v : m.vertices()) {
    if (m.status(v).deleted()) continue;
    const int source = m.property(b.index, v);
    if (index[size_t(source)] >= 0) continue;  // a second fan's copy
    index[size_t(source)] = int(cleaned.vertices.size());
    cleaned.vertices.push_back(b.points[size_t(source)]);
    cleaned.vertexNode.push_back(b.nodes[size_t(source)]);
    kept.push_back(b.origin[size_t(source)]);
  }
  std::vector<char> cleanedBand, emitted(mesh.faces.size(), 0);
  for (const FH f : m.faces()) {
    if (m.status(f).deleted()) continue;
    const int polygon = m.property(b.polygon, f);
    std::vector<int> corners;
    if (polygon < 0) {
      for (const VH v : m.fv_range(f)) corners.push_back(index[size_t(m.property(b.index, v))]);
    } else if (!emitted[size_t(polygon)]) {
      emitted[size_t(polygon)] = 1;
      for (int v : mesh.faces[size_t(polygon)]) {
        while (b.mergedInto[size_t(v)] >= 0) v = b.mergedInto[size_t(v)];
        corners.push_back(index[size_t(v)]);
      }
    } else {
      continue;
    }
    cleaned.faces.push_back(std::move(corners));
    cleanedBand.push_back(polygon < 0);
  }
  report.sliversAfter = countSlivers(cleaned, cleanedBand);
  mesh = std::move(cleaned);
  if (original) *original = std::move(kept);
  report.applied = true;
  return report;
}

}  // namespace medial
