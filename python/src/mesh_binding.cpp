// tetcut.read, tetcut.Mesh, tetcut.from_meshio: a mesh in and out of numpy and meshio.
//
// Conventions are numpy's and meshio's, not the engine's: `points` (#V by 3 float64) and `tets`
// (#T by 4 int64, rows of `points`) hold the live entities only, renumbered densely in id order
// (what TetMesh::to_raw() writes), as copies; `vertex_ids` and `tet_ids` give the engine id of
// each row, the ids a cut's report.changes and the checker's violations speak of. The engine's own
// slot arrays (tombstones included, indexed by id) are there too, read-only and without a copy,
// as slot views; see mesh_handle.hpp for why a slot view locks the mesh.
//
// Bad input raises, never crashes: a file the CLI would refuse raises ValueError with the very
// line `tetcut` prints (tools/tetcut/mesh_input.cpp formats both), arrays of the wrong shape or
// dtype raise ValueError / TypeError naming the argument, and what the mesh builder refuses
// (NaN, dangling or repeated ids, inverted tets, non-manifold input) raises ValueError with the
// builder's first problem, as `tetcut cut` and `tetcut remove` print it.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "mesh_handle.hpp"
#include "mesh_input.hpp"  // tools/tetcut: the CLI's reader and its one-line messages
#include "signature_doc.hpp"
#include "tetcut/canonical_hash.hpp"
#include "tetcut/detail/local_tables.hpp"
#include "tetcut/io.hpp"
#include "tetcut/mesh_builder.hpp"
#include "tetcut/raw_mesh.hpp"

namespace py = pybind11;

namespace tetcut::python {

void require_no_slot_views(const MeshHandle& handle) {
  if (handle.slot_views != 0) {
    throw std::runtime_error("tetcut: " + std::to_string(handle.slot_views) +
                             " slot view(s) of this mesh are alive (mesh.slot_tets, mesh.slot_points): a change "
                             "would grow or rewrite the arrays they point into; delete them first, or use the "
                             "copies mesh.tets and mesh.points");
  }
}

namespace {

// The engine id -> row of `points` for every vertex slot (-1: not live), in id order, of the
// live mesh (a TetMesh) or the published one.
template <class Mesh>
std::vector<std::int64_t> vertex_rows(const Mesh& mesh) {
  std::vector<std::int64_t> row(mesh.vertex_capacity(), -1);
  std::int64_t live = 0;
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) {
    if (mesh.is_live(VertId{v})) row[v] = live++;
  }
  return row;
}

std::string shape_text(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) s += (i ? ", " : "") + std::to_string(a.shape(i));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

py::array as_array(py::handle obj) { return py::module_::import("numpy").attr("asarray")(obj); }

void require_shape(const py::array& a, const char* name, py::ssize_t columns, const char* shape) {
  if (a.ndim() != 2 || a.shape(1) != columns) {
    throw py::value_error(std::string("tetcut: ") + name + ": expected an array of shape " + shape + ", got shape " +
                          shape_text(a));
  }
}

// `points`: any real array-like of shape (#V, 3), copied as float64.
std::vector<Vec3> points_from(py::handle obj) {
  const py::array a = as_array(obj);
  const char kind = a.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u') {
    throw py::type_error(std::string("tetcut: points: expected real numbers, got dtype ") +
                         py::str(a.dtype()).cast<std::string>());
  }
  require_shape(a, "points", 3, "(#V, 3)");
  const auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
  const auto r = d.unchecked<2>();
  std::vector<Vec3> out(static_cast<std::size_t>(r.shape(0)));
  for (py::ssize_t i = 0; i < r.shape(0); ++i) out[i] = {r(i, 0), r(i, 1), r(i, 2)};
  return out;
}

template <class Int>
std::vector<std::array<std::uint32_t, 4>> tet_rows(const py::array& a) {
  const auto d = py::array_t<Int, py::array::c_style | py::array::forcecast>::ensure(a);
  const auto r = d.template unchecked<2>();
  std::vector<std::array<std::uint32_t, 4>> out(static_cast<std::size_t>(r.shape(0)));
  for (py::ssize_t i = 0; i < r.shape(0); ++i) {
    for (int k = 0; k < 4; ++k) {
      const Int v = r(i, k);
      if constexpr (std::numeric_limits<Int>::is_signed) {
        if (v < 0) {
          throw py::value_error("tetcut: tets: negative vertex index " + std::to_string(v) + " in row " +
                                std::to_string(i));
        }
      }
      // The builder names indices past #V (dangling); past 32 bits they cannot even be stored.
      if (static_cast<std::uint64_t>(v) >= kDeadTetMarker) {
        throw py::value_error("tetcut: tets: vertex index " + std::to_string(v) + " in row " + std::to_string(i) +
                              " is out of range");
      }
      out[i][k] = static_cast<std::uint32_t>(v);
    }
  }
  return out;
}

