#include "centerline/BinaryVolume.h"

#include <algorithm>
#include <array>
#include <vector>

namespace medial {

namespace {

// A voxel with its coordinates: the fills below never divide an index back into coordinates.
struct Voxel {
  int64_t index;
  int x, y, z;
};

// Scanline flood fill from `start` (26- or 6-connected): every voxel reached where `fillable` holds is
// passed to `mark`, which must make `fillable` false for it. Whole runs along x are taken at once and only
// the first voxel of each run in a neighbouring row is pushed: sequential memory, few stack entries (the
// air around a body in a CT is most of the volume).
template <typename Fillable, typename Mark>
void scanlineFill(const BinaryVolume& v, bool connect26, const Voxel& start, Fillable fillable, Mark mark) {
  if (!fillable(start.index)) return;
  const int nx = v.size[0];
  std::vector<Voxel> stack{start};
  while (!stack.empty()) {
    const Voxel seed = stack.back();
    stack.pop_back();
    if (!fillable(seed.index)) continue;
    const int64_t rowStart = seed.index - seed.x;
    int left = seed.x, right = seed.x;
    while (left > 0 && fillable(rowStart + left - 1)) --left;
    while (right < nx - 1 && fillable(rowStart + right + 1)) ++right;
    for (int x = left; x <= right; ++x) mark(rowStart + x);
    const int reach = connect26 ? 1 : 0;  // diagonal neighbours reach one voxel beyond the run
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy) {
        if ((dy == 0 && dz == 0) || (!connect26 && dy != 0 && dz != 0)) continue;
        const int y = seed.y + dy, z = seed.z + dz;
        if (y < 0 || z < 0 || y >= v.size[1] || z >= v.size[2]) continue;
        const int64_t row = v.index(0, y, z);
        bool inRun = false;
        for (int x = std::max(0, left - reach); x <= std::min(nx - 1, right + reach); ++x) {
          const bool open = fillable(row + x);
          if (open && !inRun) stack.push_back(Voxel{row + x, x, y, z});
          inRun = open;
        }
      }
  }
}

// Labels the connected components of voxels where `member` holds (26- or 6-connected); returns the label
// per voxel (-1 for non-members) and the size of each component.
template <typename Member>
std::vector<int> labelComponents(const BinaryVolume& v, Member member, bool connect26,
                                 std::vector<int64_t>& sizes) {
  std::vector<int> label(size_t(v.voxelCount()), -1);
  int64_t start = 0;
  for (int z = 0; z < v.size[2]; ++z)
    for (int y = 0; y < v.size[1]; ++y)
      for (int x = 0; x < v.size[0]; ++x, ++start) {
        if (!member(start) || label[size_t(start)] >= 0) continue;
        const int id = int(sizes.size());
        sizes.push_back(0);
        scanlineFill(
            v, connect26, Voxel{start, x, y, z}, [&](int64_t i) { return member(i) && label[size_t(i)] < 0; },
            [&](int64_t i) {
              label[size_t(i)] = id;
              ++sizes.back();
            });
      }
  return label;
}

// Calls f(voxel) for every voxel on the volume's six faces (some more than once).
template <typename F>
void forEachBorderVoxel(const BinaryVolume& v, F f) {
  const int nx = v.size[0], ny = v.size[1], nz = v.size[2];
  for (int z = 0; z < nz; ++z)
    for (int y = 0; y < ny; ++y) {
      const bool face = z == 0 || z == nz - 1 || y == 0 || y == ny - 1;
      for (int x = 0; x < nx; x += face ? 1 : std::max(1, nx - 1)) f(Voxel{v.index(x, y, z), x, y, z});
    }
}

}  // namespace

int keepLargestComponent(BinaryVolume& volume) {
  std::vector<int64_t> sizes;
  const auto label = labelComponents(
      volume, [&](int64_t i) { return volume.inside[size_t(i)] != 0; }, true, sizes);
  if (sizes.empty()) return 0;
  const int largest = int(std::max_element(sizes.begin(), sizes.end()) - sizes.begin());
  for (int64_t i = 0; i < volume.voxelCount(); ++i) volume.inside[size_t(i)] = label[size_t(i)] == largest;
  return int(sizes.size());
}

int64_t dropBorderTouchingParts(BinaryVolume& volume) {
  // Filled from the structure's voxels on the faces, clearing as it goes: no labels, and the work is the
  // size of the removed parts.
  int64_t removed = 0;
  forEachBorderVoxel(volume, [&](const Voxel& voxel) {
    scanlineFill(
        volume, true, voxel, [&](int64_t i) { return volume.inside[size_t(i)] != 0; },
        [&](int64_t i) {
          volume.inside[size_t(i)] = 0;
          ++removed;
        });
  });
  return removed;
}

int64_t fillHoles(BinaryVolume& volume) {
  // Background 6-connected to the faces is outside; the rest of the background is a cavity.
  std::vector<uint8_t> outside(size_t(volume.voxelCount()), 0);
  forEachBorderVoxel(volume, [&](const Voxel& voxel) {
    scanlineFill(
        volume, false, voxel, [&](int64_t i) { return !volume.inside[size_t(i)] && !outside[size_t(i)]; },
        [&](int64_t i) { outside[size_t(i)] = 1; });
  });
  int64_t filled = 0;
  for (int64_t i = 0; i < volume.voxelCount(); ++i)
    if (!volume.inside[size_t(i)] && !outside[size_t(i)]) {
      volume.inside[size_t(i)] = 1;
      ++filled;
    }
  return filled;
}

std::array<int, 3> cropToStructure(BinaryVolume& volume, int margin) {
  std::array<int, 3> lo{volume.size[0], volume.size[1], volume.size[2]}, hi{-1, -1, -1};
  int64_t i = 0;
  for (int z = 0; z < volume.size[2]; ++z)
    for (int y = 0; y < volume.size[1]; ++y)
      for (int x = 0; x < volume.size[0]; ++x, ++i)
        if (volume.inside[size_t(i)]) {
          const int c[3] = {x, y, z};
          for (int a = 0; a < 3; ++a)
            lo[size_t(a)] = std::min(lo[size_t(a)], c[a]), hi[size_t(a)] = std::max(hi[size_t(a)], c[a]);
        }
  if (hi[0] < 0) return {0, 0, 0};  // empty: nothing to crop to
  std::array<int, 3> size{};
  for (size_t a = 0; a < 3; ++a) {
    lo[a] = std::max(0, lo[a] - margin);
    hi[a] = std::min(volume.size[a] - 1, hi[a] + margin);
    size[a] = hi[a] - lo[a] + 1;
  }
  if (size == volume.size) return {0, 0, 0};
  BinaryVolume cropped;
  cropped.size = size;
  cropped.spacing = volume.spacing;
  cropped.direction = volume.direction;
  cropped.origin = volume.physical(Eigen::Vector3d(lo[0], lo[1], lo[2]));
  cropped.inside.resize(size_t(cropped.voxelCount()));
  for (int z = 0; z < size[2]; ++z)
    for (int y = 0; y < size[1]; ++y) {
      const int64_t from = volume.index(lo[0], lo[1] + y, lo[2] + z);
      std::copy_n(volume.inside.begin() + from, size[0], cropped.inside.begin() + cropped.index(0, y, z));
    }
  volume = std::move(cropped);
  return lo;
}

}  // namespace medial
