// The table of `tetcut` subcommands, in the order `tetcut --help` lists them. Each command's
// help and options live in its own cmd_NAME.cpp.
#include <array>

#include "command.hpp"

namespace tetcut::cli {

namespace {

constexpr std::array kCommands = {
    CommandInfo{"info", "counts, boundary, quality statistics, manifold status, hash", &cmd_info},
    CommandInfo{"check", "runs the invariant checker, names each violated invariant", &cmd_check},
    CommandInfo{"convert", "converts between the supported formats", &cmd_convert},
    CommandInfo{"gen", "generates a mesh (cylinder, sheet, box, surface, liver)", &cmd_gen},
    CommandInfo{"repair", "makes a mesh manifold and positively oriented", &cmd_repair},
    CommandInfo{"refine", "refines by edge splitting (10 configurations or bisection)", &cmd_refine},
    CommandInfo{"remove", "removes tetrahedra without breaking the manifold (paper 3.3-3.7)", &cmd_remove},
    CommandInfo{"cut", "a cautery sweep, one cut per step", &cmd_cut},
    CommandInfo{"run", "runs a scenario file", &cmd_run},
    CommandInfo{"simulate", "elastic tissue stepped while the cautery cuts it, .vtu frames", &cmd_simulate},
    CommandInfo{"stats", "the paper's Tables 1 and 2, a strategy comparison and an HTML report", &cmd_stats},
    CommandInfo{"replay", "decodes a fuzz input into a scenario and runs it", &cmd_replay},
    CommandInfo{"minimize", "shrinks a failing scenario while it still fails", &cmd_minimize},
    CommandInfo{"check-engine", "drives any engine's adapter (engine.h) with the checker after every operation",
                &cmd_check_engine},
};

}  // namespace

std::span<const CommandInfo> commands() { return kCommands; }

const CommandInfo* find_command(std::string_view name) {
  for (const CommandInfo& c : kCommands) {
    if (c.name == name) return &c;
  }
  return nullptr;
}

}  // namespace tetcut::cli
