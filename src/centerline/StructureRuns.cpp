#include "centerline/StructureRuns.h"

#include "common/UnionFind.h"

#include <algorithm>
#include <climits>
#include <stdexcept>

namespace medial {

int StructureParts::partAt(const std::vector<VoxelRun>& runs, int x, int y, int z) const {
  if (x < 0 || y < 0 || z < 0 || x >= size[0] || y >= size[1] || z >= size[2]) return -1;
  const int64_t row = y + int64_t(size[1]) * z;
  for (int64_t k = rowStart[size_t(row)]; k < rowStart[size_t(row) + 1]; ++k)
    if (runs[size_t(k)].x0 <= x && x <= runs[size_t(k)].x1) return partOfRun[size_t(k)];
  return -1;
}

StructureParts labelParts(const std::array<int, 3>& size, const std::vector<VoxelRun>& runs) {
  StructureParts result;
  result.size = size;
  const int64_t rows = int64_t(size[1]) * size[2];
  std::vector<int64_t>& rowStart = result.rowStart;
  rowStart.assign(size_t(rows) + 1, 0);
  for (const VoxelRun& r : runs) ++rowStart[size_t(r.y + int64_t(size[1]) * r.z) + 1];
  for (int64_t r = 0; r < rows; ++r) rowStart[size_t(r) + 1] += rowStart[size_t(r)];

  // 26-connectivity: a run touches the runs of the row before it in its slice and of the three rows
  // around it in the slice before, where their x ranges overlap once widened by one voxel.
  if (runs.size() > size_t(INT_MAX)) throw std::length_error("more runs than UnionFind numbers");
  UnionFind sets(runs.size());
  auto joinRow = [&](size_t run, int y, int z) {
    if (y < 0 || y >= size[1] || z < 0) return;
    const int64_t row = y + int64_t(size[1]) * z;
    for (int64_t k = rowStart[size_t(row)]; k < rowStart[size_t(row) + 1]; ++k) {
      const VoxelRun& other = runs[size_t(k)];
      if (other.x0 > runs[run].x1 + 1) break;
      if (other.x1 >= runs[run].x0 - 1) sets.join(int(run), int(k));
    }
  };
  for (size_t i = 0; i < runs.size(); ++i) {
    joinRow(i, runs[i].y - 1, runs[i].z);
    for (int dy = -1; dy <= 1; ++dy) joinRow(i, runs[i].y + dy, runs[i].z - 1);
  }

  // Parts numbered in order of their first run, then renumbered largest first.
  std::vector<int> partOfRoot(runs.size(), -1);
  std::vector<StructureParts::Part> parts;
  result.partOfRun.resize(runs.size());
  for (size_t i = 0; i < runs.size(); ++i) {
    int& id = partOfRoot[size_t(sets.find(int(i)))];
    if (id < 0) {
      id = int(parts.size());
      StructureParts::Part fresh;
      fresh.lo = {INT32_MAX, INT32_MAX, INT32_MAX};
      fresh.hi = {-1, -1, -1};
      parts.push_back(fresh);
    }
    result.partOfRun[i] = id;
    const VoxelRun& r = runs[i];
    StructureParts::Part& p = parts[size_t(id)];
    p.voxels += r.x1 - r.x0 + 1;
    p.border = p.border || r.x0 == 0 || r.x1 == size[0] - 1 || r.y == 0 || r.y == size[1] - 1 || r.z == 0 ||
               r.z == size[2] - 1;
    p.lo = {std::min(p.lo[0], r.x0), std::min(p.lo[1], r.y), std::min(p.lo[2], r.z)};
    p.hi = {std::max(p.hi[0], r.x1), std::max(p.hi[1], r.y), std::max(p.hi[2], r.z)};
  }
  std::vector<int> order(parts.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = int(i);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return parts[size_t(a)].voxels > parts[size_t(b)].voxels; });
  std::vector<int> rank(parts.size());
  for (size_t i = 0; i < order.size(); ++i) {
    rank[size_t(order[i])] = int(i);
    result.parts.push_back(parts[size_t(order[i])]);
  }
  for (int& id : result.partOfRun) id = rank[size_t(id)];
  return result;
}

BinaryVolume partsInBox(const BinaryVolume& frame, const std::vector<VoxelRun>& runs,
                        const StructureParts& parts, const std::vector<int>& chosen, int margin,
                        std::array<int, 3>* first) {
  BinaryVolume box;
  box.spacing = frame.spacing;
  box.direction = frame.direction;
  box.origin = frame.origin;
  if (chosen.empty()) return box;
  std::array<int, 3> lo{INT32_MAX, INT32_MAX, INT32_MAX}, hi{-1, -1, -1};
  std::vector<uint8_t> wanted(parts.parts.size(), 0);
  for (int c : chosen) {
    wanted[size_t(c)] = 1;
    for (size_t a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], parts.parts[size_t(c)].lo[a]);
      hi[a] = std::max(hi[a], parts.parts[size_t(c)].hi[a]);
    }
  }
  for (size_t a = 0; a < 3; ++a) {
    lo[a] = std::max(0, lo[a] - margin);
    box.size[a] = std::min(frame.size[a] - 1, hi[a] + margin) - lo[a] + 1;
  }
  if (first) *first = lo;
  box.origin = frame.physical(Eigen::Vector3d(lo[0], lo[1], lo[2]));
  box.inside.assign(size_t(box.voxelCount()), 0);
  for (size_t i = 0; i < runs.size(); ++i)
    if (wanted[size_t(parts.partOfRun[i])]) {
      const VoxelRun& r = runs[i];
      const int64_t at = box.index(r.x0 - lo[0], r.y - lo[1], r.z - lo[2]);
      std::fill_n(box.inside.begin() + at, r.x1 - r.x0 + 1, uint8_t(1));
    }
  return box;
}

ChosenPart largestPart(const BinaryVolume& frame, const std::vector<VoxelRun>& runs, bool dropBorder,
                       int margin) {
  ChosenPart chosen;
  const StructureParts parts = labelParts(frame.size, runs);
  int best = -1;
  for (size_t i = 0; i < parts.parts.size(); ++i) {
    const StructureParts::Part& p = parts.parts[i];
    ++chosen.parts;
    if (p.border) chosen.borderVoxels += p.voxels;
    if (best < 0 && !(dropBorder && p.border)) best = int(i);  // largest first
  }
  chosen.volume.spacing = frame.spacing;
  chosen.volume.direction = frame.direction;
  chosen.volume.origin = frame.origin;
  if (best < 0) return chosen;  // nothing left: an empty volume
  chosen.voxels = parts.parts[size_t(best)].voxels;
  chosen.volume = partsInBox(frame, runs, parts, {best}, margin, &chosen.first);
  return chosen;
}

}  // namespace medial
