#include "fuzz_failure.hpp"

#include <cstdio>
#include <cstdlib>

namespace tetcut::fuzz {

void fail(std::string_view property, std::size_t operation_index, std::string_view operation,
          std::string_view detail) {
  std::fprintf(stderr, "tetcut-fuzz: %.*s violated after operation %zu (%.*s): %.*s\n",
               static_cast<int>(property.size()), property.data(), operation_index,
               static_cast<int>(operation.size()), operation.data(), static_cast<int>(detail.size()),
               detail.data());
  std::fflush(stderr);
  std::abort();
}

}  // namespace tetcut::fuzz
