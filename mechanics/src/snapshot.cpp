#include "tetcut/mechanics/snapshot.hpp"

#include <algorithm>
#include <cstring>

namespace tetcut::mechanics {
namespace {

template <class T>
void fnv(std::uint64_t& h, std::span<const T> values) {
  const auto* bytes = reinterpret_cast<const unsigned char*>(values.data());
  for (std::size_t i = 0; i < values.size_bytes(); ++i) {
    h ^= bytes[i];
    h *= 0x100000001b3ull;
  }
}

}  // namespace

SnapshotPublisher::SnapshotPublisher(Options options) : options_(options) {
  buffers_.reserve(options_.readers + 2);
  for (std::uint32_t i = 0; i < options_.readers + 2; ++i) {
    buffers_.push_back(std::make_unique<Buffer>());
    // Even the empty frame a reader sees before the first publish carries its checksum.
    if (options_.checksums) buffers_.back()->frame.checksum = checksum_of(buffers_.back()->frame);
  }
}

SnapshotPublisher::~SnapshotPublisher() = default;

std::uint64_t SnapshotPublisher::checksum_of(const Frame& f) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  fnv(h, std::span<const std::uint64_t>(&f.sequence, 1));
  fnv(h, std::span<const Vec3>(f.positions));
  fnv(h, std::span<const Vec3>(f.velocities));
  fnv(h, std::span<const Vec3>(f.normals));
  fnv(h, std::span<const std::array<VertId, 3>>(f.triangles));
  fnv(h, std::span<const Vec3>(&f.reaction_force, 1));
  return h;
}

void SnapshotPublisher::publish(const TetMesh& mesh, const TensorMassModel& model, const RenderedSurface& surface,
                                const ChangeLog* cut, bool stepped, const Vec3& reaction_force) {
  ++sequence_;
  Changes& now = changes_[sequence_ % kKeptChanges];
  now.all_vertices = stepped;
  now.vertices.clear();
  now.triangles.clear();
  now.normals.clear();
  if (cut) {
    for (const CreatedVertex& v : cut->vertices) now.vertices.push_back(v.vertex.value);
    for (const MovedVertex& v : cut->moved) now.vertices.push_back(v.vertex.value);
    now.triangles.assign(surface.last_changed_triangles().begin(), surface.last_changed_triangles().end());
  }
  follow_surface(mesh, surface, cut, now);
  // A buffer no lease holds and not the latest: with `readers` leases at most, there is one.
  const std::uint32_t latest = latest_.load(std::memory_order_seq_cst);
  Buffer* target = nullptr;
  std::uint32_t index = 0;
  for (std::uint32_t i = 0; i < buffers_.size() && !target; ++i) {
    if (i == latest || buffers_[i]->leases.load(std::memory_order_seq_cst) != 0) continue;
    target = buffers_[i].get();
    index = i;
  }
  if (!target) {  // more leases than Options::readers: this publish is skipped, its changes kept
    ++stats_.skipped;
    return;
  }
  // Renumbered, or another mesh, since this buffer was written (TetMesh::id_epoch()): all of it.
  if (target->id_epoch != mesh.id_epoch()) target->frame.sequence = 0;
  bring_up_to_date(target->frame, mesh, model, surface);
  target->id_epoch = mesh.id_epoch();
  target->frame.reaction_force = reaction_force;
  target->frame.sequence = sequence_;
  if (options_.checksums) target->frame.checksum = checksum_of(target->frame);
  latest_.store(index, std::memory_order_seq_cst);
  ++stats_.publishes;
}

void SnapshotPublisher::follow_surface(const TetMesh& mesh, const RenderedSurface& surface, const ChangeLog* cut,
                                       Changes& now) {
  const auto slots = surface.triangle_slots();
  if (incident_.size() < mesh.vertex_capacity()) incident_.resize(mesh.vertex_capacity());
  if (followed_epoch_ != mesh.id_epoch()) {
    // The first publish, or another numbering: every buffer's next write is a full copy, whose
    // normals are all summed again, so only the followed surface is rebuilt here.
    for (auto& list : incident_) list.clear();
    slots_.assign(slots.size(), {kNoVert, kNoVert, kNoVert});
    for (std::uint32_t s = 0; s < slots.size(); ++s) add_slot(s, slots[s].v, now.normals);
    followed_epoch_ = mesh.id_epoch();
    now.normals.clear();
    return;
  }
  if (!cut) return;
  if (slots_.size() < slots.size()) slots_.resize(slots.size(), {kNoVert, kNoVert, kNoVert});
  for (std::uint32_t s : surface.last_changed_triangles()) {
    drop_slot(s, now.normals);
    add_slot(s, slots[s].v, now.normals);
  }
  // A vertex the cut made or moved changes the normals of every vertex of its triangles.
  auto moved = [&](std::uint32_t v) {
    if (v >= incident_.size()) return;
    for (std::uint32_t s : incident_[v])
      for (VertId w : slots_[s]) now.normals.push_back(w.value);
  };
  for (const CreatedVertex& v : cut->vertices) moved(v.vertex.value);
  for (const MovedVertex& v : cut->moved) moved(v.vertex.value);
  std::sort(now.normals.begin(), now.normals.end());
  now.normals.erase(std::unique(now.normals.begin(), now.normals.end()), now.normals.end());
}