// `tets`: any integer array-like of shape (#T, 4), indices into points.
std::vector<std::array<std::uint32_t, 4>> tets_from(py::handle obj) {
  const py::array a = as_array(obj);
  const char kind = a.dtype().kind();
  if (kind != 'i' && kind != 'u') {
    throw py::type_error(std::string("tetcut: tets: expected integer vertex indices, got dtype ") +
                         py::str(a.dtype()).cast<std::string>());
  }
  require_shape(a, "tets", 4, "(#T, 4)");
  if (a.shape(0) == 0) throw py::value_error("tetcut: tets: no tetrahedra");
  return kind == 'i' ? tet_rows<std::int64_t>(a) : tet_rows<std::uint64_t>(a);
}

// The builder's verdict, with the words `tetcut cut` and `tetcut remove` use; the mesh with its
// labels (the builder keeps the tet order: TetId = row of raw.tets), published once.
MeshPtr build(const RawMesh& raw, const std::string& where) {
  BuildResult built = build_mesh(raw);
  if (!built.ok()) {
    throw py::value_error("tetcut: " + where + "not a valid manifold mesh: " + built.problems.front().message +
                          " (" + std::to_string(built.problems.size()) + " problem(s); see tetcut check)");
  }
  auto handle = std::make_shared<MeshHandle>();
  handle->mesh = std::move(*built.mesh);
  handle->labels.set(handle->mesh, raw.labels);
  handle->published.publish_all(handle->mesh, handle->labels);
  return handle;
}

// `labels`: None, or #T integers in [0, kMaxTetLabel] (RawMesh::labels), one per row of tets.
std::vector<std::uint32_t> labels_from(py::handle obj, std::size_t tets) {
  if (obj.is_none()) return {};
  const py::array a = as_array(obj);
  const char kind = a.dtype().kind();
  if (kind != 'i' && kind != 'u') {
    throw py::type_error("tetcut: labels: expected integers, got dtype " + py::str(a.dtype()).cast<std::string>());
  }
  if (a.ndim() != 1 || static_cast<std::size_t>(a.shape(0)) != tets) {
    throw py::value_error("tetcut: labels: expected an array of shape (" + std::to_string(tets) + ",), one per tet, got shape " +
                          shape_text(a));
  }
  const auto d = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
  std::vector<std::uint32_t> out(tets);
  for (std::size_t t = 0; t < tets; ++t) {
    const std::int64_t l = d.data()[t];
    if (l < 0 || l > std::int64_t{kMaxTetLabel}) {
      throw py::value_error("tetcut: labels: " + std::to_string(l) + " in row " + std::to_string(t) +
                            " is not a label (an integer in 0.." + std::to_string(kMaxTetLabel) + ")");
    }
    out[t] = static_cast<std::uint32_t>(l);
  }
  return out;
}

// Rows of `raw.positions` no tet names. The engine's vertices are its tets' corners: such a row
// would become a tombstone (no row of mesh.points), and mesh.points would no longer line up
// with the points given, so they are refused unless the caller asks for them to be dropped.
void require_every_point_used(const RawMesh& raw, bool drop) {
  if (drop) return;
  std::vector<bool> used(raw.positions.size(), false);
  for (const auto& t : raw.tets)
    for (std::uint32_t v : t)
      if (v < used.size()) used[v] = true;  // past the end: the builder's "dangling" message
  std::vector<std::size_t> unused;
  for (std::size_t v = 0; v < used.size(); ++v)
    if (!used[v]) unused.push_back(v);
  if (unused.empty()) return;
  std::string rows;
  for (std::size_t i = 0; i < std::min<std::size_t>(unused.size(), 5); ++i) rows += (i ? ", " : "") + std::to_string(unused[i]);
  if (unused.size() > 5) rows += ", ...";
  throw py::value_error("tetcut: points: " + std::to_string(unused.size()) + " of " + std::to_string(raw.positions.size()) +
                        " points are used by no tet (rows " + rows + "); a mesh's vertices are its tets' corners. "
                        "drop_unused_points=True drops them (mesh.vertex_ids then gives each row of mesh.points its "
                        "row in these points)");
}

MeshPtr from_arrays(py::handle points, py::handle tets, py::handle labels, bool drop_unused_points) {
  RawMesh raw;
  raw.positions = points_from(points);
  raw.tets = tets_from(tets);
  raw.labels = labels_from(labels, raw.tets.size());
  MeshPtr h = build(raw, "");  // first: a dangling index is the builder's to name
  require_every_point_used(raw, drop_unused_points);
  return h;
}

