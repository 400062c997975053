// `tetcut cut MESH --diameter D --from X,Y,Z --to X,Y,Z --step S [--strategy S]
//  [--check every|end|none] [--out M] [--report R.json] [--frames DIR]`: a cautery sweep, one
// cut every S along the segment, as the paper's electric lancet (3.6).
#include <cmath>
#include <cstdio>
#include <ostream>
#include <sstream>

#include "args.hpp"
#include "command.hpp"
#include "cut_report_json.hpp"
#include "mesh_input.hpp"
#include "tetcut/canonical_hash.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/invariants/check.hpp"
#include "tetcut/io.hpp"
#include "tetcut/mesh_builder.hpp"

namespace tetcut::cli {
namespace {

constexpr OptionSpec kSpecs[] = {
    {"--diameter", true}, {"--from", true},  {"--to", true},     {"--step", true},   {"--strategy", true},
    {"--check", true},    {"--out", true},   {"--report", true}, {"--frames", true}, {"--dref-factor", true},
    {"--p", true},        {"--depth", true}, {"--split", true},
};

int usage(std::ostream& err, const std::string& message) {
  err << "tetcut cut: " << message << "\n"
      << "usage: tetcut cut MESH --diameter D --from X,Y,Z --to X,Y,Z --step S [--strategy basic|neighbours|combined|wide]\n"
         "                      [--check every|end|none] [--out M] [--report R.json] [--frames DIR]\n";
  return 2;
}

}  // namespace

int cmd_cut(Args args, std::ostream& out, std::ostream& err) {
  const ArgParseResult parsed = parse_args(args, kSpecs);
  if (!parsed.ok()) return usage(err, parsed.error);
  const ParsedArgs& a = parsed.args;
  if (a.positionals.size() != 1) return usage(err, "expected exactly one MESH");
  const auto diameter = parse_double(a.value("--diameter").value_or(""));
  const auto from = parse_vec3(a.value("--from").value_or(""));
  const auto to = parse_vec3(a.value("--to").value_or(""));
  const auto step = parse_double(a.value("--step").value_or(""));
  if (!diameter || !from || !to || !step) return usage(err, "--diameter, --from, --to and --step are required numbers");
  if (*step <= 0) return usage(err, "--step must be positive");
  const double length = norm(*to - *from);
  if (length / *step > 1e6) return usage(err, "more than a million cuts: increase --step");

  CutParams params;
  params.tool_diameter = *diameter;
  if (const auto s = a.value("--strategy")) {
    const auto strategy = parse_removal_strategy(*s);
    if (!strategy) return usage(err, "--strategy must be basic, neighbours, combined or wide");
    params.strategy = *strategy;
  }
  if (const auto s = a.value("--split")) {
    if (*s == "templates") params.split_method = SplitMethod::kTemplates;
    else if (*s == "bisection") params.split_method = SplitMethod::kBisection;
    else return usage(err, "--split must be templates or bisection");
  }
  if (const auto v = a.value("--dref-factor")) {
    const auto x = parse_double(*v);
    if (!x) return usage(err, "--dref-factor expects a number");
    params.d_ref_factor = *x;
  }
  if (const auto v = a.value("--p")) {
    const auto x = parse_double(*v);
    if (!x) return usage(err, "--p expects a number");
    params.p = *x;
  }
  if (const auto v = a.value("--depth")) {
    const auto x = parse_uint(*v);
    if (!x || *x > 64) return usage(err, "--depth expects an integer up to 64");
    params.search_depth = static_cast<std::uint32_t>(*x);
  }
  if (const auto invalid = validate(params)) return usage(err, *invalid);
  const std::string check = a.value("--check").value_or("every");
  if (check != "every" && check != "end" && check != "none") return usage(err, "--check must be every, end or none");

  const std::optional<RawMesh> raw = load_mesh(a.positionals[0], err);
  if (!raw) return 2;
  BuildResult built = build_mesh(*raw);
  if (!built.ok()) {
    err << "tetcut: " << a.positionals[0] << ": not a valid manifold mesh: " << built.problems.front().message
        << " (see tetcut check)\n";
    return 2;
  }
  TetMesh& mesh = *built.mesh;
  Cutter cutter(mesh, params);
  invariants::LocalChecker local(mesh.raw_view());
  std::vector<scenario::CutRecord> cuts;
  const auto steps = static_cast<std::uint64_t>(std::floor(length / *step));
  bool valid = true;
  std::string violation;
  for (std::uint64_t k = 0; k <= steps; ++k) {
    const Vec3 centre = steps == 0 ? *from : *from + (static_cast<double>(k) * *step / length) * (*to - *from);
    const CutReport r = cutter.cut(centre);
    cuts.push_back({0, centre, r});
    if (!r.ok) err << "tetcut cut: cut " << k << " rolled back: " << r.failure << "\n";
    if (check == "every") {
      const invariants::CheckReport c = local.after_operation(mesh.raw_view(), cutter.last_removed(), cutter.last_created());
      if (!c.ok()) {
        valid = false;
        violation = std::string(invariants::id_string(c.violations.front().id)) + " after cut " + std::to_string(k) + ": " +
                    c.violations.front().detail;
        break;
      }
    }
    if (const auto dir = a.value("--frames")) {
      char name[32];
      std::snprintf(name, sizeof name, "/frame_%05llu.vtu", static_cast<unsigned long long>(k));
      const WriteResult w = write_mesh(*dir + name, mesh);
      if (!w.ok) {
        err << "tetcut: " << w.error << "\n";
        return 2;
      }
    }
  }
  if (valid && check != "none") {
    const invariants::CheckReport c = invariants::check_mesh(mesh.raw_view());
    if (!c.ok()) {
      valid = false;
      violation = std::string(invariants::id_string(c.violations.front().id)) + " at the end: " + c.violations.front().detail;
    }
  }
  const std::string hash = hash_to_hex(canonical_hash(mesh));
  std::uint64_t removed = 0, created = 0, unresolved = 0;
  for (const auto& c : cuts) {
    removed += c.report.tets_removed;
    created += c.report.tets_created;
    unresolved += c.report.unresolved;
  }
  out << cuts.size() << " cuts: " << removed << " tets removed, " << created << " created, " << unresolved
      << " unresolved, " << mesh.num_tets() << " tets left\n"
      << "per cut (all cuts): p50 " << percentile_us(cuts, 0.5) << " us, p90 " << percentile_us(cuts, 0.9)
      << " us, p99 " << percentile_us(cuts, 0.99) << " us, max " << percentile_us(cuts, 1.0) << " us; first cut "
      << (cuts.empty() ? 0.0 : cuts.front().report.time.total_us) << " us\n"
      << "hash " << hash << "\n";
  if (!valid) out << "INVARIANT VIOLATED: " << violation << "\n";
  if (const auto path = a.value("--out")) {
    const WriteResult w = write_mesh(*path, mesh);
    if (!w.ok) {
      err << "tetcut: " << w.error << "\n";
      return 2;
    }
  }
  if (const auto path = a.value("--report")) {
    const WriteResult w = write_file_atomically(*path, cut_report_json(cuts, hash, valid));
    if (!w.ok) {
      err << "tetcut: " << w.error << "\n";
      return 2;
    }
  }
  return valid ? 0 : 1;
}

}  // namespace tetcut::cli
