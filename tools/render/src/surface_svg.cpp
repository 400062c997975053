#include "tetcut/render/surface_svg.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "tetcut/render/colour.hpp"
#include "tetcut/render/svg_writer.hpp"

namespace tetcut::render {
namespace {

constexpr int kMinSize = 16, kMaxSize = 8192;
constexpr double kMargin = 8.0;       // pixels around the picture
constexpr double kTitleHeight = 22.0;  // band above the picture when there is a title
// Shading: a third ambient so faces turned from the light still read as surface.
constexpr double kAmbient = 0.35, kDiffuse = 0.75;

bool size_ok(int s) { return s >= kMinSize && s <= kMaxSize; }

// Orthonormal camera frame: `eye` points from the scene towards the viewer, `right` and `up`
// span the screen (right x up = eye, so outward CCW triangles facing the viewer stay CCW).
struct Camera {
  Vec3 eye, right, up;
};

Camera camera(double azimuth_deg, double elevation_deg) {
  const double az = azimuth_deg * std::numbers::pi / 180.0, el = elevation_deg * std::numbers::pi / 180.0;
  Camera c;
  c.eye = {std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)};
  c.right = {-std::sin(az), std::cos(az), 0.0};
  c.up = cross(c.eye, c.right);
  return c;
}

Vec3 normalised(const Vec3& v) {
  const double n = norm(v);
  return n > 0.0 ? (1.0 / n) * v : v;
}

struct Drawn {
  double depth;  // along eye: larger is nearer
  std::uint32_t index;
  Rgb colour;
};

}  // namespace

std::optional<std::string> validate(const SurfaceView& view) {
  if (!size_ok(view.width) || !size_ok(view.height))
    return "surface picture size must be between 16 and 8192 pixels each way";
  if (!std::isfinite(view.azimuth_deg) || !std::isfinite(view.elevation_deg))
    return "surface view angles must be finite";
  if (!parse_colour(view.base_colour)) return "base colour '" + view.base_colour + "' is not #rrggbb";
  if (!parse_colour(view.cut_colour)) return "cut colour '" + view.cut_colour + "' is not #rrggbb";
  return std::nullopt;
}

std::string surface_svg(std::span<const SurfaceTriangle> triangles, const SurfaceView& view) {
  const SurfaceView defaults;
  const int width = size_ok(view.width) ? view.width : defaults.width;
  const int height = size_ok(view.height) ? view.height : defaults.height;
  const bool angles_ok = std::isfinite(view.azimuth_deg) && std::isfinite(view.elevation_deg);
  const Camera cam = angles_ok ? camera(view.azimuth_deg, view.elevation_deg)
                               : camera(defaults.azimuth_deg, defaults.elevation_deg);
  const Rgb base = parse_colour(view.base_colour).value_or(*parse_colour(defaults.base_colour));
  const Rgb cut = parse_colour(view.cut_colour).value_or(*parse_colour(defaults.cut_colour));
  // Over the viewer's upper left shoulder.
  const Vec3 light = normalised(cam.eye + 0.6 * cam.up - 0.5 * cam.right);

  // Fit: the projected extent of every vertex (culled or not, so the framing does not jump
  // when the view turns), centred on the bounding box centre, scaled to the free area.
  Vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (const SurfaceTriangle& t : triangles)
    for (const Vec3& p : {t.a, t.b, t.c}) {
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
  const Vec3 centre = triangles.empty() ? Vec3{} : 0.5 * (lo + hi);
  double half_w = 0.0, half_h = 0.0;
  for (const SurfaceTriangle& t : triangles)
    for (const Vec3& p : {t.a, t.b, t.c}) {
      half_w = std::max(half_w, std::fabs(dot(p - centre, cam.right)));
      half_h = std::max(half_h, std::fabs(dot(p - centre, cam.up)));
    }
  const double top = view.title.empty() ? kMargin : kTitleHeight + kMargin;
  const double free_w = width - 2.0 * kMargin, free_h = height - top - kMargin;
  double scale = 1.0;
  if (half_w > 0.0 || half_h > 0.0)
    scale = std::min(half_w > 0.0 ? free_w / (2.0 * half_w) : HUGE_VAL, half_h > 0.0 ? free_h / (2.0 * half_h) : HUGE_VAL);
  // Rounding to 0.1 could push an extreme vertex 0.05 outside the free area, never outside the
  // viewBox: the margin is far larger.
  const double sx0 = 0.5 * width, sy0 = top + 0.5 * free_h;

  std::vector<Drawn> drawn;
  drawn.reserve(triangles.size());
  for (std::uint32_t i = 0; i < triangles.size(); ++i) {
    const SurfaceTriangle& t = triangles[i];
    const Vec3 n = cross(t.b - t.a, t.c - t.a);
    if (!(dot(n, cam.eye) > 0.0)) continue;  // back-facing, edge-on or degenerate
    const double lambert = std::max(0.0, dot(normalised(n), light));
    const Vec3 g = (1.0 / 3.0) * (t.a + t.b + t.c);
    drawn.push_back({dot(g - centre, cam.eye), i, scaled(t.cut ? cut : base, kAmbient + kDiffuse * lambert)});
  }
  std::stable_sort(drawn.begin(), drawn.end(), [](const Drawn& x, const Drawn& y) { return x.depth < y.depth; });

  SvgWriter svg(width, height, view.id, view.title);
  if (!view.title.empty()) svg.text(0.5 * width, kMargin + 14.0, view.title, TextAnchor::kMiddle, 14);
  // Adjacent polygons drawn edge to edge leave anti-aliasing seams, hairlines of background
  // across the surface. A thin stroke of each polygon's own colour closes them; fill and stroke
  // both take `currentColor`, so each polygon carries its colour once, in `color`.
  svg.raw("<g fill=\"currentColor\" stroke=\"currentColor\" stroke-width=\"0.6\" stroke-linejoin=\"round\">");
  for (const Drawn& d : drawn) {
    const SurfaceTriangle& t = triangles[d.index];
    svg.raw("<polygon points=\"");
    bool first = true;
    for (const Vec3& p : {t.a, t.b, t.c}) {
      if (!first) svg.raw(" ");
      first = false;
      svg.number(sx0 + scale * dot(p - centre, cam.right));
      svg.raw(",");
      svg.number(sy0 - scale * dot(p - centre, cam.up));
    }
    svg.raw("\" color=\"");
    svg.raw(to_hex(d.colour));
    svg.raw("\"/>");
  }
  svg.raw("</g>");
  return svg.finish();
}

}  // namespace tetcut::render
