// The run-time half of the threading contract (tetcut/thread_contract.hpp): an atomic count of
// a mesh's readers and a flag for its writer, so that calls that overlap against the contract
// stop the process with both names. No lock: a reader or a writer that keeps the contract pays
// one atomic read-modify-write on the way in and one on the way out.
#include "tetcut/thread_contract.hpp"

#include <cstdio>
#include <cstdlib>

#include "tetcut/mesh.hpp"

#ifndef TETCUT_THREAD_CHECKS
#define TETCUT_THREAD_CHECKS 1
#endif

namespace tetcut {
namespace detail {
namespace {

[[noreturn]] void violated(const char* what, const char* other, const char* other_kind) {
  std::fprintf(stderr,
               "tetcut: threading contract violated: %s while %s %s on another thread uses the same mesh "
               "(a change needs the mesh to itself: engine/include/tetcut/thread_contract.hpp)\n",
               what, other_kind, other ? other : "a call");
  std::fflush(stderr);
  std::abort();
}

}  // namespace

void MeshUse::enter_write(const char* what) const {
  if constexpr (TETCUT_THREAD_CHECKS) {
    const std::thread::id me = std::this_thread::get_id();
    std::uint64_t expected = 0;
    if (state_.compare_exchange_strong(expected, kWriter, std::memory_order_seq_cst)) {
      writer_.store(me, std::memory_order_seq_cst);
      writing_.store(what, std::memory_order_relaxed);
      depth_ = 1;
      return;
    }
    if ((expected & kWriter) != 0 && writer_.load(std::memory_order_seq_cst) == me) {  // nested, same thread
      ++depth_;
      return;
    }
    if ((expected & kWriter) != 0) violated(what, writing_.load(std::memory_order_relaxed), "the change");
    violated(what, reading_.load(std::memory_order_relaxed), "the read");
  }
}

void MeshUse::leave_write() const {
  if constexpr (TETCUT_THREAD_CHECKS) {
    if (--depth_ > 0) return;
    writer_.store(std::thread::id{}, std::memory_order_seq_cst);
    state_.fetch_and(~kWriter, std::memory_order_seq_cst);
  }
}

void MeshUse::enter_read(const char* what) const {
  if constexpr (TETCUT_THREAD_CHECKS) {
    const std::uint64_t before = state_.fetch_add(1, std::memory_order_seq_cst);
    if ((before & kWriter) != 0 && writer_.load(std::memory_order_seq_cst) != std::this_thread::get_id())
      violated(what, writing_.load(std::memory_order_relaxed), "the change");
    reading_.store(what, std::memory_order_relaxed);
  }
}

void MeshUse::leave_read() const {
  if constexpr (TETCUT_THREAD_CHECKS) state_.fetch_sub(1, std::memory_order_seq_cst);
}

}  // namespace detail

MeshWriteScope::MeshWriteScope(const TetMesh& mesh, const char* what) : mesh_(mesh) { mesh_.use().enter_write(what); }
MeshWriteScope::~MeshWriteScope() { mesh_.use().leave_write(); }
MeshReadScope::MeshReadScope(const TetMesh& mesh, const char* what) : mesh_(mesh) { mesh_.use().enter_read(what); }
MeshReadScope::~MeshReadScope() { mesh_.use().leave_read(); }

}  // namespace tetcut
