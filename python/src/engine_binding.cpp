// tetcut.check_engine: any engine's adapter (tetcut/harness/engine.h) driven through scenarios
// and random sweeps with the independent checker after every operation, each plan in a child
// process: what `tetcut check-engine` does (harness/, docs/engines.md), as Python dicts.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "signature_doc.hpp"
#include "tetcut/harness/engine_check.hpp"
#include "tetcut/io.hpp"

namespace py = pybind11;

namespace tetcut::python {

namespace {

py::dict plan_dict(const harness::PlanCheck& p) {
  py::dict d;
  d["plan"] = p.plan;
  d["ok"] = p.ok();
  d["level"] = p.level;
  d["operations"] = p.operations;
  d["run"] = p.run;
  d["refused"] = p.refused;
  d["failed_operation"] = p.failed_operation ? py::object(py::int_(*p.failed_operation)) : py::object(py::none());
  d["failed_operation_name"] = p.failed_operation_name;
  d["invariants"] = p.invariants;
  d["objection"] = p.objection;
  d["tets_before"] = p.tets_before;
  d["tets_after"] = p.tets_after;
  d["singular_vertices"] = p.singular_vertices;
  d["singular_edges"] = p.singular_edges;
  d["inverted_tets"] = p.inverted_tets;
  d["angle_floor_lowered"] = p.angle_floor_lowered;
  d["engine_error"] = p.engine_error;
  d["signal"] = p.signal;
  d["notes"] = p.notes;
  return d;
}

py::list check_engine(const std::string& engine, const std::optional<std::vector<std::string>>& scenario_list,
                      const std::optional<std::vector<std::string>>& mesh_list, std::uint32_t sweeps, std::uint32_t cuts,
                      std::uint64_t seed, unsigned timeout) {
  const std::vector<std::string> scenarios = scenario_list.value_or(std::vector<std::string>{});
  const std::vector<std::string> meshes = mesh_list.value_or(std::vector<std::string>{});
  if (scenarios.empty() && meshes.empty()) throw py::value_error("tetcut: check_engine: give scenarios or meshes");
  if (cuts == 0 || sweeps == 0) throw py::value_error("tetcut: check_engine: sweeps and cuts must be positive");
  std::vector<harness::EnginePlan> plans;
  harness::AdapterInfo adapter;
  std::vector<harness::PlanCheck> checks;
  {
    py::gil_scoped_release release;  // the children never touch Python
    try {
      adapter = harness::probe_adapter(engine);
      for (const std::string& path : scenarios) plans.push_back(harness::plan_from_scenario(path));
      for (const std::string& path : meshes) {
        ReadResult read = read_mesh(path);
        if (!read.mesh) throw std::runtime_error(read.error->message());
        for (std::uint32_t k = 0; k < sweeps; ++k) {
          plans.push_back(harness::random_sweep_plan(std::filesystem::path(path).filename().string(), *read.mesh,
                                                     seed + k, cuts));
          plans.back().mesh_path = path;
        }
      }
    } catch (const std::exception& e) {
      py::gil_scoped_acquire acquire;
      throw py::value_error(std::string("tetcut: ") + e.what());
    }
    harness::EngineCheckOptions options;
    options.timeout_seconds = timeout;
    for (const harness::EnginePlan& plan : plans) checks.push_back(harness::check_plan(adapter, plan, options));
  }
  py::list out;
  for (const harness::PlanCheck& p : checks) out.append(plan_dict(p));
  return out;
}

}  // namespace

void bind_engine_check(py::module_& m) {
  m.def("check_engine", &check_engine, py::arg("engine"), py::kw_only(), py::arg("scenarios") = py::none(),
        py::arg("meshes") = py::none(), py::arg("sweeps") = 1, py::arg("cuts") = 24,
        py::arg("seed") = 1, py::arg("timeout") = 600,
        signature_doc("check_engine", "engine, *, scenarios=None, meshes=None, sweeps=1, cuts=24, seed=1, timeout=600",
                      R"doc(Drives a cutting engine's adapter with the independent checker after every operation.

engine: the adapter, a shared library implementing tetcut/harness/engine.h (docs/engines.md).
scenarios: scenario files to run; meshes: mesh files to sweep at random (sweeps per mesh, cuts
per sweep, seed of the first). Each plan runs in a child process, so an engine that crashes is
reported (its "signal" and "engine_error") instead of taking Python down; timeout is per plan,
in seconds. Returns one dict per plan, as `tetcut check-engine --json` gives them: "ok",
"failed_operation" (1-based, None: none) and its name, "invariants", "objection",
"singular_vertices", "singular_edges", ... ValueError when the adapter does not load or a file
cannot be read. Releases the GIL.)doc")
            .c_str());
}

}  // namespace tetcut::python
