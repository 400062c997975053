// `tetcut simulate MESH|SCENARIO.scn [--sweep FROM TO STEP]... --fix "x<10" --gravity 0,0,-9.81`:
// the elastic tissue (tetcut::mechanics, tensor-mass linear elasticity) stepped at a fixed time
// step while the cautery cuts it, as the paper's simulator did: per frame one cut, the model and
// the rendered surface updated from the cut's ChangeLog, then --steps explicit steps.
//
// The tool moves in the world: each sweep point is mapped to the rest configuration through
// the deformed tet that holds it (TensorMassModel::rest_point), and the rest mesh is cut there
// (a point outside the deformed tissue is cut where it is). With --swept (a scenario's `sweep
// ... swept`, `cut A B`) a frame's cut is the capsule from one sweep point to the next, both ends
// mapped so when the frame starts. The time step follows the tissue:
// --dt-factor (0.5) times the stable-step estimate (StableStepEstimator: a few power iterations on
// M^-1 K, between 2/3 of the critical step 2 / omega_max and the step itself), before the first
// cut and again after each cut that changed the mesh (the small tets a cut makes lower the
// critical step), never above the first frame's. --dt S fixes it instead. The report gives per
// frame the cut time, the update time, the step time, the step and the stable-step estimate after
// the cut, and the energy, so that a blow-up is visible; one stops the run with exit 1. A blow-up is the
// total energy (kinetic + elastic + gravity's potential) growing over a frame's steps: damped,
// it can only fall (to the integrator's O(dt) ripple, allowed up to 1 % of the energies' size),
// while an unstable step grows it exponentially. Not the displacement: a piece the resection
// frees from the fixed vertices falls under gravity (at the terminal speed g / damping), which
// is physics.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ostream>

#include "command.hpp"
#include "command_parser.hpp"
#include "json_output.hpp"
#include "mesh_input.hpp"
#include "simulation_frame.hpp"
#include "tetcut/invariants/check.hpp"
#include "tetcut/mechanics/periodic_reader.hpp"
#include "tetcut/mechanics/reaction_force.hpp"
#include "tetcut/mechanics/rendered_surface.hpp"
#include "tetcut/mechanics/snapshot.hpp"
#include "tetcut/mechanics/stable_step.hpp"
#include "tetcut/mechanics/tensor_mass.hpp"
#include "tetcut/mesh_builder.hpp"
#include "tetcut/percentile.hpp"
#include "tetcut/scenario/scenario.hpp"
#include "tetcut/scenario/sweep.hpp"

