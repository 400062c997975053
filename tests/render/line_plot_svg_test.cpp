#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "svg_test_support.hpp"
#include "tetcut/render/line_plot_svg.hpp"

namespace tetcut::render {
namespace {

using testing::attribute;
using testing::elements;

std::vector<std::pair<double, double>> series_points(const std::string& svg) {
  std::vector<std::pair<double, double>> out;
  for (const std::string& p : elements(svg, "<polyline class=\"series\""))
    for (const auto& pt : testing::points(attribute(p, "points"))) out.push_back(pt);
  return out;
}

TEST(LinePlotSvg, IsOneSvgElementWithTheGivenIdAndEscapedTitle) {
  const std::vector<double> v = {1, 2, 3};
  const std::string svg = line_plot_svg(v, {.title = "latency <us> & cuts", .id = "latency"});
  EXPECT_TRUE(testing::is_svg_document(svg));
  EXPECT_NE(svg.find("id=\"latency\""), std::string::npos);
  EXPECT_NE(svg.find(">latency &lt;us&gt; &amp; cuts</text>"), std::string::npos);
}

TEST(LinePlotSvg, OnePointPerValueAtIncreasingX) {
  const std::vector<double> v = {3, 1, 4, 1, 5, 9, 2, 6};
  const auto pts = series_points(line_plot_svg(v));
  ASSERT_EQ(pts.size(), v.size());
  for (std::size_t i = 1; i < pts.size(); ++i) EXPECT_GT(pts[i].first, pts[i - 1].first);
}

TEST(LinePlotSvg, LargerValuesAreHigherOnALinearScale) {
  const std::vector<double> v = {1, 5, 2};
  const auto pts = series_points(line_plot_svg(v));
  ASSERT_EQ(pts.size(), 3u);
  EXPECT_LT(pts[1].second, pts[2].second);
  EXPECT_LT(pts[2].second, pts[0].second);
}

TEST(LinePlotSvg, ALogScaleIsHigherForLargerValuesAndEvenPerDecade) {
  const std::vector<double> v = {5, 50, 500};
  const std::string svg = line_plot_svg(v, {.log_y = true});
  const auto pts = series_points(svg);
  ASSERT_EQ(pts.size(), 3u);
  EXPECT_LT(pts[1].second, pts[0].second);
  EXPECT_LT(pts[2].second, pts[1].second);
  EXPECT_NEAR(pts[0].second - pts[1].second, pts[1].second - pts[2].second, 0.2) << "one decade, one step";
  // Decade ticks with round labels.
  EXPECT_NE(svg.find(">10</text>"), std::string::npos);
  EXPECT_NE(svg.find(">100</text>"), std::string::npos);
}

TEST(LinePlotSvg, ValuesThatCannotBeDrawnBreakTheLine) {
  const std::vector<double> v = {10, 0, 20, 30, std::numeric_limits<double>::quiet_NaN(), 40};
  const std::string svg = line_plot_svg(v, {.log_y = true});
  EXPECT_EQ(elements(svg, "<polyline class=\"series\"").size(), 3u);
  EXPECT_EQ(series_points(svg).size(), 4u);
  EXPECT_EQ(svg.find("nan"), std::string::npos);
}

TEST(LinePlotSvg, ReferenceLinesAreDashedAndLabelled) {
  const std::vector<double> v = {8, 12, 15, 90, 11};
  const LinePlotOptions options{.log_y = true, .reference_lines = {{"p50", 12.0}, {"p99", 85.5}}};
  const std::string svg = line_plot_svg(v, options);
  EXPECT_EQ(testing::count_of(svg, "stroke-dasharray"), 2u);
  EXPECT_NE(svg.find(">p50 12</text>"), std::string::npos);
  EXPECT_NE(svg.find(">p99 85.5</text>"), std::string::npos);
  // p99 is above p50.
  std::vector<double> ys;
  for (const std::string& t : elements(svg, "<text"))
    if (attribute(t, "class") == "reference") ys.push_back(testing::number_attribute(t, "y"));
  ASSERT_EQ(ys.size(), 2u);
  EXPECT_LT(ys[1], ys[0]);
}

TEST(LinePlotSvg, AllPointsLieInsideTheViewBox) {
  std::vector<double> v;
  for (int i = 0; i < 200; ++i) v.push_back(5.0 + 495.0 * std::fabs(std::sin(i * 0.37)));
  for (bool log_y : {false, true}) {
    for (const auto& [x, y] : series_points(line_plot_svg(v, {.width = 400, .height = 250, .log_y = log_y}))) {
      EXPECT_GE(x, 0.0);
      EXPECT_LE(x, 400.0);
      EXPECT_GE(y, 0.0);
      EXPECT_LE(y, 250.0);
    }
  }
}

TEST(LinePlotSvg, TheXAxisEndsAtTheLastCutAndLabelsWholeCutNumbers) {
  const std::vector<double> v(164, 10.0);
  const std::string svg = line_plot_svg(v);
  const auto pts = series_points(svg);
  ASSERT_EQ(pts.size(), 164u);
  // The last point is at the right end of the x axis line (the second frame line).
  const auto lines = elements(svg, "<line");
  double axis_right = 0.0;
  for (const std::string& l : lines) axis_right = std::max(axis_right, testing::number_attribute(l, "x2"));
  EXPECT_NEAR(pts.back().first, axis_right, 0.1);
  EXPECT_NE(svg.find(">150</text>"), std::string::npos);
  EXPECT_EQ(svg.find(">200</text>"), std::string::npos);
  const std::string single = line_plot_svg(std::vector<double>{3.0});
  EXPECT_EQ(single.find(">0.2</text>"), std::string::npos) << "no fractional cut numbers";
}

TEST(LinePlotSvg, TheSameInputGivesTheSameBytes) {
  const std::vector<double> v = {5.5, 7.25, 6.125};
  const LinePlotOptions options{.title = "t", .reference_lines = {{"p50", 6.1}}, .id = "a"};
  EXPECT_EQ(line_plot_svg(v, options), line_plot_svg(v, options));
}

TEST(LinePlotSvg, NoValuesIsStillAPicture) {
  const std::string svg = line_plot_svg({}, {.log_y = true});
  EXPECT_TRUE(testing::is_svg_document(svg));
  EXPECT_TRUE(series_points(svg).empty());
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_EQ(svg.find("inf"), std::string::npos);
}

}  // namespace
}  // namespace tetcut::render
