// Delta debugging (Zeller and Hildebrandt's ddmin): the smallest sequence found that still
// fails, by dropping ever smaller chunks while `fails` holds, then single elements from the end
// (1-minimal for deletions). One implementation for every minimizer: `tetcut minimize` over a
// scenario's lines, and the engine harness over an engine's operations
// (harness/src/engine_regression.cpp). `fails` is not called once `stop()` says so (a budget of
// runs spent).
#pragma once

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <utility>
#include <vector>

namespace tetcut::scenario {

template <class T, class Fails, class Stop>
void delta_debug(std::vector<T>& items, Fails&& fails, Stop&& stop) {
  std::size_t parts = 2;
  while (items.size() >= 2 && !stop()) {
    const std::size_t chunk = (items.size() + parts - 1) / parts;
    bool reduced = false;
    for (std::size_t start = 0; start < items.size(); start += chunk) {
      std::vector<T> candidate(items.begin(), items.begin() + static_cast<std::ptrdiff_t>(start));
      candidate.insert(candidate.end(), items.begin() + static_cast<std::ptrdiff_t>(std::min(start + chunk, items.size())),
                       items.end());
      if (fails(candidate)) {
        items = std::move(candidate);
        parts = std::max<std::size_t>(parts - 1, 2);
        reduced = true;
        break;
      }
    }
    if (!reduced) {
      if (chunk == 1) break;
      parts = std::min(parts * 2, items.size());
    }
  }
  for (std::size_t i = items.size(); i-- > 0 && !stop();) {
    std::vector<T> candidate = items;
    candidate.erase(candidate.begin() + static_cast<std::ptrdiff_t>(i));
    if (fails(candidate)) items = std::move(candidate);
  }
}

}  // namespace tetcut::scenario
