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

const char* to_string(SplitMethod method) {
  switch (method) {
    case SplitMethod::kTemplates: return "templates";
    case SplitMethod::kBisection: return "bisection";
  }
  return "?";
}

std::optional<SplitMethod> parse_split_method(std::string_view text) {
  if (text == "templates") return SplitMethod::kTemplates;
  if (text == "bisection") return SplitMethod::kBisection;
  return std::nullopt;
}

}  // namespace tetcut
