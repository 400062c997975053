#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "svg_test_support.hpp"
#include "tetcut/render/histogram_svg.hpp"

namespace tetcut::render {
namespace {

using testing::attribute;
using testing::elements;
using testing::number_attribute;

const std::vector<double> kRadiusRatioEdges = {0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0};

std::vector<std::string> bars(const std::string& svg) { return elements(svg, "<rect class=\"bar\""); }

TEST(HistogramSvg, OneBarPerBinPerSeriesAndOneLegendKeyPerSeries) {
  const std::vector<HistogramSeries> series = {
      {"before", "#3a6ea5", {0, 0, 1, 2, 5, 9, 20, 40, 30, 3}},
      {"after", "#e08a2c", {0, 1, 2, 3, 6, 10, 25, 45, 35, 4}},
  };
  const std::string svg = histogram_svg(kRadiusRatioEdges, series, {.id = "quality"});
  EXPECT_TRUE(testing::is_svg_document(svg));
  EXPECT_NE(svg.find("id=\"quality\""), std::string::npos);
  EXPECT_EQ(bars(svg).size(), 20u) << "zero counts included";
  EXPECT_EQ(elements(svg, "<rect class=\"key\"").size(), 2u);
  EXPECT_NE(svg.find(">before</text>"), std::string::npos);
  EXPECT_NE(svg.find(">after</text>"), std::string::npos);
}

TEST(HistogramSvg, BarHeightsAreProportionalToTheValues) {
  const std::vector<HistogramSeries> series = {{"s", "#000000", {1, 2, 4}}};
  const std::vector<double> edges = {0, 1, 2, 3};
  const auto b = bars(histogram_svg(edges, series));
  ASSERT_EQ(b.size(), 3u);
  const double h0 = number_attribute(b[0], "height");
  EXPECT_GT(h0, 0.0);
  EXPECT_NEAR(number_attribute(b[1], "height"), 2 * h0, 0.2);
  EXPECT_NEAR(number_attribute(b[2], "height"), 4 * h0, 0.3);
  // Bins left to right.
  EXPECT_LT(number_attribute(b[0], "x"), number_attribute(b[1], "x"));
  EXPECT_LT(number_attribute(b[1], "x"), number_attribute(b[2], "x"));
}

TEST(HistogramSvg, NormalisingMakesSeriesOfDifferentSizesComparable) {
  const std::vector<double> edges = {0, 1, 2};
  const std::vector<HistogramSeries> series = {{"small", "", {1, 3}}, {"large", "", {10, 30}}};
  // Bars go bin by bin, series by series: small[0], large[0], small[1], large[1].
  const auto raw = bars(histogram_svg(edges, series));
  ASSERT_EQ(raw.size(), 4u);
  EXPECT_GT(number_attribute(raw[3], "height"), 5 * number_attribute(raw[2], "height"));
  const std::string svg = histogram_svg(edges, series, {.normalise = true});
  const auto normalised = bars(svg);
  ASSERT_EQ(normalised.size(), 4u);
  EXPECT_EQ(attribute(normalised[0], "height"), attribute(normalised[1], "height"));
  EXPECT_EQ(attribute(normalised[2], "height"), attribute(normalised[3], "height"));
  EXPECT_NE(svg.find(">fraction</text>"), std::string::npos) << "the default y label says what is shown";
}

TEST(HistogramSvg, SeriesWithoutAValidColourGetDistinctPaletteColours) {
  const std::vector<double> edges = {0, 1};
  const std::vector<HistogramSeries> series = {{"a", "", {1}}, {"b", "blue", {1}}};
  const auto b = bars(histogram_svg(edges, series));
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(attribute(b[0], "fill").size(), 7u);
  EXPECT_NE(attribute(b[0], "fill"), attribute(b[1], "fill"));
}

TEST(HistogramSvg, NamesAndTitlesAreEscaped) {
  const std::vector<double> edges = {0, 1};
  const std::vector<HistogramSeries> series = {{"r < 0.1 & bad", "", {1}}};
  const std::string svg = histogram_svg(edges, series, {.title = "<quality>"});
  EXPECT_NE(svg.find(">r &lt; 0.1 &amp; bad</text>"), std::string::npos);
  EXPECT_NE(svg.find(">&lt;quality&gt;</text>"), std::string::npos);
  EXPECT_EQ(svg.find("<quality>"), std::string::npos);
}

TEST(HistogramSvg, MalformedInputIsReportedAndStillDrawn) {
  const std::vector<HistogramSeries> ok = {{"s", "", {1, 2}}};
  const std::vector<double> edges = {0, 1, 2};
  EXPECT_FALSE(validate_histogram(edges, ok).has_value());
  const std::vector<double> decreasing = {0, 2, 1};
  EXPECT_TRUE(validate_histogram(decreasing, ok).has_value());
  const std::vector<HistogramSeries> short_series = {{"s", "", {1}}};
  EXPECT_TRUE(validate_histogram(edges, short_series).has_value());
  const std::vector<HistogramSeries> negative = {{"s", "", {1, -2}}};
  EXPECT_TRUE(validate_histogram(edges, negative).has_value());
  // Missing values draw as empty bars; the count of bars follows the bins.
  const std::string svg = histogram_svg(decreasing, short_series);
  EXPECT_TRUE(testing::is_svg_document(svg));
  EXPECT_EQ(bars(svg).size(), 2u);
  EXPECT_EQ(svg.find("nan"), std::string::npos);
}

TEST(HistogramSvg, TheSameInputGivesTheSameBytes) {
  const std::vector<HistogramSeries> series = {{"s", "#112233", {0.5, 0.25, 0.25}}};
  const std::vector<double> edges = {0, 0.5, 0.75, 1};
  EXPECT_EQ(histogram_svg(edges, series, {.title = "q", .normalise = true}),
            histogram_svg(edges, series, {.title = "q", .normalise = true}));
}

}  // namespace
}  // namespace tetcut::render
