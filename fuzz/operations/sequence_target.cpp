#include "operations/sequence_target.hpp"

#include <cstdlib>

#include "operations/cut_sequence_decoder.hpp"
#include "operations/removal_sequence_decoder.hpp"

namespace tetcut::fuzz {

namespace {
constexpr SequenceTarget kTargets[] = {
    {"removal_sequence", &removal_sequence::run},
    {"cut_sequence", &cut_sequence::run},
};
}  // namespace

std::span<const SequenceTarget> sequence_targets() { return kTargets; }

const SequenceTarget* find_sequence_target(std::string_view name) {
  for (const SequenceTarget& t : kTargets)
    if (t.name == name) return &t;
  return nullptr;
}

bool legacy_versions_from_env() {
  const char* env = std::getenv("TETCUT_FUZZ_CURRENT_VERSION_ONLY");
  return env == nullptr || *env == '\0' || std::string_view(env) == "0";
}

}  // namespace tetcut::fuzz
