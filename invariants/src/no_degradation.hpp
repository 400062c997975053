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
//
// And the mesh rule: the volume of tets below theta outside the tool does not grow over the
// transaction. After: the volume of the created tets below theta whose centroid is outside the
// tool's open ball (every created tet, for an operation without a tool). Before: how much of that
// same region, the created tets outside the tool, lay in removed tets below theta (at their old
// positions), the shared volume of each such created and removed pair (tet_intersection.hpp).
// Splitting a tet below theta keeps its volume on both sides; a flip that spreads a bad tet over
// good volume adds to after alone; tissue the cut removed covers nothing after, so a bad tet
// removed in the tool pays for nothing. Per-tet floors alone allow the spread: a created tet is
// held to its centroid's host, and a bad host lowers the floor of a tet that reaches well beyond
// it.
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "report_builder.hpp"
#include "tetcut/invariants/check.hpp"
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
  // tets' corners). `tool`: the cut's tool, or null for an operation without one.
  void finish(std::span<const Vec3> old_positions, std::span<const Vec3> positions, double floor,
              double min_dihedral_deg, const ToolRule* tool, ReportBuilder& report);

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
  // The mesh rule (above), after the per-tet floors, which measured what it needs.
  void check_bad_volume(std::span<const Vec3> old_positions, std::span<const Vec3> positions, double min_dihedral_deg,
                        const ToolRule* tool, ReportBuilder& report);
  // The volume created tet c (at `positions`) shares with the removed tets below theta (at
  // `old_positions`): those sharing one of its vertices or hosting its centroid when `all` is
  // false (a lower bound), every one whose box meets c's when true.
  double bad_volume_under(const Created& c, std::span<const Vec3> old_positions, std::span<const Vec3> positions,
                          double min_dihedral_deg, bool all);

  std::vector<Removed> removed_;
  std::vector<Created> created_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> by_vertex_;  // (vertex, index in removed_), sorted
  std::vector<std::uint32_t> hosts_;                               // per created tet, appended
  std::vector<std::uint32_t> host_begin_;                          // created k: hosts_[begin[k], begin[k + 1])
  std::vector<std::uint32_t> outside_;                             // the mesh rule's created tets (indices)
  std::vector<std::uint32_t> candidates_;                          // bad_volume_under's removed tets
};

}  // namespace tetcut::invariants::detail
