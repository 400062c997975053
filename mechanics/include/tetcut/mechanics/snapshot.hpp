// Snapshots a reader never waits for: what a haptic loop (1 kHz) and a renderer (60 Hz) read on
// their own threads while the cutting thread cuts and steps (thread_contract.hpp: they may not
// touch the live mesh, model or surface meanwhile).
//
// After each cut (its consumers' apply() done) or step, the cutting thread publishes a Frame: the
// deformed positions, velocities, the rendered surface's triangles and unit normals, and the
// tool's reaction force. A reader takes the latest complete one as a Lease and reads it for as
// long as it holds it; the cutter never waits for a reader and a reader never waits for the
// cutter.
//
// Why buffers and a count per buffer (readers + 2 of them) rather than a sequence lock or a
// shared_ptr swap: a sequence lock makes a reader retry a whole copy whenever a publish lands
// during it (a renderer's read of a large surface would rarely finish at 1 kHz of publishes), and
// a fresh shared_ptr per publish is an O(#V) copy and an allocation per cut. Here a publish writes
// into a buffer no reader holds, bringing it up to date with only what changed since that buffer
// was last written (the cut's vertices, the surface's changed slots and the normals they change,
// kept per publish; after a step every vertex moved, and the step itself is O(#V + #E)), then
// makes it the latest with one atomic store. A reader takes a lease with two atomic operations and a check that the latest did not
// move meanwhile (a retry only when a publish landed in those few nanoseconds). With at most
// `readers` leases held at once, some buffer is always free: a publish never waits either.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "tetcut/ids.hpp"
#include "tetcut/mechanics/rendered_surface.hpp"
#include "tetcut/mechanics/tensor_mass.hpp"
#include "tetcut/mesh.hpp"
#include "tetcut/vec3.hpp"

namespace tetcut::mechanics {

class SnapshotPublisher {
 public:
  struct Frame {
    std::uint64_t sequence = 0;  // the publish that made it: 1, 2, ... (0: nothing published yet)
    // By VertId, vertex_capacity() long (a dead vertex's entries mean nothing):
    std::vector<Vec3> positions;   // deformed: rest + displacement, in mesh units
    std::vector<Vec3> velocities;  // m/s
    // The surface's unit normal of the deformed shape (zero off it): the normalised sum of
    // cross(p1 - p0, p2 - p0) over the vertex's triangles in slot order, the p the positions
    // above, so that a frame's normals are a function of its positions and triangles alone.
    std::vector<Vec3> normals;
    // By slot, as RenderedSurface::triangle_slots() has them (all kNoVert: a free slot).
    std::vector<std::array<VertId, 3>> triangles;
    Vec3 reaction_force{};         // N, as the publisher was handed it
    std::uint64_t checksum = 0;    // of all the above, when Options::checksums
  };
  struct Options {
    std::uint32_t readers = 2;  // leases held at once, at most (each reader thread holds one)
    bool checksums = false;     // O(#V + #F) a publish: for tests and the stress harness
  };
  struct Stats {
    std::uint64_t publishes = 0;
    std::uint64_t skipped = 0;          // no free buffer (more leases than Options::readers)
    std::uint64_t full_copies = 0;      // a buffer further behind than the kept changes
    std::uint64_t vertices_copied = 0;  // entries written by publishes
    std::uint64_t triangles_copied = 0;
    std::uint64_t normals_computed = 0;  // vertices whose deformed normal a publish summed again
  };

  explicit SnapshotPublisher(Options options);
  SnapshotPublisher() : SnapshotPublisher(Options{}) {}
  ~SnapshotPublisher();
  SnapshotPublisher(const SnapshotPublisher&) = delete;
  SnapshotPublisher& operator=(const SnapshotPublisher&) = delete;

  // The cutting thread only, the consumers up to date. `cut`: the log of the cut (or undo) since
  // the last publish, which the model and the surface have applied (its vertices, the surface's
  // last changed slots and the normals around both are what a publish writes); null when none. `stepped`: the model
  // stepped since the last publish (every vertex moved: all are copied). A compaction since, or
  // another mesh (TetMesh::id_epoch()), makes every buffer's next write a full copy.
  void publish(const TetMesh& mesh, const TensorMassModel& model, const RenderedSurface& surface, const ChangeLog* cut,
               bool stepped, const Vec3& reaction_force);
  [[nodiscard]] const Stats& stats() const { return stats_; }  // the cutting thread

  // A held frame: valid until the lease ends. Any thread; never blocks.
  class Lease {
   public:
    Lease(Lease&& other) noexcept : owner_(other.owner_), buffer_(other.buffer_), frame_(other.frame_) {
      other.owner_ = nullptr;
    }
    Lease& operator=(Lease&&) = delete;
    Lease(const Lease&) = delete;
    ~Lease();
    [[nodiscard]] const Frame& operator*() const { return *frame_; }
    [[nodiscard]] const Frame* operator->() const { return frame_; }

   private:
    friend class SnapshotPublisher;
    Lease(const SnapshotPublisher* owner, std::uint32_t buffer);
    const SnapshotPublisher* owner_;
    std::uint32_t buffer_;
    const Frame* frame_ = nullptr;
  };
  [[nodiscard]] Lease latest() const;

  // What checksum a frame holds (the one a publish with Options::checksums stored).
  [[nodiscard]] static std::uint64_t checksum_of(const Frame& frame);

 private:
  struct alignas(64) Buffer {
    Frame frame;
    std::uint64_t id_epoch = 0;  // the mesh's when the frame was written (the cutting thread's)
    std::atomic<std::uint32_t> leases{0};
  };
  // The changes of one publish, for bringing older buffers up to date.
  struct Changes {
    bool all_vertices = false;
    // `normals`: the vertices one of whose triangles changed or moved (a vertex of it did).
    std::vector<std::uint32_t> vertices, triangles, normals;
  };
  static constexpr std::uint32_t kKeptChanges = 64;

  void bring_up_to_date(Frame& frame, const TetMesh& mesh, const TensorMassModel& model, const RenderedSurface& surface);
  // The surface's triangles by vertex as the publisher last saw them (the cutting thread's):
  // what a vertex's normal sums, and whose normals a moved vertex changes.
  void follow_surface(const TetMesh& mesh, const RenderedSurface& surface, const ChangeLog* cut, Changes& now);
  void add_slot(std::uint32_t slot, const std::array<VertId, 3>& triangle, std::vector<std::uint32_t>& touched);
  void drop_slot(std::uint32_t slot, std::vector<std::uint32_t>& touched);
  [[nodiscard]] Vec3 deformed_normal(const Frame& frame, std::uint32_t vertex) const;

  Options options_;
  std::vector<std::unique_ptr<Buffer>> buffers_;
  alignas(64) std::atomic<std::uint32_t> latest_{0};
  std::uint64_t sequence_ = 0;
  std::array<Changes, kKeptChanges> changes_;  // by sequence % kKeptChanges
  std::vector<std::array<VertId, 3>> slots_;           // the surface's triangle slots, as followed
  std::vector<std::vector<std::uint32_t>> incident_;   // by vertex: its slots, ascending
  std::uint64_t followed_epoch_ = 0;                   // the mesh's when slots_ was rebuilt (0: never)
  Stats stats_;
};

}  // namespace tetcut::mechanics
