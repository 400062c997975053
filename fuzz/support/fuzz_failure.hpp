// How a fuzz target reports a broken property: one line on stderr, then std::abort(), so that
// libFuzzer keeps the input as a crash and the line names what broke.
//
//   tetcut-fuzz: I5 violated after operation 7 (split): vertex 12: link is an annulus
//
// The first word after "tetcut-fuzz:" is the property's id (an invariant I1-I9 of the design, or
// one of the harness's own: reader-contract, round-trip, interpolation, checker-differential,
// refused-split, unresolved-combined, rollback-changed-mesh, mesh-queries; planted-bug, the switched-off
// bug of planted_bug.hpp that the tests of triage switch on); ci/fuzz-nightly
// deduplicates crashes by it and by the top stack frames, and reads the operation's index and
// name from the same line.
//
// `tetcut replay` runs the same targets in-process and wants the finding as a value instead:
// while a CaptureFailures object lives on the thread, fail() throws FailureError (no line, no
// abort), and the caller catches it.
#pragma once

#include <cstddef>
#include <exception>
#include <string>
#include <string_view>

namespace tetcut::fuzz {

[[noreturn]] void fail(std::string_view property, std::size_t operation_index, std::string_view operation,
                       std::string_view detail);

// What fail() was told.
struct Finding {
  std::string property;         // "I5", "unresolved-combined", ...
  std::size_t operation_index = 0;
  std::string operation;        // "remove", "cut", "sweep 2/5", ...
  std::string detail;
};

// "I5 violated after operation 7 (remove): detail", as the abort line says it.
std::string to_string(const Finding& finding);

class FailureError : public std::exception {
 public:
  explicit FailureError(Finding finding);
  [[nodiscard]] const Finding& finding() const { return finding_; }
  [[nodiscard]] const char* what() const noexcept override { return message_.c_str(); }

 private:
  Finding finding_;
  std::string message_;
};

// While alive, fail() on this thread throws FailureError instead of aborting. Nests.
class CaptureFailures {
 public:
  CaptureFailures();
  ~CaptureFailures();
  CaptureFailures(const CaptureFailures&) = delete;
  CaptureFailures& operator=(const CaptureFailures&) = delete;
};

}  // namespace tetcut::fuzz