namespace tetcut::cli {

namespace {

struct SimulateArgs {
  std::optional<std::string> input, fix, frames, report;
  std::vector<std::string> sweeps;  // FROM TO STEP, three by three
  bool swept = false;               // --sweep's points joined by capsules
  bool haptic = false;              // a reader thread on published snapshots
  std::vector<std::string> materials;  // LABEL:E,NU,RHO
  std::vector<std::uint32_t> uncuttable_labels;
  std::optional<Vec3> gravity;
  std::optional<double> diameter, dt, dt_factor, young, poisson, density, unit, damping, debris_volume;
  std::optional<std::uint64_t> steps, settle, frame_every;
  std::optional<RemovalStrategy> strategy;
};

void add_simulate_options(CLI::App& app, SimulateArgs& a) {
  opt::text(app, "INPUT", a.input, "a mesh, or a scenario (.scn) whose mesh, diameter, strategy, cuts and sweeps are run", "")
      ->required();
  // Three values an occurrence, any number of occurrences (expected(3) alone would cap the
  // option's values at three in all, refusing a second --sweep).
  app.add_option("--sweep", a.sweeps,
                 "one cut every STEP from FROM to TO, TO included when a whole number of steps away (X,Y,Z X,Y,Z S; "
                 "repeatable: the sweeps run one after the other)")
      ->type_size(3)
      ->expected(1, CLI::detail::expected_max_vector_size)
      ->allow_extra_args(false)
      ->type_name("FROM TO STEP");
  opt::flag(app, "--swept", a.swept,
            "join each --sweep's points by capsules: a frame cuts from one point to the next by every point within "
            "the tool's radius of that segment, both ends mapped to the rest shape, so no tissue stays between two "
            "points whatever the step (a scenario's sweeps say `swept` themselves)");
  opt::number(app, "--diameter", a.diameter, "the tool's diameter (mesh units; required to cut a mesh with --sweep)", "D");
  opt::strategy(app, "--strategy", a.strategy, "removal strategy (default combined)");
  opt::debris_volume(app, a.debris_volume);
  opt::text(app, "--fix", a.fix, "vertices held in place: AXIS OP VALUE, e.g. \"x<10\" (mesh units)", "RULE");
  opt::point(app, "--gravity", a.gravity, "m/s2 (default 0,0,0)", "X,Y,Z");
  opt::number(app, "--young", a.young, "Young's modulus in Pa (default 3000, liver-like)", "E");
  app.add_option("--material", a.materials,
                 "the material of the tets labelled LABEL in the mesh file (Gmsh physical tag, medit reference, VTK "
                 "cell data \"label\"): Young's modulus in Pa, Poisson ratio, density in kg/m3 (repeatable; other "
                 "labels take --young, --poisson, --density)")
      ->type_name("LABEL:E,NU,RHO");
  opt::labels(app, "--keep-label", a.uncuttable_labels,
              "tets with this label (the mesh file's) are tissue no cut takes, as the paper's Fig. 7 keeps the "
              "portal vein (repeatable)");
  opt::number(app, "--poisson", a.poisson, "Poisson ratio (default 0.45)", "NU");
  opt::number(app, "--density", a.density, "kg/m3 (default 1000)", "RHO");
  opt::number(app, "--unit", a.unit, "metres per mesh unit (default 0.001: millimetres)", "M");
  opt::number(app, "--damping", a.damping, "mass-proportional damping in 1/s (default 20)", "G");
  opt::number(app, "--dt", a.dt, "a fixed time step in s (default: --dt-factor x the stable-step estimate, after every cut)", "S");
  opt::number(app, "--dt-factor", a.dt_factor,
              "fraction of the stable-step estimate each frame steps at (default 0.5; the estimate lies between 2/3 "
              "of the critical step and the step itself)",
              "F");
  opt::count(app, "--steps", a.steps, "explicit steps per frame (default 10)");
  opt::count(app, "--settle", a.settle, "steps before the first cut (default 0)");
  opt::text(app, "--frames", a.frames, "a .vtu per frame with the displacement, for ParaView (DIR must exist)", "DIR");
  opt::count(app, "--frame-every", a.frame_every, "write every Nth frame (default 1)");
  opt::flag(app, "--haptic", a.haptic,
            "a haptic thread beside the simulation: each frame is published as a snapshot (deformed positions, "
            "surface, reaction force; mechanics::SnapshotPublisher) and a thread reads the latest every millisecond, "
            "checking each whole; the summary gives its reads, waits and lateness (a torn or backward frame fails "
            "the run)");
  opt::text(app, "--report", a.report,
            "`frames` (cut_us, update_us, step_us, stable_dt, energy, max_displacement_m per frame) and `summary`",
            "R.json");
}

// "x<10", "z >= -5": the vertices held in place.
std::optional<std::function<bool(const Vec3&)>> parse_fix(std::string text) {
  std::erase(text, ' ');
  if (text.size() < 3) return std::nullopt;
  const char axis = text[0];
  if (axis != 'x' && axis != 'y' && axis != 'z') return std::nullopt;
  std::size_t at = 1;
  std::string op;
  while (at < text.size() && (text[at] == '<' || text[at] == '>' || text[at] == '=')) op += text[at++];
  if (op != "<" && op != "<=" && op != ">" && op != ">=") return std::nullopt;
  const auto value = scenario::parse_double(text.substr(at));
  if (!value) return std::nullopt;
  return [axis, op, v = *value](const Vec3& p) {
    const double c = axis == 'x' ? p.x : axis == 'y' ? p.y : p.z;
    return op == "<" ? c < v : op == "<=" ? c <= v : op == ">" ? c > v : c >= v;
  };
}

// "3:6000,0.45,1050": a label and its material; nullopt when it does not parse.
std::optional<std::pair<std::uint32_t, mechanics::Material>> parse_material(const std::string& text) {
  const auto colon = text.find(':');
  if (colon == std::string::npos) return std::nullopt;
  const auto label = scenario::parse_double(text.substr(0, colon));
  if (!label || *label < 0 || *label > kMaxTetLabel || *label != std::floor(*label)) return std::nullopt;
  const auto values = scenario::parse_vec3(text.substr(colon + 1));  // three comma-separated numbers
  if (!values) return std::nullopt;
  return std::pair{static_cast<std::uint32_t>(*label), mechanics::Material{values->x, values->y, values->z}};
}

// The cuts of a sweep, where `tetcut cut` and a scenario place them: balls, or swept, capsules
// from each centre to the next.
void add_sweep(const Vec3& a, const Vec3& b, double step, bool swept, std::vector<scenario::CutTool>& out) {
  const std::vector<scenario::CutTool> cuts = scenario::sweep_cuts(a, b, step, swept);
  out.insert(out.end(), cuts.begin(), cuts.end());
}

// An SI value in a message: "1.338e-04 s", so that a step of microseconds or an energy of
// microjoules reads as one (std::to_string's six decimals print them as 0.000000).
std::string si(double value, const char* unit) {
  char text[48];
  std::snprintf(text, sizeof text, "%.3e %s", value, unit);
  return text;
}

// The largest displacement of a live vertex (m).
double max_displacement(const TetMesh& mesh, const mechanics::TensorMassModel& model) {
  double u = 0;
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v)
    if (mesh.is_live(VertId{v})) u = std::max(u, norm(model.displacement(VertId{v})));
  return u;
}

double microseconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count();
}

