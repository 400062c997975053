// Accumulates violations, one slot per invariant: a count, the first offending elements and the
// detail line of the first offence. The detail is formatted only for the first offence, so that
// a mesh with a million bad tets does not format a million strings.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <string>
#include <utility>

#include "tetcut/invariants/check.hpp"

namespace tetcut::invariants::detail {

// Numbers in detail lines: ids and counts in decimal, doubles so that they read back exactly.
inline std::string str(std::uint64_t x) { return std::to_string(x); }
inline std::string num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

class ReportBuilder {
 public:
  ReportBuilder() {
    for (int i = 0; i < kInvariantCount; ++i) slots_[i].id = static_cast<Invariant>(i + 1);
  }

  // One offence against `id`. `make_detail` is called only for the first one.
  template <class MakeDetail>
  void add(Invariant id, std::initializer_list<std::uint32_t> tets,
           std::initializer_list<std::uint32_t> vertices, MakeDetail&& make_detail) {
    Violation& slot = slots_[index(id)];
    if (slot.count == 0) slot.detail = std::forward<MakeDetail>(make_detail)();
    ++slot.count;
    for (std::uint32_t t : tets) list(slot.tets, t);
    for (std::uint32_t v : vertices) list(slot.vertices, v);
  }

  // `extra` more offences against `id` beyond those added one by one (not listed).
  void add_count(Invariant id, std::uint64_t extra) { slots_[index(id)].count += extra; }

  [[nodiscard]] bool has(Invariant id) const { return slots_[index(id)].count != 0; }

  // Moves the violations, in invariant order, into `report`.
  void finish(CheckReport& report) {
    for (Violation& slot : slots_) {
      if (slot.count == 0) continue;
      if (slot.count > 1) slot.detail += " (and " + std::to_string(slot.count - 1) + " more)";
      if (!report.operation.empty()) slot.detail = "after " + report.operation + ": " + slot.detail;
      report.violations.push_back(std::move(slot));
    }
  }

 private:
  static std::size_t index(Invariant id) { return static_cast<std::size_t>(id) - 1; }
  static void list(std::vector<std::uint32_t>& out, std::uint32_t x) {
    if (out.size() < kMaxListed && std::find(out.begin(), out.end(), x) == out.end()) out.push_back(x);
  }

  std::array<Violation, kInvariantCount> slots_;
};

}  // namespace tetcut::invariants::detail
