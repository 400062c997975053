#include "json_writer.hpp"

#include <cassert>
#include <charconv>
#include <cmath>
#include <ostream>

namespace tetcut::cli {

namespace {

// Length of the valid UTF-8 sequence starting at s[i], or 0 if the bytes there are not one
// (overlong forms, surrogates and code points above U+10FFFF are invalid too).
std::size_t utf8_sequence_length(std::string_view s, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char c = byte(i);
  std::size_t n = 0;
  std::uint32_t cp = 0;
  if (c < 0x80) return 1;
  if (c >= 0xC2 && c <= 0xDF) {
    n = 2;
    cp = c & 0x1Fu;
  } else if (c >= 0xE0 && c <= 0xEF) {
    n = 3;
    cp = c & 0x0Fu;
  } else if (c >= 0xF0 && c <= 0xF4) {
    n = 4;
    cp = c & 0x07u;
  } else {
    return 0;
  }
  if (i + n > s.size()) return 0;
  for (std::size_t k = 1; k < n; ++k) {
    const unsigned char cc = byte(i + k);
    if ((cc & 0xC0u) != 0x80u) return 0;
    cp = (cp << 6) | (cc & 0x3Fu);
  }
  if (n == 3 && (cp < 0x800 || (cp >= 0xD800 && cp <= 0xDFFF))) return 0;
  if (n == 4 && (cp < 0x10000 || cp > 0x10FFFF)) return 0;
  return n;
}

}  // namespace

std::string json_quote(std::string_view s) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  out.reserve(s.size() + 2);
  out.push_back('"');
  std::size_t i = 0;
  while (i < s.size()) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\b': out += "\\b"; break;
      case '\f': out += "\\f"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (c < 0x20 || c == 0x7F) {
          out += "\\u00";
          out.push_back(kHex[c >> 4]);
          out.push_back(kHex[c & 0xF]);
        } else if (c < 0x80) {
          out.push_back(static_cast<char>(c));
        } else {
          const std::size_t n = utf8_sequence_length(s, i);
          if (n == 0) {
            out += "\\ufffd";
            ++i;
          } else {
            out.append(s.substr(i, n));
            i += n;
          }
          continue;
        }
    }
    ++i;
  }
  out.push_back('"');
  return out;
}

std::string json_number(double d) {
  if (!std::isfinite(d)) return "null";
  char buffer[64];
  // Shortest round-trip representation (C++17 to_chars without a precision).
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, d);
  assert(ec == std::errc{});
  std::string s(buffer, end);
  // "-0" and integral values such as "1e+20" are valid JSON numbers already; nothing to add.
  return s;
}

void JsonWriter::newline_indent(std::size_t depth) {
  out_ << '\n';
  for (std::size_t i = 0; i < depth; ++i) out_ << "  ";
}

void JsonWriter::before_value(bool is_container) {
  if (stack_.empty()) return;
  Frame& frame = stack_.back();
  if (frame.is_object) {
    // The key already wrote the separator and the indentation.
    assert(key_pending_ && "a value in an object needs a key");
    key_pending_ = false;
    return;
  }
  if (frame.count > 0) out_ << ',';
  if (is_container) {
    newline_indent(stack_.size());
  } else if (frame.count > 0) {
    out_ << ' ';
  }
  frame.last_was_container = is_container;
  ++frame.count;
}

void JsonWriter::key(std::string_view name) {
  assert(!stack_.empty() && stack_.back().is_object && !key_pending_);
  Frame& frame = stack_.back();
  if (frame.count > 0) out_ << ',';
  newline_indent(stack_.size());
  out_ << json_quote(name) << ": ";
  ++frame.count;
  key_pending_ = true;
}

void JsonWriter::begin_object() {
  before_value(true);
  out_ << '{';
  stack_.push_back(Frame{true, 0, false});
}

void JsonWriter::begin_array() {
  before_value(true);
  out_ << '[';
  stack_.push_back(Frame{false, 0, false});
}

void JsonWriter::close(bool is_object) {
  assert(!stack_.empty() && stack_.back().is_object == is_object && !key_pending_);
  const Frame frame = stack_.back();
  stack_.pop_back();
  // Objects with content and arrays ending in a container close on their own line.
  if (frame.count > 0 && (is_object || frame.last_was_container)) newline_indent(stack_.size());
  out_ << (is_object ? '}' : ']');
}

void JsonWriter::end_object() { close(true); }
void JsonWriter::end_array() { close(false); }

void JsonWriter::value(std::string_view s) {
  before_value(false);
  out_ << json_quote(s);
}

void JsonWriter::value(bool b) {
  before_value(false);
  out_ << (b ? "true" : "false");
}

void JsonWriter::value(double d) {
  before_value(false);
  out_ << json_number(d);
}

void JsonWriter::value(std::int64_t i) {
  before_value(false);
  out_ << i;
}

void JsonWriter::value(std::uint64_t u) {
  before_value(false);
  out_ << u;
}

void JsonWriter::null() {
  before_value(false);
  out_ << "null";
}

void JsonWriter::finish() {
  assert(stack_.empty() && !key_pending_);
  out_ << '\n';
}

}  // namespace tetcut::cli
