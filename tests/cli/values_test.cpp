// The values a person writes in a scenario or on the command line (tetcut/scenario/values.hpp):
// strict numbers, points and the shared vocabulary of strategy, split method and check mode.
#include "tetcut/scenario/values.hpp"

#include <gtest/gtest.h>


namespace tetcut::scenario {
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

TEST(ParseChoices, EachValueOfTheSharedVocabularyReadsBackFromItsName) {
  for (const SplitMethod m : {SplitMethod::kTemplates, SplitMethod::kBisection})
    EXPECT_EQ(parse_split_method(to_string(m)), m);
  for (const CheckMode m : {CheckMode::kEvery, CheckMode::kEnd, CheckMode::kNone}) EXPECT_EQ(parse_check_mode(to_string(m)), m);
  for (const auto l : {invariants::CheckLevel::kLocal, invariants::CheckLevel::kFull, invariants::CheckLevel::kExact})
    EXPECT_EQ(parse_check_level(to_string(l)), l);
  EXPECT_EQ(parse_strategy("wide"), RemovalStrategy::kWide);
  for (const char* bad : {"", "Every", "all", "templates ", "full,", "fast"}) {
    EXPECT_FALSE(parse_split_method(bad).has_value()) << bad;
    EXPECT_FALSE(parse_check_mode(bad).has_value()) << bad;
    EXPECT_FALSE(parse_check_level(bad).has_value()) << bad;
    EXPECT_FALSE(parse_strategy(bad).has_value()) << bad;
  }
}

}  // namespace
}  // namespace tetcut::scenario
