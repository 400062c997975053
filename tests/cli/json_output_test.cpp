// The command line's JSON (json_output.hpp, nlohmann-json): keys in the order written, doubles
// that read back to the same bits, non-finite values as null, always valid JSON.
#include "json_output.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>

#include "core/random.hpp"

namespace tetcut::cli {
namespace {

// The double a JSON text holds, as a reader (nlohmann's, strtod-exact) gets it back.
double read_back(const Json& value) { return nlohmann::json::parse(json_text(value)).get<double>(); }

bool same_bits(double a, double b) {
  std::uint64_t x = 0, y = 0;
  std::memcpy(&x, &a, sizeof a);
  std::memcpy(&y, &b, sizeof b);
  return x == y;
}

TEST(JsonOutput, KeepsKeysInTheOrderTheyWereSet) {
  Json j;
  j["zeta"] = 1;
  j["alpha"] = true;
  j["mid"] = Json::array({1, -2, "x"});
  EXPECT_EQ(json_text(j), "{\n  \"zeta\": 1,\n  \"alpha\": true,\n  \"mid\": [\n    1,\n    -2,\n    \"x\"\n  ]\n}\n");
}

TEST(JsonOutput, AwkwardDoublesReadBackToTheSameBits) {
  const double awkward[] = {0.1, 1.0 / 3.0, 1e-300, 5e-324, 2.2250738585072014e-308, 1.7976931348623157e308,
                            -0.0, 123456789.123456789, 9007199254740993.0, 0.30000000000000004};
  for (const double d : awkward) EXPECT_TRUE(same_bits(read_back(Json(d)), d)) << json_text(Json(d));
  EXPECT_EQ(json_text(Json(0.1)), "0.1\n") << "shortest form";
  EXPECT_EQ(json_text(Json(5e-324)), "5e-324\n") << "shortest form";
  SplitMix64 rng(12345);
  for (int i = 0; i < 5000; ++i) {
    // Random bit patterns cover subnormals, huge and tiny exponents alike.
    const std::uint64_t bits = rng.next();
    double d = 0.0;
    std::memcpy(&d, &bits, sizeof d);
    if (!std::isfinite(d)) continue;
    ASSERT_TRUE(same_bits(read_back(Json(d)), d)) << json_text(Json(d));
  }
}

// JSON has no NaN or infinity: null, as tetcut always wrote them (documented in json_output.hpp).
TEST(JsonOutput, NonFiniteDoublesBecomeNull) {
  for (const double d : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                         -std::numeric_limits<double>::infinity()})
    EXPECT_EQ(json_text(Json{{"x", d}}), "{\n  \"x\": null\n}\n");
  EXPECT_EQ(json_text(number_or_null(2.5, false)), "null\n");
  EXPECT_EQ(json_text(number_or_null(2.5, true)), "2.5\n");
}

TEST(JsonOutput, EscapesControlCharactersAndReplacesInvalidUtf8) {
  const std::string odd = std::string("a\"b\\c\n\t\x01 \xc3\xa9 ") + "\xff" + "\xc3";
  const std::string text = json_text(Json(odd));
  const auto back = nlohmann::json::parse(text, nullptr, false);
  ASSERT_FALSE(back.is_discarded()) << text;
  EXPECT_EQ(back.get<std::string>(), "a\"b\\c\n\t\x01 \xc3\xa9 \xef\xbf\xbd\xef\xbf\xbd");
  EXPECT_NE(text.find("\\u0001"), std::string::npos) << text;
}

TEST(JsonOutput, WritesAFileThroughARenameAndSaysWhenItCannot) {
  std::ostringstream err;
  EXPECT_FALSE(write_json_file("/nonexistent-dir/x.json", Json{{"a", 1}}, err));
  EXPECT_TRUE(err.str().starts_with("tetcut: ")) << err.str();
  EXPECT_EQ(err.str().find('\n'), err.str().size() - 1) << "one line";
}

}  // namespace
}  // namespace tetcut::cli
