// A small streaming JSON writer for the command line's --json output (no dependency).
//
// Keys come out in the order the caller writes them, so output is deterministic and a diff of
// two reports is meaningful. Doubles use the shortest form that reads back to the same bits
// (std::to_chars); NaN and infinities, which JSON cannot express, become null. Strings are
// escaped, and bytes that are not valid UTF-8 (a file name can hold anything) become U+FFFD so
// the output is always valid JSON.
//
// Layout: objects put one key per line; arrays of scalars stay on one line; an array element
// that is an object or array starts its own line.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

namespace tetcut::cli {

class JsonWriter {
 public:
  explicit JsonWriter(std::ostream& out) : out_(out) {}

  void begin_object();
  void end_object();
  void begin_array();
  void end_array();

  // In an object, every value is preceded by its key.
  void key(std::string_view name);

  void value(std::string_view s);
  void value(const char* s) { value(std::string_view(s)); }
  void value(const std::string& s) { value(std::string_view(s)); }
  void value(bool b);
  void value(double d);
  void value(std::int64_t i);
  void value(std::uint64_t u);
  void value(int i) { value(static_cast<std::int64_t>(i)); }
  void value(unsigned u) { value(static_cast<std::uint64_t>(u)); }
  void null();

  // key + value in one call.
  template <class T>
  void field(std::string_view name, const T& v) {
    key(name);
    value(v);
  }

  // Ends the document with a newline; every container must be closed.
  void finish();

 private:
  struct Frame {
    bool is_object = false;
    std::uint32_t count = 0;
    bool last_was_container = false;
  };

  void before_value(bool is_container);
  void newline_indent(std::size_t depth);
  void close(bool is_object);

  std::ostream& out_;
  std::vector<Frame> stack_;
  bool key_pending_ = false;
};

// `s` as a quoted, escaped JSON string.
std::string json_quote(std::string_view s);

// The shortest decimal form of `d` that reads back to the same double ("null" if not finite).
std::string json_number(double d);

}  // namespace tetcut::cli
