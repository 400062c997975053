#include "support/fuzz_failure.hpp"

#include <cstdio>
#include <cstdlib>
#include <utility>

namespace tetcut::fuzz {

namespace {
thread_local int capture_depth = 0;
}  // namespace

std::string to_string(const Finding& finding) {
  return finding.property + " violated after operation " + std::to_string(finding.operation_index) + " (" +
         finding.operation + "): " + finding.detail;
}

FailureError::FailureError(Finding finding) : finding_(std::move(finding)), message_(to_string(finding_)) {}

CaptureFailures::CaptureFailures() { ++capture_depth; }
CaptureFailures::~CaptureFailures() { --capture_depth; }

void fail(std::string_view property, std::size_t operation_index, std::string_view operation,
          std::string_view detail) {
  if (capture_depth > 0)
    throw FailureError(Finding{std::string(property), operation_index, std::string(operation), std::string(detail)});
  std::fprintf(stderr, "tetcut-fuzz: %.*s violated after operation %zu (%.*s): %.*s\n",
               static_cast<int>(property.size()), property.data(), operation_index,
               static_cast<int>(operation.size()), operation.data(), static_cast<int>(detail.size()),
               detail.data());
  std::fflush(stderr);
  std::abort();
}

}  // namespace tetcut::fuzz
