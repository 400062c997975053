// `tetcut minimize SCENARIO -o OUT [--max-runs N]`: shrinks a scenario that fails (`tetcut run`
// exits 1) while it keeps failing the same way: the same kind of error (an invariant by its
// id, an expectation by its kind, a failed cut or removal), whatever line it names.
//
//   1. deletes operations, ddmin style: chunks of halves, quarters, ... then single lines;
//   2. simplifies what is left: a sweep becomes one cut (at its start, then its end), points
//      are rounded to 0, 1, 2, 3 decimals (the coarsest that still fails);
//   3. deletes single lines once more.
// Every candidate is a full `tetcut run` of the text. The result is written atomically, its
// mesh paths relative to OUT's folder.
#include <cmath>
#include <filesystem>
#include <iterator>
#include <functional>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "command.hpp"
#include "command_parser.hpp"
#include "tetcut/io.hpp"
#include "tetcut/scenario/delta_debugging.hpp"
#include "tetcut/scenario/scenario.hpp"

namespace tetcut::cli {
namespace {

namespace fs = std::filesystem;

constexpr std::uint64_t kDefaultMaxRuns = 2000;

std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

// "NAME:LINE: why" or "NAME: why" -> "why".
std::string message_of(const std::string& error, const std::string& name) {
  std::string m = error.rfind(name, 0) == 0 ? error.substr(name.size()) : error;
  if (!m.empty() && m[0] == ':') m.erase(0, 1);
  std::size_t i = 0;
  while (i < m.size() && std::isdigit(static_cast<unsigned char>(m[i]))) ++i;
  if (i > 0 && i < m.size() && m[i] == ':') m.erase(0, i + 1);
  while (!m.empty() && m[0] == ' ') m.erase(0, 1);
  return m;
}

// What must stay the same while shrinking: "invariant violated: I5", "expected tets",
// "cut failed", ...
std::string error_kind(const std::string& message) {
  for (const char* prefix : {"invariant violated at the end: ", "invariant violated: ", "check failed: "}) {
    const std::string p(prefix);
    if (message.rfind(p, 0) == 0) {
      const std::vector<std::string> w = words(message.substr(p.size()));
      return p + (w.empty() ? "" : w[0]);
    }
  }
  if (message.rfind("expected ", 0) == 0) {
    const std::vector<std::string> w = words(message);
    std::string what = w.size() > 1 && w[1] == "hash" ? "hash" : w.size() > 2 ? w[2] : "";
    while (!what.empty() && (what.back() == ',' || what.back() == ':')) what.pop_back();
    return "expected " + what;
  }
  return message.substr(0, message.find(':'));
}

struct Minimizer {
  std::string name, base_dir, kind;
  std::uint64_t runs = 0, max_runs = kDefaultMaxRuns;
  std::string last_error;

  // True iff the lines, as a scenario, fail with `kind`.
  bool fails(const std::vector<std::string>& lines) {
    if (runs >= max_runs) return false;
    ++runs;
    std::string text;
    for (const std::string& l : lines) text += l + "\n";
    const scenario::ParseResult parsed = scenario::parse(text, name, base_dir);
    if (!parsed.scenario) return false;
    const scenario::RunResult r = scenario::run(*parsed.scenario);
    if (r.exit_code != 1 || error_kind(message_of(r.error, name)) != kind) return false;
    last_error = r.error;
    return true;
  }

  // ddmin over the lines (1-minimal with respect to deleting single lines at the end).
  void delete_lines(std::vector<std::string>& lines) {
    scenario::delta_debug(lines, [this](const std::vector<std::string>& candidate) { return fails(candidate); },
                          [this] { return runs >= max_runs; });
  }

  // Replaces line i by the first of `options` that still fails.
  void try_replace(std::vector<std::string>& lines, std::size_t i, const std::vector<std::string>& options) {
    for (const std::string& o : options) {
      if (o == lines[i]) return;
      std::vector<std::string> candidate = lines;
      candidate[i] = o;
      if (fails(candidate)) {
        lines = std::move(candidate);
        return;
      }
    }
  }

  void simplify(std::vector<std::string>& lines) {
    for (std::size_t i = 0; i < lines.size() && runs < max_runs; ++i) {
      std::vector<std::string> w = words(lines[i]);
      if (w.size() == 4 && w[0] == "sweep") {
        try_replace(lines, i, {"cut " + w[1], "cut " + w[2]});
        w = words(lines[i]);
      }
      if ((w.size() == 2 && (w[0] == "cut" || w[0] == "remove")) || (w.size() == 4 && w[0] == "sweep")) {
        std::vector<std::string> options;
        for (int decimals = 0; decimals <= 3; ++decimals) {
          std::string line = w[0];
          for (std::size_t k = 1; k < w.size(); ++k) {
            line += ' ';  // appended apart: `" " + std::string&&` trips GCC 12's -Wrestrict (bug 105651)
            line += round_point(w[k], decimals, w[0] == "sweep" && k == 3);
          }
          options.push_back(line);
        }
        try_replace(lines, i, options);
      }
    }
  }

