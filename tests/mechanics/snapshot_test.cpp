// SnapshotPublisher (snapshot.hpp): every frame a reader gets equals the consumers' state when it
// was published, though each publish copies only what changed since the buffer it writes was
// last written; old leases held across publishes stay as they were; a cut's publish copies a
// small part of the mesh; and readers on two threads, while a third cuts, steps and publishes,
// only ever see whole frames (each frame's checksum is the one published with it).
#include <gtest/gtest.h>

#include <atomic>
#include <cstdio>
#include <optional>
#include <thread>
#include <vector>

#include "mechanics_test_support.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/mechanics/rendered_surface.hpp"
#include "tetcut/mechanics/snapshot.hpp"
#include "tetcut/mechanics/tensor_mass.hpp"

namespace tetcut {
namespace {

using mechanics::RenderedSurface;
using mechanics::SnapshotPublisher;
using mechanics::TensorMassModel;

// The frame a full copy gives, from the consumers directly; the normals of the deformed shape
// summed over the surface's slots in order (snapshot.hpp), not the surface's rest normals.
SnapshotPublisher::Frame direct_frame(const TetMesh& mesh, const TensorMassModel& model, const RenderedSurface& surface) {
  SnapshotPublisher::Frame f;
  const double to_mesh = 1.0 / model.params().length_unit;
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) {
    const VertId id{v};
    f.positions.push_back(mesh.position(id) + to_mesh * model.displacement(id));
    f.velocities.push_back(model.velocity(id));
  }
  for (const auto& t : surface.triangle_slots()) f.triangles.push_back(t.v);
  std::vector<Vec3> sums(f.positions.size());
  for (const auto& t : f.triangles) {
    if (t[0] == kNoVert) continue;
    const Vec3& p0 = f.positions[t[0].value];
    const Vec3 area = cross(f.positions[t[1].value] - p0, f.positions[t[2].value] - p0);
    for (VertId v : t) sums[v.value] = sums[v.value] + area;
  }
  for (const Vec3& sum : sums) {
    const double n = norm(sum);
    f.normals.push_back(n > 0 ? (1.0 / n) * sum : Vec3{});
  }
  return f;
}

// Live entries only: a dead vertex's or a free slot's entries mean nothing.
void expect_frame_equals(const SnapshotPublisher::Frame& got, const SnapshotPublisher::Frame& want, const TetMesh& mesh) {
  ASSERT_EQ(got.positions.size(), want.positions.size());
  ASSERT_EQ(got.triangles.size(), want.triangles.size());
  for (std::uint32_t v = 0; v < want.positions.size(); ++v) {
    if (!mesh.is_live(VertId{v})) continue;
    ASSERT_EQ(got.positions[v], want.positions[v]) << "vertex " << v;
    ASSERT_EQ(got.velocities[v], want.velocities[v]) << "vertex " << v;
    ASSERT_EQ(got.normals[v], want.normals[v]) << "vertex " << v;
  }
  for (std::size_t s = 0; s < want.triangles.size(); ++s) ASSERT_EQ(got.triangles[s], want.triangles[s]) << "slot " << s;
}

struct Simulation {
  TetMesh mesh = testing::load_bundled("cylinder.msh");
  Cutter cutter{mesh, {.tool_diameter = 0.4}};
  TensorMassModel model{mesh, testing::four_materials()};
  RenderedSurface surface{mesh};
  double dt = 0.0;

  Simulation() {
    model.fix_where(mesh, [](const Vec3& p) { return p.z < 0.3; });
    dt = 0.5 * model.stable_time_step(mesh).dt;
    for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v)
      if (!model.is_fixed(VertId{v})) model.set_velocity(VertId{v}, {0.01, 0.0, -0.02});
  }
  // One cut and its consumers; false when refused.
  bool cut(const Vec3& centre, ChangeLog& log) {
    log.clear();
    if (!cutter.cut(centre, &log).ok) return false;
    model.apply(mesh, log);
    surface.apply(mesh, log);
    return true;
  }
};

