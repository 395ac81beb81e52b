#include "mesh/MeshTopology.h"

#include "common/UnionFind.h"

#include <algorithm>
#include <numeric>
#include <unordered_map>

namespace medial {
namespace {

uint64_t edgeKey(int64_t a, int64_t b) {
  if (a > b) std::swap(a, b);
  return (static_cast<uint64_t>(a) << 32) | static_cast<uint64_t>(b);
}

}  // namespace

MeshTopology computeMeshTopology(int64_t vertexCount, const std::vector<std::vector<int64_t>>& faces) {
  MeshTopology t;
  std::vector<char> used(vertexCount, 0);
  std::unordered_map<uint64_t, int> faceCountPerEdge;
  faceCountPerEdge.reserve(faces.size() * 2);
  UnionFind vertexSets{size_t(vertexCount)};

  for (const auto& face : faces) {
    std::vector<int64_t> distinct(face);
    std::sort(distinct.begin(), distinct.end());
    distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
    if (distinct.size() < 3) {
      ++t.degenerateFaces;
      continue;
    }
    ++t.faces;
    for (size_t i = 0; i < face.size(); ++i) {
      const int64_t a = face[i], b = face[(i + 1) % face.size()];
      used[a] = 1;
      if (a == b) continue;
      ++faceCountPerEdge[edgeKey(a, b)];
      vertexSets.join(int(a), int(b));
    }
  }

  // Component of each used vertex, numbered densely.
  std::vector<int64_t> componentOf(vertexCount, -1);
  std::unordered_map<int64_t, int64_t> componentIndex;
  for (int64_t v = 0; v < vertexCount; ++v) {
    if (!used[v]) {
      ++t.unusedVertices;
      continue;
    }
    ++t.vertices;
    auto [it, inserted] =
        componentIndex.try_emplace(vertexSets.find(int(v)), static_cast<int64_t>(componentIndex.size()));
    componentOf[v] = it->second;
  }
  t.components = static_cast<int64_t>(componentIndex.size());

  // Per component: V, E, F and boundary loops, for chi_c = V - E + F and g_c = (2 - chi_c - b_c) / 2.
  std::vector<int64_t> chi(t.components, 0), loops(t.components, 0);
  for (int64_t v = 0; v < vertexCount; ++v)
    if (componentOf[v] >= 0) ++chi[componentOf[v]];
  for (const auto& face : faces) {
    if (face.empty() || componentOf[face[0]] < 0) continue;
    std::vector<int64_t> distinct(face);
    std::sort(distinct.begin(), distinct.end());
    if (std::unique(distinct.begin(), distinct.end()) - distinct.begin() >= 3) ++chi[componentOf[face[0]]];
  }

  UnionFind borderSets{size_t(vertexCount)};
  std::vector<char> onBorder(vertexCount, 0);
  for (const auto& [key, count] : faceCountPerEdge) {
    const int64_t a = static_cast<int64_t>(key >> 32), b = static_cast<int64_t>(key & 0xffffffffu);
    ++t.edges;
    --chi[componentOf[a]];
    if (count == 1) {
      ++t.borderEdges;
      borderSets.join(int(a), int(b));
      onBorder[a] = onBorder[b] = 1;
    } else if (count > 2) {
      ++t.nonManifoldEdges;
    }
  }
  for (int64_t v = 0; v < vertexCount; ++v)
    if (onBorder[v] && borderSets.find(int(v)) == v) ++loops[componentOf[v]];

  for (int64_t c = 0; c < t.components; ++c) {
    t.eulerCharacteristic += chi[c];
    t.boundaryLoops += loops[c];
    t.genus += std::max<int64_t>(0, (2 - chi[c] - loops[c]) / 2);
  }
  return t;
}

}  // namespace medial
