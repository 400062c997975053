// check_fragments: what the engine reports after a cut (the pieces it detached, the organ, its
// piece count), judged against the checker's own pieces (count_components, components.hpp) and
// its own measure of each: the volume and the centroid are recomputed from the positions, never
// taken from the report.
#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>
#include <utility>

#include "report_builder.hpp"
#include "tet_checks.hpp"
#include "tetcut/invariants/check.hpp"

namespace tetcut::invariants {

const char* description(FragmentFault fault) {
  switch (fault) {
    case FragmentFault::kDeadTet: return "a listed tet not live";
    case FragmentFault::kRepeatedTet: return "a tet listed twice";
    case FragmentFault::kNoPiece: return "a fragment without a live tet";
    case FragmentFault::kForeignTet: return "a tet of another piece listed";
    case FragmentFault::kMissingTet: return "a tet of the piece not listed";
    case FragmentFault::kSamePiece: return "two fragments of one piece";
    case FragmentFault::kVolume: return "fragment volume";
    case FragmentFault::kCentroid: return "fragment centroid";
    case FragmentFault::kOrganTet: return "organ tet not live";
    case FragmentFault::kOrganListed: return "the organ reported as a fragment";
    case FragmentFault::kLargerThanOrgan: return "a fragment larger than the organ";
    case FragmentFault::kPieceCount: return "piece count";
  }
  return "unknown";
}

const FragmentViolation* FragmentCheckReport::find(FragmentFault fault, std::optional<std::uint32_t> fragment) const {
  for (const FragmentViolation& v : violations)
    if (v.fault == fault && (!fragment || v.fragment == *fragment)) return &v;
  return nullptr;
}

std::string to_string(const FragmentCheckReport& report) {
  std::string out;
  for (const FragmentViolation& v : report.violations) out += std::string("fragments: ") + description(v.fault) + ": " + v.detail + '\n';
  for (const std::string& note : report.notes) out += "note: " + note + '\n';
  return out;
}

namespace {

using detail::num;
using detail::str;

std::string str(const Vec3& p) {
  std::string out(1, '(');  // appended, not "(" + ...: GCC 12 warns falsely (-Wrestrict) on that
  out += num(p.x);
  out += ", ";
  out += num(p.y);
  out += ", ";
  out += num(p.z);
  out += ')';
  return out;
}

// The checker's measure of every piece: the sum of its tets' |signed volume| (compensated), the
// rounding bound of that sum, and its volume-weighted centroid. The centroid is summed relative
// to the centre of the bounding box, so that a mesh far from the origin keeps its digits.
struct PieceMeasures {
  std::vector<detail::VolumeSum> volume;
  std::vector<double> rounding;
  std::vector<std::array<detail::VolumeSum, 3>> moment;  // sum of |volume| * (centroid - reference)
  Vec3 reference;
  double diagonal = 0.0;              // of the bounding box of the live tets' vertices
  std::uint64_t bad_reference_tets = 0;  // live tets left out: a vertex id out of range

