// tetcut.Cutter, its CutReport and report.changes; tetcut.stats.
//
// A cut releases the GIL for as long as the engine works (the mesh is held in use meanwhile,
// mesh_handle.hpp). Its net ChangeLog is always recorded, as the C++ README sweep records it,
// and kept in the report as the engine's vectors: report.changes turns them into numpy arrays
// only when read, so a loop that never reads them pays for no array (bench/python measures both).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "mesh_handle.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/stats/removal_tables.hpp"

namespace py = pybind11;

namespace tetcut::python {

namespace {

// What report.changes holds: the ChangeLog as numpy arrays (engine ids throughout).
struct Changes {
  py::array_t<std::int64_t> removed, created, parent, parents, parents_offsets;
  py::array_t<std::int64_t> new_vertices, new_vertex_edges, new_vertex_from, removed_vertices;
  py::array_t<double> new_vertex_t, new_vertex_weights;
};

struct Report {
  CutReport report;
  double wall_us = 0;  // the engine call alone, timed by the binding: Python's overhead is the rest
  ChangeLog log;
  Vec3 centre;
  std::optional<Changes> changes;
};

template <class Id>
py::array_t<std::int64_t> id_array(const std::vector<Id>& ids) {
  py::array_t<std::int64_t> a(static_cast<py::ssize_t>(ids.size()));
  std::int64_t* out = a.mutable_data();
  for (const Id& id : ids) *out++ = id.valid() ? static_cast<std::int64_t>(id.value) : -1;
  return a;
}

Changes changes_of(const ChangeLog& log) {
  Changes c;
  const auto n = static_cast<py::ssize_t>(log.created.size());
  const auto nv = static_cast<py::ssize_t>(log.vertices.size());
  c.removed = id_array(log.removed);
  c.removed_vertices = id_array(log.removed_vertices);
  c.parents = id_array(log.parents);
  c.created = py::array_t<std::int64_t>(n);
  c.parent = py::array_t<std::int64_t>(n);
  c.parents_offsets = py::array_t<std::int64_t>(n + 1);
  c.parents_offsets.mutable_data()[0] = 0;
  for (py::ssize_t i = 0; i < n; ++i) {
    const CreatedTet& t = log.created[i];
    c.created.mutable_data()[i] = t.tet.value;
    c.parent.mutable_data()[i] = t.parent.valid() ? static_cast<std::int64_t>(t.parent.value) : -1;
    c.parents_offsets.mutable_data()[i + 1] = t.parents_begin + t.parents_count;
  }
  c.new_vertices = py::array_t<std::int64_t>(nv);
  c.new_vertex_edges = py::array_t<std::int64_t>({nv, py::ssize_t{2}});
  c.new_vertex_t = py::array_t<double>(nv);
  c.new_vertex_from = py::array_t<std::int64_t>({nv, py::ssize_t{4}});
  c.new_vertex_weights = py::array_t<double>({nv, py::ssize_t{4}});
  auto edges = c.new_vertex_edges.mutable_unchecked<2>();
  auto from = c.new_vertex_from.mutable_unchecked<2>();
  auto weights = c.new_vertex_weights.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < nv; ++i) {
    const CreatedVertex& v = log.vertices[i];
    c.new_vertices.mutable_data()[i] = v.vertex.value;
    edges(i, 0) = v.on_edge() ? static_cast<std::int64_t>(v.from[0].value) : -1;
    edges(i, 1) = v.on_edge() ? static_cast<std::int64_t>(v.from[1].value) : -1;
    c.new_vertex_t.mutable_data()[i] = v.on_edge() ? v.weight[1] : std::nan("");
    for (int k = 0; k < 4; ++k) {
      from(i, k) = k < v.count ? static_cast<std::int64_t>(v.from[k].value) : -1;
      weights(i, k) = k < v.count ? v.weight[k] : 0.0;
    }
  }
  return c;
}

// A point from any array-like of 3 real numbers. A tuple or list of floats, what a loop passes
// per cut, is read directly (a few tens of ns, against the few hundred of a generic conversion:
// it is most of what Python adds to a cut, bench/python); anything else goes through numpy.
Vec3 point_from(py::handle obj, const char* name) {
  double p[3];
  bool read = false;
  if ((PyTuple_Check(obj.ptr()) || PyList_Check(obj.ptr())) && PySequence_Fast_GET_SIZE(obj.ptr()) == 3) {
    PyObject** items = PySequence_Fast_ITEMS(obj.ptr());
    read = true;
    for (int k = 0; k < 3; ++k) {
      if (PyFloat_CheckExact(items[k])) p[k] = PyFloat_AS_DOUBLE(items[k]);
      else if (PyLong_CheckExact(items[k])) p[k] = PyLong_AsDouble(items[k]);
      else read = false;
    }
    if (read && PyErr_Occurred()) throw py::error_already_set();  // an int too large for a double
  }
  if (!read) {
    const py::array a = py::module_::import("numpy").attr("asarray")(obj);
    const char kind = a.dtype().kind();
    if ((kind != 'f' && kind != 'i' && kind != 'u') || a.ndim() != 1 || a.shape(0) != 3) {
      throw py::type_error(std::string("tetcut: ") + name + ": expected 3 real numbers");
    }
    const auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
    for (int k = 0; k < 3; ++k) p[k] = d.data()[k];
  }
  for (double x : p) {
    if (!std::isfinite(x)) throw py::value_error(std::string("tetcut: ") + name + ": coordinates must be finite");
  }
  return {p[0], p[1], p[2]};
}

class PyCutter {
 public:
  PyCutter(MeshPtr handle, const CutParams& params, std::vector<std::uint32_t> keep_labels)
      : handle_(std::move(handle)), keep_labels_(std::move(keep_labels)) {
    if (const auto bad = validate(params)) throw py::value_error("tetcut: " + *bad);
    if (!keep_labels_.empty() && !handle_->labels.labelled())
      throw py::value_error("tetcut: keep_labels: the mesh has no labels");
    MeshUse use(*handle_);
    cutter_.emplace(handle_->mesh, params);
    protect();
    seen_version_ = handle_->version;
  }

