#include "command_parser.hpp"

#include <algorithm>
#include <memory>
#include <ostream>
#include <sstream>
#include <utility>
#include <vector>

namespace tetcut::cli {

namespace {

// CLI11's help, laid out as tetcut's always was: the usage line first, then what the command
// does, the options CLI11 knows, and the footer (exit codes).
class HelpFormatter : public CLI::Formatter {
 public:
  explicit HelpFormatter(std::string synopsis) : synopsis_(std::move(synopsis)) {
    column_width(34);
    label("REQUIRED", "(required)");
  }

  std::string make_usage(const CLI::App* /*app*/, std::string /*name*/) const override {
    return "usage: " + synopsis_ + "\n";
  }

  std::string make_help(const CLI::App* app, std::string name, CLI::AppFormatMode mode) const override {
    if (mode == CLI::AppFormatMode::Sub) return make_expanded(app);
    std::ostringstream out;
    std::string description = make_description(app);  // ends with the description's own newline and one more
    if (description.ends_with("\n\n")) description.pop_back();
    out << make_usage(app, name) << '\n' << description << make_positionals(app) << make_groups(app, mode)
        << make_subcommands(app, CLI::AppFormatMode::All) << '\n'
        << make_footer(app);
    return out.str();
  }

 private:
  std::string synopsis_;
};

}  // namespace

namespace opt {

std::string one_line(std::string_view s) {
  std::string out(s);
  std::replace(out.begin(), out.end(), '\n', ' ');
  std::replace(out.begin(), out.end(), '\r', ' ');
  return out;
}

CLI::Option* accepting(CLI::App& app, const std::string& name, const std::string& help, const std::string& type,
                       std::function<bool(const std::string&)> accept, const std::string& expects) {
  return app
      .add_option_function<std::string>(
          name,
          [name, accept = std::move(accept), expects](const std::string& text) {
            if (!accept(text)) throw CLI::ValidationError(name, one_line(expects + ", not '" + text + "'"));
          },
          help)
      ->type_name(type);
}

CLI::Option* text(CLI::App& app, const std::string& name, std::optional<std::string>& target, const std::string& help,
                  const std::string& type) {
  return parsed(app, name, target, help, type, [](const std::string& s) { return std::optional<std::string>(s); }, "");
}

CLI::Option* number(CLI::App& app, const std::string& name, std::optional<double>& target, const std::string& help,
                    const std::string& type) {
  return parsed(app, name, target, help, type, [](const std::string& s) { return scenario::parse_double(s); },
                "expects a finite number");
}

CLI::Option* count(CLI::App& app, const std::string& name, std::optional<std::uint64_t>& target,
                   const std::string& help, const std::string& type) {
  return parsed(app, name, target, help, type, [](const std::string& s) { return scenario::parse_uint(s); },
                "expects a non-negative integer");
}

CLI::Option* labels(CLI::App& app, const std::string& name, std::vector<std::uint32_t>& target, const std::string& help) {
  return app
      .add_option_function<std::vector<std::string>>(
          name,
          [name, &target](const std::vector<std::string>& texts) {
            for (const std::string& text : texts) {
              std::size_t begin = 0;
              for (;;) {
                const std::size_t comma = text.find(',', begin);
                const std::string one = text.substr(begin, comma == std::string::npos ? std::string::npos : comma - begin);
                const auto label = scenario::parse_uint(one);
                if (!label || *label > 0xFFFFFFFFull)
                  throw CLI::ValidationError(name, one_line("expects labels (integers from 0 to 4294967295), not '" + text + "'"));
                target.push_back(static_cast<std::uint32_t>(*label));
                if (comma == std::string::npos) break;
                begin = comma + 1;
              }
            }
          },
          help)
      ->type_name("LABEL")
      ->allow_extra_args(false);
}

CLI::Option* point(CLI::App& app, const std::string& name, std::optional<Vec3>& target, const std::string& help,
                   const std::string& type) {
  return parsed(app, name, target, help, type, [](const std::string& s) { return scenario::parse_vec3(s); },
                "expects X,Y,Z (three finite numbers)");
}

CLI::Option* number_into(CLI::App& app, const std::string& name, double& target, const std::string& help,
                         const std::string& type) {
  return accepting(
      app, name, help, type,
      [&target](const std::string& text) {
        const auto value = scenario::parse_double(text);
        if (value) target = *value;
        return value.has_value();
      },
      "expects a finite number");
}

CLI::Option* count_into(CLI::App& app, const std::string& name, std::uint32_t& target, std::uint32_t max,
                        const std::string& help, const std::string& type) {
  return accepting(
      app, name, help, type,
      [&target, max](const std::string& text) {
        const auto value = scenario::parse_uint(text);
        if (value && *value <= max) target = static_cast<std::uint32_t>(*value);
        return value && *value <= max;
      },
      "expects an integer up to " + std::to_string(max));
}

CLI::Option* flag(CLI::App& app, const std::string& name, bool& target, const std::string& help) {
  return app.add_flag(name, target, help)->disable_flag_override()->multi_option_policy(CLI::MultiOptionPolicy::Throw);
}

CLI::Option* strategy(CLI::App& app, const std::string& name, std::optional<RemovalStrategy>& target,
                      const std::string& help) {
  return parsed(app, name, target, help, "basic|neighbours|combined|wide",
                [](const std::string& s) { return scenario::parse_strategy(s); },
                "must be basic, neighbours, combined or wide");
}

CLI::Option* order(CLI::App& app, const std::string& name, std::optional<RemovalOrder>& target,
                   const std::string& help) {
  return parsed(app, name, target, help, "direct-first|surface-first-by-id|revisit",
                [](const std::string& s) { return parse_removal_order(s); },
                "must be direct-first, surface-first-by-id (or paper, its old name) or revisit");
}

CLI::Option* neighbour_set(CLI::App& app, const std::string& name, std::optional<NeighbourSetChoice>& target,
                           const std::string& help) {
  return parsed(app, name, target, help, "smallest|first",
                [](const std::string& s) { return parse_neighbour_set_choice(s); }, "must be smallest or first");
}

CLI::Option* split_method(CLI::App& app, const std::string& name, std::optional<SplitMethod>& target,
                          const std::string& help) {
  return parsed(app, name, target, help, "templates|bisection",
                [](const std::string& s) { return parse_split_method(s); },
                "must be templates or bisection");
}

CLI::Option* refinement(CLI::App& app, std::optional<RefinementRule>& target, const std::string& help) {
  return parsed(app, "--refinement", target, help, "auto|paper|graded",
                [](const std::string& s) { return parse_refinement_rule(s); }, "must be auto, paper or graded");
}

CLI::Option* check_mode(CLI::App& app, std::optional<scenario::CheckMode>& target, const std::string& help) {
  return parsed(app, "--check", target, help, "every|end|none",
                [](const std::string& s) { return scenario::parse_check_mode(s); }, "must be every, end or none");
}

CLI::Option* check_level(CLI::App& app, std::optional<invariants::CheckLevel>& target, const std::string& help) {
  return parsed(app, "--level", target, help, "local|full|exact",
                [](const std::string& s) { return scenario::parse_check_level(s); }, "must be local, full or exact");
}

void improvement(CLI::App& app, Improvement& target, const std::string& unit) {
  flag(app, "--no-improve", target.off, "no improvement pass after each " + unit + ": the paper's algorithm alone");
  number(app, "--quality-floor", target.floor,
         "the radius ratio the improvement pass lifts created tets to (I7's F; default 0.1)", "F");
  number(app, "--min-dihedral", target.min_dihedral,
         "the smallest dihedral angle, in degrees, the improvement pass lifts created tets to (I7's theta; default 15)",
         "DEG");
}

void improvement_params(const Improvement& options, CutParams& params) {
  params.improve = !options.off;
  if (options.floor) params.quality_floor = *options.floor;
  if (options.min_dihedral) params.min_dihedral_deg = *options.min_dihedral;
}

CLI::Option* debris_volume(CLI::App& app, std::optional<double>& target) {
  return number(app, "--debris-volume", target,
                "detached pieces below this volume (mesh units cubed) are removed by the cut that detached them, "
                "as debris, reported apart from the tissue removed; a piece with an uncuttable tet stays (default 0: "
                "detached pieces are only reported)",
                "V");
}

}  // namespace opt

CommandParser::CommandParser(std::string name, std::string synopsis, std::string description, std::string footer)
    : name_(std::move(name)), synopsis_(std::move(synopsis)), app_(std::move(description), "tetcut " + name_) {
  app_.formatter(std::make_shared<HelpFormatter>(synopsis_));
  app_.set_help_flag("-h,--help", "this help");
  app_.footer(std::move(footer));
  // Leftovers are collected rather than thrown at once, so that an unknown option is named
  // even when CLI11 would first complain that a required argument is missing.
  app_.allow_extras();
}

std::optional<int> CommandParser::parse(Args args, std::ostream& out, std::ostream& err) {
  // An argument no option or positional took, named as a person would: the likeliest mistake.
  const auto leftover = [this]() -> std::optional<std::string> {
    std::vector<std::string> rest = app_.remaining(true);
    std::erase(rest, "--");  // CLI11 keeps the end-of-options mark among the leftovers
    if (rest.empty()) return std::nullopt;
    const std::string& a = rest.front();
    const bool option = a.size() > 1 && a[0] == '-' && !scenario::parse_double(a);
    return (option ? "unknown option '" : "unexpected argument '") + opt::one_line(a) + "'";
  };
  // CLI11 takes a vector in reverse order (it pops arguments from the back).
  std::vector<std::string> reversed(args.rbegin(), args.rend());
  try {
    app_.parse(reversed);
  } catch (const CLI::CallForHelp&) {
    out << app_.help();  // the selected subcommand's, if any
    return kExitOk;
  } catch (const CLI::ParseError& e) {
    return usage_error(leftover().value_or(opt::one_line(e.what())), err);
  }
  if (const auto rest = leftover()) return usage_error(*rest, err);
  return std::nullopt;
}

int CommandParser::usage_error(std::string_view message, std::ostream& err) const {
  err << "tetcut " << name_ << ": " << message << '\n' << "usage: " << synopsis_ << '\n';
  return kExitBadInput;
}

void set_synopsis(CLI::App& sub, const std::string& synopsis, const std::string& footer) {
  sub.formatter(std::make_shared<HelpFormatter>(synopsis));
  if (!footer.empty()) sub.footer(footer);
}

}  // namespace tetcut::cli
