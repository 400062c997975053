// Writing SVG text: number formatting, XML escaping and the few elements every picture uses.
//
// The pictures go inline into an HTML report that must be byte-identical from run to run, so
// numbers go through std::to_chars (locale-independent by definition, unlike printf) with a
// fixed number of decimals, and nothing here depends on the environment.
#pragma once

#include <string>
#include <string_view>

namespace tetcut::render {

// `text` with &, <, >, " and ' replaced by entities: safe in element content and in attributes.
std::string xml_escape(std::string_view text);

// `value` with exactly `decimals` digits after the point ("12.30"); "-0.0" is written "0.0".
// Non-finite values are written "0" (SVG has no NaN): the callers never pass one on purpose.
std::string format_fixed(double value, int decimals);

// `value` with `digits` significant digits and no exponent for ordinary magnitudes, trailing
// zeros dropped: 12.3, 0.05, 1200, 0.000123. For tick and reference-line labels.
std::string format_significant(double value, int digits = 3);

enum class TextAnchor { kStart, kMiddle, kEnd };

// Appends elements to one <svg> document. Coordinates are in viewBox units (0,0 top left).
class SvgWriter {
 public:
  // Opens <svg xmlns=... viewBox="0 0 width height" width=.. height=..> with the given id (none
  // when empty) and an accessible <title> (none when empty).
  SvgWriter(int width, int height, std::string_view id, std::string_view title);

  // Coordinates are written with one decimal: enough for a 0.1 px grid, short enough for
  // thousands of polygons.
  void number(double value) { out_ += format_fixed(value, 1); }
  void text(double x, double y, std::string_view content, TextAnchor anchor = TextAnchor::kStart,
            int font_size = 12, std::string_view extra_attributes = {});
  void line(double x1, double y1, double x2, double y2, std::string_view stroke,
            double stroke_width = 1.0, bool dashed = false);
  // Raw markup: the caller is responsible for escaping.
  void raw(std::string_view markup) { out_ += markup; }

  // Closes the document and returns it; the writer is empty afterwards.
  std::string finish();

 private:
  std::string out_;
};

}  // namespace tetcut::render