  Report cut(const Vec3& centre) {
    MeshUse use(*handle_);
    prepare_to_mutate();
    Report r;
    r.centre = centre;
    {
      py::gil_scoped_release release;
      const auto start = std::chrono::steady_clock::now();
      r.report = cutter_->cut(centre, &r.log);
      r.wall_us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
      if (r.report.ok) handle_->labels.apply(handle_->mesh, r.log);
    }
    if (r.report.ok) seen_version_ = ++handle_->version;
    return r;
  }

  // The scenario runner's sweep (tools/scenario/src/scenario.cpp), centre for centre, so that the
  // mesh and its hash are those of `tetcut cut --from START --to END --step STEP`. Stops after the
  // first cut refused, as `tetcut cut` does (that cut's report is the last).
  std::vector<Report> sweep(const Vec3& a, const Vec3& b, double step) {
    if (!(step > 0) || !std::isfinite(step)) throw py::value_error("tetcut: step: must be positive");
    const double length = norm(b - a);
    if (length / step > 100000) throw py::value_error("tetcut: more than 100000 cuts: increase step");
    MeshUse use(*handle_);
    prepare_to_mutate();
    const auto steps = static_cast<std::uint64_t>(std::floor(length / step));
    std::vector<Report> reports(steps + 1);
    {
      py::gil_scoped_release release;
      for (std::uint64_t k = 0; k <= steps; ++k) {
        Report& r = reports[k];
        r.centre = steps == 0 ? a : a + (static_cast<double>(k) * step / length) * (b - a);
        const auto start = std::chrono::steady_clock::now();
        r.report = cutter_->cut(r.centre, &r.log);
        r.wall_us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
        if (r.report.ok) handle_->labels.apply(handle_->mesh, r.log);
        if (!r.report.ok) {
          reports.resize(k + 1);
          break;
        }
      }
    }
    seen_version_ = ++handle_->version;
    return reports;
  }

