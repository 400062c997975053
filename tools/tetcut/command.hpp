// The subcommands of the `tetcut` command line. Each takes its arguments (without the program
// and subcommand names) and the two streams, and returns the process exit code:
//   0 success, 1 an invariant is violated (or the operation failed), 2 unreadable input or bad
//   usage (with a message on `err` naming the file, line and reason).
//
// Messages to `err` are one line each, "tetcut: FILE:LINE: reason" for bad input and
// "tetcut COMMAND: reason" (followed by the command's usage line) for bad usage.
// Each command owns its help text and its parser (command_parser.hpp): `--help` / `-h` among its
// arguments prints its help on `out` and returns 0; `tetcut help NAME` runs NAME with --help.
#pragma once

#include <iosfwd>
#include <span>
#include <string>
#include <string_view>

namespace tetcut::cli {

using Args = std::span<const std::string>;

int cmd_check(Args args, std::ostream& out, std::ostream& err);
int cmd_info(Args args, std::ostream& out, std::ostream& err);
int cmd_convert(Args args, std::ostream& out, std::ostream& err);
int cmd_gen(Args args, std::ostream& out, std::ostream& err);
int cmd_repair(Args args, std::ostream& out, std::ostream& err);
int cmd_refine(Args args, std::ostream& out, std::ostream& err);
int cmd_cut(Args args, std::ostream& out, std::ostream& err);
int cmd_remove(Args args, std::ostream& out, std::ostream& err);
int cmd_run(Args args, std::ostream& out, std::ostream& err);
int cmd_stats(Args args, std::ostream& out, std::ostream& err);
int cmd_replay(Args args, std::ostream& out, std::ostream& err);
int cmd_minimize(Args args, std::ostream& out, std::ostream& err);
int cmd_simulate(Args args, std::ostream& out, std::ostream& err);
int cmd_check_engine(Args args, std::ostream& out, std::ostream& err);

inline constexpr int kExitOk = 0;
inline constexpr int kExitViolated = 1;
inline constexpr int kExitBadInput = 2;

struct CommandInfo {
  std::string_view name;
  std::string_view summary;   // one line for the command list
  int (*run)(Args, std::ostream&, std::ostream&);
};

// Every command, in the order `tetcut --help` lists them.
std::span<const CommandInfo> commands();
const CommandInfo* find_command(std::string_view name);

}  // namespace tetcut::cli
