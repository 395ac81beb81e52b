#include "centerline/BinaryVolume.h"

#include <algorithm>
#include <array>
#include <cstdlib>

namespace medial {

namespace {

// Labels the connected components of voxels where `member` holds (26- or 6-connected); returns the label
// per voxel (-1 for non-members) and the size of each component.
template <typename Member>
std::vector<int> labelComponents(const BinaryVolume& v, Member member, bool connect26, std::vector<int64_t>& sizes) {
  std::vector<int> label(size_t(v.voxelCount()), -1);
  // The neighbours as index offsets: a voxel off the volume's faces has all of them inside, without the
  // per-neighbour bounds checks (the bulk of a CT's outside air goes through this fast path).
  std::vector<std::array<int, 3>> steps;
  std::vector<int64_t> offsets;
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int length = std::abs(dx) + std::abs(dy) + std::abs(dz);
        if (length == 0 || (!connect26 && length > 1)) continue;
        steps.push_back({dx, dy, dz});
        offsets.push_back(dx + int64_t(v.size[0]) * (dy + int64_t(v.size[1]) * dz));
      }
  std::vector<int64_t> stack;
  for (int64_t start = 0; start < v.voxelCount(); ++start) {
    if (!member(start) || label[size_t(start)] >= 0) continue;
    const int id = int(sizes.size());
    sizes.push_back(0);
    label[size_t(start)] = id;
    stack.assign(1, start);
    while (!stack.empty()) {
      const int64_t at = stack.back();
      stack.pop_back();
      ++sizes.back();
      const auto c = v.coordinates(at);
      const bool interior = c[0] > 0 && c[1] > 0 && c[2] > 0 && c[0] < v.size[0] - 1 && c[1] < v.size[1] - 1 &&
                            c[2] < v.size[2] - 1;
      for (size_t n = 0; n < offsets.size(); ++n) {
        if (!interior && !v.contains(c[0] + steps[n][0], c[1] + steps[n][1], c[2] + steps[n][2])) continue;
        const int64_t next = at + offsets[n];
        if (member(next) && label[size_t(next)] < 0) {
          label[size_t(next)] = id;
          stack.push_back(next);
        }
      }
    }
  }
  return label;
}

bool onBorder(const BinaryVolume& v, int64_t index) {
  const auto c = v.coordinates(index);
  for (int a = 0; a < 3; ++a)
    if (c[size_t(a)] == 0 || c[size_t(a)] == v.size[size_t(a)] - 1) return true;
  return false;
}

}  // namespace

int keepLargestComponent(BinaryVolume& volume) {
  std::vector<int64_t> sizes;
  const auto label = labelComponents(volume, [&](int64_t i) { return volume.inside[size_t(i)] != 0; }, true, sizes);
  if (sizes.empty()) return 0;
  const int largest = int(std::max_element(sizes.begin(), sizes.end()) - sizes.begin());
  for (int64_t i = 0; i < volume.voxelCount(); ++i) volume.inside[size_t(i)] = label[size_t(i)] == largest;
  return int(sizes.size());
}

int64_t dropBorderTouchingParts(BinaryVolume& volume) {
  std::vector<int64_t> sizes;
  const auto label = labelComponents(volume, [&](int64_t i) { return volume.inside[size_t(i)] != 0; }, true, sizes);
  std::vector<bool> touches(sizes.size(), false);
  for (int64_t i = 0; i < volume.voxelCount(); ++i)
    if (label[size_t(i)] >= 0 && onBorder(volume, i)) touches[size_t(label[size_t(i)])] = true;
  int64_t removed = 0;
  for (int64_t i = 0; i < volume.voxelCount(); ++i)
    if (label[size_t(i)] >= 0 && touches[size_t(label[size_t(i)])]) {
      volume.inside[size_t(i)] = 0;
      ++removed;
    }
  return removed;
}

int64_t fillHoles(BinaryVolume& volume) {
  std::vector<int64_t> sizes;
  const auto label = labelComponents(volume, [&](int64_t i) { return volume.inside[size_t(i)] == 0; }, false, sizes);
  std::vector<bool> outside(sizes.size(), false);
  for (int64_t i = 0; i < volume.voxelCount(); ++i)
    if (label[size_t(i)] >= 0 && onBorder(volume, i)) outside[size_t(label[size_t(i)])] = true;
  int64_t filled = 0;
  for (int64_t i = 0; i < volume.voxelCount(); ++i)
    if (label[size_t(i)] >= 0 && !outside[size_t(label[size_t(i)])]) {
      volume.inside[size_t(i)] = 1;
      ++filled;
    }
  return filled;
}

}  // namespace medial
