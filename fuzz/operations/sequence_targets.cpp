#include "operations/cut_sequence_decoder.hpp"
#include "operations/removal_sequence_decoder.hpp"
#include "operations/sequence_support.hpp"

namespace tetcut::fuzz {

namespace {
constexpr SequenceTarget kTargets[] = {
    {"removal_sequence", &removal_sequence::run, &removal_sequence::decode_to_scenario, "1, 2 or 3"},
    {"cut_sequence", &cut_sequence::run, &cut_sequence::decode_to_scenario, "1, 2 or 3"},
};
}  // namespace

std::span<const SequenceTarget> sequence_targets() { return kTargets; }

const SequenceTarget* find_sequence_target(std::string_view name) {
  for (const SequenceTarget& t : kTargets)
    if (t.name == name) return &t;
  return nullptr;
}

}  // namespace tetcut::fuzz
