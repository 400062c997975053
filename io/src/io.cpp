// Dispatch by content and extension, whole-file reading, and atomic writing (temporary file +
// rename).
#include "tetcut/io.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include "content_format.hpp"
#include "text_reader.hpp"

namespace tetcut {

std::string ParseError::message() const {
  if (line == 0) return file + ": " + reason;
  return file + ":" + std::to_string(line) + ": " + reason;
}

namespace {

std::string lower_extension(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot);
  for (char& c : ext) {
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  }
  return ext;
}

std::string strip_extension(const std::string& path) {
  return path.substr(0, path.size() - lower_extension(path).size());
}

ReadResult error_result(const std::string& file, std::string reason) {
  ReadResult r;
  r.error = ParseError{file, 0, std::move(reason)};
  return r;
}

std::optional<MeshFormat> format_for(const std::string& ext) {
  if (ext == ".msh") return MeshFormat::kMsh22;
  if (ext == ".vtu") return MeshFormat::kVtu;
  if (ext == ".vtk") return MeshFormat::kVtk;
  if (ext == ".mesh") return MeshFormat::kMedit;
  if (ext == ".node" || ext == ".ele") return MeshFormat::kTetgen;
  return std::nullopt;
}

constexpr const char* kKnownMeshExtensions = ".msh, .vtu, .vtk, .mesh, .node, .ele";

}  // namespace

std::optional<ParseError> read_file(const std::string& path, std::string& contents) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return ParseError{path, 0, std::string("cannot open file: ") + std::strerror(errno)};
  // Sized by the file, read at once: a stream grown by doubling held up to twice the file, the
  // largest part of a session's peak memory on a large mesh (bench/session_memory.cpp).
  contents.clear();
  in.seekg(0, std::ios::end);
  const std::streamoff size = in ? static_cast<std::streamoff>(in.tellg()) : -1;
  in.clear();
  if (size > 0 && in.seekg(0)) {
    contents.resize(static_cast<std::size_t>(size));
    in.read(contents.data(), size);
    contents.resize(static_cast<std::size_t>(in.gcount()));
    if (in.bad()) return ParseError{path, 0, "read error"};
    in.clear();
  }
  // Whatever is there beyond the size: all of a pipe (no size to go by), what a file grew by.
  std::ostringstream rest;
  rest << in.rdbuf();
  if (in.bad()) return ParseError{path, 0, "read error"};
  contents += std::move(rest).str();
  return std::nullopt;
}

namespace {

std::string_view format_name(MeshFormat format) {
  switch (format) {
    case MeshFormat::kMsh22:
    case MeshFormat::kMsh41: return "Gmsh MSH";
    case MeshFormat::kVtu: return "VTK XML";
    case MeshFormat::kVtk: return "legacy VTK";
    case MeshFormat::kMedit: return "medit MESH";
    case MeshFormat::kTetgen: return "TetGen";
  }
  return "?";
}

// The reader the content asks for, or an error for content that is not a volume mesh (a
// surface, another VTK dataset); nullopt when the content says nothing.
struct ContentChoice {
  std::optional<MeshFormat> format;
  std::optional<std::string> refusal;
};

ContentChoice choose_by_content(const io_detail::DetectedContent& d) {
  using io_detail::ContentFormat;
  const std::string gen = "; `tetcut gen surface FILE -o OUT.msh` tetrahedralizes a closed surface";
  switch (d.format) {
    case ContentFormat::kVtkXml:
      if (d.dataset == "UnstructuredGrid") return {MeshFormat::kVtu, {}};
      if (d.dataset == "PolyData") return {{}, "the content is " + d.description + ", a surface, not a tetrahedral mesh" + gen};
      return {{}, "the content is " + d.description + ", not an UnstructuredGrid of tetrahedra"};
    case ContentFormat::kLegacyVtk:
      if (io_detail::iequals(d.dataset, "POLYDATA")) {
        return {{}, "the content is " + d.description + ", a surface, not a tetrahedral mesh" + gen};
      }
      return {MeshFormat::kVtk, {}};  // the reader names any other dataset
    case ContentFormat::kGmsh: return {MeshFormat::kMsh22, {}};
    case ContentFormat::kMedit: return {MeshFormat::kMedit, {}};
    case ContentFormat::kSurface: return {{}, "the content is " + d.description + ", not a tetrahedral mesh" + gen};
    case ContentFormat::kUnknown: break;
  }
  return {};
}

}  // namespace

