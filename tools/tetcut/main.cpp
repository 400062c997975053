// `tetcut`: the command line (design: the command line). Dispatches to the subcommands of
// command.hpp and owns the top-level help, version and the last line of defence: whatever the
// input, the process ends with exit code 0, 1 or 2 and a message, never with an uncaught
// exception.
#include <algorithm>
#include <exception>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include "command.hpp"

#ifndef TETCUT_VERSION
#define TETCUT_VERSION "unknown"
#endif

namespace {

using tetcut::cli::CommandInfo;
using tetcut::cli::kExitBadInput;
using tetcut::cli::kExitOk;

void print_usage(std::ostream& os) {
  os << "usage: tetcut COMMAND [ARGS...]\n"
        "       tetcut help COMMAND | tetcut COMMAND --help\n"
        "       tetcut --version\n"
        "\n"
        "commands:\n";
  for (const CommandInfo& c : tetcut::cli::commands()) {
    os << "  " << c.name << std::string(10 - std::min<std::size_t>(c.name.size(), 9), ' ')
       << c.summary << '\n';
  }
  os << "\n"
        "exit codes: 0 success, 1 an invariant is violated (or the operation failed),\n"
        "            2 unreadable input or bad usage\n";
}

// Every command prints its own help (command_parser.hpp).
int print_command_help(const CommandInfo& c) {
  const std::string help = "--help";
  return c.run(tetcut::cli::Args(&help, 1), std::cout, std::cerr);
}

int run(const std::vector<std::string>& argv) {
  if (argv.empty()) {
    std::cerr << "tetcut: missing command\n";
    print_usage(std::cerr);
    return kExitBadInput;
  }
  const std::string& first = argv[0];
  if (first == "--help" || first == "-h") {
    print_usage(std::cout);
    return kExitOk;
  }
  if (first == "--version") {
    std::cout << "tetcut " << TETCUT_VERSION << '\n';
    return kExitOk;
  }
  if (first == "help") {
    if (argv.size() == 1) {
      print_usage(std::cout);
      return kExitOk;
    }
    const CommandInfo* c = tetcut::cli::find_command(argv[1]);
    if (c == nullptr || argv.size() > 2) {
      std::cerr << "tetcut: help: "
                << (c == nullptr ? "unknown command '" + argv[1] + "'" : "too many arguments")
                << '\n';
      print_usage(std::cerr);
      return kExitBadInput;
    }
    return print_command_help(*c);
  }
  const CommandInfo* c = tetcut::cli::find_command(first);
  if (c == nullptr) {
    std::cerr << "tetcut: unknown " << (first.starts_with('-') ? "option" : "command") << " '"
              << first << "'\n";
    print_usage(std::cerr);
    return kExitBadInput;
  }
  return c->run(tetcut::cli::Args(argv.data() + 1, argv.size() - 1), std::cout, std::cerr);
}

}  // namespace

int main(int argc, char** argv) {
  try {
    std::vector<std::string> args(argv + (argc > 0 ? 1 : 0), argv + argc);
    const int code = run(args);
    std::cout.flush();
    return code;
  } catch (const std::bad_alloc&) {
    // An absurd size in a file that the reader did not catch: still a refusal, not a crash.
    std::cerr << "tetcut: out of memory\n";
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "tetcut: internal error: " << e.what() << '\n';
    return kExitBadInput;
  }
}