  [[nodiscard]] Vec3 centroid(std::uint32_t piece) const {
    const double v = volume[piece].value();
    const auto& m = moment[piece];
    return reference + (1.0 / v) * Vec3{m[0].value(), m[1].value(), m[2].value()};
  }
};

PieceMeasures measure(const RawMeshView& mesh, const Components& pieces) {
  PieceMeasures out;
  out.volume.resize(pieces.count);
  out.rounding.assign(pieces.count, 0.0);
  out.moment.resize(pieces.count);
  const auto tet_count = static_cast<std::uint32_t>(mesh.tets.size());
  auto usable = [&](std::uint32_t t) {
    if (pieces.of_tet[t] == kNoComponent) return false;
    for (std::uint32_t v : mesh.tets[t])
      if (v >= mesh.positions.size()) return false;
    return true;
  };

  Vec3 lo{}, hi{};
  bool any = false;
  for (std::uint32_t t = 0; t < tet_count; ++t) {
    if (!usable(t)) continue;
    for (std::uint32_t v : mesh.tets[t]) {
      const Vec3& p = mesh.positions[v];
      if (!any) lo = hi = p;
      any = true;
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
  }
  out.reference = 0.5 * (lo + hi);
  out.diagonal = norm(hi - lo);

  for (std::uint32_t t = 0; t < tet_count; ++t) {
    if (pieces.of_tet[t] == kNoComponent) continue;
    if (!usable(t)) {
      ++out.bad_reference_tets;
      continue;
    }
    const auto& q = mesh.tets[t];
    const std::uint32_t p = pieces.of_tet[t];
    const double v = std::fabs(detail::tet_volume(q, mesh.positions));
    out.volume[p].add(v);
    out.rounding[p] += detail::tet_volume_rounding_bound(q, mesh.positions);
    Vec3 c{};
    for (std::uint32_t i : q) c = c + 0.25 * (mesh.positions[i] - out.reference);
    out.moment[p][0].add(v * c.x);
    out.moment[p][1].add(v * c.y);
    out.moment[p][2].add(v * c.z);
  }
  return out;
}

// The tets of each piece, in tet order: a counting sort of Components::of_tet.
class PieceMembers {
 public:
  explicit PieceMembers(const Components& pieces) : offsets_(static_cast<std::size_t>(pieces.count) + 1, 0) {
    for (std::uint32_t p : pieces.of_tet)
      if (p != kNoComponent) ++offsets_[p + 1];
    for (std::uint32_t p = 0; p < pieces.count; ++p) offsets_[p + 1] += offsets_[p];
    tets_.resize(offsets_.back());
    std::vector<std::uint32_t> cursor(offsets_.begin(), offsets_.end() - 1);
    for (std::uint32_t t = 0; t < pieces.of_tet.size(); ++t)
      if (pieces.of_tet[t] != kNoComponent) tets_[cursor[pieces.of_tet[t]]++] = t;
  }
  [[nodiscard]] std::span<const std::uint32_t> of(std::uint32_t piece) const {
    return {tets_.data() + offsets_[piece], offsets_[piece + 1] - offsets_[piece]};
  }

 private:
  std::vector<std::uint32_t> offsets_;
  std::vector<std::uint32_t> tets_;
};

// One FragmentViolation per (fragment, fault): its count, its first tets, the detail of its
// first offence (formatted only then).
class Faults {
 public:
  explicit Faults(FragmentCheckReport& report) : report_(report) {}

  template <class MakeDetail>
  void add(FragmentFault fault, std::uint32_t fragment, std::uint32_t tet, MakeDetail&& make_detail) {
    FragmentViolation* slot = nullptr;
    for (FragmentViolation& v : report_.violations)
      if (v.fault == fault && v.fragment == fragment) slot = &v;
    if (slot == nullptr) {
      slot = &report_.violations.emplace_back();
      slot->fault = fault;
      slot->fragment = fragment;
      slot->detail = std::forward<MakeDetail>(make_detail)();
    }
    ++slot->count;
    if (tet != kNoRawRef && slot->tets.size() < kMaxListed &&
        std::find(slot->tets.begin(), slot->tets.end(), tet) == slot->tets.end())
      slot->tets.push_back(tet);
  }

  // By fragment (faults of no fragment last), then in FragmentFault order.
  void finish() {
    for (FragmentViolation& v : report_.violations) {
      if (v.count > 1) v.detail += " (and " + std::to_string(v.count - 1) + " more)";
      if (!report_.operation.empty()) v.detail = "after " + report_.operation + ": " + v.detail;
    }
    std::stable_sort(report_.violations.begin(), report_.violations.end(),
                     [](const FragmentViolation& a, const FragmentViolation& b) {
                       return std::tie(a.fragment, a.fault) < std::tie(b.fragment, b.fault);
                     });
  }

 private:
  FragmentCheckReport& report_;
};

}  // namespace

FragmentCheckReport check_fragments(const RawMeshView& mesh, const FragmentReport& report,
                                    const CheckOptions& options) {
  FragmentCheckReport out;
  out.operation = options.operation;
  out.components = count_components(mesh);
  const Components& pieces = out.components;
  const PieceMeasures measures = measure(mesh, pieces);
  const PieceMembers members(pieces);
  Faults faults(out);
  const auto tet_count = static_cast<std::uint32_t>(mesh.tets.size());
  const double tol = options.volume_rel_tolerance;
  const auto fragment_count = static_cast<std::uint32_t>(report.fragments.size());
  if (measures.bad_reference_tets > 0) {
    out.notes.push_back(str(measures.bad_reference_tets) +
                        " live tets reference a vertex out of range: left out of every volume and centroid "
                        "(check_raw names them, I1)");
  }
  auto not_live = [&](std::uint32_t t) {
    return t >= tet_count ? "out of range (the mesh has " + str(tet_count) + " tet ids)" : std::string("a tombstone");
  };

  std::vector<std::uint32_t> seen_in(tet_count, kNoRawRef);     // the fragment being read last listed it
  std::vector<std::uint32_t> first_in(tet_count, kNoRawRef);    // the first fragment to list it
  std::vector<std::uint32_t> fragment_of(pieces.count, kNoRawRef);  // the first fragment of each piece
  std::vector<std::uint32_t> piece_of(fragment_count, kNoComponent);
  std::vector<std::uint32_t> own;     // one fragment's distinct live tets
  std::vector<std::uint32_t> sorted;  // their pieces, sorted
  for (std::uint32_t f = 0; f < fragment_count; ++f) {
    const RawFragment& fragment = report.fragments[f];
    own.clear();
    for (std::uint32_t t : fragment.tets) {
      if (t >= tet_count || pieces.of_tet[t] == kNoComponent) {
        faults.add(FragmentFault::kDeadTet, f, t, [&] { return "fragment " + str(f) + " lists tet " + str(t) + ", " + not_live(t); });
        continue;
      }
      if (seen_in[t] == f) {
        faults.add(FragmentFault::kRepeatedTet, f, t, [&] { return "fragment " + str(f) + " lists tet " + str(t) + " twice"; });
        continue;
      }
      seen_in[t] = f;
      if (first_in[t] != kNoRawRef) {
        faults.add(FragmentFault::kRepeatedTet, f, t, [&] {
          return "fragment " + str(f) + " lists tet " + str(t) + ", which fragment " + str(first_in[t]) + " listed already";
        });
      } else {
        first_in[t] = f;
      }
      own.push_back(t);
    }
    if (own.empty()) {
      faults.add(FragmentFault::kNoPiece, f, kNoRawRef, [&] {
        return "fragment " + str(f) + " lists no live tet (" + str(fragment.tets.size()) + " ids listed)";
      });
      continue;
    }

    // Its piece: the one holding most of its tets, the lowest on a tie.
    sorted.clear();
    for (std::uint32_t t : own) sorted.push_back(pieces.of_tet[t]);
    std::sort(sorted.begin(), sorted.end());
    std::uint32_t piece = sorted[0];
    std::size_t most = 0;
    for (std::size_t i = 0; i < sorted.size();) {
      std::size_t j = i;
      while (j < sorted.size() && sorted[j] == sorted[i]) ++j;
      if (j - i > most) {
        most = j - i;
        piece = sorted[i];
      }
      i = j;
    }
    piece_of[f] = piece;
    const std::span<const std::uint32_t> whole = members.of(piece);

    for (std::uint32_t t : own) {
      if (pieces.of_tet[t] == piece) continue;
      faults.add(FragmentFault::kForeignTet, f, t, [&] {
        return "fragment " + str(f) + " is piece " + str(piece) + " (" + str(most) + " of its " + str(own.size()) +
               " live tets) but lists tet " + str(t) + " of piece " + str(pieces.of_tet[t]);
      });
    }
    for (std::uint32_t t : whole) {
      if (seen_in[t] == f) continue;
      faults.add(FragmentFault::kMissingTet, f, t, [&] {
        return "fragment " + str(f) + " is piece " + str(piece) + " of " + str(whole.size()) +
               " tets but does not list its tet " + str(t);
      });
    }
    if (fragment_of[piece] != kNoRawRef) {
      faults.add(FragmentFault::kSamePiece, f, own[0], [&] {
        return "fragment " + str(f) + " is piece " + str(piece) + ", which fragment " + str(fragment_of[piece]) + " is already";
      });
    } else {
      fragment_of[piece] = f;
    }

    const double volume = measures.volume[piece].value();
    const double allowed = tol * volume + measures.rounding[piece];
    if (!(std::fabs(fragment.volume - volume) <= allowed)) {
      faults.add(FragmentFault::kVolume, f, kNoRawRef, [&] {
        return "fragment " + str(f) + " (piece " + str(piece) + ") reports volume " + num(fragment.volume) +
               ", the checker measures " + num(volume) + " (tolerance " + num(allowed) + ")";
      });
    }
    if (volume > 0.0) {
      const Vec3 centroid = measures.centroid(piece);
      const double off = norm(fragment.centroid - centroid);
      const double allowed_off = tol * measures.diagonal;
      if (!(off <= allowed_off)) {
        faults.add(FragmentFault::kCentroid, f, kNoRawRef, [&] {
          return "fragment " + str(f) + " (piece " + str(piece) + ") reports centroid " + str(fragment.centroid) +
                 ", the checker measures " + str(centroid) + ": " + num(off) + " apart (tolerance " + num(allowed_off) + ")";
        });
      }
    } else {
      out.notes.push_back("fragment " + str(f) + " (piece " + str(piece) +
                          ") has no volume by the checker's measure: its centroid is not checked");
    }
  }

  if (report.organ_tet) {
    const std::uint32_t organ_tet = *report.organ_tet;
    if (organ_tet >= tet_count || pieces.of_tet[organ_tet] == kNoComponent) {
      faults.add(FragmentFault::kOrganTet, kNoRawRef, organ_tet, [&] {
        return "organ tet " + str(organ_tet) + " is " + not_live(organ_tet);
      });
    } else {
      const std::uint32_t organ = pieces.of_tet[organ_tet];
      const double organ_volume = measures.volume[organ].value();
      for (std::uint32_t f = 0; f < fragment_count; ++f) {
        const std::uint32_t piece = piece_of[f];
        if (piece == kNoComponent) continue;
        if (piece == organ) {
          faults.add(FragmentFault::kOrganListed, f, organ_tet, [&] {
            return "fragment " + str(f) + " is the organ's piece " + str(organ) + " (organ tet " + str(organ_tet) + ")";
          });
          continue;
        }
        const double volume = measures.volume[piece].value();
        const double allowed = tol * organ_volume + measures.rounding[organ] + measures.rounding[piece];
        if (!(volume <= organ_volume + allowed)) {
          faults.add(FragmentFault::kLargerThanOrgan, f, kNoRawRef, [&] {
            return "fragment " + str(f) + " (piece " + str(piece) + ") has volume " + num(volume) +
                   ", more than the organ's piece " + str(organ) + " (organ tet " + str(organ_tet) + ") with " +
                   num(organ_volume);
          });
        }
      }
    }
  }

  if (report.piece_count && *report.piece_count != pieces.count) {
    faults.add(FragmentFault::kPieceCount, kNoRawRef, kNoRawRef, [&] {
      return "the engine counts " + str(*report.piece_count) + " pieces, the checker " + str(pieces.count);
    });
  }

  faults.finish();
  return out;
}

}  // namespace tetcut::invariants
