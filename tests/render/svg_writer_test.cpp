#include <gtest/gtest.h>

#include <limits>

#include "svg_test_support.hpp"
#include "tetcut/render/colour.hpp"
#include "tetcut/render/svg_writer.hpp"

namespace tetcut::render {
namespace {

TEST(SvgText, EscapesEveryCharacterWithAMeaningInXml) {
  EXPECT_EQ(xml_escape("a < b & c > \"d\" 'e'"), "a &lt; b &amp; c &gt; &quot;d&quot; &#39;e&#39;");
  EXPECT_EQ(xml_escape("plain"), "plain");
}

TEST(SvgText, FixedFormatHasExactlyTheDecimalsAskedAndNoNegativeZero) {
  EXPECT_EQ(format_fixed(12.345, 1), "12.3");
  EXPECT_EQ(format_fixed(-3.0, 2), "-3.00");
  EXPECT_EQ(format_fixed(-0.04, 1), "0.0");
  EXPECT_EQ(format_fixed(std::numeric_limits<double>::quiet_NaN(), 1), "0");
}

TEST(SvgText, SignificantFormatKeepsThreeDigitsWithoutExponentOrTrailingZeros) {
  EXPECT_EQ(format_significant(12.345), "12.3");
  EXPECT_EQ(format_significant(0.05), "0.05");
  EXPECT_EQ(format_significant(1200.0), "1200");
  EXPECT_EQ(format_significant(0.000123), "0.000123");
  EXPECT_EQ(format_significant(500.0), "500");
  EXPECT_EQ(format_significant(0.0), "0");
  EXPECT_EQ(format_significant(-2.5), "-2.5");
}

TEST(SvgText, WriterProducesOneSvgElementWithIdAndEscapedTitle) {
  SvgWriter svg(100, 50, "my-id", "x < y");
  svg.text(1, 2, "a & b");
  const std::string out = svg.finish();
  EXPECT_TRUE(testing::is_svg_document(out)) << out;
  EXPECT_NE(out.find("id=\"my-id\""), std::string::npos);
  EXPECT_NE(out.find("viewBox=\"0 0 100 50\""), std::string::npos);
  EXPECT_NE(out.find("<title>x &lt; y</title>"), std::string::npos);
  EXPECT_NE(out.find(">a &amp; b</text>"), std::string::npos);
}

TEST(Colour, ParsesOnlyHashAndSixHexDigits) {
  EXPECT_EQ(parse_colour("#C0705a"), (Rgb{0xc0, 0x70, 0x5a}));
  EXPECT_FALSE(parse_colour("c0705a"));
  EXPECT_FALSE(parse_colour("#c0705"));
  EXPECT_FALSE(parse_colour("#c0705g"));
  EXPECT_FALSE(parse_colour("red"));
  EXPECT_EQ(to_hex({0xc0, 0x70, 0x5a}), "#c0705a");
}

TEST(Colour, ScalingRoundsAndClamps) {
  EXPECT_EQ(scaled({100, 200, 0}, 0.5), (Rgb{50, 100, 0}));
  EXPECT_EQ(scaled({100, 200, 10}, 2.0), (Rgb{200, 255, 20}));
}

}  // namespace
}  // namespace tetcut::render
