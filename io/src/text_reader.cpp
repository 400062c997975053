#include "text_reader.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <system_error>

namespace tetcut::io_detail {

bool LineReader::next(std::string_view& line) {
  if (pos_ >= text_.size()) return false;
  std::size_t end = pos_;
  while (end < text_.size() && text_[end] != '\n' && text_[end] != '\r') ++end;
  line = text_.substr(pos_, end - pos_);
  if (end < text_.size()) {
    if (text_[end] == '\r' && end + 1 < text_.size() && text_[end + 1] == '\n') ++end;
    ++end;
  }
  pos_ = end;
  ++line_;
  return true;
}

bool LineReader::take_bytes(std::size_t n, std::string_view& bytes) {
  if (n > text_.size() - pos_) return false;
  bytes = text_.substr(pos_, n);
  for (std::size_t i = pos_; i < pos_ + n; ++i) {
    if (text_[i] == '\n' || (text_[i] == '\r' && (i + 1 >= text_.size() || text_[i + 1] != '\n'))) ++line_;
  }
  pos_ += n;
  return true;
}

bool LineReader::next_nonblank(std::string_view& line) {
  const std::uint64_t previous_line = line_;
  while (next(line)) {
    if (!trim(line).empty()) return true;
  }
  // At the end, stay on the last line that held something: that is where the file stops.
  line_ = previous_line;
  return false;
}

bool next_tokens(LineReader& lines, std::vector<std::string_view>& tokens, char comment) {
  std::string_view line;
  const LineReader start = lines;
  while (lines.next(line)) {
    if (comment != '\0') {
      const std::size_t c = line.find(comment);
      if (c != std::string_view::npos) line = line.substr(0, c);
    }
    split_tokens(line, tokens);
    if (!tokens.empty()) return true;
  }
  tokens.clear();
  // At the end, stay on the last line that held something (see next_nonblank).
  lines = start;
  while (lines.next(line)) {
  }
  lines.rewind_line_count(start.line_number());
  return false;
}

void TokenReader::skip_space() {
  while (pos_ < text_.size()) {
    const char c = text_[pos_];
    if (c == '\n') {
      ++line_;
      ++pos_;
    } else if (c == '\r') {
      // CRLF counts once; a lone CR is a line end too.
      if (pos_ + 1 >= text_.size() || text_[pos_ + 1] != '\n') ++line_;
      ++pos_;
    } else if (is_space(c)) {
      ++pos_;
    } else if (comment_ != '\0' && c == comment_) {
      while (pos_ < text_.size() && text_[pos_] != '\n' && text_[pos_] != '\r') ++pos_;
    } else {
      return;
    }
  }
}

bool TokenReader::next(std::string_view& token) {
  const std::uint64_t previous_line = line_;
  skip_space();
  if (pos_ >= text_.size()) {
    // At the end, report the line of the last token, not the empty line after a final newline.
    line_ = previous_line;
    return false;
  }
  const std::size_t start = pos_;
  while (pos_ < text_.size() && !is_space(text_[pos_]) &&
         !(comment_ != '\0' && text_[pos_] == comment_)) {
    ++pos_;
  }
  token = text_.substr(start, pos_ - start);
  return true;
}

bool TokenReader::peek(std::string_view& token) {
  const std::size_t pos = pos_;
  const std::uint64_t line = line_;
  const bool got = next(token);
  pos_ = pos;
  line_ = line;
  return got;
}

std::string_view TokenReader::rest_of_line() {
  const std::size_t start = pos_;
  while (pos_ < text_.size() && text_[pos_] != '\n' && text_[pos_] != '\r') ++pos_;
  return text_.substr(start, pos_ - start);
}

void TokenReader::skip_past_blank_line() {
  LineReader lines(text_.substr(pos_));
  std::string_view line;
  lines.next(line);  // the rest of the current line
  while (lines.next(line)) {
    if (trim(line).empty()) break;
  }
  pos_ += lines.offset();
  line_ += lines.line_number();
}

bool TokenReader::take_binary(std::size_t n, std::string_view& bytes) {
  std::size_t pos = pos_;
  while (pos < text_.size() && text_[pos] != '\n' && text_[pos] != '\r') ++pos;
  if (pos >= text_.size()) return false;
  pos += text_[pos] == '\r' && pos + 1 < text_.size() && text_[pos + 1] == '\n' ? 2 : 1;
  if (n > text_.size() - pos) return false;
  bytes = text_.substr(pos, n);
  for (std::size_t i = pos_; i < pos + n; ++i) {
    if (text_[i] == '\n' || (text_[i] == '\r' && (i + 1 >= text_.size() || text_[i + 1] != '\n'))) ++line_;
  }
  pos_ = pos + n;
  return true;
}

bool check_count(ErrorSink& sink, std::uint64_t line, std::uint64_t count,
                 std::size_t remaining_bytes) {
  // The last entry may end the file without a separator, hence the + 1.
  const std::uint64_t room = (static_cast<std::uint64_t>(remaining_bytes) + 1) / 2;
  if (count > room || count > 0xFFFFFFFEull) {
    return sink.fail(line, "count " + std::to_string(count) + " exceeds file size");
  }
  return true;
}

bool parse_count(ErrorSink& sink, std::uint64_t line, std::string_view token,
                 std::size_t remaining_bytes, std::uint64_t& count) {
  std::int64_t signed_value = 0;
  if (parse_i64(token, signed_value) && signed_value < 0) {
    return sink.fail(line, "negative count " + std::to_string(signed_value));
  }
  if (!parse_u64(token, count)) {
    return sink.fail(line, "expected a count, got " + quote(token));
  }
  return check_count(sink, line, count, remaining_bytes);
}

bool parse_coordinate(ErrorSink& sink, std::uint64_t line, std::string_view token, double& value) {
  if (!parse_double(token, value)) {
    return sink.fail(line, "expected a coordinate, got " + quote(token));
  }
  if (std::isnan(value)) return sink.fail(line, "NaN coordinate");
  if (std::isinf(value)) return sink.fail(line, "infinite coordinate " + quote(token));
  return true;
}

bool parse_point(ErrorSink& sink, std::uint64_t line, const std::string_view* xyz, Vec3& p) {
  return parse_coordinate(sink, line, xyz[0], p.x) && parse_coordinate(sink, line, xyz[1], p.y) &&
         parse_coordinate(sink, line, xyz[2], p.z);
}

bool parse_id(ErrorSink& sink, std::uint64_t line, std::string_view token, std::int64_t& value) {
  if (!parse_i64(token, value)) {
    return sink.fail(line, "expected an integer id, got " + quote(token));
  }
  return true;
}

bool check_label(ErrorSink& sink, std::uint64_t line, std::int64_t value, std::string_view what, std::uint32_t& label) {
  if (value < 0 || value > std::int64_t{kMaxTetLabel}) {
    return sink.fail(line, std::string(what) + " " + std::to_string(value) + " is not a label (an integer in 0.." +
                               std::to_string(kMaxTetLabel) + ")");
  }
  label = static_cast<std::uint32_t>(value);
  return true;
}

bool parse_label(ErrorSink& sink, std::uint64_t line, std::string_view token, std::string_view what,
                 std::uint32_t& label) {
  std::int64_t value = 0;
  if (!parse_i64(token, value)) {
    return sink.fail(line, std::string(what) + " " + quote(token) + " is not a label (an integer in 0.." +
                               std::to_string(kMaxTetLabel) + ")");
  }
  return check_label(sink, line, value, what, label);
}

bool NodeIdMap::insert(std::int64_t id, std::uint32_t index) {
  if (contiguous_) {
    if (count_ == 0) {
      first_ = id;
      count_ = 1;
      return true;
    }
    // Stay in contiguous mode while ids follow each other and indices follow insertions.
    if (index == count_ && id > first_ &&
        static_cast<std::uint64_t>(id) - static_cast<std::uint64_t>(first_) == count_) {
      ++count_;
      return true;
    }
    if (find(id) != kNone) return false;
    contiguous_ = false;
    map_.reserve(static_cast<std::size_t>(count_) * 2 + 16);
    for (std::uint32_t i = 0; i < count_; ++i) map_.emplace(first_ + i, i);
  }
  return map_.emplace(id, index).second;
}

std::uint32_t NodeIdMap::find(std::int64_t id) const {
  if (contiguous_) {
    if (count_ == 0 || id < first_) return kNone;
    // first_ <= id here, so id - first_ cannot overflow negatively; guard the positive range.
    const std::uint64_t delta = static_cast<std::uint64_t>(id) - static_cast<std::uint64_t>(first_);
    return delta < count_ ? static_cast<std::uint32_t>(delta) : kNone;
  }
  const auto it = map_.find(id);
  return it == map_.end() ? kNone : it->second;
}

void IgnoredTally::add(std::string kind, std::uint64_t n, std::string noun) {
  Entry& e = counts_[kind];
  e.count += n;
  if (e.noun.empty()) e.noun = noun.empty() ? std::move(kind) : std::move(noun);
}

void IgnoredTally::emit(std::vector<std::string>& notices) const {
  for (const auto& [kind, e] : counts_) {
    notices.push_back("ignored " + std::to_string(e.count) + " " + kind);
  }
}

std::vector<CellCount> IgnoredTally::summary() const {
  std::vector<CellCount> out;
  for (const auto& entry : counts_) {
    const Entry& e = entry.second;
    auto same = std::find_if(out.begin(), out.end(), [&](const CellCount& c) { return c.noun == e.noun; });
    if (same != out.end()) {
      same->count += e.count;
    } else {
      out.push_back({e.noun, e.count});
    }
  }
  return out;
}

std::string plural_noun(std::string_view singular) {
  const auto ends_with = [&](std::string_view tail) {
    return singular.size() >= tail.size() && singular.substr(singular.size() - tail.size()) == tail;
  };
  std::string s(singular);
  // "element of type 99" -> "elements of type 99"
  if (const std::size_t of = s.find(" of "); of != std::string::npos) {
    return plural_noun(s.substr(0, of)) + s.substr(of);
  }
  if (ends_with("hedron")) return s.substr(0, s.size() - 2) + "a";
  if (ends_with("ertex")) return s.substr(0, s.size() - 2) + "ices";
  if (ends_with("x") || ends_with("s")) return s + "es";
  return s + "s";
}

ReadResult make_result(ErrorSink& sink, RawMesh&& mesh, std::vector<std::string>&& notices,
                       const IgnoredTally* ignored) {
  ReadResult result;
  if (sink.failed()) {
    result.error = sink.error();
  } else {
    result.mesh = std::move(mesh);
    if (ignored != nullptr) result.ignored = ignored->summary();
  }
  result.notices = std::move(notices);
  return result;
}

SurfaceReadResult make_surface_result(ErrorSink& sink, SurfaceMesh&& surface,
                                      std::vector<std::string>&& notices) {
  SurfaceReadResult result;
  if (sink.failed()) {
    result.error = sink.error();
  } else {
    result.surface = std::move(surface);
  }
  result.notices = std::move(notices);
  return result;
}

void add_polygon(SurfaceMesh& surface, const std::vector<std::uint32_t>& corners,
                 std::uint64_t& polygons_split) {
  for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
    surface.triangles.push_back({corners[0], corners[k], corners[k + 1]});
  }
  if (corners.size() > 3) ++polygons_split;
}

