#include "sqm/SqmRefinement.h"

#include "mesh/FaceIntersections.h"
#include "common/Parallel.h"
#include "sqm/FoldPairs.h"
#include "sqm/FoldRepair.h"
#include "sqm/SweptSpheres.h"

#include <Eigen/Geometry>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <numeric>
#include <vector>

namespace medial {

namespace {

namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;

// The width of the blend of projections (nearestSurface), in radii of the nearest surface. Chosen when the
// refinement was Catmull-Clark on truncated cones; refined twice, intersecting pairs of the humanoid / fish /
// figure / octopus before the fold repair: no blend 490 / 15 / 168 / 24; 0.2: 94 / 22
// / 31 / 0; 0.8: 16 / 24 / 14 / 0. (Blending on the outer side of bends as well cut them further, to 23 /
// 0 / 26 / 0 at 0.2, but grooved every tentacle at its nodes and sharpened the octopus's head.)
constexpr double kSurfaceBlend = 0.8;
// A point in a crease is blended again from where the blend put it, this many times: each blend halves
// its remaining depth below the crease (a fillet 0.2 r deep at a right angle after one, 0.05 r after three).
constexpr int kCreaseIterations = 2;

// The edge whose swept surface lies nearest to p among `edges`, and in `placed` where p goes: that
// projection, blended where another edge's surface lies about as near and the projection lies inside
// that edge's volume - the inner side of a bend, tubes crowding a branch node, where a point snapped to
// one surface or the other and neighbouring points folded over each other. Weights exp(-(gap - nearest
// gap) / (kSurfaceBlend r)), r the nearest surface's radius: a rounded crease where two tubes meet. On the
// outer side of a bend (the projection outside the other volume) nothing is blended: a chord there would
// groove the tube at every node.
SweptPoint nearestSurface(const Eigen::Vector3d& p, const SweptSpheres& spheres,
                          const std::vector<int>& edges, Eigen::Vector3d& placed, bool* blended = nullptr,
                          int* edge = nullptr, int* partner = nullptr) {
  static thread_local std::vector<SweptPoint> projections;  // reused: this runs for every refined vertex
  projections.clear();
  size_t nearest = 0;
  auto gap = [](const SweptPoint& c) { return std::abs(c.signedDistance()); };
  // Inside some edge's volume, the surface of the union is that volume's (or beyond): the surfaces of
  // volumes the point lies outside of are not candidates then (a leaf's fan apex at the centre of a head
  // larger than the neck went to the neck's sphere, which was nearer, and the head was lost).
  bool inside = false;
  for (int e : edges) {
    projections.push_back(spheres.project(p, e));
    inside |= projections.back().signedDistance() < 0;
  }
  auto candidate = [&](const SweptPoint& c) { return c.found && (!inside || c.signedDistance() < 0); };
  for (size_t k = 0; k < projections.size(); ++k)
    if (candidate(projections[k]) &&
        (!candidate(projections[nearest]) || gap(projections[k]) < gap(projections[nearest])))
      nearest = k;
  if (projections.empty() || !candidate(projections[nearest])) return {};
  const SweptPoint& best = projections[nearest];
  if (edge) *edge = edges[nearest];
  const Eigen::Vector3d onBest = best.onSurface();
  const double sigma = kSurfaceBlend * best.radius;
  Eigen::Vector3d sum = onBest;
  double weights = 1, strongest = 0;
  // Where p lies outside edge k's volume by more than its gap to the nearest surface, the point there is
  // outside k's volume too (one edge's volume is convex: its signed distance changes no faster than the
  // point moves); no need to project it (most candidates are such: 5.8 of 6.8 on the octopus).
  const bool exactDistances = spheres.skeleton().ellipsoidAxes.empty();
  for (size_t k = 0; k < projections.size(); ++k) {
    if (k == nearest || !projections[k].found) continue;
    if (exactDistances && projections[k].signedDistance() > gap(best)) continue;
    const double w = std::exp(-(gap(projections[k]) - gap(best)) / sigma);
    if (w < 1e-6) continue;
    const SweptPoint around = spheres.project(onBest, edges[k]);
    if (!around.found || around.distance >= around.radius) continue;  // outside it: the outer side
    sum += w * projections[k].onSurface();
    weights += w;
    if (partner && w > strongest) {
      strongest = w;
      *partner = edges[k];
    }
  }
  placed = sum / weights;
  if (blended) *blended = weights > 1;
  return best;
}

Eigen::Vector3d newellNormal(const SqmMesh& mesh, const std::vector<int>& face) {
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  for (size_t k = 0; k < face.size(); ++k)
    n += mesh.vertices[size_t(face[k])].cross(mesh.vertices[size_t(face[(k + 1) % face.size()])]);
  return n;
}

// Base vertices where two faces sharing an edge fold to an acute angle (normals > 90 degrees apart).
std::vector<Eigen::Vector3d> sharpVertices(const SqmMesh& mesh) {
  std::map<std::pair<int, int>, Eigen::Vector3d> firstNormal;
  std::vector<bool> sharp(mesh.vertices.size(), false);
  for (const auto& f : mesh.faces) {
    const Eigen::Vector3d n = newellNormal(mesh, f);
    for (size_t k = 0; k < f.size(); ++k) {
      const int a = f[k], b = f[(k + 1) % f.size()];
      const auto key = std::minmax(a, b);
      const auto [it, inserted] = firstNormal.emplace(key, n);
      if (!inserted && it->second.dot(n) < 0) sharp[size_t(a)] = sharp[size_t(b)] = true;
    }
  }
  std::vector<Eigen::Vector3d> points;
  for (size_t v = 0; v < sharp.size(); ++v)
    if (sharp[v]) points.push_back(mesh.vertices[v]);
  return points;
}

double distanceToNearest(const Eigen::Vector3d& p, const std::vector<Eigen::Vector3d>& points) {
  double best = INFINITY;
  for (const auto& q : points) best = std::min(best, (q - p).squaredNorm());
  return std::sqrt(best);
}

}  // namespace

double sharpScaleFactor(double t, double s) {
  t = std::clamp(t, 0.0, 1.0);
  const double u = 1 - t;
  return s * u * u * u + 3 * s * t * u * u + 3 * t * t * u + t * t * t;
}

namespace {

// Rings of faces around the faces that can fold, tested with them (the other face of a fold).
constexpr int kCandidateRings = 1;

// Two edges meeting at a node at less than kGentleBend degrees: their swept surfaces join smoothly there.
constexpr double kGentleBend = 30;
bool gentleBend(const Skeleton& skeleton, int e, int g) {
  const auto &a = skeleton.edges[size_t(e)], &b = skeleton.edges[size_t(g)];
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      if (a[size_t(i)] == b[size_t(j)]) {
        const Eigen::Vector3d& shared = skeleton.nodes[size_t(a[size_t(i)])];
        const Eigen::Vector3d in = (shared - skeleton.nodes[size_t(a[size_t(1 - i)])]).normalized();
        const Eigen::Vector3d out = (skeleton.nodes[size_t(b[size_t(1 - j)])] - shared).normalized();
        return in.dot(out) > std::cos(kGentleBend * M_PI / 180);
      }
  return false;
}

// The faces of a refined level that can fold at all, and a ring of faces around them: faces whose vertices
// went onto the surfaces of different edges (where two swept surfaces meet: the figure refined four times
// folded at the inner side of a bend, between faces on the surfaces of two edges sharing a node) or into a
// crease (not the inner side of a gentle bend), and faces turned by the projection by more than a right
// angle from their place on the base mesh. Elsewhere every vertex of a face went onto one smooth swept
// surface, along its normal, from a base mesh that does not fold: nothing there can fold (tubes of other
// parts may cut it: those overlaps are counted on the final mesh, sqmOverlaps). Once folds are found, the
// tests cover every face (FoldRepair).
std::vector<int> foldCandidates(const std::vector<std::vector<int>>& faces,
                                const std::vector<Eigen::Vector3d>& flat,
                                const std::vector<Eigen::Vector3d>& projected,
                                const std::vector<int>& chosenEdge, const std::vector<char>& blended,
                                const Skeleton& skeleton) {
  // Two edges' surfaces meet smoothly where the edges share a node (both hold its sphere) at a gentle bend.
  auto smoothlyJoined = [&](int a, int b) {
    if (a == b) return true;
    return a >= 0 && b >= 0 && gentleBend(skeleton, a, b);
  };
  auto normal = [](const std::vector<Eigen::Vector3d>& points, const std::vector<int>& f) {
    return (points[size_t(f[2])] - points[size_t(f[0])])
        .cross(points[size_t(f[3 % f.size()])] - points[size_t(f[1])]);
  };
  std::vector<char> marked(flat.size(), 0);
  for (size_t f = 0; f < faces.size(); ++f) {
    const auto& face = faces[f];
    bool risky = normal(projected, face).dot(normal(flat, face)) <= 0;
    for (int v : face)
      risky =
          risky || blended[size_t(v)] || !smoothlyJoined(chosenEdge[size_t(v)], chosenEdge[size_t(face[0])]);
    if (risky)
      for (int v : face) marked[size_t(v)] = 1;
  }
  for (int ring = 0; ring < kCandidateRings; ++ring) {  // grow by the faces around the marked vertices
    std::vector<char> grown = marked;
    for (const auto& face : faces)
      if (std::any_of(face.begin(), face.end(), [&](int v) { return marked[size_t(v)]; }))
        for (int v : face) grown[size_t(v)] = 1;
    marked = std::move(grown);
  }
  std::vector<int> candidates;
  for (size_t f = 0; f < faces.size(); ++f)
    if (std::any_of(faces[f].begin(), faces[f].end(), [&](int v) { return marked[size_t(v)]; }))
      candidates.push_back(int(f));
  return candidates;
}

// Whether some pair of the candidate faces that is a fold cuts each other (the search stops at the first).
bool anyFold(const std::vector<std::vector<int>>& faces, const std::vector<Eigen::Vector3d>& points,
             const std::function<bool(int, int)>& isFold, const std::vector<int>& candidates) {
  return !intersectingFaces(points, faces, 1, isFold, nullptr, &candidates).facePairs.empty();
}

// A vertex as OpenSubdiv's PrimvarRefiner interpolates it.
struct RefinedPoint {
  Eigen::Vector3d p;
  void Clear(void* = nullptr) { p.setZero(); }
  void AddWithWeight(const RefinedPoint& source, double weight) { p += weight * source.p; }
};

// A vertex's share of the projection the fold repair left it (FoldRepairResult::shares), interpolated to
// the next level.
struct RefinedShare {
  double share = 1;
  void Clear(void* = nullptr) { share = 0; }
  void AddWithWeight(const RefinedShare& source, double weight) { share += weight * source.share; }
};

std::unique_ptr<Far::TopologyRefiner> bilinearRefiner(const SqmMesh& mesh, int levels) {
  std::vector<int> counts, indices;
  for (const auto& f : mesh.faces) {
    counts.push_back(int(f.size()));
    indices.insert(indices.end(), f.begin(), f.end());
  }
  Far::TopologyDescriptor descriptor;
  descriptor.numVertices = int(mesh.vertices.size());
  descriptor.numFaces = int(mesh.faces.size());
  descriptor.numVertsPerFace = counts.data();
  descriptor.vertIndicesPerFace = indices.data();
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  std::unique_ptr<Far::TopologyRefiner> refiner(
      Factory::Create(descriptor, Factory::Options(Sdc::SCHEME_BILINEAR, Sdc::Options())));
  if (!refiner) return nullptr;
  Far::TopologyRefiner::UniformOptions uniform(levels);
  // The last level keeps only its faces' vertices (the full topology there held more memory than the
  // mesh; first runs paid for it in page faults): faces per vertex come from vertexFaces().
  uniform.fullTopologyInLastLevel = false;
  refiner->RefineUniform(uniform);
  return refiner;
}

// One face of each vertex of a level (the first that lists it).
std::vector<int> vertexFaces(const Far::TopologyLevel& level) {
  std::vector<int> face(size_t(level.GetNumVertices()), -1);
  for (int f = level.GetNumFaces() - 1; f >= 0; --f)
    for (const int v : level.GetFaceVertices(f)) face[size_t(v)] = f;
  return face;
}

std::vector<std::vector<int>> levelFaces(const Far::TopologyLevel& level) {
  std::vector<std::vector<int>> faces(size_t(level.GetNumFaces()));
  for (int f = 0; f < level.GetNumFaces(); ++f) {
    const auto vertices = level.GetFaceVertices(f);
    faces[size_t(f)].assign(vertices.begin(), vertices.end());
  }
  return faces;
}

// Per base face: the edges it can project onto, those whose swept volume comes within a radius of it and
// which are near its node on the skeleton (a tube of another part passing through is not its surface: the
// overlap is SqmUnion's work).
std::vector<std::vector<int>> nearEdgesOf(const SqmMesh& mesh, const Skeleton& skeleton,
                                          const SweptSpheres& spheres, const FoldPairs& folds) {
  std::vector<std::vector<int>> nearEdges;
  const double largestRadius = *std::max_element(skeleton.radii.begin(), skeleton.radii.end());
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    Eigen::Vector3d low = mesh.vertices[size_t(mesh.faces[f][0])], high = low;
    double radius = 0;
    for (int v : mesh.faces[f]) {
      low = low.cwiseMin(mesh.vertices[size_t(v)]);
      high = high.cwiseMax(mesh.vertices[size_t(v)]);
      const int node = v < int(mesh.vertexNode.size()) ? mesh.vertexNode[size_t(v)] : -1;
      radius = std::max(radius, node >= 0 ? skeleton.radii[size_t(node)] : largestRadius);
    }
    nearEdges.push_back(spheres.edgesNear(low, high, radius));
    const int node = folds.faceNode(int(f));
    if (node >= 0)
      nearEdges.back().erase(std::remove_if(nearEdges.back().begin(), nearEdges.back().end(),
                                            [&](int e) {
                                              return !folds.near(node, skeleton.edges[size_t(e)][0]) &&
                                                     !folds.near(node, skeleton.edges[size_t(e)][1]);
                                            }),
                             nearEdges.back().end());
  }
  return nearEdges;
}

// One level's vertices on the swept surfaces (the paper's tessellation: the bilinear points of the faces,
// projected), beside where they lie on the base mesh's tessellation, with the edge each went to and
// whether it lies in a crease between tubes.
struct LevelProjection {
  std::vector<Eigen::Vector3d> flat, projected;
  std::vector<int> chosenEdge;
  std::vector<char> blended;
};

LevelProjection projectLevel(const std::vector<RefinedPoint>& next,
                             const std::vector<RefinedPoint>& nextOnBase,
                             const std::vector<int>& faceOfVertex, const std::vector<int>& nextBaseFace,
                             const std::vector<std::vector<int>>& nearEdges, const SweptSpheres& spheres,
                             const Skeleton& skeleton, const std::vector<Eigen::Vector3d>& sharp,
                             const SharpScaling& scaling) {
  LevelProjection out;
  out.flat.resize(next.size());
  out.projected.resize(next.size());
  out.chosenEdge.assign(next.size(), -1);
  out.blended.assign(next.size(), 0);
  inParallel(next.size(), [&](size_t v) {
    const Eigen::Vector3d p = next[v].p;
    const std::vector<int>& edges = nearEdges[size_t(nextBaseFace[size_t(faceOfVertex[v])])];
    Eigen::Vector3d q = p;
    bool inCrease = false;
    int partner = -1;
    const SweptPoint surface = nearestSurface(p, spheres, edges, q, &inCrease, &out.chosenEdge[v], &partner);
    // In a crease between tubes, but for the inner side of a gentle bend along a chain.
    out.blended[v] = inCrease && !(partner >= 0 && gentleBend(skeleton, out.chosenEdge[v], partner));
    for (int again = 0; again < kCreaseIterations && inCrease; ++again) {  // further into the crease
      const Eigen::Vector3d from = q;
      nearestSurface(from, spheres, edges, q, &inCrease);
    }
    if (surface.found && !sharp.empty())  // the paper's scaling, on the nearest surface
      q = surface.centre +
          surface.radius *
              sharpScaleFactor(distanceToNearest(p, sharp) / surface.radius, scaling.minimumScale) *
              surface.direction;
    out.flat[v] = nextOnBase[v].p;
    out.projected[v] = q;
  });
  return out;
}

// The refined mesh back into plain arrays; a vertex belongs to the nearest node among the ends of its
// face's edges.
void storeRefined(const Far::TopologyLevel& last, const std::vector<RefinedPoint>& points,
                  const std::vector<int>& baseFace, const std::vector<std::vector<int>>& nearEdges,
                  const Skeleton& skeleton, std::vector<std::vector<int>> lastFaces, SqmMesh& mesh) {
  mesh.faces = lastFaces.empty() ? levelFaces(last) : std::move(lastFaces);
  mesh.vertices.clear();
  mesh.vertexNode.clear();
  const std::vector<int> faceOfVertex = vertexFaces(last);
  for (int v = 0; v < last.GetNumVertices(); ++v) {
    const Eigen::Vector3d& p = points[size_t(v)].p;
    mesh.vertices.push_back(p);
    int nearest = -1;
    auto distance = [&](int node) { return (skeleton.nodes[size_t(node)] - p).squaredNorm(); };
    for (int e : nearEdges[size_t(baseFace[size_t(faceOfVertex[size_t(v)])])])
      for (int node : skeleton.edges[size_t(e)])
        if (nearest < 0 || distance(node) < distance(nearest)) nearest = node;
    if (nearest < 0)  // no edge near: a lone node's sphere
      for (int node = 0; node < skeleton.nodeCount(); ++node)
        if (nearest < 0 || distance(node) < distance(nearest)) nearest = node;
    mesh.vertexNode.push_back(nearest);
  }
}

}  // namespace