// What to cut: a scenario's mesh, parameters and sweeps, or the command line's. One frame a tool.
struct CutPlan {
  CutParams params;
  std::string mesh_path;
  std::vector<scenario::CutTool> tools;
};

// Fills `plan` (and the scenario's uncuttable labels into `a`); an exit code when the options
// are unusable.
std::optional<int> plan_cuts(SimulateArgs& a, const CommandParser& parser, std::ostream& err, CutPlan& plan) {
  CutParams& params = plan.params;
  std::string& mesh_path = plan.mesh_path;
  std::vector<scenario::CutTool>& tools = plan.tools;
  mesh_path = *a.input;
  if (mesh_path.ends_with(".scn")) {
    const scenario::ParseResult parsed = scenario::parse_file(mesh_path);
    if (!parsed.scenario) {
      err << "tetcut: " << parsed.error << "\n";
      return kExitBadInput;
    }
    mesh_path.clear();
    for (const scenario::Op& op : parsed.scenario->ops) {
      switch (op.kind) {
        case scenario::OpKind::kMesh:
          if (mesh_path.empty()) mesh_path = op.text.front() == '/' ? op.text : parsed.scenario->base_dir + "/" + op.text;
          break;
        case scenario::OpKind::kParam:
          if (op.text == "diameter") {
            params.tool_diameter = *scenario::parse_double(op.value);
          } else if (op.text == "strategy") {
            params.strategy = *parse_removal_strategy(op.value);
          } else if (op.text == "debris_volume") {
            params.debris_volume = *scenario::parse_double(op.value);
          } else {
            return parser.usage_error(*a.input + ":" + std::to_string(op.line) +
                                          ": simulate runs only diameter, strategy and debris_volume, not " + op.text,
                                      err);
          }
          break;
        case scenario::OpKind::kSweep: add_sweep(op.a, op.b, op.step, op.swept, tools); break;
        case scenario::OpKind::kCut: tools.push_back({op.a, op.swept ? std::optional<Vec3>(op.b) : std::nullopt}); break;
        case scenario::OpKind::kUncuttable:
          a.uncuttable_labels.insert(a.uncuttable_labels.end(), op.labels.begin(), op.labels.end());
          break;
        case scenario::OpKind::kUndo:
          return parser.usage_error(*a.input + ":" + std::to_string(op.line) +
                                        ": simulate plans its cuts before it runs them and takes none back: `undo` is `tetcut run`'s",
                                    err);
        default: break;  // checks and expectations are `tetcut run`'s
      }
    }
    if (mesh_path.empty()) return parser.usage_error(*a.input + ": the scenario names no mesh", err);
  }
  const bool from_scenario = a.input->ends_with(".scn");  // a scenario sets the diameter (or takes the default)
  if (a.diameter) params.tool_diameter = *a.diameter;
  if (a.strategy) params.strategy = *a.strategy;
  if (a.debris_volume) params.debris_volume = *a.debris_volume;
  if (a.sweeps.size() % 3 != 0) return parser.usage_error("--sweep: expects FROM TO STEP", err);
  for (std::size_t i = 0; i < a.sweeps.size(); i += 3) {
    const auto from = scenario::parse_vec3(a.sweeps[i]), to = scenario::parse_vec3(a.sweeps[i + 1]);
    const auto step = scenario::parse_double(a.sweeps[i + 2]);
    if (!from || !to) return parser.usage_error("--sweep: FROM and TO expect X,Y,Z", err);
    if (!step || *step <= 0) return parser.usage_error("--sweep: STEP must be a positive number", err);
    if (norm(*to - *from) / *step > scenario::kMaxSweepCuts) return parser.usage_error("--sweep: more than 100000 cuts", err);
    add_sweep(*from, *to, *step, a.swept, tools);
  }
  // A diameter only matters to a cut: a mesh left to settle under gravity needs none.
  if (a.swept && a.sweeps.empty()) return parser.usage_error("--swept: joins the points of --sweep, and there is none", err);
  if (!tools.empty() && !a.diameter && !from_scenario) {
    return parser.usage_error("--diameter is required to cut a mesh (--sweep)", err);
  }
  if (const auto bad = validate(params)) return parser.usage_error(*bad, err);
  return std::nullopt;
}

