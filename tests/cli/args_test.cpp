// The command line's argument parsing: strict numbers and well-defined options.
#include "args.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace tetcut::cli {
namespace {

TEST(ParseDouble, AcceptsWholeFiniteNumbers) {
  EXPECT_EQ(parse_double("1.5"), 1.5);
  EXPECT_EQ(parse_double("-2"), -2.0);
  EXPECT_EQ(parse_double("+0.25"), 0.25);
  EXPECT_EQ(parse_double("1e-3"), 1e-3);
  EXPECT_EQ(parse_double("0"), 0.0);
}

TEST(ParseDouble, RefusesTrailingGarbageSpacesAndEmptiness) {
  for (const char* bad : {"", " 1", "1 ", "1.5x", "1,5", "--1", "+-1", "++1", "+", "-", "e5",
                          "0x10", "1e", "1..2"}) {
    EXPECT_FALSE(parse_double(bad).has_value()) << '"' << bad << '"';
  }
}

TEST(ParseDouble, RefusesNonFiniteValuesAndOverflow) {
  for (const char* bad : {"nan", "NaN", "inf", "-inf", "infinity", "1e999", "-1e400"}) {
    EXPECT_FALSE(parse_double(bad).has_value()) << bad;
  }
}

TEST(ParseUint, AcceptsDigitsOnlyWithin64Bits) {
  EXPECT_EQ(parse_uint("0"), 0u);
  EXPECT_EQ(parse_uint("42"), 42u);
  EXPECT_EQ(parse_uint("18446744073709551615"), 18446744073709551615ull);
  for (const char* bad : {"", "-1", "+1", "1.0", "1e3", " 1", "1 ", "18446744073709551616", "x"}) {
    EXPECT_FALSE(parse_uint(bad).has_value()) << '"' << bad << '"';
  }
}

TEST(ParseVec3, ReadsThreeCommaSeparatedNumbers) {
  const auto v = parse_vec3("1,-2.5,3e1");
  ASSERT_TRUE(v.has_value());
  EXPECT_EQ(*v, (Vec3{1.0, -2.5, 30.0}));
  for (const char* bad : {"", "1,2", "1,2,3,4", "1,,3", "1,2,", ",1,2", "1,2,nan", "1, 2,3"}) {
    EXPECT_FALSE(parse_vec3(bad).has_value()) << '"' << bad << '"';
  }
}

constexpr OptionSpec kSpecs[] = {{"--level", true}, {"--json", false}, {"-o", true}};

ArgParseResult parse(std::vector<std::string> args) { return parse_args(args, kSpecs); }

TEST(ParseArgs, SeparatesOptionsFromPositionalsInOrder) {
  const auto r = parse({"a.msh", "--level", "exact", "--json", "b.msh"});
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.args.positionals, (std::vector<std::string>{"a.msh", "b.msh"}));
  EXPECT_EQ(r.args.value("--level"), "exact");
  EXPECT_TRUE(r.args.has("--json"));
  EXPECT_EQ(r.args.value("--json"), "");
  EXPECT_FALSE(r.args.has("-o"));
}

TEST(ParseArgs, AcceptsEqualsFormAndShortOptions) {
  const auto r = parse({"--level=local", "-o", "out.msh"});
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.args.value("--level"), "local");
  EXPECT_EQ(r.args.value("-o"), "out.msh");
  EXPECT_TRUE(r.args.positionals.empty());
}

TEST(ParseArgs, DoubleDashEndsOptionsAndLoneDashIsPositional) {
  const auto r = parse({"--", "--json", "-"});
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.args.positionals, (std::vector<std::string>{"--json", "-"}));
  EXPECT_FALSE(r.args.has("--json"));
}

TEST(ParseArgs, NegativeNumbersArePositionalsNotOptions) {
  const auto r = parse({"-1.5", "-3"});
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.args.positionals, (std::vector<std::string>{"-1.5", "-3"}));
}

TEST(ParseArgs, RefusesUnknownOptionNamingIt) {
  const auto r = parse({"a.msh", "--levle", "full"});
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.error.find("'--levle'"), std::string::npos) << r.error;
}

TEST(ParseArgs, RefusesMissingValueValueOnFlagAndRepetition) {
  EXPECT_FALSE(parse({"--level"}).ok());
  EXPECT_FALSE(parse({"--json=yes"}).ok());
  EXPECT_FALSE(parse({"--json", "--json"}).ok());
  EXPECT_FALSE(parse({"--level", "full", "--level=exact"}).ok());
}

TEST(ParseArgs, EmptyValueWithEqualsIsKeptForTheCommandToJudge) {
  const auto r = parse({"--level="});
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.args.value("--level"), "");
}

}  // namespace
}  // namespace tetcut::cli
