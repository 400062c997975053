#include "tetcut/cut_strategies.hpp"

#include <utility>

namespace tetcut {
namespace {

// Each choice's spellings in one table, read both ways; the first spelling of a value is the one
// printed, the later ones are accepted aliases.
template <class Enum>
using Spellings = std::pair<std::string_view, Enum>;

constexpr Spellings<RemovalStrategy> kStrategyNames[] = {{"basic", RemovalStrategy::kBasic},
                                                         {"neighbours", RemovalStrategy::kNeighbours},
                                                         {"neighbors", RemovalStrategy::kNeighbours},
                                                         {"combined", RemovalStrategy::kCombined},
                                                         {"wide", RemovalStrategy::kWide}};
constexpr Spellings<RemovalOrder> kOrderNames[] = {{"direct-first", RemovalOrder::kDirectFirst},
                                                   {"surface-first-by-id", RemovalOrder::kSurfaceFirstById},
                                                   {"paper", RemovalOrder::kSurfaceFirstById},
                                                   {"revisit", RemovalOrder::kRevisit}};
constexpr Spellings<NeighbourSetChoice> kNeighbourSetNames[] = {{"smallest", NeighbourSetChoice::kSmallest},
                                                                {"first", NeighbourSetChoice::kFirst}};
constexpr Spellings<SplitMethod> kSplitMethodNames[] = {{"templates", SplitMethod::kTemplates},
                                                        {"bisection", SplitMethod::kBisection}};
constexpr Spellings<RefinementRule> kRefinementNames[] = {{"paper", RefinementRule::kPaper},
                                                          {"graded", RefinementRule::kGraded},
                                                          {"auto", RefinementRule::kAuto}};

template <class Enum, std::size_t N>
const char* name_of(const Spellings<Enum> (&names)[N], Enum value) {
  for (const auto& [name, v] : names)
    if (v == value) return name.data();  // the literals are NUL-terminated
  return "?";
}

template <class Enum, std::size_t N>
std::optional<Enum> value_of(const Spellings<Enum> (&names)[N], std::string_view text) {
  for (const auto& [name, v] : names)
    if (name == text) return v;
  return std::nullopt;
}

}  // namespace

const char* to_string(RemovalStrategy strategy) { return name_of(kStrategyNames, strategy); }

std::optional<RemovalStrategy> parse_removal_strategy(std::string_view text) {
  return value_of(kStrategyNames, text);
}

const char* to_string(RemovalOrder order) { return name_of(kOrderNames, order); }

std::optional<RemovalOrder> parse_removal_order(std::string_view text) { return value_of(kOrderNames, text); }

const char* to_string(NeighbourSetChoice choice) { return name_of(kNeighbourSetNames, choice); }

std::optional<NeighbourSetChoice> parse_neighbour_set_choice(std::string_view text) {
  return value_of(kNeighbourSetNames, text);
}

const char* to_string(SplitMethod method) { return name_of(kSplitMethodNames, method); }

std::optional<SplitMethod> parse_split_method(std::string_view text) { return value_of(kSplitMethodNames, text); }

const char* to_string(RefinementRule rule) { return name_of(kRefinementNames, rule); }

std::optional<RefinementRule> parse_refinement_rule(std::string_view text) { return value_of(kRefinementNames, text); }

}  // namespace tetcut
