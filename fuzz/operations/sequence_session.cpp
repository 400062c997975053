#include "operations/sequence_session.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <memory>
#include <thread>
#include <utility>

#include "tetcut/canonical_hash.hpp"

namespace tetcut::fuzz {

SequenceSession::SequenceSession(const BundledMesh& bundled)
    : checked_(bundled.mesh), cutter_(checked_.mesh(), params_with_budget(bundled)) {}

SequenceSession& SequenceSession::start(const BundledMesh& bundled, ScenarioRecorder& recorder) {
  // Keyed by the bundled mesh, which sequence_mesh() keeps for the whole process. Not a
  // std::map: no allocation per input once the few meshes have their sessions.
  static std::vector<std::pair<const BundledMesh*, std::unique_ptr<SequenceSession>>> sessions;
  auto it = std::find_if(sessions.begin(), sessions.end(), [&](const auto& s) { return s.first == &bundled; });
  if (it == sessions.end()) {
    sessions.emplace_back(&bundled, std::unique_ptr<SequenceSession>(new SequenceSession(bundled)));
    it = sessions.end() - 1;
  }
  it->second->restart(bundled, recorder);
  return *it->second;
}

void SequenceSession::restart(const BundledMesh& bundled, ScenarioRecorder& recorder) {
  recorder_ = &recorder;
  checked_.reset(bundled.mesh);
  cutter_.reset();
  const auto refused = cutter_.set_params(params_with_budget(bundled));
  checked_.require(!refused.has_value(), "cut-params", "the default parameters are refused: " + refused.value_or(""));
  unresolved_ = 0;
  changed_since_full_check_ = false;
  // A failure on demand, to test what reports failures (tetcut replay's exit code and messages)
  // without depending on a bug of the engine.
  fail_at_ = 0;
  if (const char* env = std::getenv("TETCUT_FUZZ_FAIL_AT")) fail_at_ = std::strtoull(env, nullptr, 10);
  // The same for slowness: operation N sleeps 30 s, so that ci/fuzz-nightly's
  // timeout handling can be tried without a slow engine.
  slow_at_ = 0;
  if (const char* env = std::getenv("TETCUT_FUZZ_SLOW_AT")) slow_at_ = std::strtoull(env, nullptr, 10);
  volume_.assign(mesh().tet_capacity(), 0.0);
  for (std::uint32_t t = 0; t < mesh().tet_capacity(); ++t)
    if (mesh().is_live(TetId{t})) volume_[t] = mesh().volume(TetId{t});
}

void SequenceSession::finish() {
  full_check_if_changed();
  if (recorder_->enabled()) recorder_->set_final_hash(canonical_hash(mesh()));
}

CutParams SequenceSession::params_with_budget(const BundledMesh& bundled) {
  // One cut of the fuzzer once created 44 000 tets in a 3 400-tet mesh (Remover's corner
  // refinement): seconds per input under ASan.
  CutParams params;
  params.max_tets_created = std::max<std::uint32_t>(bundled.mesh.num_tets(), 1);
  return params;
}

void SequenceSession::grow_volumes() {
  if (volume_.size() < mesh().tet_capacity()) volume_.resize(mesh().tet_capacity(), 0.0);
}

void SequenceSession::begin(const std::string& name, std::uint32_t line) {
  checked_.begin(name);
  recorder_->map_operation(checked_.operation_index(), line);
  if (checked_.operation_index() == slow_at_) std::this_thread::sleep_for(std::chrono::seconds(30));
  if (checked_.operation_index() == fail_at_)
    checked_.require(false, "injected", "TETCUT_FUZZ_FAIL_AT=" + std::to_string(fail_at_) + " (a test of the harness)");
}

void SequenceSession::set_param(const std::string& name, const std::string& value, const CutParams& params) {
  const std::uint32_t line = recorder_->add(name + " " + value);
  begin(name, line);
  const auto refused = cutter_.set_params(params);
  checked_.require(!refused.has_value(), "cut-params", name + " " + value + ": clamped value refused: " + refused.value_or(""));
  checked_.end({}, {}, 0.0);
}

OperationOutcome SequenceSession::remove_at(const Vec3& p, const std::string& name, std::uint32_t line) {
  begin(name, line);
  const TetId t = cutter_.tet_containing(p);
  if (!t.valid()) {  // nothing there (any more): a no-op, as in a scenario
    checked_.end({}, {}, 0.0);
    return {checked_.operation_index(), false, {}};
  }
  if (checked_.tracing()) checked_.describe("tet " + std::to_string(t.value) + " at " + format_point(p));
  before_ = mesh();
  return after(cutter_.remove(t));
}

OperationOutcome SequenceSession::cut_at(const Vec3& c, const std::string& name, std::uint32_t line) {
  begin(name, line);
  if (checked_.tracing()) checked_.describe("centre " + format_point(c));
  before_ = mesh();
  return after(cutter_.cut(c), &c);
}

OperationOutcome SequenceSession::cut_segment_at(const Vec3& a, const Vec3& b, const std::string& name, std::uint32_t line) {
  begin(name, line);
  if (checked_.tracing()) checked_.describe("from " + format_point(a) + " to " + format_point(b));
  before_ = mesh();
  return after(cutter_.cut_segment(a, b), &a, &b);
}

OperationOutcome SequenceSession::after(const CutReport& report, const Vec3* cut_centre, const Vec3* cut_end) {
  const std::size_t index = checked_.operation_index();
  if (!report.ok) {
    // Atomic: the mesh must be bit-identical to before, so its canonical hash is too.
    checked_.end({}, {}, 0.0);
    const std::uint64_t now = canonical_hash(mesh());
    const std::uint64_t before = canonical_hash(before_);
    checked_.require(now == before, "rollback-changed-mesh",
                     "rolled back (" + report.failure + ") but the canonical hash went from " + hash_to_hex(before) +
                         " to " + hash_to_hex(now));
    checked_.require(cutter_.last_removed().empty() && cutter_.last_created().empty(), "rollback-changed-mesh",
                     "rolled back (" + report.failure + ") but reports removed or created tets");
    return {index, true, report.failure};
  }
  double change = 0.0;
  for (TetId t : cutter_.last_removed()) change -= t.value < volume_.size() ? volume_[t.value] : 0.0;
  grow_volumes();
  for (TetId t : cutter_.last_created()) {
    volume_[t.value] = mesh().volume(t);
    change += volume_[t.value];
  }
  // The pieces the operation detached, against the checker's own union-find over the raw tets.
  pieces_bounded_ = pieces_bounded_ || report.fragment_search_bounded;
  std::vector<invariants::RawFragment> fragments;
  std::optional<std::uint32_t> organ;
  for (const Fragment& f : cutter_.last_fragments()) {
    if (f.removed) continue;
    fragments.push_back({f.tets, f.volume, f.centroid});
    organ = f.organ.value;
  }
  const invariants::FragmentCheckReport pieces = invariants::check_fragments(
      mesh().raw_view(), {.fragments = fragments, .organ_tet = organ,
                          .piece_count = pieces_bounded_ ? std::nullopt : std::optional<std::uint32_t>(cutter_.pieces())});
  if (!pieces.ok()) checked_.require(false, "fragments", invariants::to_string(pieces));
  std::optional<invariants::ToolRule> tool;
  if (cut_centre)
    tool = invariants::ToolRule{.centre = *cut_centre, .radius = cutter_.params().tool_diameter / 2,
                                .d_ref = cutter_.params().d_ref(), .left = cutter_.last_left_in_tool(),
                                .end = cut_end ? std::optional<Vec3>(*cut_end) : std::nullopt};
  checked_.end(cutter_.last_removed(), cutter_.last_created(), change, invariants::QualityRule::kNoDegradation,
               tool ? &*tool : nullptr, std::min(cutter_.params().min_dihedral_deg, cutter_.last_min_dihedral_held()),
               cutter_.last_moved());
  if (!cutter_.last_removed().empty() || !cutter_.last_created().empty()) changed_since_full_check_ = true;
  const std::uint64_t before = unresolved_;
  unresolved_ += report.unresolved;
  if (cutter_.params().strategy == RemovalStrategy::kCombined && report.unresolved > 0) {
    // What the scenario runner sees: its count of unresolved tets moves.
    recorder_->add("expect unresolved " + std::to_string(before));
    checked_.require(false, "unresolved-combined",
                     std::to_string(report.unresolved) + " of " + std::to_string(report.requested) +
                         " requested tets left unresolved by the combined strategy (" +
                         std::to_string(report.vertex_singularities) + " vertex, " +
                         std::to_string(report.edge_singularities) + " edge singularities)");
  }
  return {index, false, {}};
}

void SequenceSession::full_check() {
  const std::uint32_t line = recorder_->add("check full");
  begin("check full", line);
  checked_.end({}, {}, 0.0);
  checked_.full_check();
  changed_since_full_check_ = false;
}

SequenceStart start_sequence(std::string_view target, std::uint8_t version, FuzzedDataProvider& input,
                             ScenarioRecorder& recorder) {
  const BundledMesh& bundled = sequence_mesh(version, input.ConsumeIntegralInRange<std::size_t>(0, kSequenceMeshCount - 1));
  recorder.add("# tetcut replay --target " + std::string(target) + " (input version " + std::to_string(version) + ")");
  recorder.add("mesh " + bundled.path);
  // The session's budget (params_with_budget), so that `tetcut run` meets the same refusals.
  recorder.add("max_tets_created " + std::to_string(SequenceSession::params_with_budget(bundled).max_tets_created));
  return {bundled, SequenceSession::start(bundled, recorder)};
}

RemovalStrategy consume_strategy(std::uint8_t version, FuzzedDataProvider& input) {
  const auto last = static_cast<std::uint8_t>(version >= kSequenceVersionAllStrategies ? RemovalStrategy::kWide
                                                                                       : RemovalStrategy::kCombined);
  return static_cast<RemovalStrategy>(input.ConsumeIntegralInRange<std::uint8_t>(0, last));
}

SequenceResult run_sequence(const std::uint8_t* data, std::size_t size, const SequenceOptions& options,
                            const std::function<void(std::uint8_t, FuzzedDataProvider&, ScenarioRecorder&)>& body) {
  SequenceResult result;
  if (size == 0 || !(options.legacy_versions ? is_sequence_version(data[0]) : is_current_sequence_version(data[0]))) return result;
  result.accepted = true;
  result.version = data[0];
  FuzzedDataProvider input(data + 1, size - 1);
  ScenarioRecorder recorder(options.record_scenario);
  try {
    if (options.capture_failures) {
      const CaptureFailures capture;
      body(result.version, input, recorder);
    } else {
      body(result.version, input, recorder);
    }
  } catch (const FailureError& e) {
    result.finding = e.finding();
    result.finding_line = recorder.line_of(e.finding().operation_index);
    recorder.add("# finding: " + to_string(e.finding()));
  }
  result.scenario = recorder.text();
  if (!result.finding) result.final_hash = recorder.final_hash();
  return result;
}

}  // namespace tetcut::fuzz
