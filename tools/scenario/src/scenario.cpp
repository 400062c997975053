#include "tetcut/scenario/scenario.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iterator>
#include <fstream>
#include <sstream>

#include "core/pieces.hpp"
#include "tetcut/canonical_hash.hpp"
#include "tetcut/invariants/check.hpp"
#include "tetcut/io.hpp"
#include "tetcut/mechanics/tet_labels.hpp"
#include "tetcut/mesh_builder.hpp"
#include "tetcut/scenario/sweep.hpp"

namespace tetcut::scenario {
namespace {

std::vector<std::string> tokens_of(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream in(line.substr(0, line.find('#')));
  for (std::string t; in >> t;) out.push_back(t);
  return out;
}

bool is_param(const std::string& w) {
  return w == "diameter" || w == "dref_factor" || w == "p" || w == "depth" || w == "iterations" || w == "strategy" ||
         w == "order" || w == "neighbour_set" || w == "split" || w == "refinement" || w == "improve" || w == "quality_floor" ||
         w == "min_dihedral" || w == "max_tets_created" || w == "debris_volume" || w == "undo_history";
}

// Applies a parameter line to `params`; a message when the value is not acceptable.
std::optional<std::string> set_param(CutParams& params, const std::string& name, const std::string& value) {
  CutParams next = params;
  if (name == "strategy") {
    const auto s = parse_strategy(value);
    if (!s) return "strategy must be basic, neighbours, combined or wide";
    next.strategy = *s;
  } else if (name == "order") {
    const auto o = parse_removal_order(value);
    if (!o) return std::string("order must be direct-first, surface-first-by-id (or paper, its old name) or revisit");
    next.order = *o;
  } else if (name == "neighbour_set") {
    const auto c = parse_neighbour_set_choice(value);
    if (!c) return std::string("neighbour_set must be smallest or first");
    next.neighbour_set = *c;
  } else if (name == "split") {
    const auto m = parse_split_method(value);
    if (!m) return "split must be templates or bisection";
    next.split_method = *m;
  } else if (name == "refinement") {
    const auto r = parse_refinement_rule(value);
    if (!r) return std::string("refinement must be auto, paper or graded");
    next.refinement = *r;
  } else if (name == "improve") {
    if (value != "on" && value != "off") return std::string("improve must be on or off");
    next.improve = value == "on";
  } else if (name == "max_tets_created") {
    const auto n = parse_uint(value);
    if (!n || *n < 1 || *n > 0xFFFFFFFFull) return std::string("max_tets_created must be a positive integer");
    next.max_tets_created = static_cast<std::uint32_t>(*n);
  } else if (name == "undo_history") {
    const auto n = parse_uint(value);
    if (!n || *n > 4096) return std::string("undo_history must be an integer between 0 and 4096");
    next.undo_history = static_cast<std::uint32_t>(*n);
  } else if (name == "depth" || name == "iterations") {
    const auto n = parse_uint(value);
    if (!n || *n > 64) return name + " must be an integer between 1 and 64";
    (name == "depth" ? next.search_depth : next.max_refine_iterations) = static_cast<std::uint32_t>(*n);
  } else {
    const auto v = parse_double(value);
    if (!v) return name + " must be a finite number";
    (name == "diameter"        ? next.tool_diameter
     : name == "dref_factor"   ? next.d_ref_factor
     : name == "quality_floor" ? next.quality_floor
     : name == "min_dihedral"  ? next.min_dihedral_deg
     : name == "debris_volume" ? next.debris_volume
                               : next.p) = *v;
  }
  if (auto invalid = validate(next)) return invalid;
  params = next;
  return std::nullopt;
}


}  // namespace

ParseResult parse(const std::string& text, const std::string& name, const std::string& base_dir) {
  ParseResult result;
  Scenario s{name, base_dir, {}};
  std::istringstream in(text);
  std::string line;
  std::uint32_t n = 0;
  auto fail = [&](const std::string& why) {
    result.error = name + ":" + std::to_string(n) + ": " + why;
    return result;
  };
  CutParams probe;  // parameters are validated while parsing, so a bad value is a parse error
  while (std::getline(in, line)) {
    ++n;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::vector<std::string> t = tokens_of(line);
    if (t.empty()) continue;
    Op op{.kind = OpKind::kCut, .line = n};
    const std::string& w = t[0];
    if (w == "mesh") {
      if (t.size() != 2) return fail("expected: mesh PATH");
      op.kind = OpKind::kMesh;
      op.text = t[1];
    } else if (is_param(w)) {
      if (t.size() != 2) return fail("expected: " + w + " VALUE");
      if (auto bad = set_param(probe, w, t[1])) return fail(*bad);
      op.kind = OpKind::kParam;
      op.text = w;
      op.value = t[1];
    } else if (w == "cut") {
      // One point: the ball there; two: the capsule the tool sweeps from the first to the second.
      const auto a = t.size() == 2 || t.size() == 3 ? parse_vec3(t[1]) : std::nullopt;
      const auto b = t.size() == 3 ? parse_vec3(t[2]) : std::nullopt;
      if (!a || (t.size() == 3 && !b)) return fail("expected: cut X,Y,Z (a ball) or cut X,Y,Z X,Y,Z (a capsule) with finite numbers");
      op.kind = OpKind::kCut;
      op.a = *a;
      if (b) {
        op.b = *b;
        op.swept = true;
      }
    } else if (w == "remove") {
      const auto p = t.size() == 2 ? parse_vec3(t[1]) : std::nullopt;
      if (!p) return fail("expected: remove X,Y,Z with finite numbers");
      op.kind = OpKind::kRemove;
      op.a = *p;
    } else if (w == "sweep") {
      if (t.size() == 5 && t[4] != "swept")
        return fail("a sweep's fifth word is swept (its centres joined by capsules), not '" + t[4] + "'");
      const bool shape = t.size() == 4 || t.size() == 5;
      const auto a = shape ? parse_vec3(t[1]) : std::nullopt;
      const auto b = shape ? parse_vec3(t[2]) : std::nullopt;
      const auto step = shape ? parse_double(t[3]) : std::nullopt;
      if (!a || !b || !step || *step <= 0) return fail("expected: sweep X,Y,Z X,Y,Z STEP [swept] with STEP > 0");
      if (norm(*b - *a) / *step > 100000) return fail("sweep of more than 100000 cuts");
      op.kind = OpKind::kSweep;
      op.a = *a;
      op.b = *b;
      op.step = *step;
      op.swept = t.size() == 5;
    } else if (w == "uncuttable") {
      if (t.size() < 2) return fail("expected: uncuttable LABEL... (or: uncuttable none)");
      op.kind = OpKind::kUncuttable;
      if (!(t.size() == 2 && t[1] == "none"))
        for (std::size_t i = 1; i < t.size(); ++i) {
          const auto label = parse_uint(t[i]);
          if (!label || *label > 0xFFFFFFFFull) return fail("a label is an integer between 0 and 4294967295, not '" + t[i] + "'");
          op.labels.push_back(static_cast<std::uint32_t>(*label));
        }
    } else if (w == "compact") {
      if (t.size() > 2 || (t.size() == 2 && t[1] != "kept")) return fail("expected: compact [kept]");
      op.kind = OpKind::kCompact;
      if (t.size() == 2) op.text = t[1];
    } else if (w == "undo") {
      if (t.size() != 1) return fail("expected: undo");
      op.kind = OpKind::kUndo;
    } else if (w == "check") {
      if (t.size() > 2) return fail("expected: check [local|full|exact]");
      op.kind = OpKind::kCheck;
      op.text = t.size() == 2 ? t[1] : "full";
      if (!parse_check_level(op.text)) return fail("check level must be local, full or exact");
    } else if (w == "expect") {
      if (t.size() != 3) return fail("expected: expect hash HEX | tets N | unresolved N | components N | min_quality X");
      if (t[1] == "hash") {
        if (t[2].size() != 16 || t[2].find_first_not_of("0123456789abcdef") != std::string::npos)
          return fail("a hash is 16 lowercase hex digits");
        op.kind = OpKind::kExpectHash;
        op.text = t[2];
      } else if (t[1] == "tets" || t[1] == "unresolved" || t[1] == "components") {
        const auto c = parse_uint(t[2]);
        if (!c) return fail("expected a non-negative integer");
        op.kind = t[1] == "tets" ? OpKind::kExpectTets : t[1] == "unresolved" ? OpKind::kExpectUnresolved : OpKind::kExpectComponents;
        op.count = *c;
      } else if (t[1] == "min_quality") {
        const auto x = parse_double(t[2]);
        if (!x || *x < 0.0 || *x > 1.0) return fail("min_quality is a radius ratio between 0 and 1");
        op.kind = OpKind::kExpectMinQuality;
        op.bound = *x;
      } else {
        return fail("unknown expectation '" + t[1] + "'");
      }
    } else {
      return fail("unknown operation '" + w + "'");
    }
    s.ops.push_back(std::move(op));
  }
  result.scenario = std::move(s);
  return result;
}

ParseResult parse_file(const std::string& path, const std::string& name) {
  const std::string& shown = name.empty() ? path : name;
  std::ifstream in(path, std::ios::binary);
  if (!in) return {std::nullopt, shown + ":0: cannot open the scenario"};
  std::ostringstream text;
  text << in.rdbuf();
  const auto slash = path.find_last_of('/');
  return parse(text.str(), shown, slash == std::string::npos ? "." : path.substr(0, slash));
}

std::string mesh_path_from(const std::string& mesh, const std::string& dir) {
  namespace fs = std::filesystem;
  const fs::path m = fs::path(mesh).lexically_normal();
  const fs::path base = fs::absolute(dir).lexically_normal();
  const fs::path relative = m.lexically_relative(base);
  // The first component below the root: "/work/a/b" -> "work".
  const auto top = [](const fs::path& p) { return std::next(p.begin()) == p.end() ? fs::path() : *std::next(p.begin()); };
  return (relative.empty() || top(m) != top(base) ? m : relative).generic_string();
}

invariants::CheckOptions transaction_check_options(const CutParams& params, double min_dihedral_held_deg) {
  invariants::CheckOptions o;
  o.quality_rule = params.improve ? invariants::QualityRule::kNoDegradation : invariants::QualityRule::kReportOnly;
  o.quality_floor = params.quality_floor;
  o.min_dihedral_deg = std::min(params.min_dihedral_deg, min_dihedral_held_deg);
  return o;
}

std::vector<DetachedPiece> detached_pieces(const Cutter& cutter) {
  std::vector<DetachedPiece> pieces;
  for (const Fragment& f : cutter.last_fragments())
    pieces.push_back({static_cast<std::uint32_t>(f.tets.size()), f.volume, f.centroid, f.removed});
  return pieces;
}

invariants::CheckOptions cut_check_options(const Cutter& cutter, const Vec3& centre, const std::optional<Vec3>& end) {
  const CutParams& params = cutter.params();
  invariants::CheckOptions o = transaction_check_options(params, cutter.last_min_dihedral_held());
  const std::span<const TetId> left = cutter.last_left_in_tool();
  o.tool = invariants::ToolRule{
      .centre = centre, .radius = params.tool_diameter / 2, .d_ref = params.d_ref(), .left = left, .end = end};
  o.moved = cutter.last_moved();
  return o;
}

namespace {

// One run of a scenario: the mesh, its Cutter and local checker, the labels the change logs carry,
// and the result so far. One method per kind of operation; each returns false once the run has
// stopped (stop(): the result says why, and the mesh went to the caller).
class Run {
 public:
  Run(const Scenario& scenario, const RunOptions& options, TetMesh* mesh_out)
      : scenario_(scenario),
        options_(options),
        mesh_out_(mesh_out),
        params_(options.initial_params.value_or(CutParams{})),
        uncuttable_labels_(options.uncuttable_labels) {}

