#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

#include "svg_test_support.hpp"
#include "tetcut/box_mesh.hpp"
#include "tetcut/mesh_builder.hpp"
#include "tetcut/render/surface.hpp"
#include "tetcut/render/surface_svg.hpp"

namespace tetcut::render {
namespace {

using testing::attribute;
using testing::elements;

std::vector<SurfaceTriangle> box_surface(std::uint32_t n) {
  BuildResult r = build_mesh(make_box_mesh(n, n, n));
  EXPECT_TRUE(r.ok());
  return boundary_surface(*r.mesh);
}

// A triangle in the plane x = depth, facing +x (towards a viewer at azimuth 0, elevation 0).
SurfaceTriangle facing_plus_x(double depth, bool cut) {
  return {{depth, 0, 0}, {depth, 1, 0}, {depth, 0, 1}, cut};
}

TEST(SurfaceSvg, IsOneSvgElementWithTheGivenId) {
  const std::string svg = surface_svg(box_surface(2), {.id = "liver-before"});
  EXPECT_TRUE(testing::is_svg_document(svg));
  EXPECT_NE(svg.find("id=\"liver-before\""), std::string::npos);
  EXPECT_EQ(svg.find("<script"), std::string::npos);
  EXPECT_EQ(svg.find("href"), std::string::npos) << "no external references";
}

TEST(SurfaceSvg, DrawsExactlyTheFrontFacingTriangles) {
  // From azimuth 30, elevation 20 a box shows its +x, +y and +z sides: 8 triangles each on a
  // 2 x 2 x 2 box; the other 24 face away.
  const std::string svg = surface_svg(box_surface(2), {.azimuth_deg = 30, .elevation_deg = 20});
  EXPECT_EQ(elements(svg, "<polygon").size(), 24u);
  // From below and behind, the -x, -y and -z sides: as many.
  const std::string other = surface_svg(box_surface(2), {.azimuth_deg = 210, .elevation_deg = -20});
  EXPECT_EQ(elements(other, "<polygon").size(), 24u);
  EXPECT_NE(svg, other);
}

TEST(SurfaceSvg, AllCoordinatesLieInTheViewBoxWithOneDecimal) {
  const SurfaceView view{.azimuth_deg = 75, .elevation_deg = 40, .width = 300, .height = 200, .title = "box"};
  const std::string svg = surface_svg(box_surface(3), view);
  const auto polygons = elements(svg, "<polygon");
  ASSERT_FALSE(polygons.empty());
  for (const std::string& p : polygons) {
    const std::string list = attribute(p, "points");
    const auto pts = testing::points(list);
    ASSERT_EQ(pts.size(), 3u) << p;
    for (const auto& [x, y] : pts) {
      EXPECT_GE(x, 0.0);
      EXPECT_LE(x, 300.0);
      EXPECT_GE(y, 0.0);
      EXPECT_LE(y, 200.0);
    }
    for (std::size_t dot = list.find('.'); dot != std::string::npos; dot = list.find('.', dot + 1))
      EXPECT_TRUE(dot + 2 == list.size() || list[dot + 2] == ',' || list[dot + 2] == ' ') << list;
  }
}

TEST(SurfaceSvg, TheSameInputGivesTheSameBytes) {
  const auto surface = box_surface(3);
  EXPECT_EQ(surface_svg(surface, {.title = "t", .id = "x"}), surface_svg(surface, {.title = "t", .id = "x"}));
}

TEST(SurfaceSvg, CutTrianglesUseTheCutColourAndOthersTheBaseColour) {
  const std::vector<SurfaceTriangle> tris = {facing_plus_x(0.0, false), {{0, 2, 0}, {0, 3, 0}, {0, 2, 1}, true}};
  const std::string svg =
      surface_svg(tris, {.azimuth_deg = 0, .elevation_deg = 0, .base_colour = "#0000ff", .cut_colour = "#ff0000"});
  const auto polygons = elements(svg, "<polygon");
  ASSERT_EQ(polygons.size(), 2u);
  const std::string base_fill = attribute(polygons[0], "color"), cut_fill = attribute(polygons[1], "color");
  // Shaded, so not the exact colour, but the hue is the given one's.
  EXPECT_EQ(base_fill.substr(0, 5), "#0000");
  EXPECT_NE(base_fill, "#000000");
  EXPECT_EQ(cut_fill.substr(3), "0000");
  EXPECT_NE(cut_fill, "#000000");
}

TEST(SurfaceSvg, NearerTrianglesArePaintedAfterFartherOnes) {
  // The viewer at azimuth 0 looks along -x: the triangle at x = 1 is nearer than the one at 0.
  const SurfaceTriangle near = facing_plus_x(1.0, true), far = facing_plus_x(0.0, false);
  const SurfaceView view{.azimuth_deg = 0, .elevation_deg = 0, .base_colour = "#0000ff", .cut_colour = "#ff0000"};
  for (const auto& tris : {std::vector{near, far}, std::vector{far, near}}) {
    const auto polygons = elements(surface_svg(tris, view), "<polygon");
    ASSERT_EQ(polygons.size(), 2u);
    EXPECT_EQ(attribute(polygons[0], "color").substr(0, 5), "#0000") << "the far (base) one first";
    EXPECT_EQ(attribute(polygons[1], "color").substr(3), "0000") << "the near (cut) one last";
  }
}

TEST(SurfaceSvg, FacesTurnedToTheLightAreBrighter) {
  // Seen from the front (azimuth 0: screen right is +y, up is +z), the light comes from the
  // viewer's upper left: a face turned up-left, normal (1, -1, 1), is brighter than one turned
  // down-right, normal (1, 1, -1), both facing the viewer and the same colour otherwise.
  const SurfaceTriangle up_left = {{0, 0, 0}, {1, 1, 0}, {-1, 1, 2}, false};
  const SurfaceTriangle down_right = {{0, 0, 0}, {1, -1, 0}, {-1, -1, -2}, false};
  const SurfaceView view{.azimuth_deg = 0, .elevation_deg = 0, .base_colour = "#808080"};
  const auto lit = elements(surface_svg(std::vector{up_left}, view), "<polygon");
  const auto dark = elements(surface_svg(std::vector{down_right}, view), "<polygon");
  ASSERT_EQ(lit.size(), 1u);
  ASSERT_EQ(dark.size(), 1u);
  const auto red = [](const std::string& p) { return std::stoi(attribute(p, "color").substr(1, 2), nullptr, 16); };
  EXPECT_GT(red(lit[0]), red(dark[0]));
}

TEST(SurfaceSvg, TitleIsDrawnAndEscaped) {
  const std::string svg = surface_svg(box_surface(1), {.title = "liver <after> & more"});
  EXPECT_NE(svg.find(">liver &lt;after&gt; &amp; more</text>"), std::string::npos);
  EXPECT_EQ(svg.find("<after>"), std::string::npos);
}

TEST(SurfaceSvg, PaintIsSetOnceAndEachPolygonCarriesOnlyItsColour) {
  const std::string svg = surface_svg(box_surface(2));
  EXPECT_EQ(testing::count_of(svg, "stroke="), 1u);
  EXPECT_EQ(testing::count_of(svg, "fill="), 1u);
  for (const std::string& p : elements(svg, "<polygon")) {
    EXPECT_EQ(attribute(p, "color").size(), 7u) << p;
    EXPECT_EQ(attribute(p, "fill"), "") << p;
  }
}

TEST(SurfaceSvg, ASurfaceOfThousandsOfTrianglesStaysCompact) {
  // 4800 boundary faces, about as many as a 16k-tet liver has: well under 400 kB.
  const std::string svg = surface_svg(box_surface(20), {.title = "big"});
  EXPECT_EQ(elements(svg, "<polygon").size(), 3u * 800);
  EXPECT_LT(svg.size(), 400'000u);
}

TEST(SurfaceSvg, NothingToDrawIsStillAPicture) {
  const std::string svg = surface_svg({}, {.id = "empty"});
  EXPECT_TRUE(testing::is_svg_document(svg));
  EXPECT_EQ(elements(svg, "<polygon").size(), 0u);
  EXPECT_EQ(svg.find("nan"), std::string::npos);
}

TEST(SurfaceSvg, InvalidViewsAreReportedAndDrawnWithDefaults) {
  EXPECT_FALSE(validate(SurfaceView{}).has_value());
  EXPECT_TRUE(validate(SurfaceView{.width = 0}).has_value());
  EXPECT_TRUE(validate(SurfaceView{.base_colour = "tomato"}).has_value());
  EXPECT_TRUE(validate(SurfaceView{.azimuth_deg = std::numeric_limits<double>::infinity()}).has_value());
  const std::string svg = surface_svg(box_surface(1), {.width = -5, .base_colour = "tomato"});
  EXPECT_NE(svg.find("viewBox=\"0 0 480 360\""), std::string::npos);
}

}  // namespace
}  // namespace tetcut::render
