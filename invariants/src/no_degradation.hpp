// I7's rule for a transaction (QualityRule::kNoDegradation): no tet an operation created is worse
// than min(F, the worst tet it replaced). A removed tet is replaced when it contains a created
// tet's centroid, which the checker locates itself among the removed tets (their vertices as the
// mesh still has them: vertices that were there before an operation never move, and the local
// checker reports one that did). A created tet inside its parent has its centroid strictly inside
// it; after a flip the centroid may sit on the face between two removed tets, and then both count
// (the lenient side: the engine, which aims at one host per tet, is never held to more).
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "report_builder.hpp"
#include "tetcut/vec3.hpp"
#include "vertex_link.hpp"

namespace tetcut::invariants::detail {

class NoDegradationCheck {
 public:
  void begin();
  // Before the local checker forgets them: the removed tets and their vertices.
  void add_removed(std::uint32_t t, const RawTet& q);
  // Every created tet with valid references, and its radius ratio.
  void add_created(std::uint32_t t, const RawTet& q, double radius_ratio);
  // Locates the hosts, computes the floor min(F, worst host) and reports every created tet below
  // it, naming its quality, its hosts' and the floor.
  void finish(std::span<const Vec3> positions, double floor, ReportBuilder& report);

 private:
  struct Removed {
    std::uint32_t id;
    RawTet q;
    double ratio;  // computed when first found to host something
    Vec3 lo, hi;   // bounding box (set in finish()): most tets are rejected by it
  };
  struct Created {
    std::uint32_t id;
    RawTet q;
    double ratio;
  };
  // Indices into removed_ of the tets hosting created tet c (appended to hosts_).
  void locate(const Created& c, std::span<const Vec3> positions);
  bool hosts(const Removed& r, const Vec3& point, std::span<const Vec3> positions) const;

  std::vector<Removed> removed_;
  std::vector<Created> created_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> by_vertex_;  // (vertex, index in removed_), sorted
  std::vector<std::uint32_t> hosts_;                               // per created tet, appended
  std::vector<std::uint32_t> host_begin_;                          // created k: hosts_[begin[k], begin[k + 1])
};

}  // namespace tetcut::invariants::detail
