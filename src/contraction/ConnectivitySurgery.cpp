#include "contraction/ConnectivitySurgery.h"

#include "mesh/MeshGeometry.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <queue>

namespace medial {

namespace {

// The degenerate mesh as a simplicial complex that edge collapses edit in place.
class CollapsibleComplex {
 public:
  CollapsibleComplex(const Vertices& positions, const Faces& faces)
      : n_(int(positions.rows())),
        position_(n_),
        alive_(n_, true),
        version_(n_, 0),
        owner_(n_),
        collapsedAt_(n_, 0),
        neighbours_(n_),
        vertexFaces_(n_),
        quadric_(n_, Eigen::Matrix4d::Zero()),
        ring_(n_, 0),
        ringVersion_(n_, 0),
        ringKnown_(n_, false) {
    for (int i = 0; i < n_; ++i) {
      position_[i] = positions.row(i).transpose();
      owner_[i] = i;
    }
    faces_.reserve(size_t(faces.rows()));
    for (Eigen::Index f = 0; f < faces.rows(); ++f) {
      const std::array<int, 3> face{faces(f, 0), faces(f, 1), faces(f, 2)};
      if (face[0] == face[1] || face[1] == face[2] || face[0] == face[2]) continue;
      const int id = int(faces_.size());
      faces_.push_back(face);
      faceAlive_.push_back(true);
      for (int c = 0; c < 3; ++c) {
        vertexFaces_[face[c]].push_back(id);
        link(face[c], face[(c + 1) % 3]);
      }
    }
    aliveFaces_ = int(faces_.size());
    // Initial quadrics (7): every vertex sums K^T K over its edges.
    for (int i = 0; i < n_; ++i)
      for (int j : neighbours_[i]) quadric_[i] += edgeQuadric(i, j);
  }

  int vertexCount() const { return n_; }
  // When vertex i was collapsed (1: first, 0: never: a skeleton node).
  int collapsedAt(int i) const { return collapsedAt_[i]; }
  int aliveFaces() const { return aliveFaces_; }
  int initialFaces() const { return int(faces_.size()); }
  bool alive(int i) const { return alive_[i]; }
  unsigned version(int i) const { return version_[i]; }
  const std::vector<int>& neighbours(int i) const { return neighbours_[i]; }
  const Eigen::Vector3d& position(int i) const { return position_[i]; }

  bool edgeHasFace(int i, int j) const {
    for (int f : vertexFaces_[i])
      if (faceAlive_[f] && (faces_[f][0] == j || faces_[f][1] == j || faces_[f][2] == j)) return true;
    return false;
  }

  double length(int i, int j) const { return (position_[i] - position_[j]).norm(); }

  // Total cost (10) of collapsing i into j.
  double cost(int i, int j, double shapeWeight, double samplingWeight) const {
    const Eigen::Vector4d p(position_[j].x(), position_[j].y(), position_[j].z(), 1.0);
    const double shape = p.dot((quadric_[i] + quadric_[j]) * p);  // (8) at the kept position
    const double sampling = length(i, j) * ringLength(i);         // (9)
    return shapeWeight * shape + samplingWeight * sampling;
  }

  // The summed length of i's edges, cached until i's neighbourhood changes (its version): each collapse
  // re-ranks every edge around the vertices it touched, and each ranking needs this sum.
  double ringLength(int i) const {
    if (ringVersion_[i] != version_[i] || !ringKnown_[i]) {
      double sum = 0;
      for (int k : neighbours_[i]) sum += length(i, k);
      ring_[i] = sum;
      ringVersion_[i] = version_[i];
      ringKnown_[i] = true;
    }
    return ring_[i];
  }

  // Collapses i into j; j and i's other neighbours change (their version grows).
  void collapse(int i, int j) {
    for (int f : vertexFaces_[i]) {
      if (!faceAlive_[f]) continue;
      auto& face = faces_[f];
      if (face[0] == j || face[1] == j || face[2] == j) {
        faceAlive_[f] = false;
        --aliveFaces_;
      } else {
        std::replace(face.begin(), face.end(), i, j);
        vertexFaces_[j].push_back(f);
      }
    }
    std::vector<int> touched{j};
    for (int k : neighbours_[i]) {
      if (k == j) continue;
      unlinkOneWay(k, i);
      link(j, k);
      touched.push_back(k);
    }
    unlinkOneWay(j, i);
    quadric_[j] += quadric_[i];
    owner_[i] = j;
    collapsedAt_[i] = ++collapses_;
    alive_[i] = false;
    neighbours_[i].clear();
    vertexFaces_[i].clear();
    compactFaces(j);
    for (int v : touched) ++version_[v];
  }