int refineSqmMesh(SqmMesh& mesh, const Skeleton& skeleton, int levels, const SharpScaling& scaling,
                  bool foldRepair, RefinementReport* report) {
  RefinementReport unused;
  if (!report) report = &unused;
  if (levels <= 0 || mesh.faces.empty()) return 0;
  const auto refiner = bilinearRefiner(mesh, levels);
  if (!refiner) return 0;
  const SweptSpheres spheres(skeleton);
  const FoldPairs folds(mesh, skeleton);
  const std::vector<std::vector<int>> nearEdges = nearEdgesOf(mesh, skeleton, spheres, folds);
  const std::vector<Eigen::Vector3d> sharp =
      scaling.enabled ? sharpVertices(mesh) : std::vector<Eigen::Vector3d>{};

  // The fold repair runs on the last level only (each level projects every vertex again), unless folds are
  // left there: then everything again with the repair at every level, so that none piles up (the fish and
  // the hand refined four times).
  std::vector<RefinedPoint> points;  // projected
  std::vector<int> baseFace;
  std::vector<std::vector<int>> lastFaces;  // the last level's, once the repair has listed them
  const Far::PrimvarRefinerReal<double> primvars(*refiner);
  auto runLevels = [&](bool repairEveryLevel) {
    points.clear();
    for (const auto& v : mesh.vertices) points.push_back({v});
    std::vector<RefinedPoint> onBase = points;  // the base mesh's tessellation
    baseFace.resize(mesh.faces.size());
    for (size_t f = 0; f < baseFace.size(); ++f) baseFace[f] = int(f);
    // Repairing every level, each level's vertices keep the share of the projection the repair left the
    // coarser level (a vertex pulled halfway back is projected halfway at the next level): projected in
    // full, the finer level folded again where the coarser one was mended (the dense tree's last level,
    // 5,692 pairs) and its repair took a dozen steps there.
    std::vector<RefinedShare> shares(repairEveryLevel ? mesh.vertices.size() : 0);
    bool nothingToRedo = true;  // no fold left that repairing the coarser levels could undo
    for (int level = 1; level <= levels; ++level) {
      const Far::TopologyLevel& topology = refiner->GetLevel(level);
      std::vector<RefinedPoint> next(size_t(topology.GetNumVertices()));
      primvars.Interpolate(level, points, next);
      std::vector<RefinedPoint> nextOnBase(next.size());
      primvars.Interpolate(level, onBase, nextOnBase);
      std::vector<int> nextBaseFace(size_t(topology.GetNumFaces()));
      primvars.InterpolateFaceUniform(level, baseFace, nextBaseFace);
      const std::vector<int> faceOfVertex = vertexFaces(topology);
      LevelProjection projection = projectLevel(next, nextOnBase, faceOfVertex, nextBaseFace, nearEdges,
                                                spheres, skeleton, sharp, scaling);
      if (repairEveryLevel) {
        std::vector<RefinedShare> nextShares(next.size());
        primvars.Interpolate(level, shares, nextShares);
        shares = std::move(nextShares);
        for (size_t v = 0; v < next.size(); ++v)
          projection.projected[v] =
              projection.flat[v] + shares[v].share * (projection.projected[v] - projection.flat[v]);
      }
      // Where tubes of other parts cut each other on the base mesh at more pairs of nodes than there are
      // nodes, a first level that folds is one whose last level the repair alone leaves folded (the dense
      // tree, 210 pairs for 150 nodes, at every K: the run repairing every level followed, and made the same
      // mesh), so the run stops here for that one instead of after its last and most expensive level
      // (K = 3: 0.6 of 1.2 s). With fewer overlaps a fold at the first level is often mended at the last
      // (the hand sketch, 5 pairs for 66 nodes, and the fish and hand.swc without any, at K = 2 and 3;
      // the long chains): there the run goes on as before.
      const bool probe = foldRepair && !repairEveryLevel && level == 1 && levels > 1 &&
                         folds.baseOverlaps() >= skeleton.nodeCount();
      if (foldRepair && (repairEveryLevel || level == levels || probe)) {
        const auto isFold = [&](int f, int g) {
          return folds.isFold(nextBaseFace[size_t(f)], nextBaseFace[size_t(g)]);
        };
        auto faces = levelFaces(topology);
        std::vector<int> candidates = foldCandidates(faces, projection.flat, projection.projected,
                                                     projection.chosenEdge, projection.blended, skeleton);
        if (probe) {
          if (anyFold(faces, projection.projected, isFold, candidates)) return false;
          for (size_t v = 0; v < next.size(); ++v) next[v].p = projection.projected[v];
          points = std::move(next);
          onBase = std::move(nextOnBase);
          baseFace = std::move(nextBaseFace);
          continue;
        }
        FoldRepairResult repair =
            repairFolds(faces, projection.flat, projection.projected, isFold, std::move(candidates));
        nothingToRedo = !repair.repairable;
        if (repairEveryLevel)
          for (size_t v = 0; v < shares.size(); ++v) shares[v].share *= repair.shares[v];
        if (level == levels) {
          report->repairedVertices =
              repairEveryLevel ? int(std::count_if(shares.begin(), shares.end(),
                                                   [](const RefinedShare& s) { return s.share < 1; }))
                               : repair.movedVertices;
          lastFaces = std::move(faces);
        }
      }
      for (size_t v = 0; v < next.size(); ++v) next[v].p = projection.projected[v];
      points = std::move(next);
      onBase = std::move(nextOnBase);
      baseFace = std::move(nextBaseFace);
    }
    return nothingToRedo;
  };
  if (!runLevels(false)) runLevels(true);
  storeRefined(refiner->GetLevel(levels), points, baseFace, nearEdges, skeleton, std::move(lastFaces), mesh);
  return int(sharp.size());
}

}  // namespace medial
