// Running a piece of the harness in a forked child, so that an engine that crashes, aborts or
// hangs takes down the child and not the harness: the parent learns the signal and the last
// operation the child announced before it died.
#pragma once

#include <functional>
#include <string>

namespace tetcut::harness {

// Sends one line to the parent (newlines in it become spaces): what the child is about to do.
using Announce = std::function<void(const std::string&)>;

struct ChildOutcome {
  bool completed = false;     // the child returned a payload and exited normally
  std::string payload;        // what `work` returned (completed)
  int signal = 0;             // the signal that ended the child, 0 if none
  int exit_code = 0;          // its exit code when it exited without a payload
  std::string last_announced; // the last line the child announced ("" if none)
  std::string error;          // fork or pipe failure, or an exception `work` threw

  // "killed by signal 6 (Aborted) during cut 3 at (0, 0, 0)" and the like, for people.
  [[nodiscard]] std::string failure() const;
};

// Forks; the child runs `work(announce)` and sends back what it returns; the parent waits. When
// `timeout_seconds` > 0 the child is killed by SIGALRM once it has run that long (a hung engine).
// Streams are flushed before the fork, so the child repeats nothing the parent had buffered.
ChildOutcome run_in_child(const std::function<std::string(const Announce&)>& work, unsigned timeout_seconds = 0);

}  // namespace tetcut::harness
