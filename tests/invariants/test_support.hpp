// Small meshes and helpers shared by the checker's tests.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "tetcut/box_mesh.hpp"
#include "tetcut/invariants/check.hpp"
#include "tetcut/mesh_builder.hpp"
#include "tetcut/predicates.hpp"

namespace tetcut::invariants::testing {

// "I1 I5": the violated invariants of a report, in order; "" when valid.
inline std::string names(const CheckReport& report) {
  std::string out;
  for (const Violation& v : report.violations) {
    if (!out.empty()) out += ' ';
    out += id_string(v.id);
  }
  return out;
}

inline bool has(const CheckReport& report, Invariant id) { return report.find(id) != nullptr; }

inline CheckOptions exact() {
  CheckOptions options;
  options.level = CheckLevel::kExact;
  return options;
}

// Builds and asserts success (the builder's problems are listed otherwise).
inline TetMesh build_or_fail(const RawMesh& raw) {
  BuildResult result = build_mesh(raw);
  for (const BuildProblem& p : result.problems) ADD_FAILURE() << to_string(p.kind) << ": " << p.message;
  if (!result.ok()) return TetMesh{};
  return std::move(*result.mesh);
}

// `b` appended to `a`, vertices renumbered; positions equal to one of `a` are welded onto it
// (that is how the bowties below touch).
inline RawMesh weld(RawMesh a, const RawMesh& b) {
  std::vector<std::uint32_t> to_a(b.positions.size());
  for (std::size_t i = 0; i < b.positions.size(); ++i) {
    std::uint32_t found = static_cast<std::uint32_t>(a.positions.size());
    for (std::uint32_t j = 0; j < a.positions.size(); ++j)
      if (a.positions[j] == b.positions[i]) found = j;
    if (found == a.positions.size()) a.positions.push_back(b.positions[i]);
    to_a[i] = found;
  }
  for (const auto& t : b.tets) a.tets.push_back({to_a[t[0]], to_a[t[1]], to_a[t[2]], to_a[t[3]]});
  return a;
}

// Swaps two vertices of every negatively oriented tet.
inline void orient_positive(RawMesh& mesh) {
  for (auto& t : mesh.tets) {
    if (orientation(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]], mesh.positions[t[3]]) < 0)
      std::swap(t[1], t[2]);
  }
}

}  // namespace tetcut::invariants::testing