// The live tets' labels in id order (rows of `tets`, of to_raw()).
std::vector<std::uint32_t> live_labels(const MeshHandle& h) {
  std::vector<std::uint32_t> out;
  out.reserve(h.mesh.num_tets());
  const auto tets = h.mesh.raw_tets();
  for (std::uint32_t t = 0; t < tets.size(); ++t)
    if (tets[t][0] != kDeadTetMarker) out.push_back(h.labels.label(TetId{t}));
  return out;
}

// The CLI's reader, its notes turned into Python warnings and its failure into ValueError.
MeshPtr read(const std::string& path) {
  std::ostringstream err;
  std::optional<RawMesh> raw = cli::load_mesh(path, err);
  std::istringstream lines(err.str());
  std::string line, failure;
  while (std::getline(lines, line)) {
    if (line.find(": note: ") != std::string::npos) {
      if (PyErr_WarnEx(PyExc_UserWarning, line.c_str(), 1) < 0) throw py::error_already_set();
    } else if (!line.empty()) {
      failure = line;
    }
  }
  if (!raw) throw py::value_error(failure.empty() ? "tetcut: " + path + ": unreadable mesh" : failure);
  MeshPtr h = build(*raw, path + ": ");
  // As `tetcut` reads a file, its points no tet uses are not vertices: said, not silent.
  if (const std::size_t unused = raw->positions.size() - h->mesh.num_vertices(); unused > 0) {
    const std::string note = "tetcut: " + path + ": note: " + std::to_string(unused) + " of " +
                             std::to_string(raw->positions.size()) +
                             " points are used by no tet and are not vertices of the mesh (mesh.vertex_ids gives "
                             "each vertex's row in the file)";
    if (PyErr_WarnEx(PyExc_UserWarning, note.c_str(), 1) < 0) throw py::error_already_set();
  }
  return h;
}

// mesh.copy(): the same mesh, ids, labels and attributes, sharing nothing with the original.
MeshPtr copy_of(const MeshPtr& held) {
  MeshHandle& h = *held;
  MeshUse use(h);
  auto copy = std::make_shared<MeshHandle>();
  copy->mesh = h.mesh;
  copy->labels = h.labels;
  copy->published.publish_all(copy->mesh, copy->labels);
  copy->flat_attributes = h.flat_attributes;
  return copy;
}

// An empty mesh (a cut took every tet): what pickling one gives back. No file holds one (the
// readers refuse "no tetrahedra"), so write() refuses it too.
MeshPtr empty_mesh() { return std::make_shared<MeshHandle>(); }

py::array_t<std::int64_t> ids_array(const std::vector<std::int64_t>& ids) {
  py::array_t<std::int64_t> a(static_cast<py::ssize_t>(ids.size()));
  std::copy(ids.begin(), ids.end(), a.mutable_data());
  return a;
}

// A read-only array over memory the mesh owns, whose base keeps the mesh alive and locked.
class SlotViewLock {
 public:
  explicit SlotViewLock(MeshPtr handle) : handle_(std::move(handle)) { ++handle_->slot_views; }
  ~SlotViewLock() { --handle_->slot_views; }
  SlotViewLock(const SlotViewLock&) = delete;
  SlotViewLock& operator=(const SlotViewLock&) = delete;

 private:
  MeshPtr handle_;
};

template <class T>
py::array slot_view(const MeshPtr& handle, std::vector<py::ssize_t> shape, const T* data) {
  py::object lock = py::cast(new SlotViewLock(handle), py::return_value_policy::take_ownership);
  py::array a(py::dtype::of<T>(), std::move(shape), {}, data, lock);
  a.attr("flags").attr("writeable") = false;
  return a;
}

py::object to_meshio(const MeshPtr& h);

}  // namespace

