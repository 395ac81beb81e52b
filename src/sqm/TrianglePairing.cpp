#include "sqm/TrianglePairing.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>

namespace medial {

namespace {

// Beyond this fold about its other diagonal a quad is not convex, or barely.
constexpr double kMaxFoldAcross = 135.0;

// The quad of triangle a and triangle b (sharing an edge, same orientation), starting at a shared vertex
// so that its 0-2 diagonal is the shared edge; empty when they share no edge.
std::vector<int> joinedQuad(const std::vector<int>& a, const std::vector<int>& b) {
  for (int i = 0; i < 3; ++i) {
    const int y = a[size_t((i + 1) % 3)], z = a[size_t((i + 2) % 3)];  // edge y -> z of a; b has z -> y
    for (int j = 0; j < 3; ++j)
      if (b[size_t(j)] == z && b[size_t((j + 1) % 3)] == y)
        return {y, b[size_t((j + 2) % 3)], z, a[size_t(i)]};
  }
  return {};
}

// The quad's fold angles in degrees (180 where a split is degenerate): about its 0-2 diagonal, where its
// two triangles meet, and about the other one (near 180 when the quad is not convex).
std::array<double, 2> foldDegrees(const std::vector<Eigen::Vector3d>& x, const std::vector<int>& q) {
  auto normal = [&](int a, int b, int c) {
    const Eigen::Vector3d& p = x[size_t(q[size_t(a)])];
    return Eigen::Vector3d((x[size_t(q[size_t(b)])] - p).cross(x[size_t(q[size_t(c)])] - p));
  };
  auto angle = [](const Eigen::Vector3d& n, const Eigen::Vector3d& m) {
    if (n.norm() == 0 || m.norm() == 0) return 180.0;
    return std::acos(std::clamp(n.normalized().dot(m.normalized()), -1.0, 1.0)) * 180.0 / M_PI;
  };
  return {angle(normal(0, 1, 2), normal(0, 2, 3)), angle(normal(1, 2, 3), normal(1, 3, 0))};
}

// Maximum-weight matching of consecutive elements of `order` (a path, or a cycle when `closed`), where
// weight[k] joins order[k] and order[k + 1] (negative: not allowed). Returns the chosen k.
std::vector<size_t> matchAlong(const std::vector<double>& weight, bool closed) {
  const size_t m = weight.size() + (closed ? 0 : 1);  // elements
  // Best matching of elements first..last (a path), its chosen links.
  auto path = [&](size_t first, size_t last) {
    std::vector<size_t> chosen;
    if (last <= first || last >= m) return std::make_pair(0.0, chosen);
    const size_t n = last - first + 1;
    std::vector<double> best(n + 1, 0.0);
    for (size_t i = 2; i <= n; ++i) {
      best[i] = best[i - 1];
      const double w = weight[first + i - 2];
      if (w >= 0) best[i] = std::max(best[i], best[i - 2] + w);
    }
    for (size_t i = n; i >= 2;) {
      const double w = weight[first + i - 2];
      if (w >= 0 && best[i] == best[i - 2] + w && best[i] != best[i - 1]) {
        chosen.push_back(first + i - 2);
        i -= 2;
      } else {
        --i;
      }
    }
    return std::make_pair(best[n], chosen);
  };
  auto open = path(0, m - 1);
  if (!closed || m < 2 || weight[m - 1] < 0) return open.second;
  auto wrapped = path(1, m - 2);  // the link from the last element back to the first is taken
  if (wrapped.first + weight[m - 1] <= open.first) return open.second;
  wrapped.second.push_back(m - 1);
  return wrapped.second;
}

// The strip's triangles in walking order (each sharing an edge with the next), and whether the last
// shares one with the first; empty when the triangles do not form one simple strip.
std::vector<size_t> walkStrip(const std::vector<std::vector<int>>& faces, const std::vector<size_t>& strip,
                              bool& closed) {
  std::map<std::pair<int, int>, std::vector<size_t>> byEdge;
  for (size_t t : strip) {
    const auto& f = faces[t];
    if (f.size() != 3) return {};
    for (size_t i = 0; i < 3; ++i) byEdge[std::minmax(f[i], f[(i + 1) % 3])].push_back(t);
  }
  std::map<size_t, std::vector<size_t>> neighbours;
  for (const auto& [edge, triangles] : byEdge) {
    if (triangles.size() > 2) return {};
    if (triangles.size() == 2) {
      neighbours[triangles[0]].push_back(triangles[1]);
      neighbours[triangles[1]].push_back(triangles[0]);
    }
  }
  size_t start = strip.front();
  for (size_t t : strip) {
    if (neighbours[t].size() > 2) return {};
    if (neighbours[t].size() < 2) start = t;  // a path's end
  }
  std::vector<size_t> order{start};
  for (size_t previous = size_t(-1);;) {
    const auto& n = neighbours[order.back()];
    const auto next =
        std::find_if(n.begin(), n.end(), [&](size_t u) { return u != previous && u != order.front(); });
    if (next == n.end()) break;
    previous = order.back();
    order.push_back(*next);
  }
  if (order.size() != strip.size()) return {};
  const auto& last = neighbours[order.back()];
  closed = order.size() > 2 && std::find(last.begin(), last.end(), order.front()) != last.end();
  return order;
}

}  // namespace

int pairStripTriangles(const std::vector<Eigen::Vector3d>& vertices, std::vector<std::vector<int>>& faces,
                       const std::vector<std::vector<size_t>>& strips, double maxFoldDegrees) {
  std::vector<int> valence(vertices.size(), 0);  // on a closed surface: the faces around a vertex
  for (const auto& f : faces)
    for (int v : f) ++valence[size_t(v)];
  std::vector<size_t> removed;
  int quads = 0;
  for (const auto& strip : strips) {
    if (strip.size() < 2) continue;
    bool closed = false;
    const std::vector<size_t> order = walkStrip(faces, strip, closed);
    if (order.empty()) continue;  // not a simple strip: left as triangles
    std::vector<double> weight(order.size() - (closed ? 0 : 1));
    std::vector<std::vector<int>> quad(weight.size());
    for (size_t k = 0; k < weight.size(); ++k) {
      quad[k] = joinedQuad(faces[order[k]], faces[order[(k + 1) % order.size()]]);
      const auto fold =
          quad[k].empty() ? std::array<double, 2>{180.0, 180.0} : foldDegrees(vertices, quad[k]);
      const bool fair = fold[0] < maxFoldDegrees && fold[1] < kMaxFoldAcross;
      weight[k] = fair ? 1000.0 + (1.0 - fold[0] / 180.0) : -1.0;  // more pairs, then flatter
    }
    for (size_t k : matchAlong(weight, closed)) {
      // A quad takes an edge from both ends of the shared one; none may be left with two (a fan of four
      // paired all round would put its apex between two quads that share two edges).
      const std::vector<int>& q = quad[k];
      if (valence[size_t(q[0])] <= 3 || valence[size_t(q[2])] <= 3) continue;
      --valence[size_t(q[0])];
      --valence[size_t(q[2])];
      faces[order[k]] = quad[k];
      removed.push_back(order[(k + 1) % order.size()]);
      ++quads;
    }
  }
  std::vector<bool> gone(faces.size(), false);
  for (size_t t : removed) gone[t] = true;
  size_t kept = 0;
  for (size_t f = 0; f < faces.size(); ++f) {
    if (gone[f]) continue;
    if (kept != f) faces[kept] = std::move(faces[f]);  // a vector moved onto itself comes out empty
    ++kept;
  }
  faces.resize(kept);
  return quads;
}

}  // namespace medial
