#include "tetcut/cut_strategies.hpp"

namespace tetcut {

const char* to_string(RemovalStrategy strategy) {
  switch (strategy) {
    case RemovalStrategy::kBasic: return "basic";
    case RemovalStrategy::kNeighbours: return "neighbours";
    case RemovalStrategy::kCombined: return "combined";
    case RemovalStrategy::kWide: return "wide";
  }
  return "?";
}

std::optional<RemovalStrategy> parse_removal_strategy(std::string_view text) {
  if (text == "basic") return RemovalStrategy::kBasic;
  if (text == "neighbours" || text == "neighbors") return RemovalStrategy::kNeighbours;
  if (text == "combined") return RemovalStrategy::kCombined;
  if (text == "wide") return RemovalStrategy::kWide;
  return std::nullopt;
}

}  // namespace tetcut