namespace {

using MeshClass = py::class_<MeshHandle, MeshPtr>;

// Counts and the live mesh as arrays: copies, the zero-copy slot views, the masks.
void bind_mesh_arrays(MeshClass& mesh) {
  // The copies read the published mesh (published_mesh.hpp), never refused: during another
  // thread's cut they give the mesh as it was before it.
  mesh.def_property_readonly("num_tets", [](const MeshPtr& held) {
        MeshHandle& h = *held; return h.published.num_tets(); },
                             "Live tets (0 once a cut removed them all).");
  mesh.def_property_readonly("num_vertices", [](const MeshPtr& held) {
        MeshHandle& h = *held; return h.published.num_vertices(); },
                             "Live vertices (used by a live tet).");

  mesh.def_property_readonly(
      "points",
      [](const MeshPtr& held) {
        const PublishedMesh& m = held->published;
        py::array_t<double> a({static_cast<py::ssize_t>(m.num_vertices()), py::ssize_t{3}});
        auto w = a.mutable_unchecked<2>();
        py::ssize_t row = 0;
        for (std::uint32_t v = 0; v < m.vertex_capacity(); ++v) {
          if (!m.is_live(VertId{v})) continue;
          if (row == a.shape(0)) throw std::logic_error("tetcut: the published mesh miscounts its vertices");
          const Vec3& p = m.positions()[v];
          w(row, 0) = p.x, w(row, 1) = p.y, w(row, 2) = p.z;
          ++row;
        }
        return a;
      },
      "#V by 3 float64: the live vertices in id order (a copy), as the last change that returned left "
      "them: never refused while another thread cuts.");
  mesh.def_property_readonly(
      "vertex_ids",
      [](const MeshPtr& held) {
        const PublishedMesh& m = held->published;
        std::vector<std::int64_t> ids;
        ids.reserve(m.num_vertices());
        for (std::uint32_t v = 0; v < m.vertex_capacity(); ++v)
          if (m.is_live(VertId{v})) ids.push_back(v);
        return ids_array(ids);
      },
      "#V int64: the engine id of each row of `points` (the ids report.changes speaks of).");
  mesh.def_property_readonly(
      "tets",
      [](const MeshPtr& held) {
        const PublishedMesh& m = held->published;
        const std::vector<std::int64_t> row = vertex_rows(m);
        py::array_t<std::int64_t> a({static_cast<py::ssize_t>(m.num_tets()), py::ssize_t{4}});
        auto w = a.mutable_unchecked<2>();
        py::ssize_t r = 0;
        for (const auto& t : m.tets()) {
          if (t[0] == kDeadTetMarker) continue;
          if (r == a.shape(0)) throw std::logic_error("tetcut: the published mesh miscounts its tets");
          for (int k = 0; k < 4; ++k) w(r, k) = row[t[k]];
          ++r;
        }
        return a;
      },
      "#T by 4 int64: the live tets in id order, as rows of `points` (a copy).");
  mesh.def_property_readonly(
      "tet_ids",
      [](const MeshPtr& held) {
        const PublishedMesh& m = held->published;
        std::vector<std::int64_t> ids;
        ids.reserve(m.num_tets());
        const auto tets = m.tets();
        for (std::uint32_t t = 0; t < tets.size(); ++t)
          if (tets[t][0] != kDeadTetMarker) ids.push_back(t);
        return ids_array(ids);
      },
      "#T int64: the engine id of each row of `tets`.");

  mesh.def_property_readonly(
      "labels",
      [](const MeshPtr& held) -> py::object {
        const PublishedMesh& m = held->published;
        if (!m.labelled()) return py::none();
        py::array_t<std::int64_t> a(static_cast<py::ssize_t>(m.num_tets()));
        std::int64_t* out = a.mutable_data();
        py::ssize_t row = 0;
        for (std::uint32_t t = 0; t < m.tets().size(); ++t) {
          if (m.tets()[t][0] == kDeadTetMarker) continue;
          if (row == a.shape(0)) throw std::logic_error("tetcut: the published mesh miscounts its tets");
          out[row++] = m.labels()[t];
        }
        return py::object(std::move(a));
      },
      "#T int64, rows as `tets` (a copy): each tet's label (region, material) as the file or Mesh() gave "
      "them, carried through every cut (a tet a cut makes takes its parent's) and compaction; None when "
      "the mesh has none. As the last change that returned left them: never refused while another thread cuts.");

  mesh.def_property_readonly(
      "slot_tets",
      [](const MeshPtr& h) {
        MeshUse use(*h);
        const auto tets = h->mesh.raw_tets();
        return slot_view(h, {static_cast<py::ssize_t>(tets.size()), 4}, tets.data()->data());
      },
      R"doc(Slots by 4 uint32, read-only, no copy: the engine's tet array indexed by tet id, vertex
ids as entries (rows of slot_points); a removed tet's slot has 0xFFFFFFFF (4294967295) in
column 0 (see live_tet_mask). The one index array that is not int64: it is the engine's own
memory, not a copy. While this view (or any array made from it) is alive the mesh refuses every
change (a cut, a sweep, compact) with RuntimeError, since a cut grows and rewrites these arrays:
a view never dangles. Delete it before cutting again.)doc");
  mesh.def_property_readonly(
      "slot_points",
      [](const MeshPtr& h) {
        MeshUse use(*h);
        const auto p = h->mesh.positions();
        static_assert(sizeof(Vec3) == 3 * sizeof(double));
        return slot_view(h, {static_cast<py::ssize_t>(p.size()), 3}, &p.data()->x);
      },
      "Vertex slots by 3 float64, read-only, no copy: positions indexed by vertex id. Locks the mesh "
      "like slot_tets.");
  mesh.def_property_readonly(
      "live_tet_mask",
      [](const MeshPtr& held) {
        MeshHandle& h = *held;
        MeshUse use(h);
        const auto tets = h.mesh.raw_tets();
        py::array_t<bool> a(static_cast<py::ssize_t>(tets.size()));
        for (std::size_t t = 0; t < tets.size(); ++t) a.mutable_data()[t] = tets[t][0] != kDeadTetMarker;
        return a;
      },
      "Slots bool (a copy): which rows of slot_tets are live tets.");
  mesh.def_property_readonly(
      "live_vertex_mask",
      [](const MeshPtr& held) {
        MeshHandle& h = *held;
        MeshUse use(h);
        py::array_t<bool> a(static_cast<py::ssize_t>(h.mesh.vertex_capacity()));
        for (std::uint32_t v = 0; v < h.mesh.vertex_capacity(); ++v) a.mutable_data()[v] = h.mesh.is_live(VertId{v});
        return a;
      },
      "Vertex slots bool (a copy): which rows of slot_points are live vertices.");

}

// What a mesh measures: its surface, its volume, its canonical hash.
void bind_mesh_measures(MeshClass& mesh) {
  mesh.def(
      "surface",
      [](const MeshPtr& held) {
        MeshHandle& h = *held;
        MeshUse use(h);
        const std::vector<std::int64_t> row = vertex_rows(h.mesh);
        std::vector<FaceRef> faces;
        h.mesh.boundary_faces(faces);
        py::array_t<std::int64_t> a({static_cast<py::ssize_t>(faces.size()), py::ssize_t{3}});
        auto w = a.mutable_unchecked<2>();
        for (std::size_t i = 0; i < faces.size(); ++i) {
          for (int k = 0; k < 3; ++k) {
            w(i, k) = row[h.mesh.vertex(faces[i].tet, kFaceVerts[faces[i].face][k]).value];
          }
        }
        return a;
      },
      signature_doc("surface", "self, /",
                    "#F by 3 int64: the boundary triangles as rows of `points`, counter-clockwise seen from outside. "
                    "O(#T).").c_str());
  mesh.def(
      "volume", [](const MeshPtr& held) {
        MeshHandle& h = *held; MeshUse use(h); return h.mesh.total_volume(); },
      signature_doc("volume", "self, /", "Total volume (mesh units cubed). O(#T).").c_str());
  mesh.def(
      "hash", [](const MeshPtr& held) {
        MeshHandle& h = *held; MeshUse use(h); return hash_to_hex(canonical_hash(h.mesh)); },
      signature_doc("hash", "self, /",
                    "The canonical hash (16 hex digits) `tetcut` prints: independent of id numbering. O(#T log #T).")
          .c_str());

}

// Per-vertex attributes, which the cuts interpolate.
void bind_mesh_attributes(MeshClass& mesh) {
  mesh.def_property_readonly(
      "attribute_names",
      [](const MeshPtr& held) {
        MeshHandle& h = *held;
        std::vector<std::string> names;
        for (std::uint32_t c = 0; c < h.mesh.attributes().channel_count(); ++c)
          names.push_back(h.mesh.attributes().channel(c).name);
        return names;
      },
      "The per-vertex attribute channels, in the order added.");
  mesh.def(
      "vertex_attribute",
      [](const MeshPtr& held, const std::string& name) {
        MeshHandle& h = *held;
        MeshUse use(h);
        const VertexAttributes& attributes = h.mesh.attributes();
        const auto c = attributes.find(name);
        if (!c) throw py::key_error("tetcut: no vertex attribute named '" + name + "'");
        const std::uint32_t width = attributes.channel(*c).width;
        const auto rows = static_cast<py::ssize_t>(h.mesh.num_vertices());
        py::array_t<double> a = h.flat_attributes.count(name)
                                    ? py::array_t<double>(rows)
                                    : py::array_t<double>({rows, static_cast<py::ssize_t>(width)});
        double* out = a.mutable_data();
        for (std::uint32_t v = 0; v < h.mesh.vertex_capacity(); ++v) {
          if (!h.mesh.is_live(VertId{v})) continue;
          for (double x : attributes.value(*c, VertId{v})) *out++ = x;
        }
        return a;
      },
      py::arg("name"),
      signature_doc("vertex_attribute", "self, /, name",
                    "The channel's values (a float64 copy), rows as `points`: #V for a channel set from #V values "
                    "(meshio's shape for a scalar field), #V by width otherwise. Cuts interpolate every channel "
                    "along the edges they split (paper 3.2). KeyError for an unknown name.")
          .c_str());
  mesh.def(
      "set_vertex_attribute",
      [](const MeshPtr& held, const std::string& name, py::handle values) {
        MeshHandle& h = *held;
        MeshUse use(h);
        py::array a = as_array(values);
        const char kind = a.dtype().kind();
        if (kind != 'f' && kind != 'i' && kind != 'u') {
          throw py::type_error("tetcut: " + name + ": expected real numbers, got dtype " +
                               py::str(a.dtype()).cast<std::string>());
        }
        const bool flat = a.ndim() == 1;
        if (flat) a = a.attr("reshape")(-1, 1);
        if (a.ndim() != 2 || a.shape(0) != h.mesh.num_vertices() || a.shape(1) < 1) {
          throw py::value_error("tetcut: " + name + ": expected shape (" + std::to_string(h.mesh.num_vertices()) +
                                ",) or (" + std::to_string(h.mesh.num_vertices()) + ", width), got shape " +
                                shape_text(a));
        }
        VertexAttributes& attributes = h.mesh.attributes();
        const auto c = attributes.add_channel(name, static_cast<std::uint32_t>(a.shape(1)));
        if (!c) throw py::value_error("tetcut: " + name + ": the channel exists with another width");
        const auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
        const double* in = d.data();
        for (std::uint32_t v = 0; v < h.mesh.vertex_capacity(); ++v) {
          if (!h.mesh.is_live(VertId{v})) continue;
          for (double& x : attributes.value(*c, VertId{v})) x = *in++;
        }
        if (flat) h.flat_attributes.insert(name);
        else h.flat_attributes.erase(name);
      },
      py::arg("name"), py::arg("values"),
      signature_doc("set_vertex_attribute", "self, /, name, values",
                    "Adds (or overwrites) a channel from #V values or #V by width values, rows as `points`; "
                    "vertex_attribute() gives it back in the shape given.")
          .c_str());

}

// Writing, compaction, meshio, copies, pickling, repr.
void bind_mesh_files_and_copies(MeshClass& mesh) {
  mesh.def(
      "write",
      [](const MeshPtr& held, const std::string& path, bool binary, const std::string& compression) {
        MeshHandle& h = *held;
        MeshUse use(h);
        WriteOptions options{.binary = binary};
        if (compression == "zlib") options.compression = Compression::kZlib;
        else if (compression == "lzma") options.compression = Compression::kLzma;
        else if (compression != "none") throw py::value_error("tetcut: compression: none, zlib or lzma");
        if (h.mesh.num_tets() == 0) {
          throw py::value_error("tetcut: " + path + ": the mesh has no tets (the cuts removed them all): no format "
                                "tetcut reads holds an empty mesh (tetcut.read refuses one), so none is written");
        }
        RawMesh raw = h.mesh.to_raw();
        if (h.labels.labelled()) raw.labels = live_labels(h);
        WriteResult written;
        {
          py::gil_scoped_release release;
          written = write_mesh(path, raw, options);
        }
        if (!written.ok) throw py::value_error("tetcut: " + written.error);
      },
      py::arg("path"), py::kw_only(), py::arg("binary") = false, py::arg("compression") = "none",
      signature_doc("write", "self, /, path, *, binary=False, compression='none'",
                    "Writes the live mesh (rows as `points` and `tets`), format by extension (.msh 2.2, .vtu, .vtk, "
                    ".mesh, .node/.ele), through a temporary file and a rename, with the labels when it has them. "
                    "compression: none, zlib or lzma (.vtu). Attributes are not written. ValueError for an empty "
                    "mesh (no tets), which no reader takes.")
          .c_str());

  mesh.def(
      "compact",
      [](const MeshPtr& held, const std::string& order) {
        IdOrder id_order = IdOrder::kAlongCurve;
        if (order == "kept") {
          id_order = IdOrder::kKept;
        } else if (order != "curve") {
          throw py::value_error("order must be 'curve' or 'kept', not '" + order + "'");
        }
        MeshHandle& h = *held;
        MeshUse use(h);
        require_no_slot_views(h);
        const Renumbering r = h.mesh.compact(id_order);
        h.labels.renumber(r);
        h.published.publish_all(h.mesh, h.labels);
        ++h.version;
        std::vector<std::int64_t> tets(r.tet_old_to_new.size()), verts(r.vert_old_to_new.size());
        // int64 before the choice: `valid() ? value : -1` would make the -1 a uint32 (4294967295).
        for (std::size_t i = 0; i < tets.size(); ++i)
          tets[i] = r.tet_old_to_new[i].valid() ? std::int64_t{r.tet_old_to_new[i].value} : std::int64_t{-1};
        for (std::size_t i = 0; i < verts.size(); ++i)
          verts[i] = r.vert_old_to_new[i].valid() ? std::int64_t{r.vert_old_to_new[i].value} : std::int64_t{-1};
        return py::make_tuple(ids_array(tets), ids_array(verts));
      },
      signature_doc("compact", "self, /, order='curve'",
                    "Renumbers tets and vertices densely; returns (tet_old_to_new, vertex_old_to_new), int64 arrays "
                    "indexed by old id, -1 for a removed id (so old_to_new[old_to_new >= 0] are the kept ones). "
                    "order='curve' (the default) numbers them along a space-filling curve, so that tets near each "
                    "other in space are near each other in memory; order='kept' keeps their relative order. "
                    "ValueError for another order. Cutters on the mesh re-index before their next cut.")
          .c_str(),
      py::arg("order") = "curve");

  mesh.def("to_meshio", &to_meshio,
           signature_doc("to_meshio", "self, /",
                         "A meshio.Mesh: points, one 'tetra' cell block, each attribute channel as point_data (in the "
                         "shape vertex_attribute gives), the labels (if any) as cell_data 'label'.")
               .c_str());
  mesh.def("copy", &copy_of,
           signature_doc("copy", "self, /",
                         "An independent copy: the same ids, points, tets, labels and attributes (copy.copy and "
                         "copy.deepcopy give the same). Cutters stay on the original.")
               .c_str());
  mesh.def("__copy__", &copy_of, signature_doc("__copy__", "self, /", "mesh.copy().").c_str());
  mesh.def("__deepcopy__", [](const MeshPtr& held, py::handle) { return copy_of(held); }, py::arg("memo"),
           signature_doc("__deepcopy__", "self, /, memo", "mesh.copy(): a Mesh shares nothing with another.").c_str());
  // Pickled as the live mesh, rows as `points` and `tets` (ids renumbered densely, as compact(order="kept")
  // would), with its labels and attributes; rebuilt and validated like Mesh() when unpickled.
  mesh.def(py::pickle(
      [](py::object self) {
        const MeshPtr held = self.cast<MeshPtr>();
        py::dict attributes;
        for (py::handle name : self.attr("attribute_names")) attributes[name] = self.attr("vertex_attribute")(name);
        return py::make_tuple(1, self.attr("points"), self.attr("tets"), self.attr("labels"), attributes);
      },
      [](const py::tuple& state) {
        if (state.size() != 5 || state[0].cast<int>() != 1) throw py::value_error("tetcut: not a pickled tetcut.Mesh");
        MeshPtr h = py::len(state[2]) == 0 ? empty_mesh() : from_arrays(state[1], state[2], state[3], false);
        py::object mesh = py::cast(h);
        for (auto item : state[4].cast<py::dict>()) mesh.attr("set_vertex_attribute")(item.first, item.second);
        return h;
      }));
  mesh.def("__repr__", [](const MeshPtr& held) {
        MeshHandle& h = *held;
    return "<tetcut.Mesh " + std::to_string(h.published.num_vertices()) + " vertices, " +
           std::to_string(h.published.num_tets()) +
           " tets>";
  });

}

// The module-level ways to a mesh: tetcut.read, tetcut.from_meshio.
void bind_mesh_readers(py::module_& m) {
  m.def("read", &read, py::arg("path"), signature_doc("read", "path", R"doc(Reads a mesh file (Gmsh, VTK legacy and XML, medit, TetGen; format by content, else by
extension) and builds it. Raises ValueError with the line `tetcut` prints ("tetcut: FILE:LINE:
reason"); the reader's notes come as UserWarning, and so do points no tet uses, which are not
vertices of the mesh (as `tetcut` reads the file).)doc").c_str());

  m.def(
      "from_meshio",
      [](py::handle meshio_mesh, bool drop_unused_points) {
        py::list blocks;
        std::vector<std::size_t> tetra_blocks;
        std::size_t index = 0;
        for (py::handle block : meshio_mesh.attr("cells")) {
          if (block.attr("type").cast<std::string>() == "tetra") {
            blocks.append(block.attr("data"));
            tetra_blocks.push_back(index);
          }
          ++index;
        }
        if (blocks.empty()) throw py::value_error("tetcut: the meshio mesh has no 'tetra' cells");
        py::module_ numpy = py::module_::import("numpy");
        py::object tets = numpy.attr("concatenate")(blocks);
        // The labels: the first integer cell_data under a name the file readers take (io.hpp),
        // meshio's for each format, its tetra blocks' values concatenated as the tets are.
        py::object labels = py::none();
        const py::dict cell_data = meshio_mesh.attr("cell_data");
        for (const char* name : {"label", "gmsh:physical", "medit:ref", "CellEntityIds", "tetgen:ref"}) {
          if (!cell_data.contains(name)) continue;
          const py::list per_block = py::list(cell_data[name]);
          py::list parts;
          for (std::size_t b : tetra_blocks) parts.append(as_array(per_block[b]).attr("reshape")(-1));
          py::array values = as_array(numpy.attr("concatenate")(parts));
          const char kind = values.dtype().kind();
          if (kind != 'i' && kind != 'u') continue;
          labels = values;
          break;
        }
        MeshPtr h = from_arrays(meshio_mesh.attr("points"), tets, labels, drop_unused_points);
        // Point data on the points the mesh kept (rows of `points`).
        const py::ssize_t n = py::len(meshio_mesh.attr("points"));
        py::object mesh = py::cast(h);
        std::vector<std::int64_t> kept;
        for (std::uint32_t v = 0; v < h->mesh.vertex_capacity(); ++v)
          if (h->mesh.is_live(VertId{v})) kept.push_back(v);
        for (auto item : meshio_mesh.attr("point_data").cast<py::dict>()) {
          py::array values = as_array(item.second);
          const char kind = values.dtype().kind();
          if (values.ndim() < 1 || values.ndim() > 2 || values.shape(0) != n || (kind != 'f' && kind != 'i' && kind != 'u'))
            continue;
          mesh.attr("set_vertex_attribute")(item.first, values[ids_array(kept)]);
        }
        return h;
      },
      py::arg("mesh"), py::kw_only(), py::arg("drop_unused_points") = false,
      signature_doc("from_meshio", "mesh, *, drop_unused_points=False",
                    "A Mesh from a meshio.Mesh: its points, its 'tetra' cells, its real point_data as attributes "
                    "(in meshio's shapes), its labels from the first integer cell_data named label, gmsh:physical, "
                    "medit:ref, CellEntityIds or tetgen:ref. Validated as Mesh(points, tets, labels, "
                    "drop_unused_points=...) is: points no tetra uses (a file's other cells') are refused unless "
                    "dropped.")
          .c_str());
}

}  // namespace

void bind_mesh(py::module_& m) {
  made_by_the_module_only(py::class_<SlotViewLock>(
      m, "_SlotViewLock", "Keeps a mesh alive and unchanged while a slot view of it exists (internal)."));

  py::class_<MeshHandle, MeshPtr> mesh(m, "Mesh", R"doc(A manifold tetrahedral mesh (the engine's TetMesh), validated when made.

Mesh(points, tets, labels=None, *, drop_unused_points=False); tetcut.read(path) and
tetcut.from_meshio(m) make one too. Index arrays are int64 everywhere but in the zero-copy slot
views (slot_tets: uint32, 0xFFFFFFFF for a removed tet). copy.copy, copy.deepcopy, mesh.copy()
and pickle work (a pickled mesh comes back with its ids renumbered densely, as compact(order="kept") would).
repr: "<tetcut.Mesh V vertices, T tets>".)doc");
  mesh.def(py::init(&from_arrays), py::arg("points"), py::arg("tets"), py::arg("labels") = py::none(), py::kw_only(),
           py::arg("drop_unused_points") = false,
           signature_doc("__init__", "self, /, points, tets, labels=None, *, drop_unused_points=False", R"doc(A mesh from arrays, copied and validated.

points: #V by 3 (any real array-like); tets: #T by 4 integer vertex indices (rows of points,
0-based, positively oriented); labels: #T integers in 0..2^31-1 (a region, a material per tet)
or None. Every point must be some tet's corner: ValueError naming the unused rows, unless
drop_unused_points=True drops them (mesh.vertex_ids then gives each row of mesh.points its row
in `points`). ValueError with the message `tetcut` prints for what the builder refuses (NaN,
dangling or repeated indices, inverted tets, a non-manifold input); ValueError / TypeError naming
the argument for a wrong shape or dtype.)doc").c_str());

  bind_mesh_arrays(mesh);
  bind_mesh_measures(mesh);
  bind_mesh_attributes(mesh);
  bind_mesh_files_and_copies(mesh);
  bind_mesh_readers(m);
}

namespace {

py::object to_meshio(const MeshPtr& h) {
  py::module_ meshio = py::module_::import("meshio");
  py::object mesh = py::cast(h);
  py::dict point_data;
  for (std::uint32_t c = 0; c < h->mesh.attributes().channel_count(); ++c) {
    const std::string name = h->mesh.attributes().channel(c).name;
    point_data[py::str(name)] = mesh.attr("vertex_attribute")(name);  // in the shape it was given
  }
  py::list cells;
  cells.append(py::make_tuple("tetra", mesh.attr("tets")));
  py::dict cell_data;
  if (h->labels.labelled()) {
    py::list per_block;
    per_block.append(mesh.attr("labels"));
    cell_data["label"] = per_block;
  }
  return meshio.attr("Mesh")(mesh.attr("points"), cells, py::arg("point_data") = point_data,
                             py::arg("cell_data") = cell_data);
}

}  // namespace

}  // namespace tetcut::python
