// One command's parser (command_parser.hpp): CLI11 for the options, our strict parsers for
// the values, one line and the usage for every refusal, the help listing every option.
#include "command_parser.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

namespace tetcut::cli {
namespace {

struct Parsed {
  std::optional<int> code;
  std::string out, err;
  std::optional<std::string> mesh;
  std::optional<double> diameter;
  std::optional<std::uint64_t> depth;
  std::optional<Vec3> from;
  std::optional<RemovalStrategy> strategy;
  std::optional<scenario::CheckMode> check;
  bool json = false;
};

Parsed parse(const std::vector<std::string>& args) {
  Parsed p;
  CommandParser parser("demo", "tetcut demo MESH [--diameter D] [--json]", "A command for the tests.\n", "exit: 0");
  CLI::App& app = parser.app();
  opt::text(app, "MESH", p.mesh, "the mesh", "")->required();
  opt::number(app, "--diameter", p.diameter, "the tool's diameter", "D");
  opt::count(app, "--depth", p.depth, "a depth");
  opt::point(app, "--from", p.from, "a point");
  opt::strategy(app, "--strategy", p.strategy, "removal strategy");
  opt::check_mode(app, p.check, "when to check");
  opt::flag(app, "--json", p.json, "as JSON");
  std::ostringstream out, err;
  p.code = parser.parse(args, out, err);
  p.out = out.str();
  p.err = err.str();
  return p;
}

// "tetcut demo: ..." naming `what`, then the usage line: two lines, exit 2.
::testing::AssertionResult refused(const std::vector<std::string>& args, const std::string& what) {
  std::string joined;
  for (const auto& a : args) joined += a + " ";
  const Parsed p = parse(args);
  auto failure = [&](const std::string& why) { return ::testing::AssertionFailure() << joined << ": " << why << "\n" << p.err; };
  if (p.code != 2) return failure("exit code not 2");
  if (!p.err.starts_with("tetcut demo: ")) return failure("not prefixed with the command");
  if (p.err.find(what) == std::string::npos) return failure("does not name '" + what + "'");
  if (p.err.find("\nusage: tetcut demo MESH") == std::string::npos) return failure("no usage line");
  if (std::count(p.err.begin(), p.err.end(), '\n') != 2) return failure("not one line and the usage");
  if (!p.out.empty()) return failure("wrote to stdout");
  return ::testing::AssertionSuccess();
}

TEST(CommandParser, ReadsOptionsBothWaysAndNegativeNumbersAsValues) {
  const Parsed p = parse({"m.msh", "--diameter", "-0.5", "--depth=12", "--from", "-1,+2,3e-1", "--strategy", "wide",
                          "--check", "end", "--json"});
  ASSERT_FALSE(p.code.has_value()) << p.err;
  EXPECT_EQ(p.mesh, "m.msh");
  EXPECT_EQ(p.diameter, -0.5);
  EXPECT_EQ(p.depth, 12u);
  EXPECT_EQ(p.from, (Vec3{-1.0, 2.0, 0.3}));
  EXPECT_EQ(p.strategy, RemovalStrategy::kWide);
  EXPECT_EQ(p.check, scenario::CheckMode::kEnd);
  EXPECT_TRUE(p.json);
  const Parsed q = parse({"m.msh"});
  ASSERT_FALSE(q.code.has_value()) << q.err;
  EXPECT_FALSE(q.diameter.has_value()) << "absent stays absent";
}

TEST(CommandParser, DoubleDashEndsTheOptions) {
  const Parsed p = parse({"--", "--json"});
  ASSERT_FALSE(p.code.has_value()) << p.err;
  EXPECT_EQ(p.mesh, "--json");
  EXPECT_FALSE(p.json);
}

TEST(CommandParser, RefusesNumbersCli11WouldAcceptWithOneLine) {
  for (const char* bad : {"1e3x", "nan", "inf", "-inf", "", " 1", "1 ", "0x10", "1e999", "1,5", "++1"})
    EXPECT_TRUE(refused({"m.msh", "--diameter", bad}, std::string("--diameter: expects a finite number, not '") + bad + "'"));
  for (const char* bad : {"-1", "1.0", "18446744073709551616", "x", ""})
    EXPECT_TRUE(refused({"m.msh", "--depth", bad}, "--depth: expects a non-negative integer"));
  for (const char* bad : {"1,2", "1,2,nan", "1,,3"}) EXPECT_TRUE(refused({"m.msh", "--from", bad}, "--from: expects X,Y,Z"));
  EXPECT_TRUE(refused({"m.msh", "--strategy", "fast"}, "--strategy: must be basic, neighbours, combined or wide, not 'fast'"));
  EXPECT_TRUE(refused({"m.msh", "--check", "always"}, "--check: must be every, end or none, not 'always'"));
}

TEST(CommandParser, RefusesUnknownOptionsMissingValuesRepetitionAndExtras) {
  EXPECT_TRUE(refused({"m.msh", "--diamter", "1"}, "--diamter"));
  EXPECT_TRUE(refused({"m.msh", "--diameter"}, "--diameter"));
  EXPECT_TRUE(refused({"m.msh", "--diameter", "1", "--diameter=2"}, "--diameter"));
  EXPECT_TRUE(refused({"m.msh", "--json", "--json"}, "--json"));
  EXPECT_TRUE(refused({"m.msh", "--json=yes"}, "json"));
  EXPECT_TRUE(refused({"m.msh", "n.msh"}, "n.msh"));
  EXPECT_TRUE(refused({}, "MESH"));
  EXPECT_TRUE(refused({"m.msh", "--diameter", "a\nb"}, "--diameter"));  // a newline in a value stays on its line
}

TEST(CommandParser, HelpListsEveryOptionOnStdoutAndExitsZero) {
  for (const std::vector<std::string>& args : {std::vector<std::string>{"--help"}, {"m.msh", "-h"}}) {
    const Parsed p = parse(args);
    ASSERT_EQ(p.code, 0);
    EXPECT_TRUE(p.err.empty());
    EXPECT_TRUE(p.out.starts_with("usage: tetcut demo MESH")) << p.out;
    EXPECT_NE(p.out.find("A command for the tests."), std::string::npos) << p.out;
    for (const char* option : {"--diameter D", "--depth N", "--from X,Y,Z", "--strategy basic|neighbours|combined|wide",
                               "--check every|end|none", "--json", "the tool's diameter", "exit: 0"})
      EXPECT_NE(p.out.find(option), std::string::npos) << option << "\n" << p.out;
  }
}

}  // namespace
}  // namespace tetcut::cli