ReadResult read_mesh(const std::string& path) {
  const std::string ext = lower_extension(path);
  const auto by_extension = format_for(ext);
  if (by_extension == MeshFormat::kTetgen) {
    // The pair shares its base name; the extension of each file keeps the case the user gave.
    const std::string base = strip_extension(path);
    const bool upper = path.size() >= 4 && path.substr(path.size() - ext.size()) != ext;
    const std::string node_path = base + (upper ? ".NODE" : ".node");
    const std::string ele_path = base + (upper ? ".ELE" : ".ele");
    std::string node_text;
    std::string ele_text;
    if (auto e = read_file(node_path, node_text)) return ReadResult{std::nullopt, std::move(e), {}, {}};
    if (auto e = read_file(ele_path, ele_text)) return ReadResult{std::nullopt, std::move(e), {}, {}};
    return read_tetgen(node_text, node_path, ele_text, ele_path);
  }
  std::string text;
  if (auto e = read_file(path, text)) return ReadResult{std::nullopt, std::move(e), {}, {}};
  const io_detail::DetectedContent detected = io_detail::detect_content(text);
  const ContentChoice by_content = choose_by_content(detected);
  if (by_content.refusal) return error_result(path, *by_content.refusal);
  std::string notice;
  if (by_content.format && !by_extension) {
    notice = "unknown extension '" + ext + "': the content is " + detected.description + ", read as such";
  } else if (by_content.format && format_name(*by_content.format) != format_name(*by_extension)) {
    notice = "the extension '" + ext + "' says " + std::string(format_name(*by_extension)) + " but the content is " +
             detected.description + ": read as " + std::string(format_name(*by_content.format));
  }
  const std::optional<MeshFormat> format = by_content.format ? by_content.format : by_extension;
  if (!format) {
    return error_result(path, "unknown extension '" + ext + "' (known: " + kKnownMeshExtensions +
                                  ") and the content is not a mesh format tetcut reads: " + detected.description);
  }
  ReadResult result;
  switch (*format) {
    case MeshFormat::kMsh22:
    case MeshFormat::kMsh41: result = read_msh(text, path); break;
    case MeshFormat::kVtu: result = read_vtu(text, path); break;
    case MeshFormat::kVtk: result = read_vtk(text, path); break;
    case MeshFormat::kMedit: result = read_medit(text, path); break;
    case MeshFormat::kTetgen: return error_result(path, "a TetGen pair is read by its .node or .ele name");
  }
  if (!notice.empty()) result.notices.insert(result.notices.begin(), notice);
  return result;
}

std::string no_tetrahedra_reason(const ReadResult& result) {
  std::string held;
  for (std::size_t i = 0; i < result.ignored.size(); ++i) {
    const CellCount& c = result.ignored[i];
    if (i > 0) held += i + 1 == result.ignored.size() ? " and " : ", ";
    held += std::to_string(c.count) + " " + (c.count == 1 ? c.noun : io_detail::plural_noun(c.noun));
  }
  if (held.empty()) {
    const std::size_t points = result.mesh ? result.mesh->positions.size() : 0;
    held = points == 0 ? "no points and no cells" : std::to_string(points) + (points == 1 ? " point" : " points") + " and no cells";
  }
  return held + ", no tetrahedra";
}

