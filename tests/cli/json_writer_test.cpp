// The JSON writer: deterministic layout, exact doubles, escaped strings, always valid JSON.
#include "json_writer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>

#include "detail/random.hpp"

namespace tetcut::cli {
namespace {

TEST(JsonWriter, WritesKeysInTheOrderGivenWithAStableLayout) {
  std::ostringstream os;
  JsonWriter json(os);
  json.begin_object();
  json.field("zeta", 1);
  json.field("alpha", true);
  json.key("list");
  json.begin_array();
  json.value(std::uint64_t{1});
  json.value(std::int64_t{-2});
  json.value("x");
  json.end_array();
  json.key("objects");
  json.begin_array();
  json.begin_object();
  json.field("id", "I5");
  json.end_object();
  json.end_array();
  json.key("empty");
  json.begin_object();
  json.end_object();
  json.key("none");
  json.begin_array();
  json.end_array();
  json.key("nothing");
  json.null();
  json.end_object();
  json.finish();
  EXPECT_EQ(os.str(),
            "{\n"
            "  \"zeta\": 1,\n"
            "  \"alpha\": true,\n"
            "  \"list\": [1, -2, \"x\"],\n"
            "  \"objects\": [\n"
            "    {\n"
            "      \"id\": \"I5\"\n"
            "    }\n"
            "  ],\n"
            "  \"empty\": {},\n"
            "  \"none\": [],\n"
            "  \"nothing\": null\n"
            "}\n");
}

TEST(JsonNumber, IsShortestAndReadsBackToTheSameBits) {
  EXPECT_EQ(json_number(1.0), "1");
  EXPECT_EQ(json_number(0.1), "0.1");
  EXPECT_EQ(json_number(-2.5), "-2.5");
  SplitMix64 rng(12345);
  for (int i = 0; i < 2000; ++i) {
    // Random bit patterns cover subnormals, huge and tiny exponents alike.
    std::uint64_t bits = rng.next();
    double d = 0.0;
    static_assert(sizeof d == sizeof bits);
    std::memcpy(&d, &bits, sizeof d);
    if (!std::isfinite(d)) continue;
    const std::string s = json_number(d);
    EXPECT_EQ(std::strtod(s.c_str(), nullptr), d) << s;
  }
  EXPECT_EQ(std::strtod(json_number(1.0 / 3.0).c_str(), nullptr), 1.0 / 3.0);
}

TEST(JsonNumber, NonFiniteBecomesNull) {
  EXPECT_EQ(json_number(std::numeric_limits<double>::quiet_NaN()), "null");
  EXPECT_EQ(json_number(std::numeric_limits<double>::infinity()), "null");
  EXPECT_EQ(json_number(-std::numeric_limits<double>::infinity()), "null");
}

TEST(JsonQuote, EscapesQuotesBackslashesAndControlCharacters) {
  EXPECT_EQ(json_quote("plain"), "\"plain\"");
  EXPECT_EQ(json_quote("a\"b\\c"), "\"a\\\"b\\\\c\"");
  EXPECT_EQ(json_quote("l1\nl2\tx\r"), "\"l1\\nl2\\tx\\r\"");
  EXPECT_EQ(json_quote(std::string("\x01\x1f\x7f", 3)), "\"\\u0001\\u001f\\u007f\"");
  EXPECT_EQ(json_quote(std::string("a\0b", 3)), "\"a\\u0000b\"");
}

TEST(JsonQuote, KeepsValidUtf8AndReplacesInvalidBytes) {
  EXPECT_EQ(json_quote("foie \xc3\xa9 \xe2\x82\xac \xf0\x9f\x98\x80"),
            "\"foie \xc3\xa9 \xe2\x82\xac \xf0\x9f\x98\x80\"");
  EXPECT_EQ(json_quote("\xff"), "\"\\ufffd\"");
  EXPECT_EQ(json_quote("\xc3"), "\"\\ufffd\"");              // truncated sequence
  EXPECT_EQ(json_quote("\xc0\xaf"), "\"\\ufffd\\ufffd\"");   // overlong '/'
  EXPECT_EQ(json_quote("\xed\xa0\x80"), "\"\\ufffd\\ufffd\\ufffd\"");  // surrogate
}

}  // namespace
}  // namespace tetcut::cli
