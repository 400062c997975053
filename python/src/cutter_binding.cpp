// tetcut.Cutter, its CutReport, report.changes and the pieces a cut detached (tetcut.Fragment);
// tetcut.stats.
//
// A cut releases the GIL for as long as the engine works (the mesh is held in use meanwhile,
// mesh_handle.hpp). Its net ChangeLog is always recorded, as the C++ README sweep records it,
// and kept in the report as the engine's vectors: report.changes turns them into numpy arrays
// only when read, so a loop that never reads them pays for no array (bench/python measures both).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "mesh_handle.hpp"
#include "signature_doc.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/scenario/sweep.hpp"
#include "tetcut/stats/removal_tables.hpp"

namespace py = pybind11;

namespace tetcut::python {

namespace {

// What report.changes holds: the ChangeLog as numpy arrays (engine ids throughout).
struct Changes {
  py::array_t<std::int64_t> removed, created, parent, parents, parents_offsets;
  py::array_t<std::int64_t> new_vertices, new_vertex_edges, new_vertex_from, removed_vertices;
  py::array_t<double> new_vertex_t, new_vertex_weights;
  py::array_t<std::int64_t> moved_vertices, moved_vertex_from;
  py::array_t<double> moved_vertex_weights, moved_vertex_before;
  bool undo = false;  // ChangeLog::undo: Cutter.undo()'s, restoring what a cut took
};

// A piece a cut detached (the engine's Fragment), copied when the cut returns: the engine's views
// are valid only until its next cut. Copying costs nothing for a cut that detached nothing.
struct PyFragment {
  std::vector<TetId> tets;  // sorted by id (dead when removed as debris)
  double volume = 0.0;
  Vec3 centroid{};
  bool removed = false;
  TetId organ;
};

std::vector<PyFragment> copy_of(std::span<const Fragment> fragments) {
  std::vector<PyFragment> out;
  out.reserve(fragments.size());
  for (const Fragment& f : fragments)
    out.push_back({std::vector<TetId>(f.tets.begin(), f.tets.end()), f.volume, f.centroid, f.removed, f.organ});
  return out;
}

struct Report {
  CutReport report;
  std::vector<PyFragment> fragments;  // Cutter::last_fragments() when the cut returned
  double wall_us = 0;  // the engine call alone, timed by the binding: Python's overhead is the rest
  ChangeLog log;
  Vec3 centre;               // the ball's centre, or the capsule's first end
  std::optional<Vec3> end;   // the capsule's other end (Cutter.cut_segment, a swept sweep); none: a ball
  std::optional<Changes> changes;
};

template <class Id>
py::array_t<std::int64_t> id_array(const std::vector<Id>& ids) {
  py::array_t<std::int64_t> a(static_cast<py::ssize_t>(ids.size()));
  std::int64_t* out = a.mutable_data();
  for (const Id& id : ids) *out++ = id.valid() ? static_cast<std::int64_t>(id.value) : -1;
  return a;
}

// Cached in the report and handed out as they are: read-only, so that a user writing into one
// (an in-place sort, a fill) cannot change what report.changes gives the next reader.
void make_read_only(py::array& a) {
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
}

Changes changes_of(const ChangeLog& log) {
  Changes c;
  c.undo = log.undo;
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
  const auto nm = static_cast<py::ssize_t>(log.moved.size());
  c.moved_vertices = py::array_t<std::int64_t>(nm);
  c.moved_vertex_from = py::array_t<std::int64_t>({nm, py::ssize_t{4}});
  c.moved_vertex_weights = py::array_t<double>({nm, py::ssize_t{4}});
  c.moved_vertex_before = py::array_t<double>({nm, py::ssize_t{3}});
  auto moved_from = c.moved_vertex_from.mutable_unchecked<2>();
  auto moved_weights = c.moved_vertex_weights.mutable_unchecked<2>();
  auto moved_before = c.moved_vertex_before.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < nm; ++i) {
    const MovedVertex& v = log.moved[static_cast<std::size_t>(i)];
    c.moved_vertices.mutable_data()[i] = v.vertex.value;
    for (int k = 0; k < 4; ++k) {
      moved_from(i, k) = k < v.count ? static_cast<std::int64_t>(v.from[k].value) : -1;
      moved_weights(i, k) = k < v.count ? v.weight[k] : 0.0;
    }
    moved_before(i, 0) = v.before.x, moved_before(i, 1) = v.before.y, moved_before(i, 2) = v.before.z;
  }
  for (py::array* a : std::initializer_list<py::array*>{&c.removed, &c.created, &c.parent, &c.parents, &c.parents_offsets,
                       &c.new_vertices, &c.new_vertex_edges, &c.new_vertex_from, &c.removed_vertices,
                       &c.new_vertex_t, &c.new_vertex_weights, &c.moved_vertices, &c.moved_vertex_from,
                       &c.moved_vertex_weights, &c.moved_vertex_before})
    make_read_only(*a);
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
    MeshUse use(*handle_);
    require_known_labels();
    cutter_.emplace(handle_->mesh, params);
    handle_->labels.keep_history(params.undo_history);
    protect();
    seen_version_ = handle_->version;
  }

  // One cut by the ball at `centre`, or with `end` by the capsule from `centre` to `end`
  // (Cutter::cut_segment).
  Report cut(const Vec3& centre, const std::optional<Vec3>& end = std::nullopt) {
    MeshUse use(*handle_);
    prepare_to_mutate();
    Report r;
    r.centre = centre;
    r.end = end;
    {
      py::gil_scoped_release release;
      engine_cut(r);
    }
    if (r.report.ok) {
      handle_->published.publish(handle_->mesh, handle_->labels, r.log);  // the GIL back: no reader mid-copy
      seen_version_ = ++handle_->version;
    }
    last_fragments_ = r.fragments;
    return r;
  }