  RunResult run() {
    for (const Op& op : scenario_.ops)
      if (!step(op)) return std::move(result_);
    finish();
    return std::move(result_);
  }

 private:
  bool step(const Op& op) {
    if (op.kind != OpKind::kMesh && op.kind != OpKind::kParam && !cutter_) {
      stop(op, 2, "no mesh loaded yet (use: mesh PATH)");
      return false;
    }
    switch (op.kind) {
      case OpKind::kMesh: return load_mesh(op);
      case OpKind::kUncuttable: return set_uncuttable(op);
      case OpKind::kParam: return set_parameter(op);
      case OpKind::kCut:
      case OpKind::kSweep: return cut(op);
      case OpKind::kRemove: return remove(op);
      case OpKind::kCompact: compact(op.text == "kept" ? IdOrder::kKept : IdOrder::kAlongCurve); return true;
      case OpKind::kUndo: return undo(op);
      case OpKind::kCheck: return check(op);
      case OpKind::kExpectHash:
      case OpKind::kExpectTets:
      case OpKind::kExpectComponents:
      case OpKind::kExpectMinQuality:
      case OpKind::kExpectUnresolved: return expect(op);
    }
    return true;
  }

  bool load_mesh(const Op& op) {
    const std::string path = op.text.front() == '/' ? op.text : scenario_.base_dir + "/" + op.text;
    ReadResult read = read_mesh(path);
    if (!read.mesh) {
      stop(op, 2, read.error ? read.error->message() : "cannot read " + path);
      return false;
    }
    BuildResult built = build_mesh(*read.mesh);
    if (!built.ok()) {
      stop(op, 2, path + ": not a valid manifold mesh: " + built.problems.front().message);
      return false;
    }
    if (cutter_) result_.removal += cutter_->removal_report();
    cutter_.reset();
    mesh_ = std::move(*built.mesh);
    cutter_.emplace(mesh_, params_);
    search_bounded_ = false;
    local_.emplace(mesh_.raw_view());
    const std::vector<std::uint32_t>& file_labels = read.mesh->labels;
    const bool one_label = read.mesh->labelled() && std::all_of(file_labels.begin(), file_labels.end(),
                                                                [&](std::uint32_t l) { return l == file_labels[0]; });
    uniform_label_ = one_label ? std::optional<std::uint32_t>(file_labels[0]) : std::nullopt;
    labelled_ = read.mesh->labelled() && !one_label;
    if (labelled_) {
      labels_ = mechanics::TetLabels(mesh_, read.mesh->labels);  // the builder keeps the file's tet order: TetId = index
      labels_.keep_history(params_.undo_history);
      log_.reserve(4096);
    }
    if (auto bad = protect()) {
      stop(op, 2, path + ": " + *bad);
      return false;
    }
    return true;
  }

