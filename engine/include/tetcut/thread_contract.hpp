// The threading contract, and the check that enforces what of it can be seen at run time.
//
// A simulator cuts on one thread and reads on others (a haptic loop at 1 kHz, a renderer at
// 60 Hz). What may run at the same time:
//
//   TetMesh           Any number of threads may call its const members at once, while no thread
//                     changes it. A change (a Cutter's cut, cut_segment, remove, undo, reset,
//                     compact or set_uncuttable, TetMesh::compact(), any non-const member) needs
//                     the mesh to itself: no other thread may read or change it meanwhile.
//   Cutter            One thread at a time. It changes its mesh, so the mesh rule above holds
//                     for each of its calls too; two Cutters on one mesh never cut at once.
//   ChangeLog         A plain value: the call it is handed to writes it; after the call returns
//                     it is the caller's, and may be read by any number of threads.
//   TensorMassModel,  One thread at a time for a change (apply, step, set_*); const members from
//   RenderedSurface,  any number of threads while none changes it. apply() reads the mesh, so
//   TetLabels         it counts as a reader of the mesh: not while a cut runs.
//
// Everything else is for the thread that owns it. A reader that must not wait for a cut reads
// copies the cutting thread made between cuts, never the live objects.
//
// Enforced: every changing call of a Cutter and TetMesh::compact() takes the mesh for writing,
// the consumers' apply() and MeshReadScope for reading (an atomic counter in the mesh, no lock:
// about 20 instructions a call). When a writer meets a reader or a writer from another thread,
// or a reader a writer, the process stops with a message naming both calls (std::abort: a data
// race is undefined behaviour, and a crash later would name neither). What it cannot see: a
// read that takes no scope (a const member called directly), which ThreadSanitizer finds.
// Build option TETCUT_THREAD_CHECKS (CMake, default ON) turns it off: the calls then cost nothing.
#pragma once

#include <atomic>
#include <cstdint>
#include <thread>

namespace tetcut {

class TetMesh;

namespace detail {

// The mesh's record of who uses it: the writer's thread and nesting depth, and how many readers.
// Copying a mesh copies no use: the copy starts unused.
class MeshUse {
 public:
  MeshUse() = default;
  MeshUse(const MeshUse&) {}
  MeshUse& operator=(const MeshUse&) { return *this; }

  // `what` names the call in the message: a string literal.
  void enter_write(const char* what) const;
  void leave_write() const;
  void enter_read(const char* what) const;
  void leave_read() const;

 private:
  static constexpr std::uint64_t kWriter = std::uint64_t{1} << 63;
  mutable std::atomic<std::uint64_t> state_{0};  // kWriter | readers
  mutable std::atomic<std::thread::id> writer_{};
  mutable std::uint32_t depth_ = 0;  // the writer's nesting, touched by the writer only
  mutable std::atomic<const char*> writing_{nullptr}, reading_{nullptr};  // for the message
};

}  // namespace detail

// A changing call on a mesh, for as long as it lives (the Cutter's entry points hold one).
class MeshWriteScope {
 public:
  MeshWriteScope(const TetMesh& mesh, const char* what);
  ~MeshWriteScope();
  MeshWriteScope(const MeshWriteScope&) = delete;
  MeshWriteScope& operator=(const MeshWriteScope&) = delete;

 private:
  const TetMesh& mesh_;
};

// A read of a mesh that another thread may cut, declared: held around the reads, it makes an
// overlapping cut stop the process with both names, instead of a silent race. The consumers'
// apply() hold one.
class MeshReadScope {
 public:
  MeshReadScope(const TetMesh& mesh, const char* what);
  ~MeshReadScope();
  MeshReadScope(const MeshReadScope&) = delete;
  MeshReadScope& operator=(const MeshReadScope&) = delete;

 private:
  const TetMesh& mesh_;
};

}  // namespace tetcut
