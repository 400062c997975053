#include "tetcut/mechanics/periodic_reader.hpp"

#include <utility>

#ifdef __linux__
#include <sys/prctl.h>
#endif

namespace tetcut::mechanics {

namespace {

using Clock = std::chrono::steady_clock;

double us_since(Clock::time_point t) { return std::chrono::duration<double, std::micro>(Clock::now() - t).count(); }

}  // namespace

PeriodicReader::PeriodicReader(const SnapshotPublisher& publisher, Options options,
                               std::function<void(const SnapshotPublisher::Frame&)> on_frame)
    : publisher_(publisher), options_(options), on_frame_(std::move(on_frame)), thread_([this] { run(); }) {}

PeriodicReader::~PeriodicReader() { stop(); }

PeriodicReader::Figures PeriodicReader::stop() {
  if (!thread_.joinable()) return {};
  done_.store(true, std::memory_order_relaxed);
  thread_.join();
  return std::move(figures_);
}

void PeriodicReader::run() {
#ifdef __linux__
  prctl(PR_SET_TIMERSLACK, 1UL, 0UL, 0UL, 0UL);
#endif
  Clock::time_point next = Clock::now() + options_.period;
  while (!done_.load(std::memory_order_relaxed)) {
    std::this_thread::sleep_until(next);
    const double late = us_since(next);
    next += options_.period;
    const Clock::time_point t0 = Clock::now();
    const SnapshotPublisher::Lease frame = publisher_.latest();
    const double wait = us_since(t0);
    const Clock::time_point t1 = Clock::now();
    if (options_.check_checksums && SnapshotPublisher::checksum_of(*frame) != frame->checksum) ++figures_.torn;
    if (frame->sequence < figures_.last_sequence) ++figures_.backwards;
    figures_.last_sequence = frame->sequence;
    if (on_frame_) on_frame_(*frame);
    const double read = us_since(t1);
    if (figures_.reads++ < options_.max_timed) {
      figures_.late_us.push_back(late);
      figures_.wait_us.push_back(wait);
      figures_.read_us.push_back(read);
    }
  }
}

}  // namespace tetcut::mechanics