  // The sweep's centres as `tetcut cut --from START --to END --step STEP`, a scenario's sweep and
  // `tetcut simulate --sweep` place them (scenario::sweep_centres, the end included within a
  // billionth of a step), so that the mesh and its hash are the command's; `swept`: joined by
  // capsules, one from each centre to the next (scenario::sweep_cuts, `--swept`). Stops after the
  // first cut refused, as `tetcut cut` does (that cut's report is the last).
  std::vector<Report> sweep(const Vec3& a, const Vec3& b, double step, bool swept) {
    if (!(step > 0) || !std::isfinite(step)) throw py::value_error("tetcut: step: must be positive");
    if (norm(b - a) / step > scenario::kMaxSweepCuts)
      throw py::value_error("tetcut: step: more than 100000 cuts: increase step");
    MeshUse use(*handle_);
    prepare_to_mutate();
    const std::vector<scenario::CutTool> tools = scenario::sweep_cuts(a, b, step, swept);
    std::vector<Report> reports(tools.size());
    {
      py::gil_scoped_release release;
      for (std::size_t k = 0; k < tools.size(); ++k) {
        Report& r = reports[k];
        r.centre = tools[k].centre;
        r.end = tools[k].end;
        engine_cut(r);
        if (!r.report.ok) {
          reports.resize(k + 1);
          break;
        }
      }
    }
    for (const Report& r : reports)  // the GIL back: no reader mid-copy
      if (r.report.ok) handle_->published.publish(handle_->mesh, handle_->labels, r.log);
    seen_version_ = ++handle_->version;
    last_fragments_ = reports.empty() ? std::vector<PyFragment>{} : reports.back().fragments;
    return reports;
  }

  [[nodiscard]] const CutParams& params() const { return cutter_->params(); }
  void set_params(const CutParams& params) {
    MeshUse use(*handle_);
    if (const auto bad = cutter_->set_params(params)) throw py::value_error("tetcut: " + *bad);
    handle_->labels.keep_history(params.undo_history);
  }

  // Cutter::undo(): the last cut this Cutter kept taken back, the labels with it; its net change
  // (changes.undo True). RuntimeError with the engine's reason when there is none to take back
  // (another Cutter's cut or a compaction since counts as a change made outside this Cutter).
  Changes undo() {
    MeshUse use(*handle_);
    require_no_slot_views(*handle_);
    ChangeLog log;
    std::optional<std::string> refused;
    {
      py::gil_scoped_release release;
      refused = cutter_->undo(&log);
    }
    if (refused) throw std::runtime_error("tetcut: Cutter.undo: " + *refused);
    handle_->labels.apply(handle_->mesh, log);
    handle_->published.publish(handle_->mesh, handle_->labels, log);
    seen_version_ = ++handle_->version;
    last_fragments_.clear();
    return changes_of(log);
  }
  [[nodiscard]] std::uint32_t undo_depth() const {
    MeshUse use(*handle_);
    return cutter_->undo_depth();
  }
  [[nodiscard]] RemovalReport removal_report() const { return cutter_->removal_report(); }
  [[nodiscard]] const MeshPtr& mesh() const { return handle_; }
  // The pieces the last cut detached, as copied when it returned (Cutter.last_fragments()).
  [[nodiscard]] const std::vector<PyFragment>& last_fragments() const { return last_fragments_; }
  // The mesh's face-connected pieces as the engine keeps them (Cutter::pieces()): as of this
  // Cutter's last cut or indexing (another Cutter's cuts count from this one's next cut).
  [[nodiscard]] std::uint32_t pieces() const {
    MeshUse use(*handle_);  // not while this Cutter's cut in another thread updates it
    return cutter_->pieces();
  }

 private:
  // The engine's cut of r's tool (the ball at r.centre, or the capsule to r.end) into r, timed
  // alone, the labels carried through it. The GIL released by the caller.
  void engine_cut(Report& r) {
    const auto start = std::chrono::steady_clock::now();
    r.report = r.end ? cutter_->cut_segment(r.centre, *r.end, &r.log) : cutter_->cut(r.centre, &r.log);
    r.wall_us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
    if (r.report.ok) handle_->labels.apply(handle_->mesh, r.log);
    if (r.report.fragments > 0) r.fragments = copy_of(cutter_->last_fragments());
  }

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

  // keep_labels: each label must be some tet's, so that a typo is not a protection that protects
  // nothing.
  void require_known_labels() const {
    if (keep_labels_.empty()) return;
    if (!handle_->labels.labelled()) throw py::value_error("tetcut.Cutter: keep_labels: the mesh has no labels (mesh.labels is None)");
    std::set<std::uint32_t> present;
    const TetMesh& mesh = handle_->mesh;
    for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t)
      if (mesh.is_live(TetId{t})) present.insert(handle_->labels.label(TetId{t}));
    for (std::uint32_t l : keep_labels_) {
      if (present.count(l)) continue;
      std::string labels;
      for (std::uint32_t p : present) {
        if (!labels.empty()) labels += ", ";  // appended apart: `"" + std::string&&` trips GCC 12's -Wstringop-overflow under LTO
        labels += std::to_string(p);
      }
      throw py::value_error("tetcut.Cutter: keep_labels: no tet is labelled " + std::to_string(l) + " (the mesh's labels: " +
                            labels + ")");
    }
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
  std::vector<PyFragment> last_fragments_;
};

// Shared: methods take the holder, which pybind11 refuses for an instance __init__ never made.
using CutterPtr = std::shared_ptr<PyCutter>;

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
  removal["stopped_by_budget"] = r.stopped_by_budget;
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

// The N arguments of a METH_FASTCALL method, positional then by keyword, in the order of
// `names`; TypeError `usage` unless each is given exactly once.
template <std::size_t N>
std::array<PyObject*, N> fast_arguments(const std::array<const char*, N>& names, const char* usage, PyObject* const* args,
                                        Py_ssize_t nargs, PyObject* kwnames) {
  const Py_ssize_t nkw = kwnames ? PyTuple_GET_SIZE(kwnames) : 0;
  if (nargs + nkw != static_cast<Py_ssize_t>(N)) throw py::type_error(usage);
  std::array<PyObject*, N> given{};
  for (Py_ssize_t i = 0; i < nargs; ++i) given[static_cast<std::size_t>(i)] = args[i];
  for (Py_ssize_t k = 0; k < nkw; ++k) {
    std::size_t slot = static_cast<std::size_t>(nargs);
    while (slot < N && PyUnicode_CompareWithASCIIString(PyTuple_GET_ITEM(kwnames, k), names[slot]) != 0) ++slot;
    if (slot == N || given[slot]) throw py::type_error(usage);
    given[slot] = args[nargs + k];
  }
  return given;
}

