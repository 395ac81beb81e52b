/// \file
/// Parallel: runs independent work items on every core with plain threads (the refinement's projection of
/// a level's vertices, the union's winding-number tests per patch and its cutting per cluster).
#pragma once

#include <algorithm>
#include <atomic>
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

/// Runs work(i) for i in [0, count), each core taking the next item when it is free: for few items of
/// unequal size (the union's clusters, largest first).
inline void inParallelEach(size_t count, const std::function<void(size_t)>& work) {
  const size_t threads = std::clamp<size_t>(std::thread::hardware_concurrency(), 1, 16);
  std::atomic<size_t> next{0};
  const auto worker = [&] {
    for (size_t i = next++; i < count; i = next++) work(i);
  };
  if (threads == 1 || count < 2) {
    worker();
    return;
  }
  std::vector<std::thread> pool;
  for (size_t t = 1; t < std::min(threads, count); ++t) pool.emplace_back(worker);
  worker();
  for (auto& thread : pool) thread.join();
}

}  // namespace medial
