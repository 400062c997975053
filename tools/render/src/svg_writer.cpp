#include "tetcut/render/svg_writer.hpp"

#include <charconv>
#include <cmath>

namespace tetcut::render {

std::string xml_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string format_fixed(double value, int decimals) {
  if (!std::isfinite(value)) return "0";
  char buffer[64];
  auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, decimals);
  if (ec != std::errc{}) return "0";  // only for magnitudes no picture has
  std::string out(buffer, end);
  // Rounding a tiny negative value gives "-0.0": the same position as "0.0", one byte shorter,
  // and identical whichever side of zero rounding noise fell.
  if (out[0] == '-' && out.find_first_not_of("-0.") == std::string::npos) out.erase(0, 1);
  return out;
}

std::string format_significant(double value, int digits) {
  if (!std::isfinite(value)) return "0";
  if (value == 0.0) return "0";
  // Decimals needed so that `digits` significant digits show; never negative (no exponent).
  const int magnitude = static_cast<int>(std::floor(std::log10(std::fabs(value))));
  int decimals = digits - 1 - magnitude;
  if (decimals < 0) decimals = 0;
  if (decimals > 12) decimals = 12;
  std::string out = format_fixed(value, decimals);
  if (out.find('.') != std::string::npos) {
    while (out.back() == '0') out.pop_back();
    if (out.back() == '.') out.pop_back();
  }
  return out;
}

SvgWriter::SvgWriter(int width, int height, std::string_view id, std::string_view title) {
  out_ += "<svg xmlns=\"http://www.w3.org/2000/svg\"";
  if (!id.empty()) {
    out_ += " id=\"";
    out_ += xml_escape(id);
    out_ += '"';
  }
  const std::string w = std::to_string(width), h = std::to_string(height);
  out_ += " width=\"" + w + "\" height=\"" + h + "\" viewBox=\"0 0 " + w + ' ' + h + "\"";
  out_ += " font-family=\"sans-serif\">";
  if (!title.empty()) {
    out_ += "<title>";
    out_ += xml_escape(title);
    out_ += "</title>";
  }
}

void SvgWriter::text(double x, double y, std::string_view content, TextAnchor anchor, int font_size,
                     std::string_view extra_attributes) {
  out_ += "<text x=\"";
  number(x);
  out_ += "\" y=\"";
  number(y);
  out_ += "\" font-size=\"" + std::to_string(font_size) + '"';
  if (anchor == TextAnchor::kMiddle) out_ += " text-anchor=\"middle\"";
  if (anchor == TextAnchor::kEnd) out_ += " text-anchor=\"end\"";
  if (!extra_attributes.empty()) {
    out_ += ' ';
    out_ += extra_attributes;
  }
  out_ += '>';
  out_ += xml_escape(content);
  out_ += "</text>";
}

void SvgWriter::line(double x1, double y1, double x2, double y2, std::string_view stroke,
                     double stroke_width, bool dashed) {
  out_ += "<line x1=\"";
  number(x1);
  out_ += "\" y1=\"";
  number(y1);
  out_ += "\" x2=\"";
  number(x2);
  out_ += "\" y2=\"";
  number(y2);
  out_ += "\" stroke=\"";
  out_ += xml_escape(stroke);
  out_ += "\" stroke-width=\"" + format_significant(stroke_width, 3) + '"';
  if (dashed) out_ += " stroke-dasharray=\"5,4\"";
  out_ += "/>";
}

std::string SvgWriter::finish() {
  out_ += "</svg>";
  std::string done;
  done.swap(out_);
  return done;
}

}  // namespace tetcut::render