// The model's materials, damping and gravity, the vertices held in place, the time stepping.
struct ModelPlan {
  mechanics::ModelParams params;
  std::function<bool(const Vec3&)> fixed;
  double dt_factor = 0.5;
  std::uint64_t steps = 10, frame_every = 1;
};

std::optional<int> plan_model(const SimulateArgs& a, const CommandParser& parser, std::ostream& err, ModelPlan& plan) {
  mechanics::ModelParams& model_params = plan.params;
  mechanics::Material& material = model_params.materials.front();
  if (a.young) material.young = *a.young;
  if (a.poisson) material.poisson = *a.poisson;
  if (a.density) material.density = *a.density;
  for (const std::string& text : a.materials) {
    const auto entry = parse_material(text);
    if (!entry) return parser.usage_error("--material: expects LABEL:E,NU,RHO (LABEL an integer >= 0), not '" + text + "'", err);
    model_params.label_materials.push_back(*entry);
  }
  std::sort(model_params.label_materials.begin(), model_params.label_materials.end(),
            [](const auto& x, const auto& y) { return x.first < y.first; });
  if (a.unit) model_params.length_unit = *a.unit;
  model_params.damping = a.damping.value_or(20.0);
  model_params.gravity = a.gravity.value_or(Vec3{});
  if (const auto bad = mechanics::validate(model_params)) return parser.usage_error(*bad, err);
  if (a.fix) {
    auto rule = parse_fix(*a.fix);
    if (!rule) return parser.usage_error("--fix: expects AXIS OP VALUE (x, y or z; <, <=, > or >=), not '" + *a.fix + "'", err);
    plan.fixed = *rule;
  }
  plan.dt_factor = a.dt_factor.value_or(0.5);
  if (!(plan.dt_factor > 0)) return parser.usage_error("--dt-factor: must be positive", err);
  if (a.dt && !(*a.dt > 0)) return parser.usage_error("--dt: must be positive", err);
  plan.steps = a.steps.value_or(10);
  plan.frame_every = std::max<std::uint64_t>(1, a.frame_every.value_or(1));
  return std::nullopt;
}

// --keep-label: the tets with those labels in the file are set uncuttable on the cutter and the
// checker. An exit code when the mesh has no labels or the cutter refuses them.
std::optional<int> keep_labels(const SimulateArgs& a, const RawMesh& raw, const std::string& mesh_path, Cutter& cutter,
                               invariants::LocalChecker& local, const CommandParser& parser, std::ostream& err) {
  if (a.uncuttable_labels.empty()) return std::nullopt;
  if (!raw.labelled()) return parser.usage_error("--keep-label: " + mesh_path + " has no labels", err);
  std::vector<TetId> uncuttable;
  for (std::uint32_t t = 0; t < raw.labels.size(); ++t)
    if (std::find(a.uncuttable_labels.begin(), a.uncuttable_labels.end(), raw.labels[t]) != a.uncuttable_labels.end())
      uncuttable.push_back(TetId{t});  // the builder keeps the file's tet order
  if (const auto bad = cutter.set_uncuttable(uncuttable)) return parser.usage_error(*bad, err);
  local.set_uncuttable(uncuttable);  // the checker's own record, which I10 holds the cuts to
  return std::nullopt;
}