  bool set_uncuttable(const Op& op) {
    uncuttable_labels_ = op.labels;
    if (auto bad = protect()) {
      stop(op, 2, *bad);
      return false;
    }
    return true;
  }

  bool set_parameter(const Op& op) {
    if (auto bad = set_param(params_, op.text, op.value)) {
      stop(op, 2, *bad);
      return false;
    }
    if (cutter_) cutter_->set_params(params_);
    if (labelled_) labels_.keep_history(params_.undo_history);
    return true;
  }

  // An `undo` line: the last cut or removal taken back, the labels with it (their own history),
  // then the local check around what came back. Quality is reported, not judged: the tets that
  // come back are the ones that were there, held to the floors when they were made.
  bool undo(const Op& op) {
    if (auto refused = cutter_->undo(log_if_labelled())) {
      stop(op, 1, "undo refused: " + *refused);
      return false;
    }
    if (labelled_) labels_.apply(mesh_, log_);
    ++result_.undos;
    if (options_.check == CheckMode::kEvery) {
      invariants::CheckOptions o = transaction_check_options(params_, cutter_->last_min_dihedral_held());
      o.quality_rule = invariants::QualityRule::kReportOnly;
      o.moved = cutter_->last_moved();  // moved back within the undone cut's reach
      if (const auto reach = cutter_->last_undone_reach())
        o.reach = invariants::ToolRule{
            .centre = reach->a, .radius = reach->radius, .d_ref = reach->d_ref, .left = {}, .end = reach->b};
      const invariants::CheckReport r =
          local_->after_operation(mesh_.raw_view(), cutter_->last_removed(), cutter_->last_created(), o);
      if (!r.ok()) {
        stop(op, 1, "invariant violated after the undo: " + violations(r));
        return false;
      }
    }
    return true;
  }

