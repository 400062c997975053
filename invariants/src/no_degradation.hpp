// I7's rule for a transaction (QualityRule::kNoDegradation): every tet an operation created has a
// radius ratio of at least min(F, its worst host's) and a smallest dihedral angle of at least
// min(theta, its worst host's), each tet its own floors. Its hosts are the removed tets that
// contain its centroid, which the checker locates itself: the created tet's centroid at the new
// positions, in the removed tets at their old positions (an existing vertex moves only within
// the cut's reach, and as the change log says; the local checker keeps the old positions and
// holds every move to that rule), and a host's quality is the one it had. A created tet inside
// its parent has its centroid strictly inside it; after a flip the centroid may sit on the face
// between two removed tets, and then both count (the lenient side: the engine, which aims at one
// host per tet, is never held to more). A created tet whose centroid no removed tet holds (a
// vertex moved out of the region the removed tets covered) is held to the worst host of the
// operation. A created tet at or above F and theta is not located.
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
  // Every created tet with valid references, its radius ratio and smallest dihedral angle.
  void add_created(std::uint32_t t, const RawTet& q, double radius_ratio, double min_dihedral_deg);
  // Locates the hosts of every created tet below F or theta and reports each below its floors,
  // naming its quality, its hosts' and the floors. `old_positions`: the vertices as they were
  // before the operation (the removed tets' corners); `positions`: as they are now (the created
  // tets' corners).
  void finish(std::span<const Vec3> old_positions, std::span<const Vec3> positions, double floor,
              double min_dihedral_deg, ReportBuilder& report);

 private:
  struct Removed {
    std::uint32_t id;
    RawTet q;
    double ratio;     // computed when first found to host something
    double dihedral;  // its smallest dihedral angle, with the ratio
    Vec3 lo, hi;   // bounding box as it was (set in finish()): most tets are rejected by it
  };
  struct Created {
    std::uint32_t id;
    RawTet q;
    double ratio;
    double dihedral;
  };
  // Removed tet k's quality as it was, measured once.
  void measure(Removed& r, std::span<const Vec3> old_positions) const;
  // Indices into removed_ of the tets hosting created tet c (appended to hosts_).
  void locate(const Created& c, std::span<const Vec3> old_positions, std::span<const Vec3> positions);
  bool hosts(const Removed& r, const Vec3& point, std::span<const Vec3> old_positions) const;

  std::vector<Removed> removed_;
  std::vector<Created> created_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> by_vertex_;  // (vertex, index in removed_), sorted
  std::vector<std::uint32_t> hosts_;                               // per created tet, appended
  std::vector<std::uint32_t> host_begin_;                          // created k: hosts_[begin[k], begin[k + 1])
};

}  // namespace tetcut::invariants::detail
