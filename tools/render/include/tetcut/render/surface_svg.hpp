// A picture of a triangulated surface: orthographic view, flat shading, painter's algorithm.
//
// The camera looks at the centre of the triangles' bounding box from the direction given by
// azimuth (about +z, from +x towards +y) and elevation (above the xy plane): z is up on screen.
// Triangles facing away from the viewer are culled (surfaces are closed and outward oriented),
// the rest are drawn far to near by centroid depth, ties kept in input order, so nearer
// triangles paint over farther ones. Shading is Lambert with the light over the viewer's upper
// left shoulder: colour = base x (ambient + diffuse x max(0, n.l)).
#pragma once

#include <optional>
#include <span>
#include <string>

#include "tetcut/render/surface.hpp"

namespace tetcut::render {

struct SurfaceView {
  double azimuth_deg = 30.0;
  double elevation_deg = 20.0;
  int width = 480;   // viewBox size, pixels
  int height = 360;
  std::string title;                   // drawn above the picture when not empty
  std::string base_colour = "#c0705a";  // original surface ("#rrggbb")
  std::string cut_colour = "#f0c850";   // surfaces exposed by cuts
  std::string id;                      // the <svg> element's id attribute, none when empty
};

// A message when the view cannot be drawn (sizes not in 16..8192, angles not finite, colours not
// "#rrggbb"); nullopt when valid.
std::optional<std::string> validate(const SurfaceView& view);

// One <polygon points="x,y x,y x,y" color="#rrggbb"/> per front-facing triangle, inside one
// group that fills and strokes with currentColor (so the shaded colour is written once per
// polygon, in `color`). Coordinates are rounded to 0.1 and lie inside the viewBox. The same input gives the same
// bytes. An invalid view falls back to the defaults for the invalid fields.
std::string surface_svg(std::span<const SurfaceTriangle> triangles, const SurfaceView& view = {});

}  // namespace tetcut::render