  // A `cut` line (a ball, or a capsule from a to b) or a `sweep` line (balls, or capsules joined
  // centre to centre): each cut checked with its own tool.
  bool cut(const Op& op) {
    const std::vector<CutTool> tools =
        op.kind == OpKind::kSweep ? sweep_cuts(op.a, op.b, op.step, op.swept)
                                  : std::vector{CutTool{op.a, op.swept ? std::optional<Vec3>(op.b) : std::nullopt}};
    for (const CutTool& tool : tools) {
      const CutReport r = tool.end ? cutter_->cut_segment(tool.centre, *tool.end, log_if_labelled())
                                   : cutter_->cut(tool.centre, log_if_labelled());
      if (r.ok && labelled_) labels_.apply(mesh_, log_);
      result_.cuts.push_back({op.line, tool.centre, tool.end, r, detached_pieces(*cutter_)});
      count(r);
      if (!r.ok) {
        stop(op, 1, "cut failed: " + r.failure);
        return false;
      }
      if (!after(op, &tool)) return false;
      if (options_.after_cut) {
        if (auto bad = options_.after_cut(mesh_, result_.cuts.size() - 1, current_labels())) {
          stop(op, 2, *bad);
          return false;
        }
      }
    }
    return true;
  }

  bool remove(const Op& op) {
    const TetId t = cutter_->tet_containing(op.a);
    if (!t.valid()) return true;  // nothing there any more: a no-op, as a cautery in the air
    const CutReport r = cutter_->remove(t, log_if_labelled());
    if (r.ok && labelled_) labels_.apply(mesh_, log_);
    count(r);
    if (!r.ok) {
      stop(op, 1, "removal failed: " + r.failure);
      return false;
    }
    return after(op);
  }

