// The parser of one `tetcut` subcommand: CLI11 (Debian's libcli11-dev) for the structure of the
// command line, our strict parsers (tetcut/scenario/values.hpp) for every value.
//
// CLI11 does what a hand-written parser did: option names and "--opt value" / "--opt=value",
// "--" ending the options, negative numbers as values, an unknown option, a missing value or
// an option given twice refused, and the help listing generated from the options themselves,
// so it cannot drift from what is parsed. Where CLI11 serves worse we keep ours:
//   - numbers: CLI11 reads "nan", "inf", " 1", "0x10" and an empty value (as 0) and lets 1e999
//     overflow to infinity; every value here is bound as text and read by values.hpp, so those
//     are refused with "--opt: expects ..., not 'text'";
//   - messages: a CLI11 error becomes our one line, "tetcut NAME: message", followed by the
//     usage line, exit 2 (CLI11's own exit() prints several lines and uses its own codes);
//   - the usage line is the command's hand-written synopsis ("tetcut cut MESH --diameter D ..."),
//     which says what goes together better than CLI11's "[OPTIONS] MESH".
#pragma once

#include <cstdint>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include <CLI/CLI.hpp>

#include "command.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/scenario/values.hpp"

namespace tetcut::cli {

// Options and positionals of `app` whose value is read strictly; `target` is set only when the
// option is given. `type` is the value's name in the help ("D", "X,Y,Z").
namespace opt {

// A message on one line whatever it holds.
std::string one_line(std::string_view s);

// An option whose text `accept` takes (true) or refuses (false): "NAME: EXPECTS, not 'TEXT'".
CLI::Option* accepting(CLI::App& app, const std::string& name, const std::string& help, const std::string& type,
                       std::function<bool(const std::string&)> accept, const std::string& expects);

// An option whose text goes through `read`, which returns the value or nothing.
template <class T, class Read>
CLI::Option* parsed(CLI::App& app, const std::string& name, std::optional<T>& target, const std::string& help,
                    const std::string& type, Read read, const std::string& expects) {
  return accepting(
      app, name, help, type,
      [&target, read](const std::string& text) {
        auto value = read(text);
        if (value) target = std::move(*value);
        return value.has_value();
      },
      expects);
}

CLI::Option* text(CLI::App& app, const std::string& name, std::optional<std::string>& target, const std::string& help,
                  const std::string& type = "TEXT");
CLI::Option* number(CLI::App& app, const std::string& name, std::optional<double>& target, const std::string& help,
                    const std::string& type = "X");
CLI::Option* count(CLI::App& app, const std::string& name, std::optional<std::uint64_t>& target,
                   const std::string& help, const std::string& type = "N");
CLI::Option* point(CLI::App& app, const std::string& name, std::optional<Vec3>& target, const std::string& help,
                   const std::string& type = "X,Y,Z");
// Into a plain variable that keeps its default when the option is absent.
CLI::Option* number_into(CLI::App& app, const std::string& name, double& target, const std::string& help,
                         const std::string& type = "X");
CLI::Option* count_into(CLI::App& app, const std::string& name, std::uint32_t& target, std::uint32_t max,
                        const std::string& help, const std::string& type = "N");
// Labels (RawMesh::labels, as the mesh file gives them): "--keep-label 2 --keep-label 5" or
// "--keep-label 2,5", appended to `target`.
CLI::Option* labels(CLI::App& app, const std::string& name, std::vector<std::uint32_t>& target, const std::string& help);
// Present or not; "--flag=value" and a second "--flag" are refused.
CLI::Option* flag(CLI::App& app, const std::string& name, bool& target, const std::string& help);
// The shared vocabulary of values.hpp, each read by its one parser.
CLI::Option* strategy(CLI::App& app, const std::string& name, std::optional<RemovalStrategy>& target,
                      const std::string& help);
// --order direct-first|surface-first-by-id|revisit, "paper" accepted for surface-first-by-id
// (CutParams::order).
CLI::Option* order(CLI::App& app, const std::string& name, std::optional<RemovalOrder>& target,
                   const std::string& help);
// --neighbour-set smallest|first (CutParams::neighbour_set: paper 3.5's two readings).
CLI::Option* neighbour_set(CLI::App& app, const std::string& name, std::optional<NeighbourSetChoice>& target,
                           const std::string& help);
CLI::Option* split_method(CLI::App& app, const std::string& name, std::optional<SplitMethod>& target,
                          const std::string& help);
// --refinement auto|paper|graded (CutParams::refinement).
CLI::Option* refinement(CLI::App& app, std::optional<RefinementRule>& target, const std::string& help);
CLI::Option* check_mode(CLI::App& app, std::optional<scenario::CheckMode>& target, const std::string& help);
CLI::Option* check_level(CLI::App& app, std::optional<invariants::CheckLevel>& target, const std::string& help);
// The improvement pass that ends each `unit` ("cut", "request"): --no-improve, --quality-floor
// and --min-dihedral, read into CutParams by improvement_params().
struct Improvement {
  bool off = false;
  std::optional<double> floor;
  std::optional<double> min_dihedral;
};
void improvement(CLI::App& app, Improvement& target, const std::string& unit);
void improvement_params(const Improvement& options, CutParams& params);
// --debris-volume V (CutParams::debris_volume): `cut`, `run` and `simulate` share its words.
CLI::Option* debris_volume(CLI::App& app, std::optional<double>& target);
}  // namespace opt

class CommandParser {
 public:
  // `name` as in "tetcut NAME"; `synopsis` the usage line; `description` the prose of the help
  // (before the option list); `footer` what follows it (exit codes).
  CommandParser(std::string name, std::string synopsis, std::string description, std::string footer);

  [[nodiscard]] CLI::App& app() { return app_; }

  // Parses the arguments. Returns nothing when the command should go on; otherwise the exit
  // code, having printed the help to `out` (--help: 0) or one line and the usage to `err` (2).
  std::optional<int> parse(Args args, std::ostream& out, std::ostream& err);

  // For a mistake found after parsing: "tetcut NAME: message" and the usage line; returns 2.
  int usage_error(std::string_view message, std::ostream& err) const;

 private:
  std::string name_, synopsis_;
  CLI::App app_;
};

// Gives a subcommand (tetcut gen's kinds) its own usage line and footer in the help.
void set_synopsis(CLI::App& sub, const std::string& synopsis, const std::string& footer = "");

}  // namespace tetcut::cli
