#include "mesh/BoxPairs.h"

#include "common/Parallel.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace medial {

namespace {

constexpr int kCoordinateBits = 21;  // cell coordinates packed three to a 64-bit key
constexpr int64_t kMaxCellsPerAxis = (int64_t(1) << kCoordinateBits) - 1;
constexpr int64_t kMaxCellsPerBox = 4096;  // a box over more cells is tested against all others instead
// Cells of three times the median box's longest side: on SQM chains of 10^5 nodes 1.5x faster than cells
// of one side (fewer cells per box) and as fast as four or six sides (more boxes per cell).
constexpr double kCellScale = 3;

struct Grid {
  Eigen::Vector3d origin;
  double cell = 1;
  Eigen::Array3i cellOf(const Eigen::Vector3d& p) const {
    return ((p - origin) / cell).array().floor().cast<int>().cwiseMax(0).cwiseMin(int(kMaxCellsPerAxis));
  }
};

uint64_t keyOf(const Eigen::Array3i& c) {
  return (uint64_t(c.x()) << (2 * kCoordinateBits)) | (uint64_t(c.y()) << kCoordinateBits) | uint64_t(c.z());
}

bool overlap(const Box3& a, const Box3& b) {
  return (a.low.array() <= b.high.array()).all() && (b.low.array() <= a.high.array()).all();
}

// Cells of kCellScale median box sides, coarser if the grid would not fit the keys.
Grid gridFor(const std::vector<Box3>& boxes) {
  Grid grid;
  Eigen::Vector3d low = boxes[0].low, high = boxes[0].high;
  std::vector<double> sides(boxes.size());
  for (size_t b = 0; b < boxes.size(); ++b) {
    low = low.cwiseMin(boxes[b].low);
    high = high.cwiseMax(boxes[b].high);
    sides[b] = (boxes[b].high - boxes[b].low).maxCoeff();
  }
  std::nth_element(sides.begin(), sides.begin() + long(sides.size() / 2), sides.end());
  const double extent = (high - low).maxCoeff();
  grid.origin = low;
  grid.cell = std::max({kCellScale * sides[sides.size() / 2], extent / double(kMaxCellsPerAxis - 1), 1e-300});
  return grid;
}

using Entry = std::pair<uint64_t, int>;  // a cell's key and a box in it

// The pairs of a bucket's entries that overlap, each reported in one cell only: the one holding the low
// corner of the two boxes' overlap. Within a cell the boxes are swept along x (sorted by their low x, each
// tested only against those starting before it ends): a cell of a refined mesh where tubes overlap holds
// dozens of faces, and testing all pairs there took most of the search.
void pairsInBucket(const std::vector<Box3>& boxes, const std::vector<char>* selected, const Grid& grid,
                   std::vector<Entry>::iterator first, std::vector<Entry>::iterator last,
                   std::vector<std::pair<int, int>>& pairs, std::vector<Box3>& cellBoxes,
                   std::vector<int>& cellIds) {
  std::sort(first, last);  // a handful of cells per bucket: equal keys become runs
  for (auto run = first; run != last;) {
    auto end = run;
    while (end != last && end->first == run->first) ++end;
    std::sort(run, end, [&](const Entry& a, const Entry& b) {
      const double ax = boxes[size_t(a.second)].low.x(), bx = boxes[size_t(b.second)].low.x();
      return ax < bx || (ax == bx && a.second < b.second);
    });
    cellBoxes.clear();
    cellIds.clear();
    for (auto e = run; e != end; ++e) {
      cellBoxes.push_back(boxes[size_t(e->second)]);
      cellIds.push_back(e->second);
    }
    for (size_t a = 0; a < cellBoxes.size(); ++a) {
      const Box3& p = cellBoxes[a];
      for (size_t b = a + 1; b < cellBoxes.size() && cellBoxes[b].low.x() <= p.high.x(); ++b) {
        const int i = cellIds[a], j = cellIds[b];
        if (selected && !(*selected)[size_t(i)] && !(*selected)[size_t(j)]) continue;
        const Box3& q = cellBoxes[b];
        if (overlap(p, q) && keyOf(grid.cellOf(p.low.cwiseMax(q.low))) == run->first)
          pairs.emplace_back(std::min(i, j), std::max(i, j));
      }
    }
    run = end;
  }
}

}  // namespace

