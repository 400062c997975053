// Runs a program as a user would and collects what it did: exit code or signal, stdout, stderr.
#pragma once

#include <string>
#include <vector>

namespace tetcut::test {

struct ProcessResult {
  bool exited = false;  // false: killed by a signal (or could not be started)
  int exit_code = -1;   // when exited
  int signal = 0;       // when killed
  std::string out;
  std::string err;
};

// Runs `program` with `args`, stdout and stderr captured through files in `scratch_dir`.
// Sanitizer reports are given exit code 86 (not 1, which tetcut uses), so that a sanitizer
// finding can never pass for an ordinary exit code.
ProcessResult run_process(const std::string& program, const std::vector<std::string>& args,
                          const std::string& scratch_dir);

}  // namespace tetcut::test
