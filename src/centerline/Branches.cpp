#include "centerline/Branches.h"

#include "centerline/TubularClusters.h"

#include <algorithm>
#include <deque>

namespace medial {

namespace {

// The 26 neighbours of a voxel that lie in the volume.
template <typename Visit>
void forNeighbours(const BinaryVolume& v, int64_t voxel, Visit visit) {
  const auto c = v.coordinates(voxel);
  for (int dk = -1; dk <= 1; ++dk)
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di) {
        if (!di && !dj && !dk) continue;
        if (v.contains(c[0] + di, c[1] + dj, c[2] + dk)) visit(v.index(c[0] + di, c[1] + dj, c[2] + dk));
      }
}

}  // namespace

BranchVolumes splitBranches(const BinaryVolume& v, int64_t seed, int minimumLength,
                            const std::vector<float>* centrality) {
  BranchVolumes result;
  if (seed < 0) seed = lowestVoxel(v);
  if (seed < 0 || seed >= v.voxelCount() || !v.inside[size_t(seed)]) {
    result.error =
        seed < 0 ? "the structure is empty (no voxel selected)" : "the seed lies outside the structure";
    return result;
  }
  std::vector<int> layer;
  const auto layers = manhattanLayers(v, seed, layer);

  // Pieces: the 26-connected parts of every layer, each linked to the piece of the previous layer it touches.
  std::vector<int> piece(size_t(v.voxelCount()), -1);
  std::vector<int> pieceParent, pieceLayer;
  std::vector<std::vector<int64_t>> pieceVoxels;
  for (int l = 0; l < int(layers.size()); ++l)
    for (int64_t first : layers[size_t(l)]) {
      if (piece[size_t(first)] >= 0) continue;
      const int id = int(pieceVoxels.size());
      pieceVoxels.emplace_back();
      pieceLayer.push_back(l);
      pieceParent.push_back(-1);
      std::deque<int64_t> queue{first};
      piece[size_t(first)] = id;
      while (!queue.empty()) {
        const int64_t at = queue.front();
        queue.pop_front();
        pieceVoxels[size_t(id)].push_back(at);
        forNeighbours(v, at, [&](int64_t next) {
          if (layer[size_t(next)] == l && piece[size_t(next)] < 0) {
            piece[size_t(next)] = id;
            queue.push_back(next);
          }
          if (l > 0 && layer[size_t(next)] == l - 1 && pieceParent[size_t(id)] < 0)
            pieceParent[size_t(id)] = piece[size_t(next)];
        });
      }
    }

  // Height of every piece: the most layers below it down to a leaf (pieces come in layer order, so one
  // backward pass suffices); a child is significant when its subtree is at least `minimumLength` deep.
  const int count = int(pieceVoxels.size());
  std::vector<int> height(static_cast<size_t>(count), 1);
  std::vector<std::vector<int>> children(static_cast<size_t>(count));
  for (int p = count - 1; p >= 0; --p)
    if (pieceParent[size_t(p)] >= 0) {
      height[size_t(pieceParent[size_t(p)])] =
          std::max(height[size_t(pieceParent[size_t(p)])], height[size_t(p)] + 1);
      children[size_t(pieceParent[size_t(p)])].push_back(p);
    }

  // Branches: a piece continues its parent's branch unless the parent has two or more significant children;
  // insignificant subtrees stay in the branch they leave.
  std::vector<int> branchOf(static_cast<size_t>(count), -1);
  auto newBranch = [&](int parentBranch, int64_t start) {
    result.voxels.emplace_back();
    result.parent.push_back(parentBranch);
    result.start.push_back(start);
    return int(result.voxels.size()) - 1;
  };
  for (int p = 0; p < count; ++p) {
    if (pieceParent[size_t(p)] < 0) {
      if (p == piece[size_t(seed)])
        branchOf[size_t(p)] = newBranch(-1, seed);
      else
        continue;  // unreached from the seed cannot happen: layers only hold reached voxels
    }
    const int b = branchOf[size_t(p)];
    if (b < 0) continue;
    int significant = 0;
    for (int c : children[size_t(p)]) significant += height[size_t(c)] >= minimumLength;
    for (int c : children[size_t(p)]) {
      const bool split = significant >= 2 && height[size_t(c)] >= minimumLength;
      if (!split) {
        branchOf[size_t(c)] = b;
        continue;
      }
      const auto& first = pieceVoxels[size_t(c)];
      int64_t start = first.front();
      if (centrality)
        start = *std::max_element(first.begin(), first.end(), [&](int64_t x, int64_t y) {
          return (*centrality)[size_t(x)] < (*centrality)[size_t(y)];
        });
      branchOf[size_t(c)] = newBranch(b, start);
    }
  }
  for (int p = 0; p < count; ++p)
    if (branchOf[size_t(p)] >= 0)
      for (int64_t voxel : pieceVoxels[size_t(p)])
        result.voxels[size_t(branchOf[size_t(p)])].push_back(voxel);
  return result;
}

}  // namespace medial
