/// \file
/// Parallel: runs independent work items on every core with plain threads (the refinement's projection of
/// a level's vertices, the union's winding-number tests per patch).
#pragma once

#include <algorithm>
#include <cstddef>
#include <functional>
#include <thread>
#include <vector>

namespace medial {

/// Runs work(i) for i in [0, count), the range split into one chunk per core; below `serialBelow` items
/// (too little work to pay for threads) on the calling thread.
inline void inParallel(size_t count, const std::function<void(size_t)>& work, size_t serialBelow = 4096) {
  const size_t threads = std::clamp<size_t>(std::thread::hardware_concurrency(), 1, 16);
  if (threads == 1 || count < serialBelow) {
    for (size_t i = 0; i < count; ++i) work(i);
    return;
  }
  std::vector<std::thread> pool;
  for (size_t t = 0; t < threads; ++t)
    pool.emplace_back([&, t] {
      for (size_t i = t * count / threads; i < (t + 1) * count / threads; ++i) work(i);
    });
  for (auto& thread : pool) thread.join();
}

}  // namespace medial
