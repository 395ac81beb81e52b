/// \file
/// StructureRuns: the structure of a large volume without full-volume masks. The selected voxels are read
/// once into runs along x (two threads, one per half of the slices); runs join into 26-connected parts by
/// union-find with the runs of the neighbouring rows; the part to follow (the largest, leaving out parts that
/// touch the volume's border when asked: the air around a body) - or several parts, for a colon split by
/// collapsed segments - is written straight into its bounding box grown by a margin. This replaces a
/// full-size mask, a flood fill of the air outside and a full-size label volume by a pass that reads each
/// voxel once.
#pragma once

#include "centerline/BinaryVolume.h"

#include <cstdint>
#include <thread>
#include <vector>

namespace medial {

/// Voxels x0..x1 (inclusive) of row (y, z) of a volume.
struct VoxelRun {
  int y;   ///< the row's y
  int z;   ///< the row's z
  int x0;  ///< the run's first x
  int x1;  ///< the run's last x (inclusive)
};

/// The runs of voxels where `selected(index)` holds, rows in order (z, then y), runs in x order; two
/// threads, one per half of the slices.
template <typename Selected>
std::vector<VoxelRun> selectedRuns(const std::array<int, 3>& size, const Selected& selected);

/// The 26-connected parts of a volume's runs (union-find over the runs of neighbouring rows).
struct StructureParts {
  /// One 26-connected part.
  struct Part {
    int64_t voxels = 0;       ///< voxels of the part
    bool border = false;      ///< touches the volume's border
    std::array<int, 3> lo{};  ///< bounding box's first voxel
    std::array<int, 3> hi{};  ///< bounding box's last voxel (inclusive)
  };
  std::vector<Part> parts;        ///< largest first
  std::vector<int> partOfRun;     ///< per run: its part
  std::vector<int64_t> rowStart;  ///< the runs of row y + ny * z: rowStart[row] .. rowStart[row + 1]
  std::array<int, 3> size{};      ///< the volume's size in voxels
  /// The part holding voxel (x, y, z), or -1 when it is not selected.
  int partAt(const std::vector<VoxelRun>& runs, int x, int y, int z) const;
};

/// The 26-connected parts of `runs` (selectedRuns of a volume of `size` voxels).
StructureParts labelParts(const std::array<int, 3>& size, const std::vector<VoxelRun>& runs);

/// The voxels of the `chosen` parts in the union of their boxes grown by `margin` (kept within the
/// volume), in `frame`'s space (its size, origin, spacing and direction; its voxels are not read);
/// `first` receives the box's first voxel in the whole volume.
BinaryVolume partsInBox(const BinaryVolume& frame, const std::vector<VoxelRun>& runs,
                        const StructureParts& parts, const std::vector<int>& chosen, int margin,
                        std::array<int, 3>* first = nullptr);

/// The part largestPart() chose, cut out of the volume.
struct ChosenPart {
  BinaryVolume volume;         ///< the part in its box grown by `margin` (kept within the volume)
  std::array<int, 3> first{};  ///< the box's first voxel in the whole volume
  int64_t voxels = 0;          ///< of the part
  int parts = 0;               ///< 26-connected parts of the selection
  int64_t borderVoxels = 0;    ///< voxels of the parts that touch the border (left out when dropBorder)
};

/// The largest 26-connected part of the runs (of those not touching the border when `dropBorder`), in
/// `frame`'s space (its size, origin, spacing and direction; its voxels are not read). Empty when no part
/// is left.
ChosenPart largestPart(const BinaryVolume& frame, const std::vector<VoxelRun>& runs, bool dropBorder,
                       int margin = 1);

/// \cond INTERNAL
// ---- implementation of the template ----

template <typename Selected>
void runsOfSlices(const std::array<int, 3>& size, const Selected& selected, int zBegin, int zEnd,
                  std::vector<VoxelRun>& runs) {
  for (int z = zBegin; z < zEnd; ++z)
    for (int y = 0; y < size[1]; ++y) {
      const int64_t row = int64_t(size[0]) * (y + int64_t(size[1]) * z);
      int x = 0;
      while (x < size[0]) {
        while (x < size[0] && !selected(row + x)) ++x;
        if (x == size[0]) break;
        const int start = x;
        while (x < size[0] && selected(row + x)) ++x;
        runs.push_back({y, z, start, x - 1});
      }
    }
}

template <typename Selected>
std::vector<VoxelRun> selectedRuns(const std::array<int, 3>& size, const Selected& selected) {
  const int half = size[2] / 2;
  std::vector<VoxelRun> low, high;
  std::thread second([&] { runsOfSlices(size, selected, half, size[2], high); });
  runsOfSlices(size, selected, 0, half, low);
  second.join();
  low.insert(low.end(), high.begin(), high.end());
  return low;
}

/// \endcond

}  // namespace medial