TEST(Snapshot, EveryFrameIsTheStateItWasPublishedWithAndACutCopiesLittle) {
  Simulation sim;
  SnapshotPublisher publisher;
  EXPECT_EQ(publisher.latest()->sequence, 0u);  // nothing published yet: an empty frame
  publisher.publish(sim.mesh, sim.model, sim.surface, nullptr, true, {});
  expect_frame_equals(*publisher.latest(), direct_frame(sim.mesh, sim.model, sim.surface), sim.mesh);
  // A lease held across publishes keeps its frame.
  std::optional<SnapshotPublisher::Lease> held = publisher.latest();
  const SnapshotPublisher::Frame first = **held;
  ChangeLog log;
  for (int k = 0; k < 24; ++k) {
    const Vec3 centre{-0.8 + 0.07 * k, 0.2, 2.0 + 0.02 * k};
    if (k % 3 == 2) {
      sim.model.step(sim.dt);
      publisher.publish(sim.mesh, sim.model, sim.surface, nullptr, true, {1.0 * k, 0, 0});
    } else {
      ASSERT_TRUE(sim.cut(centre, log)) << "cut " << k;
      publisher.publish(sim.mesh, sim.model, sim.surface, &log, false, {1.0 * k, 0, 0});
    }
    const SnapshotPublisher::Lease now = publisher.latest();
    EXPECT_EQ(now->sequence, static_cast<std::uint64_t>(k + 2));
    EXPECT_EQ(now->reaction_force.x, 1.0 * k);
    expect_frame_equals(*now, direct_frame(sim.mesh, sim.model, sim.surface), sim.mesh);
    if (k == 12) held.reset();  // the held buffer comes back 13 publishes behind: brought up to date
    if (held) {
      EXPECT_EQ((*held)->positions, first.positions);
    }
  }
  EXPECT_EQ(publisher.stats().skipped, 0u);
  // Each buffer's first write copies everything (4: readers + 2), none after.
  EXPECT_LE(publisher.stats().full_copies, 4u);
  // Cuts alone: a publish writes what the cuts since its buffer's last write changed (two
  // publishes' worth, buffers taking turns), not the mesh.
  const std::uint64_t copied_before = publisher.stats().vertices_copied, full_before = publisher.stats().full_copies;
  const std::uint64_t normals_before = publisher.stats().normals_computed;
  int cuts = 0;
  for (int k = 0; k < 12; ++k) {
    if (!sim.cut({-0.8 + 0.13 * k, -0.3, 3.0}, log)) continue;
    publisher.publish(sim.mesh, sim.model, sim.surface, &log, false, {});
    ++cuts;
    expect_frame_equals(*publisher.latest(), direct_frame(sim.mesh, sim.model, sim.surface), sim.mesh);
  }
  ASSERT_GT(cuts, 6);
  EXPECT_EQ(publisher.stats().full_copies, full_before);
  const double per_cut = static_cast<double>(publisher.stats().vertices_copied - copied_before) / cuts;
  std::printf("a cut's publish copied %.0f vertex entries on average (the mesh has %u vertices)\n", per_cut,
              sim.mesh.num_vertices());
  EXPECT_LT(per_cut, 0.25 * sim.mesh.num_vertices());
  const double normals_per_cut = static_cast<double>(publisher.stats().normals_computed - normals_before) / cuts;
  std::printf("and summed %.0f deformed normals again\n", normals_per_cut);
  EXPECT_LT(normals_per_cut, 0.25 * sim.mesh.num_vertices());
}

TEST(Snapshot, ACompactionMakesTheNextPublishAFullCopy) {
  Simulation sim;
  SnapshotPublisher publisher;
  publisher.publish(sim.mesh, sim.model, sim.surface, nullptr, true, {});
  ChangeLog log;
  ASSERT_TRUE(sim.cut({0, 0, 2}, log));
  publisher.publish(sim.mesh, sim.model, sim.surface, &log, false, {});
  const Renumbering r = sim.cutter.compact();
  (void)r;
  TensorMassModel model(sim.mesh, testing::four_materials());  // consumers rebuilt after a compaction
  RenderedSurface surface(sim.mesh);
  const std::uint64_t full = publisher.stats().full_copies;
  publisher.publish(sim.mesh, model, surface, nullptr, true, {});
  EXPECT_EQ(publisher.stats().full_copies, full + 1);
  expect_frame_equals(*publisher.latest(), direct_frame(sim.mesh, model, surface), sim.mesh);
}