// The frames: one cut each, the consumers updated, the checker, the steps; and their figures.
class Simulation {
 public:
  Simulation(const SimulateArgs& a, const ModelPlan& plan, TetMesh& mesh, Cutter& cutter,
             invariants::LocalChecker& local, mechanics::TensorMassModel& model, mechanics::RenderedSurface& surface,
             mechanics::StableStepEstimator& stable_step, double initial_stable_dt, double dt)
      : a_(a), plan_(plan), mesh_(mesh), cutter_(cutter), local_(local), model_(model), surface_(surface),
        stable_step_(stable_step), dt_(dt), min_stable_(initial_stable_dt), stable_dt_(initial_stable_dt), min_dt_(dt) {
    log_.reserve(1u << 14);
    energy_ = model_.energy();
    max_u_ = max_displacement(mesh_, model_);  // after settling, should no frame follow
  }

  enum class Frame { kDone, kStopped, kWriteFailed };

  // Where the tissue at world point p is at rest (p itself outside the deformed tissue).
  Vec3 rest_of(const Vec3& p) {
    return model_.rest_point(mesh_, p, [&](const Vec3& q) { return cutter_.tet_containing(q); }).value_or(p);
  }

  // Frame k, the tool in the world: the ball at tool.centre, or the capsule from it to tool.end.
  Frame frame(std::size_t k, const scenario::CutTool& tool, std::ostream& err) {
    const Vec3& centre = tool.centre;
    const auto t0 = std::chrono::steady_clock::now();
    // Both ends of a capsule mapped before the cut: the tool's path through the tissue as it is now.
    const scenario::CutTool rest{rest_of(centre), tool.end ? std::optional<Vec3>(rest_of(*tool.end)) : std::nullopt};
    log_.clear();
    const CutReport r = rest.end ? cutter_.cut_segment(rest.centre, *rest.end, &log_) : cutter_.cut(rest.centre, &log_);
    cut_us_.push_back(microseconds_since(t0));
    const auto t1 = std::chrono::steady_clock::now();
    model_.apply(mesh_, log_);
    surface_.apply(mesh_, log_);
    update_us_.push_back(microseconds_since(t1));
    if (!r.ok) ++cuts_refused_;
    // The tissue rule too (I10), at the tool where the rest mesh was cut.
    const invariants::CheckReport check =
        local_.after_operation(mesh_.raw_view(), cutter_.last_removed(), cutter_.last_created(),
                               r.ok ? scenario::cut_check_options(cutter_, rest.centre, rest.end)
                                    : scenario::transaction_check_options(cutter_.params(),
                                                                          cutter_.last_min_dihedral_held()));
    if (!check.ok()) {
      failure_ = "frame " + std::to_string(k) + ": " + invariants::id_string(check.violations.front().id) + " violated: " +
                 check.violations.front().detail;
      return Frame::kStopped;
    }
    // The estimate follows the cut: a few iterations from the last ones (stable_step.hpp); a cut
    // that changed nothing leaves it where it was. The step follows it, unless fixed by --dt.
    if (!log_.removed.empty() || !log_.created.empty()) stable_dt_ = stable_step_.update(model_).dt;
    min_stable_ = std::min(min_stable_, stable_dt_);
    const double frame_dt = a_.dt ? dt_ : std::min(dt_, plan_.dt_factor * stable_dt_);
    min_dt_ = std::min(min_dt_, frame_dt);
    if (frame_dt > stable_dt_) ++unstable_frames_;
    const mechanics::Energy before_steps = model_.energy();
    const auto t2 = std::chrono::steady_clock::now();
    for (std::uint64_t s = 0; s < plan_.steps; ++s) model_.step(frame_dt);
    step_us_.push_back(plan_.steps ? microseconds_since(t2) / static_cast<double>(plan_.steps) : 0.0);
    energy_ = model_.energy();
    max_u_ = max_displacement(mesh_, model_);
    // What a haptic device renders: the tissue's push on the tool where it is in the world.
    const Vec3 reaction = mechanics::reaction_force(mesh_, model_, centre, tool.end.value_or(centre),
                                                    cutter_.params().tool_diameter / 2, forces_);
    if (publisher_) publisher_->publish(mesh_, model_, surface_, &log_, plan_.steps > 0, reaction);
    Json record{{"frame", k}, {"centre", {centre.x, centre.y, centre.z}}};
    if (tool.end) record["end"] = {tool.end->x, tool.end->y, tool.end->z};  // a capsule's other end, in the world
    record.update(Json{{"cut_ok", r.ok},
                       {"tets", mesh_.num_tets()},
                       {"removed", log_.removed.size()},
                       {"created", log_.created.size()},
                       {"cut_us", cut_us_.back()},
                       {"update_us", update_us_.back()},
                       {"step_us", step_us_.back()},
                       {"dt", frame_dt},
                       {"stable_dt", stable_dt_},
                       {"energy", {{"kinetic", energy_.kinetic}, {"elastic", energy_.elastic}, {"gravity", energy_.gravity},
                                   {"total", energy_.total()}}},
                       {"max_displacement_m", max_u_},
                       {"reaction_force_n", {reaction.x, reaction.y, reaction.z}},
                       {"fragments", r.fragments},
                       {"debris_pieces_removed", r.debris_pieces_removed},
                       {"debris_volume_removed", r.debris_volume_removed}});
    fragments_ += r.fragments;
    debris_pieces_ += r.debris_pieces_removed;
    frames_.push_back(std::move(record));
    if (a_.frames && k % plan_.frame_every == 0) {
      char name[32];
      std::snprintf(name, sizeof name, "/frame_%05zu.vtu", k);
      if (const auto bad = write_simulation_frame(*a_.frames + name, mesh_, model_)) {
        err << "tetcut: " << *bad << "\n";
        return Frame::kWriteFailed;
      }
      ++written_;
    }
    if (blew_up(k, before_steps, frame_dt)) return Frame::kStopped;
    return Frame::kDone;
  }

