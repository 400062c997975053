// mechanics::PeriodicReader (periodic_reader.hpp): it reads every frame whole while another thread
// publishes, and a reader left running keeps timing only its first max_timed reads, so that a loop
// running for hours does not grow without bound, while it goes on counting and checking them all.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

#include "mechanics_test_support.hpp"
#include "tetcut/mechanics/periodic_reader.hpp"
#include "tetcut/mechanics/rendered_surface.hpp"
#include "tetcut/mechanics/snapshot.hpp"
#include "tetcut/mechanics/tensor_mass.hpp"

namespace tetcut {
namespace {

using mechanics::PeriodicReader;
using mechanics::SnapshotPublisher;

TEST(PeriodicReader, KeepsTimingOnlyItsFirstReadsButChecksThemAll) {
  TetMesh mesh = testing::load_bundled("cylinder.msh");
  mechanics::TensorMassModel model(mesh, testing::four_materials());
  mechanics::RenderedSurface surface(mesh);
  SnapshotPublisher publisher({.readers = 1, .checksums = true});
  publisher.publish(mesh, model, surface, nullptr, true, {});
  std::atomic<std::uint64_t> seen{0};
  PeriodicReader reader(publisher, {.period = std::chrono::microseconds(200), .max_timed = 3},
                        [&](const SnapshotPublisher::Frame&) { seen.fetch_add(1, std::memory_order_relaxed); });
  // Publishes go on while it reads, until it has read more frames than it times (or 30 s, which
  // fails below).
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (seen.load(std::memory_order_relaxed) < 8 && std::chrono::steady_clock::now() < give_up) {
    model.step(1e-6);
    publisher.publish(mesh, model, surface, nullptr, true, {});
  }
  const PeriodicReader::Figures figures = reader.stop();
  EXPECT_GE(figures.reads, 8u);
  EXPECT_EQ(figures.reads, seen.load());
  EXPECT_EQ(figures.wait_us.size(), 3u);
  EXPECT_EQ(figures.read_us.size(), 3u);
  EXPECT_EQ(figures.late_us.size(), 3u);
  EXPECT_EQ(figures.torn, 0u);
  EXPECT_EQ(figures.backwards, 0u);
  EXPECT_GT(figures.last_sequence, 1u);
  // Stopped once: a second stop has nothing more to give.
  EXPECT_EQ(reader.stop().reads, 0u);
}

}  // namespace
}  // namespace tetcut