  [[nodiscard]] const CutParams& params() const { return cutter_->params(); }
  void set_params(const CutParams& params) {
    MeshUse use(*handle_);
    if (const auto bad = cutter_->set_params(params)) throw py::value_error("tetcut: " + *bad);
  }
  [[nodiscard]] RemovalReport removal_report() const { return cutter_->removal_report(); }
  [[nodiscard]] const MeshPtr& mesh() const { return handle_; }

 private:
  // Another Cutter cut the mesh, or it was compacted, since this one indexed it: index it again.
  void prepare_to_mutate() {
    require_no_slot_views(*handle_);
    if (seen_version_ != handle_->version || !cutter_->indexes_current_mesh()) {
      py::gil_scoped_release release;
      cutter_->reset();
      protect();  // a reset forgets the ids; the labels still name the tets
    }
    seen_version_ = handle_->version;
  }

  // The tets whose label is one of keep_labels_, as the labels stand now: uncuttable
  // (Cutter::set_uncuttable(), the paper's Fig. 7).
  void protect() {
    if (keep_labels_.empty()) return;
    std::vector<TetId> tets;
    const TetMesh& mesh = handle_->mesh;
    for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t)
      if (mesh.is_live(TetId{t}) &&
          std::find(keep_labels_.begin(), keep_labels_.end(), handle_->labels.label(TetId{t})) != keep_labels_.end())
        tets.push_back(TetId{t});
    (void)cutter_->set_uncuttable(tets);  // live tets of the mesh it indexes: never refused
  }

  MeshPtr handle_;
  std::vector<std::uint32_t> keep_labels_;
  std::optional<Cutter> cutter_;
  std::uint64_t seen_version_ = 0;
};

// Shared: methods take the holder, which pybind11 refuses for an instance __init__ never made.
using CutterPtr = std::shared_ptr<PyCutter>;

RemovalStrategy strategy_from(const std::string& s) {
  const auto v = parse_removal_strategy(s);
  if (!v) throw py::value_error("tetcut: strategy: basic, neighbours, combined or wide, not '" + s + "'");
  return *v;
}

SplitMethod split_from(const std::string& s) {
  const auto v = parse_split_method(s);
  if (!v) throw py::value_error("tetcut: split: templates or bisection, not '" + s + "'");
  return *v;
}

py::dict stats_of(const CutterPtr& held) {
  const PyCutter& cutter = *held;
  const RemovalReport r = [&] {
    MeshUse use(*cutter.mesh());  // not while another thread's cut adds to it
    return cutter.removal_report();
  }();
  const stats::Table1Row t1 = stats::table1_row(r);
  const stats::Table2Row t2 = stats::table2_row(r);
  py::dict removal;
  removal["requested"] = r.requested;
  removal["repeated_requests"] = r.repeated_requests;
  removal["removed"] = r.removed;
  removal["unresolved"] = r.unresolved;
  removal["direct"] = r.direct;
  removal["surface_requested"] = r.surface_requested;  // Table 1's population: a face on the surface
  removal["surface_direct"] = r.surface_direct;
  removal["vertex_singularities"] = r.vertex_singularities;
  removal["edge_singularities"] = r.edge_singularities;
  removal["resolved_by_neighbours"] = r.resolved_by_neighbours;
  removal["resolved_by_refinement"] = r.resolved_by_refinement;
  removal["resolved_by_optimized_refinement"] = r.resolved_by_optimized_refinement;
  removal["resolved_by_fallback"] = r.resolved_by_fallback;
  removal["tets_removed"] = r.tets_removed;
  removal["tets_created"] = r.tets_created;
  removal["edges_split"] = r.edges_split;
  removal["attempts_undone"] = r.attempts_undone;
  removal["mean_cardinality"] = r.mean_cardinality();
  removal["cardinality_per_selected"] = r.cardinality_per_selected();
  py::dict table1;
  table1["operations"] = t1.operations;
  table1["all_operations"] = t1.all_operations;
  table1["removable_pct"] = t1.removable_pct;
  table1["vertex_pct"] = t1.vertex_pct;
  table1["edge_pct"] = t1.edge_pct;
  py::dict table2;
  table2["vertex_unresolved_pct"] = t2.vertex_unresolved_pct;
  table2["vertex_cardinality"] = t2.vertex_cardinality;
  table2["edge_unresolved_pct"] = t2.edge_unresolved_pct;
  table2["edge_cardinality"] = t2.edge_cardinality;
  table2["global_unresolved_pct"] = t2.global_unresolved_pct;
  table2["global_cardinality"] = t2.global_cardinality;
  table2["global_cardinality_per_selected"] = t2.global_cardinality_per_selected;
  table2["combined_unresolved_pct"] = t2.combined_unresolved_pct;
  py::dict out;
  out["removal"] = removal;
  out["table1"] = table1;
  out["table2"] = table2;
  return out;
}