// A fast method's report, or its exception set as Python's error (nullptr).
template <class MakeReport>
PyObject* report_or_error(MakeReport&& make) {
  try {
    auto* report = new Report(make());
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

PyObject* cut_fast(PyObject* self, PyObject* const* args, Py_ssize_t nargs, PyObject* kwnames) {
  return report_or_error([&] {
    const auto [centre] =
        fast_arguments<1>({"centre"}, "tetcut: Cutter.cut() takes one argument, centre", args, nargs, kwnames);
    // As a holder: an instance made by __new__ without __init__ has none, and is refused here.
    const auto held = py::cast<CutterPtr>(py::handle(self));
    return held->cut(point_from(centre, "centre"));
  });
}

// Cutter.cut_segment(a, b): the capsule, bound as cut() is (a simulator calls it once a frame).
PyObject* cut_segment_fast(PyObject* self, PyObject* const* args, Py_ssize_t nargs, PyObject* kwnames) {
  return report_or_error([&] {
    const auto [a, b] =
        fast_arguments<2>({"a", "b"}, "tetcut: Cutter.cut_segment() takes two arguments, a and b", args, nargs, kwnames);
    const auto held = py::cast<CutterPtr>(py::handle(self));
    const Vec3 from = point_from(a, "a");
    return held->cut(from, point_from(b, "b"));
  });
}

PyMethodDef cut_method = {
    "cut", reinterpret_cast<PyCFunction>(reinterpret_cast<void (*)()>(&cut_fast)), METH_FASTCALL | METH_KEYWORDS,
    // A method descriptor of the class (PyDescr_NewMethod), for which "$self" is CPython's form.
    "cut($self, /, centre)\n--\n\nOne cut with the tool centred at `centre` (3 real numbers, mesh units): a "
    "CutReport. Atomic: report.ok False means refused, the mesh bit-identical to before. Releases the GIL while the "
    "engine works."};

PyMethodDef cut_segment_method = {
    "cut_segment", reinterpret_cast<PyCFunction>(reinterpret_cast<void (*)()>(&cut_segment_fast)),
    METH_FASTCALL | METH_KEYWORDS,
    "cut_segment($self, /, a, b)\n--\n\nOne cut by the capsule the tool sweeps from `a` to `b` (3 real numbers each, "
    "mesh units): every tet whose centroid is within the tool's radius of the segment and whose edges are within "
    "D_ref, as cut() takes a ball's; the tissue a stroke passes through between two samples, whatever the sampling. "
    "A CutReport (report.centre is a, report.end is b), atomic as cut(); cut_segment(c, c) is cut(c), bit for bit. "
    "Releases the GIL while the engine works."};

// Keyword arguments read one by one, so that an error names the keyword: pybind11's overload
// resolution says only "incompatible constructor arguments" and lists every parameter's type.
class Keywords {
 public:
  Keywords(std::string where, const py::kwargs& given, std::vector<std::string> known)
      : where_(std::move(where)), given_(given) {
    for (auto item : given) {
      const std::string name = py::str(item.first);
      if (std::find(known.begin(), known.end(), name) != known.end()) continue;
      std::string all;
      for (const std::string& k : known) all += (all.empty() ? "" : ", ") + k;
      const py::list close = py::module_::import("difflib").attr("get_close_matches")(name, known, 1);
      throw py::type_error(where_ + ": unknown keyword '" + name + "'" +
                           (close.empty() ? std::string() : " (did you mean '" + py::str(close[0]).cast<std::string>() + "'?)") +
                           "; the keywords: " + all);
    }
  }

  // The value given for `name`, converted to T, or nullopt; TypeError naming it when it does not convert.
  template <class T>
  std::optional<T> get(const char* name, const char* expected) const {
    if (!given_.contains(name)) return std::nullopt;
    const py::handle value = given_[name];
    if constexpr (std::is_integral_v<T> && std::is_unsigned_v<T> && !std::is_same_v<T, bool>) {
      // An int out of range is a value error, named as one (pybind11 calls it a failed cast).
      if (PyLong_Check(value.ptr()) && !PyBool_Check(value.ptr())) {
        const py::int_ i = py::reinterpret_borrow<py::int_>(value);
        if (i < py::int_(0) || i > py::int_(std::numeric_limits<T>::max())) {
          throw py::value_error(where_ + ": " + name + "=" + text(name) + ": expected " +
                                expected + " up to " + std::to_string(std::numeric_limits<T>::max()));
        }
      }
    }
    try {
      return value.cast<T>();
    } catch (const py::cast_error&) {
      throw py::type_error(where_ + ": " + name + ": expected " + expected + ", got " +
                           py::str(py::type::handle_of(value).attr("__name__")).cast<std::string>());
    }
  }

  [[nodiscard]] const std::string& where() const { return where_; }
  // The value given for `name` as the caller wrote it (its repr).
  [[nodiscard]] std::string text(const char* name) const { return py::repr(given_[name]); }

 private:
  std::string where_;
  const py::kwargs& given_;
};

// A parameter out of range: the engine's words for it, after the keyword and the value given.
void check_one(const Keywords& k, const char* name, const CutParams& with_it) {
  if (const auto bad = validate(with_it)) throw py::value_error(k.where() + ": " + name + "=" + k.text(name) + ": " + *bad);
}

// Cutter(mesh, *, tool_diameter, ...): every CutParams field by keyword, tool_diameter required
// (in the mesh's units: no default suits meshes in millimetres and in metres alike), each
// checked on its own so that the error names it.
CutterPtr make_cutter(const py::args& args, const py::kwargs& kwargs) {
  const std::string where = "tetcut.Cutter";
  py::object mesh_object;
  if (args.size() == 1 && !kwargs.contains("mesh")) {
    mesh_object = args[0];
  } else if (args.empty() && kwargs.contains("mesh")) {
    mesh_object = kwargs["mesh"];
  } else {
    throw py::type_error(where + "(mesh, *, tool_diameter, ...) takes the mesh and every parameter by keyword; got " +
                         std::to_string(args.size()) + " positional argument(s)");
  }
  MeshPtr mesh;
  try {
    mesh = mesh_object.cast<MeshPtr>();
  } catch (const py::cast_error&) {
    throw py::type_error(where + ": mesh: expected a tetcut.Mesh, got " +
                         py::str(py::type::handle_of(mesh_object).attr("__name__")).cast<std::string>());
  }
  if (!mesh) throw py::type_error(where + ": mesh: expected a tetcut.Mesh, got None");
  const Keywords k(where, kwargs,
                   {"mesh", "tool_diameter", "strategy", "split", "order", "neighbour_set", "d_ref_factor", "p", "search_depth",
                    "max_refine_iterations", "max_tets_created", "improve", "quality_floor", "min_dihedral_deg", "refinement",
                    "debris_volume", "fragment_search_bound", "keep_labels", "undo_history"});
  CutParams params;
  auto set = [&](const char* name, auto CutParams::*field, const char* expected) {
    using T = std::remove_reference_t<decltype(params.*field)>;
    const auto value = k.get<T>(name, expected);
    if (!value) return;
    CutParams alone;  // defaults and this one: the engine's message is about it alone
    alone.*field = *value;
    check_one(k, name, alone);
    params.*field = *value;
  };
  const auto diameter = k.get<double>("tool_diameter", "a real number");
  if (!diameter) {
    throw py::type_error(where + ": tool_diameter is required: the tool's diameter in the mesh's units (no default "
                         "suits every mesh)");
  }
  set("tool_diameter", &CutParams::tool_diameter, "a real number");
  set("d_ref_factor", &CutParams::d_ref_factor, "a real number");
  set("p", &CutParams::p, "a real number");
  set("quality_floor", &CutParams::quality_floor, "a real number");
  set("min_dihedral_deg", &CutParams::min_dihedral_deg, "a real number");
  set("debris_volume", &CutParams::debris_volume, "a real number");
  set("search_depth", &CutParams::search_depth, "a non-negative integer");
  set("max_refine_iterations", &CutParams::max_refine_iterations, "a non-negative integer");
  set("max_tets_created", &CutParams::max_tets_created, "a non-negative integer");
  set("fragment_search_bound", &CutParams::fragment_search_bound, "a non-negative integer");
  set("undo_history", &CutParams::undo_history, "a non-negative integer");
  set("improve", &CutParams::improve, "True or False");
  if (const auto s = k.get<std::string>("strategy", "a str")) {
    const auto v = parse_removal_strategy(*s);
    if (!v) throw py::value_error(where + ": strategy: basic, neighbours, combined or wide, not '" + *s + "'");
    params.strategy = *v;
  }
  if (const auto s = k.get<std::string>("split", "a str")) {
    const auto v = parse_split_method(*s);
    if (!v) throw py::value_error(where + ": split: templates or bisection, not '" + *s + "'");
    params.split_method = *v;
  }
  if (const auto s = k.get<std::string>("refinement", "a str")) {
    const auto v = parse_refinement_rule(*s);
    if (!v) throw py::value_error(where + ": refinement: auto, paper or graded, not '" + *s + "'");
    params.refinement = *v;
  }
  if (const auto s = k.get<std::string>("order", "a str")) {
    const auto v = parse_removal_order(*s);
    if (!v)
      throw py::value_error(where + ": order: direct-first, surface-first-by-id (or paper, its old name) or revisit, not '" +
                            *s + "'");
    params.order = *v;
  }
  if (const auto s = k.get<std::string>("neighbour_set", "a str")) {
    const auto v = parse_neighbour_set_choice(*s);
    if (!v) throw py::value_error(where + ": neighbour_set: smallest or first, not '" + *s + "'");
    params.neighbour_set = *v;
  }
  std::vector<std::uint32_t> keep_labels =
      k.get<std::vector<std::uint32_t>>("keep_labels", "a sequence of labels (integers in 0..2^32-1)").value_or(std::vector<std::uint32_t>{});
  return std::make_shared<PyCutter>(std::move(mesh), params, std::move(keep_labels));
}

// The text signature of Cutter.__init__, its defaults the engine's (CutParams{}).
std::string cutter_init_doc() {
  const CutParams d;
  auto real = [](double x) { return py::repr(py::float_(x)).cast<std::string>(); };
  const std::string parameters =
      "self, /, mesh, *, tool_diameter, strategy='" + std::string(to_string(d.strategy)) + "', split='" +
      to_string(d.split_method) + "', order='" + to_string(d.order) + "', neighbour_set='" + to_string(d.neighbour_set) +
      "', refinement='" + to_string(d.refinement) + "', d_ref_factor=" + real(d.d_ref_factor) +
      ", p=" + real(d.p) + ", search_depth=" + std::to_string(d.search_depth) +
      ", max_refine_iterations=" + std::to_string(d.max_refine_iterations) +
      ", max_tets_created=" + std::to_string(d.max_tets_created) + ", improve=" + (d.improve ? "True" : "False") +
      ", quality_floor=" + real(d.quality_floor) + ", min_dihedral_deg=" + real(d.min_dihedral_deg) +
      ", debris_volume=" + real(d.debris_volume) + ", fragment_search_bound=" + std::to_string(d.fragment_search_bound) +
      ", keep_labels=(), undo_history=" + std::to_string(d.undo_history);
  return signature_doc("__init__", parameters, R"doc(The cautery tool on `mesh`: indexes it (O(#T)), then cuts in O(tool).

tool_diameter (required, mesh units) and the other CutParams fields (engine/include/tetcut/cut.hpp)
by keyword: strategy basic|neighbours|combined|wide, split templates|bisection, order
direct-first|paper, refinement auto|paper|graded (auto: graded for a tool fine for the mesh, else
the paper's loop), d_ref_factor (D_ref = d_ref_factor x tool_diameter, paper 3.2), p (shell edge
ratio, 3.2), search_depth (3.5), max_refine_iterations, max_tets_created, improve (the improvement
pass), quality_floor (its radius-ratio floor F), min_dihedral_deg (its dihedral-angle floor theta,
degrees: every created tet reaches min(F, its host's) and min(theta, its host's)), debris_volume
(mesh units cubed: the pieces a cut detaches below it are removed in that cut, as debris; 0: only
reported), fragment_search_bound (the tets the search for detached pieces visits at most).
keep_labels: labels (mesh.labels) whose tets no cut takes (Cutter::set_uncuttable, the paper's
Fig. 7), each some tet's label. undo_history: the cuts Cutter.undo() can take back (0: none
kept; at most 4096; each costs about 0.9 MB reserved once).
TypeError naming an unknown keyword or a value of the wrong type; ValueError naming one out of
range or a label no tet has.)doc");
}

// A CutReport field as a read-only attribute: one line per field in bind_cutter.
// (A field of CutReport or of its base RequestCounts.)
template <class Owner, class T>
  requires std::is_base_of_v<Owner, CutReport>
void report_field(py::class_<Report>& c, const char* name, T Owner::*field, const char* doc) {
  c.def_property_readonly(name, [field](const Report& r) { return r.report.*field; }, doc);
}

std::string changes_repr(const Changes& c) {
  return "<tetcut.Changes " + std::to_string(c.removed.size()) + " removed, " + std::to_string(c.created.size()) +
         " created, " + std::to_string(c.new_vertices.size()) + " new vertices, " +
         std::to_string(c.moved_vertices.size()) + " moved vertices, " + std::to_string(c.removed_vertices.size()) +
         " removed vertices>";
}

// tetcut.Changes: a cut's net change as numpy arrays.
void bind_changes(py::module_& m) {
  py::class_<Changes> changes(m, "Changes", R"doc(A cut's net change (the engine's ChangeLog) as numpy arrays of engine ids.

mesh.tet_ids and mesh.vertex_ids name them; apply the removals first, then the creations. Net: a
tet the refinement made and the removal then took is in neither list, and a parent the
refinement replaced is in `removed` even though the tool never reached it, so len(removed)
exceeds report.tets_removed whenever the cut refined. Every array is int64 (float64 for
new_vertex_t and new_vertex_weights) and read-only: built once, on first access of
report.changes, and the same arrays on every access.)doc");
  made_by_the_module_only(changes);
  changes.def_readonly("removed", &Changes::removed, "#R int64: tets live before the cut and gone after, sorted.")
      .def_readonly("created", &Changes::created, "#C int64: tets live after and not before, sorted.")
      .def_readonly("parent", &Changes::parent, "#C int64: each created tet's first parent (its only one for a split).")
      .def_readonly("parents", &Changes::parents, "int64, flat: created[i]'s parents are parents[parents_offsets[i]:parents_offsets[i+1]].")
      .def_readonly("parents_offsets", &Changes::parents_offsets, "#C+1 int64: where each created tet's parents start in `parents`.")
      .def_readonly("new_vertices", &Changes::new_vertices, "#N int64: vertices the cut made and still uses.")
      .def_readonly("new_vertex_edges", &Changes::new_vertex_edges,
                    "#N by 2 int64: the old edge each new vertex lies on (-1, -1 when it was moved off it).")
      .def_readonly("new_vertex_t", &Changes::new_vertex_t, "#N float64: its parameter along that edge (NaN when off).")
      .def_readonly("new_vertex_from", &Changes::new_vertex_from,
                    "#N by 4 int64: the old vertices it is a convex combination of (-1 padded).")
      .def_readonly("new_vertex_weights", &Changes::new_vertex_weights, "#N by 4 float64: their weights (sum 1).")
      .def_readonly("removed_vertices", &Changes::removed_vertices, "int64: vertices no tet uses any more.")
      .def_readonly("moved_vertices", &Changes::moved_vertices,
                    "#M int64: vertices there before the cut that its improvement pass moved (within the cut's reach), sorted; "
                    "every tet around one is in removed and created.")
      .def_readonly("moved_vertex_from", &Changes::moved_vertex_from,
                    "#M by 4 int64: the old vertices its new position is a combination of (-1 padded); "
                    "compute every new and moved vertex's values from the old ones before writing any.")
      .def_readonly("moved_vertex_weights", &Changes::moved_vertex_weights, "#M by 4 float64: their weights (sum 1).")
      .def_readonly("moved_vertex_before", &Changes::moved_vertex_before, "#M by 3 float64: where it was before the cut.")
      .def_readonly("undo", &Changes::undo,
                    "True for Cutter.undo()'s: `removed` are the tets the cut made, `created` (no parents) the tets it "
                    "took, back under their ids, `moved_vertices` back where they were (moved_vertex_before: where the "
                    "cut had put them; moved_vertex_from / _weights: where they are now in a tet around them before "
                    "the undo), `new_vertices` (no origin) the vertices it took.")
      .def("__repr__", &changes_repr);
}

std::string fragment_repr(const PyFragment& f) {
  char text[160];
  std::snprintf(text, sizeof text, "<tetcut.Fragment %zu tets, volume %.6g, centroid (%.6g, %.6g, %.6g)%s>",
                f.tets.size(), f.volume, f.centroid.x, f.centroid.y, f.centroid.z, f.removed ? ", removed as debris" : "");
  return text;
}

// tetcut.Fragment: a piece a cut detached from the organ (the engine's Fragment, copied).
void bind_fragment(py::module_& m) {
  py::class_<PyFragment> fragment(m, "Fragment", R"doc(A face-connected piece a cut detached from the organ (the engine's Fragment).

Of the pieces a cut's new surface bounds that were one piece before it, the largest by volume is
the organ and is not listed; the others are, each once (report.detached, Cutter.last_fragments()).
Copied when the cut returned: its tets are the engine ids of that moment (mesh.tet_ids names them
until a later cut or compaction changes them). A piece removed as debris (Cutter debris_volume)
has removed True and its tets are gone from the mesh.)doc");
  made_by_the_module_only(fragment);
  fragment
      .def_property_readonly("tets", [](const PyFragment& f) { return id_array(f.tets); },
                             "#P int64: the piece's tets (engine ids, sorted), a new array on each access.")
      .def_readonly("volume", &PyFragment::volume, "The piece's volume (mesh units cubed).")
      .def_property_readonly(
          "centroid", [](const PyFragment& f) { return std::array<double, 3>{f.centroid.x, f.centroid.y, f.centroid.z}; },
          "[x, y, z]: the piece's volume-weighted centroid (mesh units).")
      .def_readonly("removed", &PyFragment::removed,
                    "True when the cut removed it as debris (below the Cutter's debris_volume, no uncuttable tet).")
      .def_property_readonly(
          "organ", [](const PyFragment& f) { return f.organ.valid() ? static_cast<std::int64_t>(f.organ.value) : -1; },
          "A live tet (engine id) of the piece it came away from, the organ.")
      .def("__repr__", &fragment_repr);
}

// tetcut.CutReport: the engine's CutReport field by field, the times, the changes.
void bind_report(py::module_& m) {
  py::class_<Report> report(m, "CutReport", R"doc(What one cut did: the engine's CutReport, field by field, and its change log.

The counts are the engine's (and `tetcut cut --report`'s): tets_removed and tets_created count
tets, while report.changes lists the net ids a simulator updates (see Changes). A cut that
removes every tet (a tool larger than the organ) is ok: the mesh is then empty (num_tets 0).)doc");
  made_by_the_module_only(report);
  report.def_property_readonly("centre", [](const Report& r) { return std::array<double, 3>{r.centre.x, r.centre.y, r.centre.z}; },
                               "[x, y, z]: where the tool was centred (mesh units); a capsule's first end.");
  report.def_property_readonly("end", [](const Report& r) -> std::optional<std::array<double, 3>> {
        if (!r.end) return std::nullopt;
        return std::array<double, 3>{r.end->x, r.end->y, r.end->z};
      },
      "[x, y, z]: a capsule's other end (Cutter.cut_segment, a swept sweep: the tool swept from centre to end); "
      "None for a ball.");
  // One line per CutReport field (engine/include/tetcut/cut.hpp), documented as the header is;
  // python/tests/test_docs.py fails on a field of the header that is not here.
  report_field(report, "ok", &CutReport::ok, "False: refused and rolled back, the mesh as before (failure says why).");
  report_field(report, "failure", &CutReport::failure, "Why the cut was refused, for people ('' when ok).");
  report.def_property_readonly("refusal", [](const Report& r) { return std::string(to_string(r.report.refusal)); },
                               "Why the cut was refused, as a word: 'none' when ok, else 'stale index', 'parameters', "
                               "'request', 'degenerate split', 'tet budget', 'quality floor' or 'tissue rule'.");
  report_field(report, "tets_hit", &CutReport::tets_hit, "Live tets meeting the ball before refinement.");
  report_field(report, "refine_iterations", &CutReport::refine_iterations, "Rounds of the refinement loop (paper 3.2).");
  report_field(report, "edges_split", &CutReport::edges_split, "Edges the refinement loop split.");
  report_field(report, "tets_refined", &CutReport::tets_refined, "Parents the refinement loop replaced by their children.");
  report_field(report, "requested", &CutReport::requested,
               "|T_removal| (paper 3.3): tets selected for removal, children of selected tets that joined it included.");
  report_field(report, "requests", &CutReport::requests,
               "Removal requests made: a tet another request's set swallowed is not requested (requests <= requested).");
  report_field(report, "tets_removed", &CutReport::tets_removed, "Tets removed, neighbour sets included (not net: see Changes).");
  report_field(report, "tets_created", &CutReport::tets_created,
               "Tets created, by refinement and by removal, still there at the end (net).");
  report_field(report, "direct", &CutReport::direct, "Requests removable directly (paper 3.3: no singularity).");
  report_field(report, "vertex_singularities", &CutReport::vertex_singularities,
               "Requests whose removal alone would leave a singular vertex (paper 3.4).");
  report_field(report, "edge_singularities", &CutReport::edge_singularities,
               "Requests whose removal alone would leave a singular edge (paper 3.4).");
  report_field(report, "resolved_by_neighbours", &CutReport::resolved_by_neighbours,
               "Singular requests resolved by removing a neighbour set (paper 3.5).");
  report_field(report, "resolved_by_refinement", &CutReport::resolved_by_refinement,
               "Singular requests resolved by local refinement (paper 3.4 / 3.7).");
  report_field(report, "resolved_by_fallback", &CutReport::resolved_by_fallback,
               "Singular requests resolved by the fallback construction (docs/removal-proof.md).");
  report_field(report, "unresolved", &CutReport::unresolved,
               "Requests left in place (the mesh still valid); a tet left twice counts twice.");
  report_field(report, "stopped_by_budget", &CutReport::stopped_by_budget,
               "Requests left in place because the cut's tet budget had run out (a kept piece's, in an ok cut), not "
               "in `unresolved`.");
  report_field(report, "kept_pieces_requested", &CutReport::kept_pieces_requested,
               "Pieces of unselected tets a removal-time split left inside the tool, each requested once; counted in "
               "`requests` too.");
  report_field(report, "left_in_tool", &CutReport::left_in_tool,
               "The tissue rule: live cuttable tets with their centroid in the tool and their edges within D_ref (what "
               "the paper's selection takes) still there after the cut: unresolved requests' tets and pieces their "
               "request did not remove. 0: the cut took all the tissue its rule takes.");
  report_field(report, "volume_left_in_tool", &CutReport::volume_left_in_tool,
               "Volume of cuttable tissue still inside the tool's ball: of each live cuttable tet meeting it, the part "
               "inside (exact for tets wholly in or out, else the midpoint rule on the tet's 8 equal children).");
  report_field(report, "volume_removed", &CutReport::volume_removed,
               "Volume the cut removed as tissue (removal requests and the improvement pass's slivers).");
  report_field(report, "tets_removed_beyond_tool", &CutReport::tets_removed_beyond_tool,
               "Of the tets removed, those whose centroid lies outside the tool.");
  report_field(report, "volume_removed_beyond_tool", &CutReport::volume_removed_beyond_tool,
               "Of the volume removed, the part outside the tool's ball (estimated as volume_left_in_tool).");
  report_field(report, "tets_removed_beyond_reach", &CutReport::tets_removed_beyond_reach,
               "Removed tets with a corner beyond the cut's reach (the tool's ball grown by D_ref).");
  report_field(report, "uncuttable_in_tool", &CutReport::uncuttable_in_tool,
               "Uncuttable tets (Cutter keep_labels) the tool selected and left in place.");
  report_field(report, "min_radius_ratio", &CutReport::min_radius_ratio,
               "Worst radius ratio of the tets the cut created, after the improvement pass (1 when none).");
  report_field(report, "min_radius_ratio_before_improvement", &CutReport::min_radius_ratio_before_improvement,
               "The same before the improvement pass.");
  report_field(report, "min_dihedral_deg", &CutReport::min_dihedral_deg,
               "Smallest dihedral angle (degrees) of the tets the cut created, after the improvement pass (180 when none).");
  report_field(report, "min_dihedral_deg_before_improvement", &CutReport::min_dihedral_deg_before_improvement,
               "The same before the improvement pass.");
  report_field(report, "quality_floor", &CutReport::quality_floor,
               "The lowest radius-ratio floor of a created tet, each min(quality_floor, its host's).");
  report_field(report, "dihedral_floor_deg", &CutReport::dihedral_floor_deg,
               "The lowest dihedral floor (degrees) of a created tet, each min(min_dihedral_deg, its host's).");
  report_field(report, "min_dihedral_held_deg", &CutReport::min_dihedral_held_deg,
               "The theta the cut held its created tets to: min_dihedral_deg, or 10 then 0 when the improvement pass "
               "could not reach it (a refused cut costs more than an angle below theta).");
  report_field(report, "angle_retries", &CutReport::angle_retries,
               "Times the improvement pass went on at a lower theta.");
  report_field(report, "quality_met", &CutReport::quality_met, "Every created tet reaches its floors.");
  report_field(report, "improvement_flips", &CutReport::improvement_flips, "Flips the improvement pass made.");
  report_field(report, "improvement_collapses", &CutReport::improvement_collapses, "Edge collapses the improvement pass made.");
  report_field(report, "improvement_moves", &CutReport::improvement_moves, "Vertex moves (smoothing) the improvement pass made.");
  report_field(report, "vertices_moved", &CutReport::vertices_moved,
               "Vertices there before the cut that the pass moved, within the cut's reach (changes.moved_vertices).");
  report_field(report, "mesh_rule_retries", &CutReport::mesh_rule_retries,
               "1 when the pass was made again with every plan held to the mesh rule (the volume below theta outside "
               "the tool does not grow), because its first run grew it.");
  report_field(report, "improvement_insertions", &CutReport::improvement_insertions,
               "Edge splits the improvement pass made and kept (insertion at an edge's midpoint).");
  report_field(report, "tets_removed_by_improvement", &CutReport::tets_removed_by_improvement,
               "Slivers the improvement pass let go with the tissue (apart from tets_removed).");
  report_field(report, "fragments", &CutReport::fragments,
               "Pieces the cut detached from the organ (the largest piece its new surface bounds), those removed as "
               "debris included: listed by report.detached.");
  report_field(report, "fragment_tets_visited", &CutReport::fragment_tets_visited,
               "Tets the search for detached pieces visited (a walk from the cut's new surface that stops once every "
               "piece but the largest is walked).");
  report_field(report, "fragment_search_bounded", &CutReport::fragment_search_bounded,
               "True when that search stopped at the Cutter's fragment_search_bound with pieces it could not tell "
               "apart, which are not reported (Cutter.pieces may then count short).");
  report_field(report, "debris_pieces_removed", &CutReport::debris_pieces_removed,
               "Detached pieces the cut removed as debris (below the Cutter's debris_volume): not tissue, so not in "
               "tets_removed or volume_removed.");
  report_field(report, "debris_tets_removed", &CutReport::debris_tets_removed, "The tets of those pieces.");
  report_field(report, "debris_volume_removed", &CutReport::debris_volume_removed, "Their volume (mesh units cubed).");
  report_field(report, "d_ref", &CutReport::d_ref,
               "The D_ref the cut was refined and judged at: d_ref_factor x tool_diameter (paper 3.2).");
  report.def_property_readonly("refinement", [](const Report& r) { return std::string(to_string(r.report.refinement)); },
                               "The refinement rule of the attempt that ended the cut: 'paper' or 'graded'.");
  report_field(report, "retries", &CutReport::retries,
               "Attempts rolled back before the one that ended the cut: with refinement='auto', a cut whose tets the "
               "improvement pass could not lift is made again with the graded rule, at the same D_ref.");
  report.def_readonly("wall_us", &Report::wall_us,
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
        d["finish"] = t.finish_us;
        d["pieces"] = t.pieces_us;
        d["total"] = t.total_us;
        return d;
      }, "{stage: microseconds} for locate, refine, select, remove, improve, finish (the tissue audit, the commit "
         "and the change log), pieces (the search for detached pieces and the debris removed) and total (the whole "
         "call): the engine's CutReport.time.")
      .def_property_readonly("detached", [](const Report& r) { return r.fragments; },
                             "list of Fragment: the pieces this cut detached (len == fragments), copied when it "
                             "returned; those removed as debris have removed True.")
      .def_property_readonly("changes", [](Report& r) -> const Changes& {
        if (!r.changes) r.changes = changes_of(r.log);
        return *r.changes;
      }, py::return_value_policy::reference_internal, "The net change as numpy arrays (Changes), built on first access.")
      .def("__repr__", [](const Report& r) {
        auto text = [](const Vec3& p) {
          char out[96];
          std::snprintf(out, sizeof out, "(%.6g, %.6g, %.6g)", p.x, p.y, p.z);
          return std::string(out);
        };
        const std::string where = r.end ? "from " + text(r.centre) + " to " + text(*r.end) : "at " + text(r.centre);
        return "<tetcut.CutReport " + where + ": " +
               (r.report.ok ? "ok" : "refused: " + r.report.failure) + ", " + std::to_string(r.report.tets_removed) +
               " removed, " + std::to_string(r.report.tets_created) + " created>";
      });
}

}  // namespace

