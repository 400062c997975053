// Working memory that is ready before the first operation needs it, so that the first cut costs
// what the others do.
//
// std::vector::reserve() allocates but does not touch: the pages arrive one fault at a time,
// inside whichever operation first writes there. On the virtual machines simulators and CI run
// on, a fault costs microseconds, and a first cut that faults its working memory in costs many
// times what the next one does. reserve_touched() allocates and writes the whole
// capacity once, then restores the size: the capacity stays, and so do the pages. A vector that
// already has the capacity is left alone: it was touched when it got it (here, or by a cut that
// grew it), and Cutter::reset() on the next mesh then costs nothing here.
#pragma once

#include <cstddef>
#include <vector>

namespace tetcut::detail {

template <class T>
void reserve_touched(std::vector<T>& v, std::size_t n) {
  if (v.capacity() >= n) return;
  v.reserve(n);
  const std::size_t size = v.size();
  v.resize(v.capacity());
  v.resize(size);
}

}  // namespace tetcut::detail