// Cutter.cut(centre), as a METH_FASTCALL method of the class: pybind11's generic dispatcher
// (argument vectors, overload resolution, the return type looked up by name) costs about as much
// again as all the rest of what Python adds to a cut, and the goal is at most 2 us in all
// (python/bench/test_overhead.py). Same conversions, same exceptions as the other methods.
const py::detail::type_info* report_type = nullptr;

PyObject* cut_fast(PyObject* self, PyObject* const* args, Py_ssize_t nargs, PyObject* kwnames) {
  try {
    const Py_ssize_t nkw = kwnames ? PyTuple_GET_SIZE(kwnames) : 0;
    if (nargs + nkw != 1 || (nkw == 1 && PyUnicode_CompareWithASCIIString(PyTuple_GET_ITEM(kwnames, 0), "centre") != 0)) {
      throw py::type_error("tetcut: Cutter.cut() takes one argument, centre");
    }
    // As a holder: an instance made by __new__ without __init__ has none, and is refused here.
    const auto held = py::cast<CutterPtr>(py::handle(self));
    PyCutter& cutter = *held;
    auto* report = new Report(cutter.cut(point_from(args[0], "centre")));
    return py::detail::type_caster_generic::cast(report, py::return_value_policy::take_ownership, {}, report_type,
                                                 nullptr, nullptr)
        .ptr();
  } catch (py::error_already_set& e) {
    e.restore();
  } catch (py::builtin_exception& e) {
    e.set_error();
  } catch (const std::bad_alloc&) {
    PyErr_NoMemory();
  } catch (const std::exception& e) {
    PyErr_SetString(PyExc_RuntimeError, e.what());
  }
  return nullptr;
}

PyMethodDef cut_method = {
    "cut", reinterpret_cast<PyCFunction>(reinterpret_cast<void (*)()>(&cut_fast)), METH_FASTCALL | METH_KEYWORDS,
    "cut(centre) -> CutReport\n\nOne cut with the tool centred there (3 real numbers): atomic (report.ok False: the "
    "mesh is bit-identical to before). Releases the GIL."};

}  // namespace