void bind_cutter(py::module_& m) {
  bind_changes(m);
  bind_fragment(m);
  bind_report(m);

  py::class_<PyCutter, CutterPtr> cutter(m, "Cutter", R"doc(The cautery tool on a mesh (the engine's Cutter).

Cutter(mesh, *, tool_diameter, ...) indexes the mesh once, then each cut costs O(tool). It keeps
the mesh alive; several Cutters may share one mesh (each re-indexes when another changed it).)doc");
  cutter.def(py::init(&make_cutter), cutter_init_doc().c_str())
      .def("sweep",
           [](const CutterPtr& c, py::handle start, py::handle end, double step, bool swept) {
             return c->sweep(point_from(start, "start"), point_from(end, "end"), step, swept);
           },
           py::arg("start"), py::arg("end"), py::arg("step"), py::arg("swept") = false,
           signature_doc("sweep", "self, /, start, end, step, swept=False",
                         "One cut every `step` from start to end, as `tetcut cut --from --to --step`, a scenario's "
                         "sweep and `tetcut simulate --sweep` place them: the end is the last centre when it is a "
                         "whole number of steps away, to within a billionth of a step. swept=True joins those "
                         "centres by capsules, one cut_segment from each to the next (`tetcut cut --swept`): no "
                         "tissue stays between two centres whatever the step, and a sweep of one centre is one "
                         "ball. A list of CutReport; stops after a refused cut (its report is the last). Releases "
                         "the GIL.")
               .c_str())
      .def_property("tool_diameter", [](const CutterPtr& c) { return c->params().tool_diameter; },
                    [](const CutterPtr& c, double d) {
                      CutParams p = c->params();
                      p.tool_diameter = d;
                      c->set_params(p);
                    },
                    "The tool's diameter (mesh units); settable between cuts (ValueError when not positive).")
      .def("undo", [](const CutterPtr& c) { return c->undo(); },
           signature_doc("undo", "self, /",
                         "Takes back the last cut (cut, cut_segment, a sweep's last) this Cutter kept "
                         "(undo_history): the mesh bit for bit as before it, labels included, and this Cutter "
                         "as if it had never been made, so the same cuts give the same hashes. Called again, "
                         "the cut before. Returns its Changes (undo True). RuntimeError, nothing changed, when "
                         "none is kept: undo_history 0, all taken back, or the history emptied by "
                         "mesh.compact(), another Cutter's cut or a change of undo_history. Releases the GIL.")
               .c_str())
      .def_property_readonly("undo_depth", [](const CutterPtr& c) { return c->undo_depth(); },
                             "How many cuts undo() can take back now (at most undo_history).")
      .def_property("undo_history", [](const CutterPtr& c) { return c->params().undo_history; },
                    [](const CutterPtr& c, std::uint32_t n) {
                      CutParams p = c->params();
                      p.undo_history = n;
                      c->set_params(p);
                    },
                    "The cuts undo() can keep (0: none); settable between cuts, which empties the history "
                    "when it changes (ValueError above 4096).")
      .def_property_readonly("strategy", [](const CutterPtr& c) { return std::string(to_string(c->params().strategy)); },
                             "The removal strategy: basic, neighbours, combined or wide (paper 3.4-3.7).")
      .def_property_readonly("mesh", [](const CutterPtr& c) { return c->mesh(); }, "The Mesh this Cutter cuts.")
      .def("last_fragments", [](const CutterPtr& c) { return c->last_fragments(); },
           signature_doc("last_fragments", "self, /",
                         "The pieces this Cutter's last cut detached (a sweep's: its last cut's), as a list of "
                         "Fragment copied when the cut returned: report.detached of that cut.")
               .c_str())
      .def_property_readonly("pieces", [](const CutterPtr& c) { return c->pieces(); },
                             "The mesh's face-connected pieces, kept by every cut without a scan (the engine's "
                             "Cutter::pieces()): 1 for an organ in one piece, 2 once a cut detached a piece, and "
                             "back to 1 when that piece went as debris. As of this Cutter's last cut or indexing; "
                             "exact unless a cut's search for pieces was bounded (report.fragment_search_bounded).")
      .def("__repr__", [](const CutterPtr& c) {
        const CutParams& p = c->params();
        return "<tetcut.Cutter tool_diameter=" + py::repr(py::float_(p.tool_diameter)).cast<std::string>() +
               " strategy=" + to_string(p.strategy) + " on " + py::repr(py::cast(c->mesh())).cast<std::string>() + ">";
      });
  // cut(): the one call a simulation loop makes per frame, bound without pybind11's dispatcher.
  report_type = py::detail::get_type_info(typeid(Report));
  cutter.attr("cut") = py::reinterpret_steal<py::object>(
      PyDescr_NewMethod(reinterpret_cast<PyTypeObject*>(cutter.ptr()), &cut_method));
  cutter.attr("cut_segment") = py::reinterpret_steal<py::object>(
      PyDescr_NewMethod(reinterpret_cast<PyTypeObject*>(cutter.ptr()), &cut_segment_method));

  m.def("stats", &stats_of, py::arg("cutter").none(false), signature_doc("stats", "cutter", R"doc(The paper's statistics (Tables 1 and 2, section 3.6) over every removal request this Cutter made
since it was made or last re-indexed: {"removal": counts, "table1": {...}, "table2": {...}}, as
`tetcut stats` computes its rows (tools/stats/removal_tables). A NaN is a ratio over nothing. Not
`tetcut stats` itself, which reruns the paper's five scenarios (tens of seconds): run that command.)doc").c_str());
}

}  // namespace tetcut::python
