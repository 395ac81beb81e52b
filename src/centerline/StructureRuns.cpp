#include "centerline/StructureRuns.h"

#include "common/UnionFind.h"

#include <algorithm>
#include <climits>
#include <stdexcept>

namespace medial {

ChosenPart largestPart(const BinaryVolume& frame, const std::vector<VoxelRun>& runs, bool dropBorder,
                       int margin) {
  ChosenPart chosen;
  const auto& size = frame.size;
  // rowStart[y + ny * z] .. rowStart[... + 1]: the runs of a row.
  const int64_t rows = int64_t(size[1]) * size[2];
  std::vector<int64_t> rowStart(size_t(rows) + 1, 0);
  for (const VoxelRun& r : runs) ++rowStart[size_t(r.y + int64_t(size[1]) * r.z) + 1];
  for (int64_t r = 0; r < rows; ++r) rowStart[size_t(r) + 1] += rowStart[size_t(r)];

  // 26-connectivity: a run touches the runs of the row before it in its slice and of the three rows
  // around it in the slice before, where their x ranges overlap once widened by one voxel.
  if (runs.size() > size_t(INT_MAX)) throw std::length_error("more runs than UnionFind numbers");
  UnionFind parts(runs.size());
  auto joinRow = [&](size_t run, int y, int z) {
    if (y < 0 || y >= size[1] || z < 0) return;
    const int64_t row = y + int64_t(size[1]) * z;
    for (int64_t k = rowStart[size_t(row)]; k < rowStart[size_t(row) + 1]; ++k) {
      const VoxelRun& other = runs[size_t(k)];
      if (other.x0 > runs[run].x1 + 1) break;
      if (other.x1 >= runs[run].x0 - 1) parts.join(int(run), int(k));
    }
  };
  for (size_t i = 0; i < runs.size(); ++i) {
    joinRow(i, runs[i].y - 1, runs[i].z);
    for (int dy = -1; dy <= 1; ++dy) joinRow(i, runs[i].y + dy, runs[i].z - 1);
  }

  struct Part {
    int64_t voxels = 0;
    bool border = false;
    std::array<int, 3> lo{INT32_MAX, INT32_MAX, INT32_MAX}, hi{-1, -1, -1};
  };
  std::vector<Part> part(runs.size());
  for (size_t i = 0; i < runs.size(); ++i) {
    const VoxelRun& r = runs[i];
    Part& p = part[size_t(parts.find(int(i)))];
    p.voxels += r.x1 - r.x0 + 1;
    p.border = p.border || r.x0 == 0 || r.x1 == size[0] - 1 || r.y == 0 || r.y == size[1] - 1 || r.z == 0 ||
               r.z == size[2] - 1;
    p.lo = {std::min(p.lo[0], r.x0), std::min(p.lo[1], r.y), std::min(p.lo[2], r.z)};
    p.hi = {std::max(p.hi[0], r.x1), std::max(p.hi[1], r.y), std::max(p.hi[2], r.z)};
  }
  size_t best = runs.size();
  for (size_t i = 0; i < runs.size(); ++i) {
    if (size_t(parts.find(int(i))) != i) continue;
    ++chosen.parts;
    if (part[i].border) chosen.borderVoxels += part[i].voxels;
    if (dropBorder && part[i].border) continue;
    if (best == runs.size() || part[i].voxels > part[best].voxels) best = i;
  }
  chosen.volume.spacing = frame.spacing;
  chosen.volume.direction = frame.direction;
  chosen.volume.origin = frame.origin;
  if (best == runs.size()) return chosen;  // nothing left: an empty volume

  const Part& p = part[best];
  std::array<int, 3> lo{}, boxSize{};
  for (size_t a = 0; a < 3; ++a) {
    lo[a] = std::max(0, p.lo[a] - margin);
    boxSize[a] = std::min(size[a] - 1, p.hi[a] + margin) - lo[a] + 1;
  }
  chosen.first = lo;
  chosen.voxels = p.voxels;
  BinaryVolume& box = chosen.volume;
  box.size = boxSize;
  box.origin = frame.physical(Eigen::Vector3d(lo[0], lo[1], lo[2]));
  box.inside.assign(size_t(box.voxelCount()), 0);
  for (size_t i = 0; i < runs.size(); ++i)
    if (size_t(parts.find(int(i))) == best) {
      const VoxelRun& r = runs[i];
      const int64_t at = box.index(r.x0 - lo[0], r.y - lo[1], r.z - lo[2]);
      std::fill_n(box.inside.begin() + at, r.x1 - r.x0 + 1, uint8_t(1));
    }
  return chosen;
}

}  // namespace medial