// Another mesh through the same publisher (a simulation reset): every buffer is written whole
// (the new mesh's id_epoch() is not the old one's), so no frame mixes the old mesh's triangles
// with the new one's; buffers that took only the new mesh's changes would. And the empty frame a
// reader sees before the first publish is whole too.
TEST(Snapshot, AnotherMeshMakesEveryBufferWhole) {
  SnapshotPublisher publisher({.readers = 2, .checksums = true});
  const SnapshotPublisher::Frame& empty = *publisher.latest();
  EXPECT_EQ(SnapshotPublisher::checksum_of(empty), empty.checksum);
  {
    Simulation first;
    publisher.publish(first.mesh, first.model, first.surface, nullptr, true, {});
    ChangeLog log;
    std::size_t triangles_changed = 0;
    for (int k = 0; k < 6; ++k) {
      ASSERT_TRUE(first.cut({-0.8 + 0.13 * k, -0.3, 3.0}, log)) << "cut " << k;
      triangles_changed += first.surface.last_changed_triangles().size();
      publisher.publish(first.mesh, first.model, first.surface, &log, false, {});
    }
    ASSERT_GT(triangles_changed, 0u);  // the old mesh's surface is not the new one's
  }
  Simulation second;
  const std::uint64_t full = publisher.stats().full_copies;
  for (int k = 0; k < 5; ++k) {
    second.model.step(second.dt);
    publisher.publish(second.mesh, second.model, second.surface, nullptr, true, {});
    expect_frame_equals(*publisher.latest(), direct_frame(second.mesh, second.model, second.surface), second.mesh);
  }
  // With no lease held, publishes alternate between two buffers: each is written whole once.
  EXPECT_EQ(publisher.stats().full_copies, full + 2);
}

// Two readers (a haptic loop spinning, a renderer pausing) while the cutting thread sweeps,
// steps and publishes with checksums: every frame either reads is whole.
TEST(Snapshot, ReadersOnOtherThreadsOnlyEverSeeWholeFrames) {
  Simulation sim;
  SnapshotPublisher publisher({.readers = 2, .checksums = true});
  publisher.publish(sim.mesh, sim.model, sim.surface, nullptr, true, {});
  std::atomic<bool> done{false};
  std::atomic<std::uint64_t> torn{0}, backwards{0};
  std::vector<std::uint64_t> reads(2, 0);
  auto reader = [&](int which) {
    std::uint64_t last = 0;
    while (!done.load()) {
      const SnapshotPublisher::Lease frame = publisher.latest();
      if (SnapshotPublisher::checksum_of(*frame) != frame->checksum) ++torn;
      if (frame->sequence < last) ++backwards;
      last = frame->sequence;
      ++reads[which];
      if (which == 1) std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
  };
  std::thread haptic(reader, 0), render(reader, 1);
  ChangeLog log;
  int cuts = 0;
  for (int k = 0; k < 60; ++k) {
    if (sim.cut({-0.9 + 0.03 * k, -0.3 + 0.01 * k, 1.0 + 0.04 * k}, log)) {
      ++cuts;
      publisher.publish(sim.mesh, sim.model, sim.surface, &log, false, {});
    }
    sim.model.step(sim.dt);
    publisher.publish(sim.mesh, sim.model, sim.surface, nullptr, true, {0, 0, 1.0 * k});
  }
  done = true;
  haptic.join();
  render.join();
  EXPECT_GT(cuts, 30);
  EXPECT_EQ(torn.load(), 0u);
  EXPECT_EQ(backwards.load(), 0u);
  EXPECT_GT(reads[0], 0u);
  EXPECT_GT(reads[1], 0u);
  EXPECT_EQ(publisher.stats().skipped, 0u);
}

}  // namespace
}  // namespace tetcut