WriteResult write_mesh_as(const std::string& path, const RawMesh& mesh, MeshFormat format, const WriteOptions& options) {
  const bool binary = options.binary || options.compression != Compression::kNone;
  if (mesh.labelled() && mesh.labels.size() != mesh.tets.size()) {
    return WriteResult{false, path + ": " + std::to_string(mesh.labels.size()) + " labels for " +
                                  std::to_string(mesh.tets.size()) + " tets"};
  }
  for (std::size_t t = 0; t < mesh.labels.size(); ++t) {
    if (mesh.labels[t] > kMaxTetLabel) {
      return WriteResult{false, path + ": tet " + std::to_string(t) + " has label " + std::to_string(mesh.labels[t]) +
                                    ", above " + std::to_string(kMaxTetLabel)};
    }
  }
  if (options.compression != Compression::kNone && format != MeshFormat::kVtu) {
    return WriteResult{false, path + ": only VTU (.vtu) is written compressed"};
  }
  switch (format) {
    case MeshFormat::kMsh22: return write_file_atomically(path, binary ? format_msh22_binary(mesh) : format_msh22(mesh));
    case MeshFormat::kMsh41: return write_file_atomically(path, binary ? format_msh41_binary(mesh) : format_msh41(mesh));
    case MeshFormat::kVtu:
      return write_file_atomically(path, binary ? format_vtu_binary(mesh, options.compression) : format_vtu(mesh));
    case MeshFormat::kVtk: return write_file_atomically(path, binary ? format_vtk_binary(mesh) : format_vtk(mesh));
    case MeshFormat::kMedit:
    case MeshFormat::kTetgen:
      if (binary) return WriteResult{false, path + ": " + std::string(format_name(format)) + " is written as text only"};
      break;
  }
  if (format == MeshFormat::kMedit) return write_file_atomically(path, format_medit(mesh));
  const std::string base = strip_extension(path);
  // Each file of the pair is atomic; the .ele goes last, so a reader never finds a new .ele
  // that refers to an old .node.
  WriteResult r = write_file_atomically(base + ".node", format_tetgen_node(mesh));
  if (!r.ok) return r;
  return write_file_atomically(base + ".ele", format_tetgen_ele(mesh));
}

WriteResult write_mesh(const std::string& path, const RawMesh& mesh, const WriteOptions& options) {
  const auto format = format_for(lower_extension(path));
  if (!format) {
    return WriteResult{false, path + ": unknown extension '" + lower_extension(path) +
                                  "' (known: " + kKnownMeshExtensions + ")"};
  }
  return write_mesh_as(path, mesh, *format, options);
}

WriteResult write_mesh(const std::string& path, const TetMesh& mesh) {
  return write_mesh(path, mesh.to_raw());
}

WriteResult write_mesh(const std::string& path, const TetMesh& mesh, std::span<const std::uint32_t> tet_labels) {
  RawMesh raw = mesh.to_raw();  // live tets in id order
  raw.labels.reserve(raw.tets.size());
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t) {
    if (!mesh.is_live(TetId{t})) continue;
    if (t >= tet_labels.size()) {
      return WriteResult{false, path + ": no label for tet " + std::to_string(t) + " (" +
                                    std::to_string(tet_labels.size()) + " labels)"};
    }
    raw.labels.push_back(tet_labels[t]);
  }
  return write_mesh(path, raw);
}

SurfaceReadResult read_surface(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (ext != ".off" && ext != ".stl" && ext != ".obj" && ext != ".vtk" && ext != ".vtp") {
    SurfaceReadResult r;
    r.error = ParseError{path, 0, "unknown extension '" + ext + "' (known: .off, .stl, .obj, .vtk, .vtp)"};
    return r;
  }
  std::string text;
  if (auto e = read_file(path, text)) return SurfaceReadResult{std::nullopt, std::move(e), {}};
  if (ext == ".off") return read_off(text, path);
  if (ext == ".stl") return read_stl(text, path);
  if (ext == ".obj") return read_obj(text, path);
  // VTK: XML or legacy, whichever the content is.
  if (io_detail::detect_content(text).format == io_detail::ContentFormat::kVtkXml) return read_vtp(text, path);
  return read_vtk_polydata(text, path);
}

WriteResult write_file_atomically(const std::string& path, std::string_view contents) {
  static std::atomic<std::uint64_t> counter{0};
  std::string temp;
  int fd = -1;
  for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
    temp = path + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(counter++);
    fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0 && errno != EEXIST) break;
  }
  if (fd < 0) {
    return WriteResult{false, path + ": cannot create temporary file: " + std::strerror(errno)};
  }
  const char* data = contents.data();
  std::size_t left = contents.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, data, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      const std::string reason = std::strerror(errno);
      ::close(fd);
      ::unlink(temp.c_str());
      return WriteResult{false, path + ": write failed: " + reason};
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  const bool synced = ::fsync(fd) == 0;
  const int sync_errno = errno;
  const bool closed = ::close(fd) == 0;
  if (!synced || !closed) {
    const std::string reason = std::strerror(synced ? errno : sync_errno);
    ::unlink(temp.c_str());
    return WriteResult{false, path + ": write failed: " + reason};
  }
  if (::rename(temp.c_str(), path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    ::unlink(temp.c_str());
    return WriteResult{false, path + ": cannot rename temporary file: " + reason};
  }
  return WriteResult{};
}

}  // namespace tetcut
