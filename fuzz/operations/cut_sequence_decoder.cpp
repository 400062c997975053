#include "operations/cut_sequence_decoder.hpp"

#include <cmath>
#include <vector>

#include "operations/sequence_session.hpp"
#include "remove/removal.hpp"

namespace tetcut::fuzz::cut_sequence {
namespace {

// max_operation_size: the most steps of a sweep.
constexpr VersionedLimits kLimits{{24, 16, 8}, {8, 8, 4}};
// A sweep is cut into 1..kSweepPieces pieces (then steps are doubled until there are at most
// max_operation_size).
constexpr std::uint32_t kSweepPieces = 8;

enum class Op : std::uint8_t { kParam, kCutPoint, kCutSurface, kSweep, kLast = kSweep };

struct Context {
  std::uint8_t version;
  const BundledMesh& bundled;
  const SequenceLimits& limits;
  CutParams params;
  double quantum;  // of coordinates
};

Vec3 rounded(const Vec3& p, double quantum) {
  return {round_to(p.x, quantum), round_to(p.y, quantum), round_to(p.z, quantum)};
}

// Two significant digits.
double round_significant(double x) { return round_to(x, coordinate_quantum(x, 1)); }

// 10^u, u uniform in [lo, hi]: every order of magnitude as likely as the next.
double consume_log_uniform(FuzzedDataProvider& input, double lo_exponent, double hi_exponent) {
  return std::pow(10.0, consume_in(input, lo_exponent, hi_exponent));
}

void param(SequenceSession& session, Context& ctx, FuzzedDataProvider& input) {
  CutParams& p = ctx.params;
  // A name the scenario knows; not a std::string assigned from short literals, which GCC 12
  // at -O3 mistakes for an overlapping copy (-Wrestrict, GCC bug 105651).
  const char* name = nullptr;
  std::string value;
  // Version 3: the ranges a user reaches by mistake (a tool in micrometres, a factor off by a
  // hundred, p a hair above 1); up to 10^4 mean edges is a thousand times a fuzz mesh's size.
  const bool wide_ranges = ctx.version >= kSequenceVersionWideParams;
  // Version 5: the paper's readings too (order, 3.5's set); before, 6 was the last (split).
  switch (input.ConsumeIntegralInRange<int>(0, ctx.version >= kSequenceVersionReadings ? 8 : 6)) {
    case 0:
      p.tool_diameter = round_significant(ctx.bundled.mean_edge * (wide_ranges ? consume_log_uniform(input, -2.0, 4.0)
                                                                         : consume_in(input, 0.5, 2.0)));
      name = "diameter", value = format_number(p.tool_diameter);
      break;
    case 1:
      p.d_ref_factor = wide_ranges ? round_significant(consume_log_uniform(input, -2.5, 1.0)) : round_to(consume_in(input, 1.0, 3.0), 0.01);
      name = "dref_factor", value = format_number(p.d_ref_factor);
      break;
    case 2:
      p.p = wide_ranges ? 1.0 + round_significant(consume_log_uniform(input, -3.0, 1.0)) : round_to(consume_in(input, 1.1, 3.0), 0.01);
      name = "p", value = format_number(p.p);
      break;
    case 3:
      p.search_depth = input.ConsumeIntegralInRange<std::uint32_t>(1, 16);
      name = "depth", value = std::to_string(p.search_depth);
      break;
    case 4:
      p.max_refine_iterations = input.ConsumeIntegralInRange<std::uint32_t>(1, kSweepPieces);
      name = "iterations", value = std::to_string(p.max_refine_iterations);
      break;
    case 5:
      p.strategy = consume_strategy(ctx.version, input);
      name = "strategy", value = to_string(p.strategy);
      break;
    case 6:
      p.split_method = input.ConsumeBool() ? SplitMethod::kBisection : SplitMethod::kTemplates;
      name = "split", value = to_string(p.split_method);
      break;
    case 7:
      p.order = static_cast<RemovalOrder>(
          input.ConsumeIntegralInRange<std::uint8_t>(0, static_cast<std::uint8_t>(RemovalOrder::kRevisit)));
      name = "order", value = to_string(p.order);
      break;
    default:
      p.neighbour_set = input.ConsumeBool() ? NeighbourSetChoice::kFirst : NeighbourSetChoice::kSmallest;
      name = "neighbour_set", value = to_string(p.neighbour_set);
      break;
  }
  session.set_param(name, value, p);
}

Vec3 point_in_box(const Context& ctx, FuzzedDataProvider& input) {
  const Box& box = ctx.bundled.box;
  const Vec3 margin = 0.1 * (box.hi - box.lo);
  const Vec3 lo = box.lo - margin, span = (box.hi + margin) - lo;
  return rounded({lo.x + span.x * consume_unit(input), lo.y + span.y * consume_unit(input),
                  lo.z + span.z * consume_unit(input)},
                 ctx.quantum);
}

// Where a tool meets the surface: a boundary tet's centroid, moved by up to a tool radius.
Vec3 point_near_surface(SequenceSession& session, const Context& ctx, FuzzedDataProvider& input) {
  const TetMesh& mesh = session.mesh();
  const TetId t = consume_live_tet_where(mesh, input, [&](TetId c) { return mesh.boundary_face_count(c) > 0; });
  if (!t.valid()) return point_in_box(ctx, input);
  const auto v = mesh.tet(t);
  const Vec3 c = 0.25 * (mesh.position(v[0]) + mesh.position(v[1]) + mesh.position(v[2]) + mesh.position(v[3]));
  const double r = 0.5 * ctx.params.tool_diameter;
  return rounded(c + Vec3{consume_in(input, -r, r), consume_in(input, -r, r), consume_in(input, -r, r)}, ctx.quantum);
}

void cut(SequenceSession& session, const Vec3& c, const std::string& name) {
  const std::string text = "cut " + format_point(c);
  const std::uint32_t line = session.recorder().add(text);
  const OperationOutcome outcome = session.cut_at(c, name, line);
  if (outcome.rolled_back)
    session.recorder().replace(line, "# " + text + "   rolled back (" + outcome.reason + "): the mesh is as before");
}

// A sweep, cut by cut exactly as the scenario runner spaces them. If one of its cuts is rolled
// back the sweep line cannot stand in the scenario (`tetcut run` stops at a failed cut), so it
// is rewritten as its single cuts with the rolled back one commented out.
void sweep(SequenceSession& session, const Context& ctx, FuzzedDataProvider& input) {
  const Vec3 a = point_near_surface(session, ctx, input);
  Vec3 dir{consume_in(input, -1, 1), consume_in(input, -1, 1), consume_in(input, -1, 1)};
  if (norm(dir) < 1e-3) dir = {1, 0, 0};
  const double length = consume_in(input, 0.5, 4.0) * ctx.params.tool_diameter;
  const Vec3 b = rounded(a + (length / norm(dir)) * dir, ctx.quantum);
  const std::uint32_t pieces = input.ConsumeIntegralInRange<std::uint32_t>(1, kSweepPieces);
  // Version 6: the samples joined by capsules.
  const bool swept = ctx.version >= kSequenceVersionSwept && input.ConsumeBool();
  const double actual = norm(b - a);
  double step = round_to(actual / pieces, ctx.quantum);
  if (!(step > 0)) step = ctx.quantum;
  while (actual > 0 && std::floor(actual / step) > static_cast<double>(ctx.limits.max_operation_size)) step *= 2;
  const std::string text =
      "sweep " + format_point(a) + " " + format_point(b) + " " + format_number(step) + (swept ? " swept" : "");
  ScenarioRecorder& recorder = session.recorder();
  const std::uint32_t line = recorder.add(text);
  const auto steps = actual > 0 ? static_cast<std::uint64_t>(std::floor(actual / step)) : 0;
  // The scenario runner's cuts (scenario::sweep_cuts): a ball at each sample, or swept, a
  // capsule from each sample to the next (a sweep of one sample is one ball).
  auto sample = [&](std::uint64_t k) { return steps == 0 ? a : a + (static_cast<double>(k) * step / actual) * (b - a); };
  const std::uint64_t cuts = swept && steps > 0 ? steps : steps + 1;
  auto cut_text = [&](std::uint64_t k) {
    return swept && steps > 0 ? "cut " + format_point(sample(k)) + " " + format_point(sample(k + 1)) : "cut " + format_point(sample(k));
  };
  std::vector<std::size_t> done;  // operation indices of the cuts so far
  bool expanded = false;
  for (std::uint64_t k = 0; k < cuts; ++k) {
    const std::string name = "sweep " + std::to_string(k + 1) + "/" + std::to_string(cuts);
    const std::uint32_t cut_line = expanded ? recorder.add(cut_text(k)) : line;
    const OperationOutcome outcome = swept && steps > 0 ? session.cut_segment_at(sample(k), sample(k + 1), name, cut_line)
                                                        : session.cut_at(sample(k), name, cut_line);
    if (outcome.rolled_back) {
      if (!expanded) {
        recorder.replace(line, "# " + text + "   (as single cuts: cut " + std::to_string(k + 1) + " rolled back)");
        for (std::size_t j = 0; j < done.size(); ++j) recorder.map_operation(done[j], recorder.add(cut_text(j)));
        recorder.add("# " + cut_text(k) + "   rolled back (" + outcome.reason + "): the mesh is as before");
        expanded = true;
      } else {
        recorder.replace(cut_line, "# " + cut_text(k) + "   rolled back (" + outcome.reason + "): the mesh is as before");
      }
    }
    done.push_back(outcome.index);
  }
}

void body(std::uint8_t version, FuzzedDataProvider& input, ScenarioRecorder& recorder) {
  const SequenceLimits& limits = kLimits.of(version);
  const SequenceStart start = start_sequence("cut_sequence", version, input, recorder);
  SequenceSession& session = start.session;
  Context ctx{version, start.bundled, limits, session.cutter().params(),
              coordinate_quantum(start.bundled.box.diagonal(), 3)};
  run_operations(start, input, limits, [&] {
    const Op op = static_cast<Op>(input.ConsumeIntegralInRange<std::uint8_t>(0, static_cast<std::uint8_t>(Op::kLast)));
    switch (op) {
      case Op::kParam: param(session, ctx, input); break;
      case Op::kCutPoint: cut(session, point_in_box(ctx, input), "cut"); break;
      case Op::kCutSurface: cut(session, point_near_surface(session, ctx, input), "cut"); break;
      case Op::kSweep: sweep(session, ctx, input); break;
    }
  });
}

}  // namespace

SequenceResult run(const std::uint8_t* data, std::size_t size, const SequenceOptions& options) {
  return run_sequence(data, size, options, body);
}

}  // namespace tetcut::fuzz::cut_sequence