void bind_cutter(py::module_& m) {
  py::class_<Changes> changes(m, "Changes", R"doc(
A cut's net change (the engine's ChangeLog) as numpy arrays of engine ids (mesh.tet_ids and
mesh.vertex_ids name them): apply removals first, then creations.)doc");
  made_by_the_module_only(changes);
  changes.def_readonly("removed", &Changes::removed, "#R int64: tets live before the cut and gone after, sorted.")
      .def_readonly("created", &Changes::created, "#C int64: tets live after and not before, sorted.")
      .def_readonly("parent", &Changes::parent, "#C int64: each created tet's first parent (its only one for a split).")
      .def_readonly("parents", &Changes::parents, "All parents, flat: created[i]'s are parents[parents_offsets[i]:parents_offsets[i+1]].")
      .def_readonly("parents_offsets", &Changes::parents_offsets, "#C+1 int64.")
      .def_readonly("new_vertices", &Changes::new_vertices, "#N int64: vertices the cut made and still uses.")
      .def_readonly("new_vertex_edges", &Changes::new_vertex_edges,
                    "#N by 2 int64: the old edge each new vertex lies on (-1, -1 when it was moved off it).")
      .def_readonly("new_vertex_t", &Changes::new_vertex_t, "#N float64: its parameter along that edge (NaN when off).")
      .def_readonly("new_vertex_from", &Changes::new_vertex_from,
                    "#N by 4 int64: the old vertices it is a convex combination of (-1 padded).")
      .def_readonly("new_vertex_weights", &Changes::new_vertex_weights, "#N by 4 float64: their weights (sum 1).")
      .def_readonly("removed_vertices", &Changes::removed_vertices, "int64: vertices no tet uses any more.");

  py::class_<Report> report(m, "CutReport", "What one cut did (the engine's CutReport); report.changes as numpy arrays.");
  made_by_the_module_only(report);
  report.def_property_readonly("centre", [](const Report& r) { return std::array<double, 3>{r.centre.x, r.centre.y, r.centre.z}; })
      .def_property_readonly("ok", [](const Report& r) { return r.report.ok; }, "False: refused and rolled back (failure says why).")
      .def_property_readonly("failure", [](const Report& r) { return r.report.failure; })
      .def_property_readonly("tets_hit", [](const Report& r) { return r.report.tets_hit; })
      .def_property_readonly("refine_iterations", [](const Report& r) { return r.report.refine_iterations; })
      .def_property_readonly("edges_split", [](const Report& r) { return r.report.edges_split; })
      .def_property_readonly("tets_refined", [](const Report& r) { return r.report.tets_refined; })
      .def_property_readonly("requested", [](const Report& r) { return r.report.requested; })
      .def_property_readonly("requests", [](const Report& r) { return r.report.requests; })
      .def_property_readonly("tets_removed", [](const Report& r) { return r.report.tets_removed; })
      .def_property_readonly("tets_created", [](const Report& r) { return r.report.tets_created; })
      .def_property_readonly("direct", [](const Report& r) { return r.report.direct; })
      .def_property_readonly("vertex_singularities", [](const Report& r) { return r.report.vertex_singularities; })
      .def_property_readonly("edge_singularities", [](const Report& r) { return r.report.edge_singularities; })
      .def_property_readonly("resolved_by_neighbours", [](const Report& r) { return r.report.resolved_by_neighbours; })
      .def_property_readonly("resolved_by_refinement", [](const Report& r) { return r.report.resolved_by_refinement; })
      .def_property_readonly("resolved_by_fallback", [](const Report& r) { return r.report.resolved_by_fallback; })
      .def_property_readonly("unresolved", [](const Report& r) { return r.report.unresolved; })
      .def_property_readonly("uncuttable_in_tool", [](const Report& r) { return r.report.uncuttable_in_tool; })
      .def_property_readonly("min_radius_ratio", [](const Report& r) { return r.report.min_radius_ratio; })
      .def_property_readonly("min_radius_ratio_before_improvement",
                             [](const Report& r) { return r.report.min_radius_ratio_before_improvement; })
      .def_property_readonly("quality_floor", [](const Report& r) { return r.report.quality_floor; })
      .def_property_readonly("quality_met", [](const Report& r) { return r.report.quality_met; })
      .def_property_readonly("improvement_flips", [](const Report& r) { return r.report.improvement_flips; })
      .def_property_readonly("improvement_collapses", [](const Report& r) { return r.report.improvement_collapses; })
      .def_property_readonly("improvement_moves", [](const Report& r) { return r.report.improvement_moves; })
      .def_property_readonly("d_ref", [](const Report& r) { return r.report.d_ref; })
      .def_readonly("wall_us", &Report::wall_us,
                    "Wall time of the engine's cut alone (microseconds), timed around the C++ call by the binding: "
                    "what a C++ caller would measure; a Python caller's own timing minus this is the binding's cost.")
      .def_property_readonly("time_us", [](const Report& r) {
        const CutTimings& t = r.report.time;
        py::dict d;
        d["locate"] = t.locate_us;
        d["refine"] = t.refine_us;
        d["select"] = t.select_us;
        d["remove"] = t.remove_us;
        d["improve"] = t.improve_us;
        d["total"] = t.total_us;
        return d;
      }, "Microseconds per stage and in total.")
      .def_property_readonly("changes", [](Report& r) -> const Changes& {
        if (!r.changes) r.changes = changes_of(r.log);
        return *r.changes;
      }, py::return_value_policy::reference_internal, "The net change as numpy arrays, built on first access.")
      .def("__repr__", [](const Report& r) {
        return std::string("<tetcut.CutReport ") + (r.report.ok ? "ok" : "refused: " + r.report.failure) + ", " +
               std::to_string(r.report.tets_removed) + " removed, " + std::to_string(r.report.tets_created) + " created>";
      });

  py::class_<PyCutter, CutterPtr> cutter(m, "Cutter", R"doc(
The cautery tool on a mesh (the engine's Cutter): indexes the mesh once, then cuts in O(tool).

Cutter(mesh, tool_diameter=1.0, strategy="combined", ...): the parameters of CutParams
(engine/include/tetcut/cut.hpp); ValueError for one out of range. Keeps the mesh alive.
keep_labels: labels (mesh.labels) whose tets no cut takes, as the paper's Fig. 7 keeps the portal
vein (Cutter::set_uncuttable); ValueError on a mesh without labels.)doc");
  cutter.def(py::init([](MeshPtr mesh, double tool_diameter, const std::string& strategy, const std::string& split,
                       double d_ref_factor, double p, std::uint32_t search_depth, std::uint32_t max_refine_iterations,
                       std::uint32_t max_tets_created, bool improve, double quality_floor,
                       std::vector<std::uint32_t> keep_labels) {
             CutParams params{.tool_diameter = tool_diameter, .d_ref_factor = d_ref_factor, .p = p,
                              .search_depth = search_depth, .max_refine_iterations = max_refine_iterations,
                              .max_tets_created = max_tets_created, .strategy = strategy_from(strategy),
                              .split_method = split_from(split), .improve = improve, .quality_floor = quality_floor};
             return std::make_shared<PyCutter>(std::move(mesh), params, std::move(keep_labels));
           }),
           py::arg("mesh").none(false), py::kw_only(), py::arg("tool_diameter") = 1.0, py::arg("strategy") = "combined",
           py::arg("split") = "templates", py::arg("d_ref_factor") = 1.5, py::arg("p") = 1.5,
           py::arg("search_depth") = 10, py::arg("max_refine_iterations") = 8, py::arg("max_tets_created") = 20000,
           py::arg("improve") = true, py::arg("quality_floor") = 0.1,
           py::arg("keep_labels") = std::vector<std::uint32_t>{})
      .def("sweep",
           [](const CutterPtr& c, py::handle start, py::handle end, double step) {
             return c->sweep(point_from(start, "start"), point_from(end, "end"), step);
           },
           py::arg("start"), py::arg("end"), py::arg("step"),
           "One cut every `step` from start to end (end included when a whole number of steps away), as "
           "`tetcut cut --from --to --step`; stops after a refused cut. Releases the GIL.")
      .def_property("tool_diameter", [](const CutterPtr& c) { return c->params().tool_diameter; },
                    [](const CutterPtr& c, double d) {
                      CutParams p = c->params();
                      p.tool_diameter = d;
                      c->set_params(p);
                    })
      .def_property_readonly("strategy", [](const CutterPtr& c) { return std::string(to_string(c->params().strategy)); })
      .def_property_readonly("mesh", [](const CutterPtr& c) { return c->mesh(); });
  // cut(): the one call a simulation loop makes per frame, bound without pybind11's dispatcher.
  report_type = py::detail::get_type_info(typeid(Report));
  cutter.attr("cut") = py::reinterpret_steal<py::object>(
      PyDescr_NewMethod(reinterpret_cast<PyTypeObject*>(cutter.ptr()), &cut_method));

  m.def("stats", &stats_of, py::arg("cutter").none(false), R"doc(
The paper's statistics (Tables 1 and 2, section 3.6) over every removal request this Cutter made
since it was made or last re-indexed: {"removal": counts, "table1": {...}, "table2": {...}}, as
`tetcut stats` computes its rows (tools/stats/removal_tables). A NaN is a ratio over nothing. Not
`tetcut stats` itself, which reruns the paper's five scenarios (tens of seconds): run that command.)doc");
}

}  // namespace tetcut::python
