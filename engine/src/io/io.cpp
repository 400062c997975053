// Dispatch by extension, whole-file reading, and atomic writing (temporary file + rename).
#include "tetcut/io.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

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
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) return ParseError{path, 0, "read error"};
  contents = std::move(buffer).str();
  return std::nullopt;
}

ReadResult read_mesh(const std::string& path) {
  const std::string ext = lower_extension(path);
  const auto format = format_for(ext);
  if (!format) {
    return error_result(path, "unknown extension '" + ext + "' (known: " + kKnownMeshExtensions + ")");
  }
  if (*format == MeshFormat::kTetgen) {
    // The pair shares its base name; the extension of each file keeps the case the user gave.
    const std::string base = strip_extension(path);
    const bool upper = path.size() >= 4 && path.substr(path.size() - ext.size()) != ext;
    const std::string node_path = base + (upper ? ".NODE" : ".node");
    const std::string ele_path = base + (upper ? ".ELE" : ".ele");
    std::string node_text;
    std::string ele_text;
    if (auto e = read_file(node_path, node_text)) return ReadResult{std::nullopt, std::move(e), {}};
    if (auto e = read_file(ele_path, ele_text)) return ReadResult{std::nullopt, std::move(e), {}};
    return read_tetgen(node_text, node_path, ele_text, ele_path);
  }
  std::string text;
  if (auto e = read_file(path, text)) return ReadResult{std::nullopt, std::move(e), {}};
  switch (*format) {
    case MeshFormat::kMsh22:
    case MeshFormat::kMsh41: return read_msh(text, path);
    case MeshFormat::kVtu: return read_vtu(text, path);
    case MeshFormat::kVtk: return read_vtk(text, path);
    case MeshFormat::kMedit: return read_medit(text, path);
    case MeshFormat::kTetgen: break;
  }
  return error_result(path, "unknown extension '" + ext + "'");
}

WriteResult write_mesh_as(const std::string& path, const RawMesh& mesh, MeshFormat format) {
  switch (format) {
    case MeshFormat::kMsh22: return write_file_atomically(path, format_msh22(mesh));
    case MeshFormat::kMsh41: return write_file_atomically(path, format_msh41(mesh));
    case MeshFormat::kVtu: return write_file_atomically(path, format_vtu(mesh));
    case MeshFormat::kVtk: return write_file_atomically(path, format_vtk(mesh));
    case MeshFormat::kMedit: return write_file_atomically(path, format_medit(mesh));
    case MeshFormat::kTetgen: {
      const std::string base = strip_extension(path);
      // Each file of the pair is atomic; the .ele goes last, so a reader never finds a new .ele
      // that refers to an old .node.
      WriteResult r = write_file_atomically(base + ".node", format_tetgen_node(mesh));
      if (!r.ok) return r;
      return write_file_atomically(base + ".ele", format_tetgen_ele(mesh));
    }
  }
  return WriteResult{false, path + ": unknown format"};
}

WriteResult write_mesh(const std::string& path, const RawMesh& mesh) {
  const auto format = format_for(lower_extension(path));
  if (!format) {
    return WriteResult{false, path + ": unknown extension '" + lower_extension(path) +
                                  "' (known: " + kKnownMeshExtensions + ")"};
  }
  return write_mesh_as(path, mesh, *format);
}

WriteResult write_mesh(const std::string& path, const TetMesh& mesh) {
  return write_mesh(path, mesh.to_raw());
}

SurfaceReadResult read_surface(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (ext != ".off" && ext != ".stl" && ext != ".obj") {
    SurfaceReadResult r;
    r.error = ParseError{path, 0, "unknown extension '" + ext + "' (known: .off, .stl, .obj)"};
    return r;
  }
  std::string text;
  if (auto e = read_file(path, text)) return SurfaceReadResult{std::nullopt, std::move(e), {}};
  if (ext == ".off") return read_off(text, path);
  if (ext == ".stl") return read_stl(text, path);
  return read_obj(text, path);
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