  // Each frame published for a reader thread (--haptic), from the state before the first.
  void publish_to(mechanics::SnapshotPublisher& publisher) {
    publisher_ = &publisher;
    publisher.publish(mesh_, model_, surface_, nullptr, true, {});
  }

  // The summary, printed and in the report; the command's exit code. `haptic`: what the reader
  // thread measured (--haptic), else null.
  int finish(const std::string& mesh_path, std::uint32_t fixed_count, double initial_stable_dt,
             const mechanics::PeriodicReader::Figures* haptic, std::ostream& out, std::ostream& err) {
    auto p = [](const std::vector<double>& v, double q) { return v.empty() ? 0.0 : percentile(v, q); };
    if (haptic && (haptic->torn || haptic->backwards) && failure_.empty())
      failure_ = "the haptic thread read " + std::to_string(haptic->torn) + " torn and " +
                 std::to_string(haptic->backwards) + " backward frames";
    Json summary = {{"mesh", mesh_path},
                    {"frames", frames_.size()},
                    {"cuts_refused", cuts_refused_},
                    {"fixed_vertices", fixed_count},
                    {"dt", dt_},
                    {"dt_min", min_dt_},
                    {"dt_factor", a_.dt ? Json(nullptr) : Json(plan_.dt_factor)},
                    {"stable_dt_initial", initial_stable_dt},
                    {"stable_dt_min", min_stable_},
                    {"frames_above_stable_dt", unstable_frames_},
                    {"cut_us_p50", p(cut_us_, 0.5)},
                    {"cut_us_p99", p(cut_us_, 0.99)},
                    {"update_us_p50", p(update_us_, 0.5)},
                    {"update_us_p99", p(update_us_, 0.99)},
                    {"step_us_p50", p(step_us_, 0.5)},
                    {"energy_final", energy_.total()},
                    {"max_displacement_m", max_u_},
                    {"frames_written", written_},
                    {"ok", failure_.empty()},
                    {"failure", failure_},
                    {"fragments", fragments_},
                    {"debris_pieces_removed", debris_pieces_}};
    out << "simulate: " << frames_.size() << " frames of " << plan_.steps << " steps at dt " << si(dt_, "s")
        << " (stable step estimate " << si(initial_stable_dt, "s") << " before the cuts, " << si(min_stable_, "s")
        << " at worst after), " << fixed_count << " fixed vertices, " << cuts_refused_ << " cuts refused, "
        << fragments_ << " pieces detached (" << debris_pieces_ << " removed as debris)\n"
        << "  per frame: cut p50 " << p(cut_us_, 0.5) << " us, update p50 " << p(update_us_, 0.5) << " us, step p50 "
        << p(step_us_, 0.5) << " us; final energy " << si(energy_.total(), "J") << ", largest displacement "
        << si(max_u_, "m") << "\n";
    if (haptic) {
      summary["haptic"] = {{"period_us", 1000},
                           {"reads", haptic->reads},
                           {"publishes", publisher_->stats().publishes},
                           {"wait_us_p50", p(haptic->wait_us, 0.5)},
                           {"wait_us_p99", p(haptic->wait_us, 0.99)},
                           {"read_us_p99", p(haptic->read_us, 0.99)},
                           {"late_us_p50", p(haptic->late_us, 0.5)},
                           {"late_us_p99", p(haptic->late_us, 0.99)},
                           {"torn", haptic->torn},
                           {"backwards", haptic->backwards}};
      out << "  haptic thread: " << haptic->reads << " reads of " << publisher_->stats().publishes
          << " frames published, wait p99 " << p(haptic->wait_us, 0.99) << " us, late p99 " << p(haptic->late_us, 0.99)
          << " us, " << haptic->torn << " torn, " << haptic->backwards << " backwards\n";
    }
    if (a_.report && !write_json_file(*a_.report, Json{{"summary", summary}, {"frames", frames_}}, err)) return kExitBadInput;
    if (!failure_.empty()) {
      err << "tetcut simulate: " << failure_ << "\n";
      return kExitViolated;
    }
    return kExitOk;
  }