void polygon_notice(std::uint64_t polygons_split, std::vector<std::string>& notices) {
  if (polygons_split > 0) {
    notices.push_back("split " + std::to_string(polygons_split) + " polygons into triangle fans");
  }
}

void append_double(std::string& out, double value) {
  char buf[40];
  const auto r = std::to_chars(buf, buf + sizeof buf, value);
  out.append(buf, r.ptr);
}

void append_point(std::string& out, const Vec3& p) {
  append_double(out, p.x);
  out += ' ';
  append_double(out, p.y);
  out += ' ';
  append_double(out, p.z);
}

void append_uint(std::string& out, std::uint64_t value) {
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, value);
  out.append(buf, r.ptr);
}

void append_point_lines(std::string& out, const std::vector<Vec3>& positions, std::string_view prefix,
                        std::string_view suffix) {
  for (const Vec3& p : positions) {
    out += prefix;
    append_point(out, p);
    out += suffix;
  }
}

void append_numbered_points(std::string& out, const std::vector<Vec3>& positions) {
  for (std::size_t i = 0; i < positions.size(); ++i) {
    append_uint(out, i + 1);
    out += ' ';
    append_point(out, positions[i]);
    out += '\n';
  }
}

void append_numbered_tets(std::string& out, const std::vector<std::array<std::uint32_t, 4>>& tets,
                          std::string_view fields, std::span<const std::uint32_t> last_column) {
  for (std::size_t t = 0; t < tets.size(); ++t) {
    append_uint(out, t + 1);
    out += fields;
    for (std::uint32_t v : tets[t]) {
      out += ' ';
      append_uint(out, std::uint64_t{v} + 1);
    }
    if (!last_column.empty()) {
      out += ' ';
      append_uint(out, last_column[t]);
    }
    out += '\n';
  }
}

}  // namespace tetcut::io_detail
