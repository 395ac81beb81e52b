#include "mesh/EdgeCoarsening.h"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <algorithm>
#include <numeric>

namespace medial {

namespace {

struct CoarseningTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
  VertexAttributes(OpenMesh::Attributes::Status);
  EdgeAttributes(OpenMesh::Attributes::Status);
  HalfedgeAttributes(OpenMesh::Attributes::Status);
  FaceAttributes(OpenMesh::Attributes::Status);
};
using Mesh = OpenMesh::TriMesh_ArrayKernelT<CoarseningTraits>;

constexpr double kLengthFactor = 1.5;     // collapse edges shorter than this x the mean edge length
constexpr double kMinNormalCosine = 0.2;  // a triangle may turn by at most acos(0.2), about 78 degrees
constexpr int kMaxPasses = 60;

// Whether moving v to `to` (its edge to `other` collapsing) turns a triangle of v's that survives too far.
bool turnsOver(const Mesh& m, Mesh::VertexHandle v, Mesh::VertexHandle other, const Mesh::Point& to) {
  for (const auto f : m.vf_range(v)) {
    Mesh::Point before[3], after[3];
    int k = 0;
    bool collapses = false;
    for (const auto u : m.fv_range(f)) {
      collapses = collapses || u == other;
      before[k] = m.point(u);
      after[k++] = u == v ? to : m.point(u);
    }
    if (collapses) continue;
    const Mesh::Point n0 = (before[1] - before[0]) % (before[2] - before[0]);
    const Mesh::Point n1 = (after[1] - after[0]) % (after[2] - after[0]);
    if ((n0 | n1) <= kMinNormalCosine * n0.norm() * n1.norm()) return true;
  }
  return false;
}

double meanEdgeLength(const Mesh& m) {
  double sum = 0;
  size_t count = 0;
  for (const auto e : m.edges())
    if (!m.status(e).deleted()) {
      sum += m.calc_edge_length(e);
      ++count;
    }
  return count > 0 ? sum / double(count) : 0;
}

}  // namespace

CoarsenedMesh coarsenEdges(const TriangleMesh& mesh, Eigen::Index targetVertices) {
  CoarsenedMesh result;
  const Eigen::Index n = mesh.vertices.rows();
  Mesh m;
  m.reserve(size_t(n), size_t(3 * mesh.faces.rows() / 2), size_t(mesh.faces.rows()));
  for (Eigen::Index v = 0; v < n; ++v)
    m.add_vertex(Mesh::Point(mesh.vertices(v, 0), mesh.vertices(v, 1), mesh.vertices(v, 2)));
  // OpenMesh reports a face it cannot add on its error stream; here that only means "not a 2-manifold".
  omerr().disable();
  bool manifold = true;
  for (Eigen::Index f = 0; f < mesh.faces.rows() && manifold; ++f) {
    const Mesh::VertexHandle a(mesh.faces(f, 0)), b(mesh.faces(f, 1)), c(mesh.faces(f, 2));
    manifold = a != b && b != c && c != a && m.add_face(a, b, c).is_valid();
  }
  omerr().enable();
  if (!manifold) return result;

  std::vector<int> absorbedBy(static_cast<size_t>(n));
  std::iota(absorbedBy.begin(), absorbedBy.end(), 0);
  Eigen::Index alive = 0;
  for (const auto v : m.vertices()) alive += !m.is_isolated(v);
  std::vector<unsigned char> touched(static_cast<size_t>(n));
  for (int pass = 0; pass < kMaxPasses && alive > targetVertices; ++pass) {
    const double threshold = kLengthFactor * meanEdgeLength(m);
    std::fill(touched.begin(), touched.end(), 0);
    const Eigen::Index before = alive;
    for (const auto e : m.edges()) {
      if (alive <= targetVertices) break;
      if (m.status(e).deleted()) continue;
      const auto h = m.halfedge_handle(e, 0);
      const auto from = m.from_vertex_handle(h), to = m.to_vertex_handle(h);
      if (touched[size_t(from.idx())] || touched[size_t(to.idx())] || m.calc_edge_length(e) > threshold)
        continue;
      if (!m.is_collapse_ok(h)) continue;
      const Mesh::Point middle = 0.5 * (m.point(from) + m.point(to));
      if (turnsOver(m, from, to, middle) || turnsOver(m, to, from, middle)) continue;
      m.set_point(to, middle);
      m.collapse(h);  // `from` goes into `to`
      absorbedBy[size_t(from.idx())] = to.idx();
      touched[size_t(to.idx())] = 1;
      --alive;
    }
    if (alive == before) break;  // nothing left to collapse under the rules
  }

  // Compact numbering of the vertices left, each input vertex's survivor, the faces.
  std::vector<int> compact(static_cast<size_t>(n), -1);
  int kept = 0;
  for (const auto v : m.vertices())
    if (!m.status(v).deleted() && !m.is_isolated(v)) compact[size_t(v.idx())] = kept++;
  result.mesh.vertices.resize(kept, 3);
  for (const auto v : m.vertices())
    if (compact[size_t(v.idx())] >= 0) {
      const Mesh::Point& p = m.point(v);
      result.mesh.vertices.row(compact[size_t(v.idx())]) << p[0], p[1], p[2];
    }
  result.mesh.faces.resize(Eigen::Index(m.n_faces()), 3);
  Eigen::Index row = 0;
  for (const auto f : m.faces()) {
    if (m.status(f).deleted()) continue;
    int c = 0;
    for (const auto v : m.fv_range(f)) result.mesh.faces(row, c++) = compact[size_t(v.idx())];
    ++row;
  }
  result.mesh.faces.conservativeResize(row, 3);
  result.representative.assign(static_cast<size_t>(n), -1);
  for (Eigen::Index v = 0; v < n; ++v) {
    int survivor = int(v);
    while (absorbedBy[size_t(survivor)] != survivor) survivor = absorbedBy[size_t(survivor)];
    result.representative[size_t(v)] = compact[size_t(survivor)];
  }
  result.ok = true;
  return result;
}

}  // namespace medial