 private:
  // A blow-up: the total energy growing over the frame's steps. Damped, it can only fall (to the
  // integrator's O(dt) ripple, allowed up to 1 % of the energies' size).
  bool blew_up(std::size_t k, const mechanics::Energy& before_steps, double frame_dt) {
    const double size = before_steps.kinetic + std::abs(before_steps.elastic) + std::abs(before_steps.gravity) +
                        energy_.kinetic + std::abs(energy_.elastic) + std::abs(energy_.gravity);
    if (std::isfinite(energy_.total()) && !(energy_.total() - before_steps.total() > 1e-2 * size)) return false;
    failure_ = "blow-up at frame " + std::to_string(k) + ": the energy went from " + si(before_steps.total(), "J") +
               " to " + si(energy_.total(), "J") + " in " + std::to_string(plan_.steps) + " steps of " +
               si(frame_dt, "s") + " (stable step estimate " + si(stable_dt_, "s") + ")";
    return true;
  }

  const SimulateArgs& a_;
  const ModelPlan& plan_;
  TetMesh& mesh_;
  Cutter& cutter_;
  invariants::LocalChecker& local_;
  mechanics::TensorMassModel& model_;
  mechanics::RenderedSurface& surface_;
  mechanics::StableStepEstimator& stable_step_;
  const double dt_;
  Json frames_ = Json::array();
  std::vector<double> cut_us_, update_us_, step_us_;
  double min_stable_;
  std::uint64_t unstable_frames_ = 0, cuts_refused_ = 0, written_ = 0;
  std::uint64_t fragments_ = 0, debris_pieces_ = 0;  // pieces the cuts detached, and of them debris removed
  ChangeLog log_;
  std::vector<Vec3> forces_;  // the elastic forces, scratch of reaction_force()
  mechanics::SnapshotPublisher* publisher_ = nullptr;
  std::string failure_;
  mechanics::Energy energy_;
  double max_u_ = 0;
  double stable_dt_, min_dt_;
};

}  // namespace

