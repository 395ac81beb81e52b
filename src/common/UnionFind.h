/// \file
/// UnionFind: disjoint sets over the integers 0..n-1 with path halving, for the connected components of
/// meshes, skeletons and graphs. join(a, b) hangs a's root under b's, so which root represents a set is
/// predictable (the last joined-to), as the algorithms that number components in root order rely on.
#pragma once

#include <cstddef>
#include <numeric>
#include <vector>

namespace medial {

/// Disjoint sets over 0..n-1 (see the file).
class UnionFind {
 public:
  /// `count` singleton sets.
  explicit UnionFind(size_t count) : parent_(count) { std::iota(parent_.begin(), parent_.end(), 0); }

  /// The representative of x's set.
  int find(int x) {
    while (parent_[size_t(x)] != x) x = parent_[size_t(x)] = parent_[size_t(parent_[size_t(x)])];
    return x;
  }
  /// Joins the sets of a and b; false when they were one already.
  bool join(int a, int b) {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    parent_[size_t(a)] = b;
    return true;
  }
  /// The number of elements.
  size_t size() const { return parent_.size(); }

 private:
  std::vector<int> parent_;
};

}  // namespace medial
