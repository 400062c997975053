#include "operations/scenario_recorder.hpp"

#include <charconv>
#include <cmath>
#include <utility>

namespace tetcut::fuzz {

std::string format_number(double x) {
  if (x == 0.0) x = 0.0;  // no "-0"
  char buffer[64];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, x);
  return ec == std::errc{} ? std::string(buffer, end) : std::string("0");
}

std::string format_point(const Vec3& p) {
  return format_number(p.x) + "," + format_number(p.y) + "," + format_number(p.z);
}

double round_to(double x, double quantum) {
  // Dividing by 1/quantum (an exact integer power of ten for quantum <= 1) and reading the
  // result back through text gives the double the text "k e-d" denotes: what a scenario reads.
  const double k = std::round(x / quantum);
  std::string text = format_number(k) + "e" + std::to_string(static_cast<int>(std::lround(std::log10(quantum))));
  double value = 0.0;
  std::from_chars(text.data(), text.data() + text.size(), value);
  return value;
}

double coordinate_quantum(double diagonal, int digits) {
  const double d = diagonal > 0.0 && std::isfinite(diagonal) ? diagonal : 1.0;
  return std::pow(10.0, std::floor(std::log10(d)) - digits);
}

std::uint32_t ScenarioRecorder::add(std::string line) {
  if (!enabled_) return 0;
  lines_.push_back(std::move(line));
  return lines();
}

void ScenarioRecorder::replace(std::uint32_t number, std::string line) {
  if (enabled_ && number >= 1 && number <= lines_.size()) lines_[number - 1] = std::move(line);
}

void ScenarioRecorder::map_operation(std::size_t index, std::uint32_t number) {
  if (!enabled_) return;
  if (operation_lines_.size() <= index) operation_lines_.resize(index + 1, 0);
  operation_lines_[index] = number;
}

std::uint32_t ScenarioRecorder::line_of(std::size_t index) const {
  return index < operation_lines_.size() ? operation_lines_[index] : 0;
}

std::string ScenarioRecorder::text() const {
  std::string out;
  for (const std::string& line : lines_) {
    out += line;
    out += '\n';
  }
  return out;
}

}  // namespace tetcut::fuzz