  // The node that finally holds vertex i (following the collapse chain).
  int finalOwner(int i) {
    int root = i;
    while (owner_[root] != root) root = owner_[root];
    while (owner_[i] != root) {
      const int next = owner_[i];
      owner_[i] = root;
      i = next;
    }
    return root;
  }

 private:
  // K_ij^T K_ij of (6): squared distance to the line through the edge.
  Eigen::Matrix4d edgeQuadric(int i, int j) const {
    Eigen::Vector3d a = position_[j] - position_[i];
    const double len = a.norm();
    if (!(len > 0)) return Eigen::Matrix4d::Zero();
    a /= len;
    const Eigen::Vector3d b = a.cross(position_[i]);
    Eigen::Matrix<double, 3, 4> k;
    k << 0, -a.z(), a.y(), -b.x(),  //
        a.z(), 0, -a.x(), -b.y(),   //
        -a.y(), a.x(), 0, -b.z();
    return k.transpose() * k;
  }

  void link(int i, int j) {
    if (std::find(neighbours_[i].begin(), neighbours_[i].end(), j) == neighbours_[i].end()) {
      neighbours_[i].push_back(j);
      neighbours_[j].push_back(i);
    }
  }
  void unlinkOneWay(int from, int to) {
    auto& list = neighbours_[from];
    list.erase(std::remove(list.begin(), list.end(), to), list.end());
  }
  void compactFaces(int j) {
    auto& list = vertexFaces_[j];
    list.erase(std::remove_if(list.begin(), list.end(), [&](int f) { return !faceAlive_[f]; }), list.end());
  }