  void compact(IdOrder order) {
    result_.removal += cutter_->removal_report();
    if (const Renumbering renumbering = mesh_.compact(order); labelled_) labels_.renumber(renumbering);
    cutter_.emplace(mesh_, params_);
    search_bounded_ = false;
    local_.emplace(mesh_.raw_view());
    (void)protect();  // the same labelled tets as before: it cannot refuse now
  }

  bool check(const Op& op) {
    invariants::CheckOptions o;
    // `check local` in a file has no operation to look around: it checks the whole mesh.
    o.level = *parse_check_level(op.text) == invariants::CheckLevel::kExact ? invariants::CheckLevel::kExact
                                                                             : invariants::CheckLevel::kFull;
    const invariants::CheckReport r = invariants::check_mesh(mesh_.raw_view(), o);
    if (!r.ok()) {
      stop(op, 1, "check failed: " + violations(r));
      return false;
    }
    return true;
  }

  // An `expect` line: what it expects, else why not.
  std::optional<std::string> unmet(const Op& op) const {
    switch (op.kind) {
      case OpKind::kExpectHash: {
        const std::string h = hash_to_hex(canonical_hash(mesh_));
        if (h != op.text) return "expected hash " + op.text + ", got " + h;
        break;
      }
      case OpKind::kExpectTets:
        if (mesh_.num_tets() != op.count)
          return "expected " + std::to_string(op.count) + " tets, got " + std::to_string(mesh_.num_tets());
        break;
      case OpKind::kExpectComponents: {
        // The count every cut keeps (Cutter::pieces()), and a scan of the mesh as its witness:
        // exact unless a search for pieces was bounded, which may leave the kept count short.
        const std::uint64_t kept = cutter_->pieces();
        const std::uint64_t scanned = face_connected_pieces(mesh_).count;
        if (search_bounded_ ? kept > scanned : kept != scanned)
          return "the Cutter counts " + std::to_string(kept) + " connected pieces, a scan of the mesh " +
                 std::to_string(scanned) + (search_bounded_ ? " (a search for pieces was bounded)" : "") +
                 ": the engine's count is wrong";
        const std::uint64_t pieces = search_bounded_ ? scanned : kept;
        if (pieces != op.count)
          return "expected " + std::to_string(op.count) + " connected pieces, got " + std::to_string(pieces);
        break;
      }
      case OpKind::kExpectMinQuality: {
        // The checker's measure of what the cuts left created, not the engine's own account.
        const double worst = result_.created_quality.tets == 0 ? 1.0 : result_.created_quality.min_radius_ratio;
        if (!(worst >= op.bound))
          return "expected every created tet to have radius ratio >= " + std::to_string(op.bound) + ", the worst has " +
                 std::to_string(worst);
        break;
      }
      case OpKind::kExpectUnresolved:
        if (result_.unresolved != op.count)
          return "expected " + std::to_string(op.count) + " unresolved, got " + std::to_string(result_.unresolved);
        break;
      default:
        break;
    }
    return std::nullopt;
  }

