#pragma once
// Runs f(row) for every row in [0, rows) on `threads` std::threads (0: hardware concurrency).
// Rows are handed out in interleaved order (thread t takes t, t + T, ...), every row is computed
// by exactly one thread and writes only its own output, so results do not depend on the thread
// count.
#include <algorithm>
#include <thread>
#include <vector>

namespace pyro {

template <class F>
void parallel_rows(int rows, int threads, F&& f) {
  int t = threads > 0 ? threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  t = std::max(1, std::min(t, rows));
  if (t == 1) {
    for (int r = 0; r < rows; ++r) f(r);
    return;
  }
  std::vector<std::thread> pool;
  pool.reserve(t);
  for (int k = 0; k < t; ++k)
    pool.emplace_back([&, k] {
      for (int r = k; r < rows; r += t) f(r);
    });
  for (std::thread& th : pool) th.join();
}

}  // namespace pyro