  // "X,Y,Z" (or a single number) with every number rounded to `decimals` places.
  static std::string round_point(const std::string& text, int decimals, bool positive) {
    std::string out;
    std::size_t begin = 0;
    while (true) {
      const std::size_t comma = text.find(',', begin);
      const std::string part = text.substr(begin, comma == std::string::npos ? std::string::npos : comma - begin);
      const auto v = scenario::parse_double(part);
      if (!v) return text;
      const double scale = std::pow(10.0, decimals);
      double r = std::round(*v * scale) / scale;
      if (positive && r <= 0) return text;
      if (r == 0) r = 0;  // no "-0"
      std::ostringstream s;
      s.precision(decimals);
      s << std::fixed << r;
      std::string number = s.str();
      if (number.find('.') != std::string::npos) {
        while (number.back() == '0') number.pop_back();
        if (number.back() == '.') number.pop_back();
      }
      out += (out.empty() ? "" : ",") + number;
      if (comma == std::string::npos) break;
      begin = comma + 1;
    }
    return out;
  }
};

std::string trim(const std::string& s) {
  const std::size_t b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const std::size_t e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

}  // namespace

int cmd_minimize(Args args, std::ostream& out, std::ostream& err) {
  std::optional<std::string> scenario_path, out_path;
  std::optional<std::uint64_t> max_runs;
  CommandParser parser(
      "minimize", "tetcut minimize SCENARIO -o OUT [--max-runs N]",
      "Shrinks a failing scenario (one `tetcut run` exits 1 on) while it keeps failing with the\n"
      "same kind of error (an invariant by its id, an expectation by its kind, a failed cut):\n"
      "deletes operations (ddmin: chunks, then single lines), turns sweeps into single cuts and\n"
      "rounds coordinates. Every candidate is a full run. Writes OUT atomically.\n",
      "exit: 0 written, 2 the scenario does not fail (or does not parse), unwritable OUT, or bad\n"
      "usage");
  CLI::App& app = parser.app();
  opt::text(app, "SCENARIO", scenario_path, "the failing scenario", "")->required();
  opt::text(app, "-o", out_path, "the minimized scenario (mesh paths relative to its folder)", "OUT")->required();
  opt::count(app, "--max-runs", max_runs, "stop after N runs of candidates (default 2000)");
  if (const auto code = parser.parse(args, out, err)) return *code;
  Minimizer m;
  if (max_runs) {
    if (*max_runs == 0) return parser.usage_error("--max-runs: must be positive", err);
    m.max_runs = *max_runs;
  }
  const std::string& path = *scenario_path;
  std::string text;
  if (const auto error = read_file(path, text)) {
    err << "tetcut: " << error->message() << "\n";
    return kExitBadInput;
  }
  const scenario::ParseResult original = scenario::parse_file(path);
  if (!original.scenario) {
    err << "tetcut: " << original.error << "\n";
    return kExitBadInput;
  }
  m.name = original.scenario->name;
  m.base_dir = original.scenario->base_dir;
  const scenario::RunResult first = scenario::run(*original.scenario);
  if (first.exit_code != 1) {
    err << "tetcut: " << path << ": "
        << (first.ok ? "passes: only a failing scenario (tetcut run exits 1) can be minimized"
                     : "does not run (" + first.error + "): only a failing scenario can be minimized")
        << "\n";
    return kExitBadInput;
  }
  m.kind = error_kind(message_of(first.error, m.name));
  m.last_error = first.error;

  // The operations: every non-empty line without its comment.
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    line = trim(line.substr(0, line.find('#')));
    if (!line.empty()) lines.push_back(line);
  }
  const std::size_t before = lines.size();
  m.delete_lines(lines);
  m.simplify(lines);
  m.delete_lines(lines);

  // Mesh paths as seen from OUT's folder.
  const fs::path out_dir = fs::absolute(fs::path(*out_path)).parent_path().lexically_normal();
  std::string result = "# minimized by tetcut minimize from " + path + " (" + std::to_string(before) + " -> " +
                       std::to_string(lines.size()) + " operations)\n# fails with: " + m.kind + "\n";
  for (std::string line : lines) {
    const std::vector<std::string> w = words(line);
    if (w.size() == 2 && w[0] == "mesh") {
      const fs::path mesh = w[1].front() == '/' ? fs::path(w[1]) : fs::absolute(fs::path(m.base_dir) / w[1]);
      line = "mesh " + scenario::mesh_path_from(mesh.string(), out_dir.string());
    }
    result += line + "\n";
  }
  const WriteResult w = write_file_atomically(*out_path, result);
  if (!w.ok) {
    err << "tetcut: " << w.error << "\n";
    return kExitBadInput;
  }
  out << before << " -> " << lines.size() << " operations in " << m.runs << " runs"
      << (m.runs >= m.max_runs ? " (stopped at --max-runs)" : "") << "; still fails: " << m.last_error << "\n";
  out << "wrote " << *out_path << "\n";
  return kExitOk;
}

}  // namespace tetcut::cli