void SnapshotPublisher::add_slot(std::uint32_t slot, const std::array<VertId, 3>& triangle,
                                 std::vector<std::uint32_t>& touched) {
  slots_[slot] = triangle;
  if (triangle[0] == kNoVert) return;
  for (VertId v : triangle) {
    if (v.value >= incident_.size()) incident_.resize(v.value + 1);
    auto& list = incident_[v.value];
    list.insert(std::lower_bound(list.begin(), list.end(), slot), slot);
    touched.push_back(v.value);
  }
}

void SnapshotPublisher::drop_slot(std::uint32_t slot, std::vector<std::uint32_t>& touched) {
  const std::array<VertId, 3> old = slots_[slot];
  if (old[0] == kNoVert) return;
  for (VertId v : old) {
    auto& list = incident_[v.value];
    const auto at = std::lower_bound(list.begin(), list.end(), slot);
    if (at != list.end() && *at == slot) list.erase(at);
    touched.push_back(v.value);
  }
  slots_[slot] = {kNoVert, kNoVert, kNoVert};
}

Vec3 SnapshotPublisher::deformed_normal(const Frame& f, std::uint32_t v) const {
  Vec3 sum{};
  if (v < incident_.size())
    for (std::uint32_t s : incident_[v]) {
      const std::array<VertId, 3>& t = slots_[s];
      const Vec3& p0 = f.positions[t[0].value];
      sum = sum + cross(f.positions[t[1].value] - p0, f.positions[t[2].value] - p0);
    }
  const double n = norm(sum);
  return n > 0 ? (1.0 / n) * sum : Vec3{};
}

void SnapshotPublisher::bring_up_to_date(Frame& f, const TetMesh& mesh, const TensorMassModel& model,
                                         const RenderedSurface& surface) {
  const std::uint32_t vertices = mesh.vertex_capacity();
  const auto slots = surface.triangle_slots();
  f.positions.resize(vertices);
  f.velocities.resize(vertices);
  f.normals.resize(vertices);
  f.triangles.resize(slots.size());
  const double to_mesh = 1.0 / model.params().length_unit;
  auto vertex = [&](std::uint32_t v) {
    if (v >= vertices) return;
    const VertId id{v};
    const bool modelled = v < model.vertex_capacity();
    f.positions[v] = mesh.position(id) + (modelled ? to_mesh * model.displacement(id) : Vec3{});
    f.velocities[v] = modelled ? model.velocity(id) : Vec3{};
    ++stats_.vertices_copied;
  };
  // After the positions and triangles: a normal sums its triangles at the frame's positions.
  auto normal = [&](std::uint32_t v) {
    if (v >= vertices) return;
    f.normals[v] = deformed_normal(f, v);
    ++stats_.normals_computed;
  };
  auto triangle = [&](std::uint32_t s) {
    if (s >= slots.size()) return;
    f.triangles[s] = slots[s].v;
    ++stats_.triangles_copied;
  };
  if (f.sequence == 0 || sequence_ - f.sequence >= kKeptChanges) {
    ++stats_.full_copies;
    for (std::uint32_t v = 0; v < vertices; ++v) vertex(v);
    for (std::uint32_t s = 0; s < slots.size(); ++s) triangle(s);
    for (std::uint32_t v = 0; v < vertices; ++v) normal(v);
    return;
  }
  bool all = false;
  for (std::uint64_t q = f.sequence + 1; q <= sequence_ && !all; ++q) all = changes_[q % kKeptChanges].all_vertices;
  if (all)
    for (std::uint32_t v = 0; v < vertices; ++v) vertex(v);
  for (std::uint64_t q = f.sequence + 1; q <= sequence_; ++q) {
    const Changes& c = changes_[q % kKeptChanges];
    if (!all)
      for (std::uint32_t v : c.vertices) vertex(v);
    for (std::uint32_t s : c.triangles) triangle(s);
  }
  if (all)
    for (std::uint32_t v = 0; v < vertices; ++v) normal(v);
  else
    for (std::uint64_t q = f.sequence + 1; q <= sequence_; ++q)
      for (std::uint32_t v : changes_[q % kKeptChanges].normals) normal(v);
}

SnapshotPublisher::Lease SnapshotPublisher::latest() const {
  for (;;) {
    const std::uint32_t i = latest_.load(std::memory_order_seq_cst);
    buffers_[i]->leases.fetch_add(1, std::memory_order_seq_cst);
    if (latest_.load(std::memory_order_seq_cst) == i) return Lease(this, i);
    buffers_[i]->leases.fetch_sub(1, std::memory_order_seq_cst);  // a publish moved it: again
  }
}

SnapshotPublisher::Lease::Lease(const SnapshotPublisher* owner, std::uint32_t buffer)
    : owner_(owner), buffer_(buffer), frame_(&owner->buffers_[buffer]->frame) {}

SnapshotPublisher::Lease::~Lease() {
  if (owner_) owner_->buffers_[buffer_]->leases.fetch_sub(1, std::memory_order_seq_cst);
}

}  // namespace tetcut::mechanics