std::vector<std::pair<int, int>> overlappingBoxPairs(const std::vector<Box3>& boxes,
                                                     const std::vector<char>* selected) {
  std::vector<std::pair<int, int>> pairs;
  if (boxes.size() < 2) return pairs;
  const Grid grid = gridFor(boxes);
  const auto isSelected = [&](size_t b) { return !selected || (*selected)[b]; };
  const auto cellsOf = [&](size_t b, auto&& visit) {
    const Eigen::Array3i from = grid.cellOf(boxes[b].low), to = grid.cellOf(boxes[b].high);
    for (int x = from.x(); x <= to.x(); ++x)
      for (int y = from.y(); y <= to.y(); ++y)
        for (int z = from.z(); z <= to.z(); ++z) visit(keyOf({x, y, z}));
  };
  std::vector<int> large;  // boxes over too many cells
  std::vector<char> isLarge(boxes.size(), 0);
  for (size_t b = 0; b < boxes.size(); ++b) {
    const Eigen::Array3i from = grid.cellOf(boxes[b].low), to = grid.cellOf(boxes[b].high);
    if ((to - from + 1).cast<int64_t>().prod() > kMaxCellsPerBox) {
      large.push_back(int(b));
      isLarge[b] = 1;
    }
  }
  // With a selection, only the cells its boxes cover.
  std::vector<uint64_t> selectedCells;
  if (selected) {
    for (size_t b = 0; b < boxes.size(); ++b)
      if (isSelected(b) && !isLarge[b]) cellsOf(b, [&](uint64_t key) { selectedCells.push_back(key); });
    std::sort(selectedCells.begin(), selectedCells.end());
    selectedCells.erase(std::unique(selectedCells.begin(), selectedCells.end()), selectedCells.end());
  }
  // (cell, box) entries, grouped by cell with a counting sort on a hash of the key.
  std::vector<Entry> entries;
  for (size_t b = 0; b < boxes.size(); ++b)
    if (!isLarge[b])
      cellsOf(b, [&](uint64_t key) {
        if (!selected || std::binary_search(selectedCells.begin(), selectedCells.end(), key))
          entries.emplace_back(key, int(b));
      });
  const size_t buckets = std::max<size_t>(1, entries.size());
  const auto bucketOf = [&](uint64_t key) { return size_t((key * 0x9E3779B97F4A7C15ull) >> 20) % buckets; };
  std::vector<size_t> start(buckets + 1, 0);
  for (const auto& e : entries) ++start[bucketOf(e.first) + 1];
  for (size_t k = 0; k < buckets; ++k) start[k + 1] += start[k];
  std::vector<Entry> grouped(entries.size());
  std::vector<size_t> fill(start.begin(), start.end() - 1);
  for (const auto& e : entries) grouped[fill[bucketOf(e.first)]++] = e;
  entries.clear();
  entries.shrink_to_fit();
  // Buckets in chunks, one list of pairs per chunk, joined in chunk order: the same order on any core count.
  constexpr size_t chunks = 64;
  std::vector<std::vector<std::pair<int, int>>> found(chunks);
  inParallel(
      chunks,
      [&](size_t c) {
        std::vector<Box3> cellBoxes;
        std::vector<int> cellIds;
        for (size_t k = c * buckets / chunks; k < (c + 1) * buckets / chunks; ++k)
          pairsInBucket(boxes, selected, grid, grouped.begin() + long(start[k]),
                        grouped.begin() + long(start[k + 1]), found[c], cellBoxes, cellIds);
      },
      1);
  for (const auto& part : found) pairs.insert(pairs.end(), part.begin(), part.end());
  // Boxes over many cells against every other box (a pair of two such boxes once).
  for (int a : large)
    for (size_t b = 0; b < boxes.size(); ++b)
      if (int(b) != a && (!isLarge[b] || int(b) > a) && (isSelected(size_t(a)) || isSelected(b)) &&
          overlap(boxes[size_t(a)], boxes[b]))
        pairs.emplace_back(std::min(a, int(b)), std::max(a, int(b)));
  return pairs;
}

}  // namespace medial
