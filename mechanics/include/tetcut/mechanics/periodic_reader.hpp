// A thread that reads a SnapshotPublisher's latest frame at a fixed period, as a haptic loop
// (1 kHz) or a renderer (60 Hz) does beside the cutting thread, and holds every frame it reads to
// being whole: its checksum the one published with it (when the publisher computes them), its
// sequence never going back. It measures what such a loop feels: how long the lease took (the
// wait), how long the read took, and how late each wake-up came against its schedule.
//
// Scheduling: std::this_thread::sleep_until on steady_clock from the default (SCHED_OTHER)
// policy, no real-time priority, which needs no privilege; on Linux the thread asks for no timer
// slack (the kernel's default lets a wake-up slip by 50 us to batch it with others). A simulator
// that needs a tighter loop gives the thread SCHED_FIFO itself.
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <thread>
#include <vector>

#include "tetcut/mechanics/snapshot.hpp"

namespace tetcut::mechanics {

class PeriodicReader {
 public:
  struct Figures {
    std::uint64_t reads = 0;
    std::vector<double> wait_us, read_us, late_us;  // one entry a read, for the first max_timed reads
    std::uint64_t torn = 0;       // frames whose checksum was not the one published with them
    std::uint64_t backwards = 0;  // frames older than one read before
    std::uint64_t last_sequence = 0;
  };
  struct Options {
    std::chrono::microseconds period{1000};
    bool check_checksums = true;  // the publisher's Options::checksums must be on
    // Reads timed at most: 24 bytes each, so that a loop left running for hours does not grow
    // without bound (2^20: about 17 minutes at 1 kHz, 25 MB). Later reads are still checked.
    std::size_t max_timed = std::size_t{1} << 20;
  };

  // Starts the thread. `on_frame`, when given, runs on it for every frame read, the lease held
  // (what a haptic loop does with the frame: render its reaction force); its time is the read's.
  PeriodicReader(const SnapshotPublisher& publisher, Options options,
                 std::function<void(const SnapshotPublisher::Frame&)> on_frame = {});
  PeriodicReader(const PeriodicReader&) = delete;
  PeriodicReader& operator=(const PeriodicReader&) = delete;
  ~PeriodicReader();  // stops it

  // Stops the thread after its current read and returns what it measured (once; later calls
  // return empty figures).
  Figures stop();

 private:
  void run();

  const SnapshotPublisher& publisher_;
  Options options_;
  std::function<void(const SnapshotPublisher::Frame&)> on_frame_;
  std::atomic<bool> done_{false};
  Figures figures_;
  std::thread thread_;
};

}  // namespace tetcut::mechanics