  int n_;
  std::vector<Eigen::Vector3d> position_;
  std::vector<bool> alive_;
  std::vector<unsigned> version_;
  std::vector<int> owner_;
  std::vector<int> collapsedAt_;
  int collapses_ = 0;
  std::vector<std::vector<int>> neighbours_;
  std::vector<std::vector<int>> vertexFaces_;
  std::vector<Eigen::Matrix4d> quadric_;
  mutable std::vector<double> ring_;
  mutable std::vector<unsigned> ringVersion_;
  mutable std::vector<bool> ringKnown_;
  std::vector<std::array<int, 3>> faces_;
  std::vector<bool> faceAlive_;
  int aliveFaces_ = 0;
};

// A vertex's cheapest collapse. The queue holds one per vertex: `stamp` tells whether it is still the
// vertex's latest ranking (an edge per entry, as before, pushed ~20 entries per collapse: at 104k vertices
// ten million entries whose sifting was most of the surgery's time).
struct Candidate {
  double key;
  int from, to;
  unsigned stamp;
  bool operator>(const Candidate& other) const { return key > other.key; }
};
using CandidateQueue = std::priority_queue<Candidate, std::vector<Candidate>, std::greater<Candidate>>;

// Runs collapses from a queue until it empties or no face is left; key(i, j) ranks collapsing i into j,
// orient(candidate) may turn the popped edge round (from <-> to) before it collapses, accept(candidate)
// may reject it (and stops the pass when it returns false). A collapse of i into j changes the keys of
// edges out of the vertices it touched (their rings and faces changed) and into j (its quadric grew):
// j and its neighbours are ranked again.
template <class Key, class Orient, class Accept>
int runCollapses(CollapsibleComplex& complex, Key key, Orient orient, Accept accept,
                 const std::function<bool(double)>& progress, bool& aborted) {
  CandidateQueue queue;
  std::vector<unsigned> stamp(size_t(complex.vertexCount()), 0);
  std::vector<int> rankedAt(size_t(complex.vertexCount()), -1);
  int collapses = 0;
  const auto rank = [&](int v) {
    if (rankedAt[size_t(v)] == collapses) return;
    rankedAt[size_t(v)] = collapses;
    ++stamp[size_t(v)];
    double best = INFINITY;
    int to = -1;
    for (int k : complex.neighbours(v)) {
      if (!complex.edgeHasFace(v, k)) continue;
      const double c = key(v, k);
      if (c < best) {
        best = c;
        to = k;
      }
    }
    if (to >= 0) queue.push({best, v, to, stamp[size_t(v)]});
  };
  for (int v = 0; v < complex.vertexCount(); ++v) rank(v);

  while (!queue.empty() && complex.aliveFaces() > 0) {
    Candidate c = queue.top();
    queue.pop();
    if (!complex.alive(c.from) || stamp[size_t(c.from)] != c.stamp) continue;
    if (!complex.alive(c.to) || !complex.edgeHasFace(c.from, c.to)) {  // not expected: rank it afresh
      rankedAt[size_t(c.from)] = -1;
      rank(c.from);
      continue;
    }
    if (!accept(c)) break;
    orient(c);
    complex.collapse(c.from, c.to);
    ++collapses;
    rank(c.to);
    for (int k : complex.neighbours(c.to)) rank(k);
    if (collapses % 2048 == 0 && progress &&
        !progress(1.0 - double(complex.aliveFaces()) / std::max(1, complex.initialFaces()))) {
      aborted = true;
      break;
    }
  }
  return collapses;
}

}  // namespace

CurveSkeleton collapseToCurveSkeleton(const Vertices& contracted, const Faces& faces,
                                      const SurgeryParameters& p,
                                      const std::function<bool(double)>& progress) {
  CurveSkeleton skeleton;
  CollapsibleComplex complex(contracted, faces);
  bool aborted = false;

  // 1. Pre-pass: shortest edges first while they are shorter than delta; the direction of each collapse
  //    follows the total cost so that the quadrics stay meaningful (chosen when the edge comes up).
  const double delta = p.deltaFraction * boundingBoxDiagonal(contracted);
  auto total = [&](int i, int j) { return complex.cost(i, j, p.shapeWeight, p.samplingWeight); };
  skeleton.prePassCollapses = runCollapses(
      complex, [&](int i, int j) { return complex.length(i, j); },
      [&](Candidate& c) {
        if (total(c.to, c.from) < total(c.from, c.to)) std::swap(c.from, c.to);
      },
      [&](const Candidate& c) { return c.key <= delta; }, progress, aborted);

  // 2. Cost-ranked collapses until no triangle is left.
  if (!aborted)
    skeleton.costCollapses = runCollapses(
        complex, total, [](Candidate&) {}, [](const Candidate&) { return true; }, progress, aborted);
  if (aborted) return {};
  skeleton.remainingFaces = complex.aliveFaces();

  std::vector<int> nodeOf(size_t(complex.vertexCount()), -1);
  std::vector<Eigen::Vector3d> nodes;
  for (int v = 0; v < complex.vertexCount(); ++v)
    if (complex.alive(v) && !complex.neighbours(v).empty()) {
      nodeOf[size_t(v)] = int(nodes.size());
      nodes.push_back(complex.position(v));
    }
  // A piece that collapsed to a single point becomes an isolated node; vertices no face used are ignored.
  std::vector<bool> used(size_t(complex.vertexCount()), false);
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int c = 0; c < 3; ++c) used[size_t(faces(f, c))] = true;
  for (int v = 0; v < complex.vertexCount(); ++v)
    if (complex.alive(v) && complex.neighbours(v).empty() && used[size_t(v)]) {
      nodeOf[size_t(v)] = int(nodes.size());
      nodes.push_back(complex.position(v));
    }
  skeleton.nodes.resize(Eigen::Index(nodes.size()), 3);
  for (size_t k = 0; k < nodes.size(); ++k) skeleton.nodes.row(Eigen::Index(k)) = nodes[k].transpose();
  for (int v = 0; v < complex.vertexCount(); ++v)
    if (complex.alive(v))
      for (int k : complex.neighbours(v))
        if (v < k) skeleton.edges.emplace_back(nodeOf[size_t(v)], nodeOf[size_t(k)]);
  skeleton.collapseOrder.resize(size_t(complex.vertexCount()));
  for (int v = 0; v < complex.vertexCount(); ++v) skeleton.collapseOrder[size_t(v)] = complex.collapsedAt(v);
  skeleton.vertexToNode.resize(size_t(complex.vertexCount()));
  for (int v = 0; v < complex.vertexCount(); ++v)
    skeleton.vertexToNode[size_t(v)] = used[size_t(v)] ? nodeOf[size_t(complex.finalOwner(v))] : -1;
  return skeleton;
}

}  // namespace medial