int cmd_simulate(Args args, std::ostream& out, std::ostream& err) {
  SimulateArgs a;
  CommandParser parser(
      "simulate",
      "tetcut simulate MESH|SCENARIO.scn [--sweep FROM TO STEP]... [--swept] [--diameter D] [--strategy S] "
      "[--debris-volume V] [--fix RULE] "
      "[--gravity X,Y,Z] [--young E] [--poisson NU] [--density RHO] [--material LABEL:E,NU,RHO]... [--keep-label L]... [--unit M] [--damping G] [--dt S] "
      "[--steps N] [--settle N] [--frames DIR] [--frame-every N] [--haptic] [--report R.json]",
      "Linear-elastic tissue (tensor-mass, Cotin, Delingette and Ayache 2000) stepped at a fixed\n"
      "time step (semi-implicit Euler) while the cautery cuts it: per frame one cut, the model and\n"
      "the rendered surface updated from the cut's change log, then --steps steps. The sweep points\n"
      "are in the world: each is mapped to the rest shape through the deformed tissue before the\n"
      "cut. --swept cuts from each sweep point to the next (a capsule, both ends mapped) per frame.\n"
      "A blow-up (the total energy growing over a frame's steps, or not finite) fails the run.\n",
      "exit: 0, 1 a blow-up or an invariant broke, 2 bad input or usage");
  add_simulate_options(parser.app(), a);
  if (const auto code = parser.parse(args, out, err)) return *code;
  CutPlan cuts;
  if (const auto code = plan_cuts(a, parser, err, cuts)) return *code;
  ModelPlan plan;
  if (const auto code = plan_model(a, parser, err, plan)) return *code;

  const std::optional<RawMesh> raw = load_mesh(cuts.mesh_path, err);
  if (!raw) return kExitBadInput;
  BuildResult built = build_mesh(*raw);
  if (!built.ok()) {
    err << "tetcut: " << cuts.mesh_path << ": " << built.problems.front().message << "\n";
    return kExitBadInput;
  }
  TetMesh mesh = std::move(*built.mesh);

  Cutter cutter(mesh, cuts.params);
  invariants::LocalChecker local(mesh.raw_view());
  if (const auto code = keep_labels(a, *raw, cuts.mesh_path, cutter, local, parser, err)) return *code;
  // The file's labels choose the materials (TetId = the file's tet index: the builder keeps the order).
  mechanics::TensorMassModel model(mesh, plan.params, raw->labels);
  mechanics::RenderedSurface surface(mesh);
  const std::uint32_t fixed_count = plan.fixed ? model.fix_where(mesh, plan.fixed) : 0;
  mechanics::StableStepEstimator stable_step;
  const mechanics::StableStepEstimator::Estimate initial = stable_step.estimate(model);
  if (!std::isfinite(initial.dt) && !a.dt) return parser.usage_error("--fix: every vertex is fixed: nothing moves", err);
  const double dt = a.dt.value_or(plan.dt_factor * initial.dt);
  for (std::uint64_t s = 0; s < a.settle.value_or(0); ++s) model.step(dt);

  Simulation simulation(a, plan, mesh, cutter, local, model, surface, stable_step, initial.dt, dt);
  // --haptic: one reader, so two buffers besides the one it holds; checksums, so that it can
  // tell a torn frame.
  std::optional<mechanics::SnapshotPublisher> publisher;
  std::optional<mechanics::PeriodicReader> reader;
  if (a.haptic) {
    publisher.emplace(mechanics::SnapshotPublisher::Options{.readers = 1, .checksums = true});
    simulation.publish_to(*publisher);
    reader.emplace(*publisher, mechanics::PeriodicReader::Options{.period = std::chrono::microseconds(1000)});
  }
  for (std::size_t k = 0; k < cuts.tools.size(); ++k) {
    const Simulation::Frame frame = simulation.frame(k, cuts.tools[k], err);
    if (frame == Simulation::Frame::kWriteFailed) return kExitBadInput;
    if (frame == Simulation::Frame::kStopped) break;
  }
  std::optional<mechanics::PeriodicReader::Figures> haptic;
  if (reader) haptic = reader->stop();
  return simulation.finish(cuts.mesh_path, fixed_count, initial.dt, haptic ? &*haptic : nullptr, out, err);
}

}  // namespace tetcut::cli