  bool expect(const Op& op) {
    if (auto why = unmet(op)) {
      stop(op, 1, *why);
      return false;
    }
    return true;
  }

  void finish() {
    if (options_.check == CheckMode::kEnd && cutter_) {
      const invariants::CheckReport r = invariants::check_mesh(mesh_.raw_view());
      if (!r.ok()) {
        result_.ok = false;
        result_.exit_code = 1;
        result_.reason = "invariant violated at the end: " + violations(r);
        result_.error = scenario_.name + ": " + result_.reason;
      }
    }
    if (cutter_) result_.removal += cutter_->removal_report();
    result_.hash = hash_to_hex(canonical_hash(mesh_));
    result_.tets = mesh_.num_tets();
    keep_labels();
    if (mesh_out_) *mesh_out_ = std::move(mesh_);
  }

  ChangeLog* log_if_labelled() {
    if (!labelled_) return nullptr;
    log_.clear();
    return &log_;
  }

  // The labels by TetId now (empty: unlabelled). A single label is spelt out only when asked for
  // (a result, a frame), which is O(tets) as writing the mesh is.
  std::span<const std::uint32_t> current_labels() {
    if (labelled_) return labels_.by_tet();
    if (!uniform_label_) return {};
    spelt_out_.assign(mesh_.tet_capacity(), *uniform_label_);
    return spelt_out_;
  }

  void keep_labels() {
    const std::span<const std::uint32_t> now = current_labels();
    result_.labels.assign(now.begin(), now.end());
  }

  // Sets the uncuttable tets (those with an uncuttable label now) on the cutter and the checker.
  std::optional<std::string> protect() {
    uncuttable_tets_.clear();
    auto kept = [&](std::uint32_t label) {
      return std::find(uncuttable_labels_.begin(), uncuttable_labels_.end(), label) != uncuttable_labels_.end();
    };
    if (!uncuttable_labels_.empty()) {
      if (!labelled_ && !uniform_label_) return std::string("uncuttable labels need a mesh whose tets carry labels");
      for (std::uint32_t t = 0; t < mesh_.tet_capacity(); ++t)
        if (mesh_.is_live(TetId{t}) && kept(labelled_ ? labels_.label(TetId{t}) : *uniform_label_))
          uncuttable_tets_.push_back(TetId{t});
    }
    if (auto bad = cutter_->set_uncuttable(uncuttable_tets_)) return bad;
    local_->set_uncuttable(uncuttable_tets_);
    return std::nullopt;
  }

  void stop(const Op& op, int code, const std::string& why) {
    result_.ok = false;
    result_.exit_code = code;
    result_.failed_line = op.line;
    result_.error = scenario_.name + ":" + std::to_string(op.line) + ": " + why;
    result_.reason = why;
    result_.tets = mesh_.num_tets();
    if (cutter_) result_.removal += cutter_->removal_report();
    keep_labels();
    if (mesh_out_) *mesh_out_ = std::move(mesh_);  // the run returns right after
  }

  static std::string violations(const invariants::CheckReport& r) {
    std::string s;
    for (const invariants::Violation& v : r.violations)
      s += std::string(s.empty() ? "" : "; ") + invariants::id_string(v.id) + " " + invariants::description(v.id) + ": " + v.detail;
    return s;
  }

  // A cut's or a removal's counts, and what one that succeeded created, for the run's quality figures.
  void count(const CutReport& r) {
    search_bounded_ = search_bounded_ || r.fragment_search_bounded;
    result_.removals += r.tets_removed + r.tets_removed_by_improvement;
    result_.unresolved += r.unresolved;
    if (!r.ok) return;
    result_.min_created_radius_ratio = std::min(result_.min_created_radius_ratio, r.min_radius_ratio);
    invariants::pool(result_.created_quality, invariants::quality_of(mesh_.raw_view(), cutter_->last_created()));
  }

  // After every mutating operation: the growth guard, then the local check (or none); a cut's
  // with its tool.
  bool after(const Op& op, const CutTool* cut_tool = nullptr) {
    if (options_.max_tets != 0 && mesh_.num_tets() > options_.max_tets) {
      stop(op, 1, "the mesh grew past " + std::to_string(options_.max_tets) + " tets (" +
                      std::to_string(mesh_.num_tets()) + ")");
      return false;
    }
    if (options_.check == CheckMode::kNone || !cutter_) return true;
    if (options_.check == CheckMode::kEvery) {
      const invariants::CheckOptions o = cut_tool ? cut_check_options(*cutter_, cut_tool->centre, cut_tool->end)
                                                  : transaction_check_options(params_, cutter_->last_min_dihedral_held());
      const invariants::CheckReport r =
          local_->after_operation(mesh_.raw_view(), cutter_->last_removed(), cutter_->last_created(), o);
      if (!r.ok()) {
        stop(op, 1, "invariant violated: " + violations(r));
        return false;
      }
    }
    return true;
  }

  const Scenario& scenario_;
  const RunOptions& options_;
  TetMesh* mesh_out_;
  RunResult result_;
  TetMesh mesh_;
  std::optional<Cutter> cutter_;
  std::optional<invariants::LocalChecker> local_;
  // The tets' labels, when the mesh file has them: each cut's change log carries them on.
  // (A plain member and a flag: GCC 12 sees an optional's vectors as maybe uninitialized.)
  mechanics::TetLabels labels_;
  bool labelled_ = false;
  // A file whose tets all have one label (a Gmsh file's single volume, as every bundled mesh):
  // every tet a cut makes has it too, so nothing is tracked and the cuts run as without labels
  // (a cut that fills a caller's log costs about 1 us more on the bundled resection).
  std::optional<std::uint32_t> uniform_label_;
  ChangeLog log_;
  std::vector<std::uint32_t> spelt_out_;
  CutParams params_;
  // The labels whose tets the cutter must leave, and the tets that have one now (by the labels
  // the change logs carry): set on the cutter whenever it is made anew or the labels change.
  std::vector<std::uint32_t> uncuttable_labels_;
  std::vector<TetId> uncuttable_tets_;
  // A search for pieces was bounded since the Cutter was made: Cutter::pieces() may be short.
  bool search_bounded_ = false;
};

}  // namespace

RunResult run(const Scenario& scenario, const RunOptions& options, TetMesh* mesh_out) {
  return Run(scenario, options, mesh_out).run();
}

}  // namespace tetcut::scenario
