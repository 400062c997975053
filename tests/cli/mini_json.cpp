#include "mini_json.hpp"

#include <cstdlib>

namespace tetcut::test {

const Json* Json::get(std::string_view key) const {
  for (const auto& [k, v] : members) {
    if (k == key) return &v;
  }
  return nullptr;
}

namespace {

class Parser {
 public:
  explicit Parser(std::string_view s) : s_(s) {}

  std::optional<Json> document() {
    auto v = value();
    skip_ws();
    if (!v || pos_ != s_.size()) return std::nullopt;
    return v;
  }

 private:
  void skip_ws() {
    while (pos_ < s_.size() && (s_[pos_] == ' ' || s_[pos_] == '\n' || s_[pos_] == '\t' ||
                                s_[pos_] == '\r')) {
      ++pos_;
    }
  }
  bool eat(char c) {
    skip_ws();
    if (pos_ < s_.size() && s_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }
  bool literal(std::string_view word) {
    if (s_.substr(pos_, word.size()) != word) return false;
    pos_ += word.size();
    return true;
  }

  std::optional<std::string> string() {
    if (!eat('"')) return std::nullopt;
    std::string out;
    while (pos_ < s_.size()) {
      const char c = s_[pos_++];
      if (c == '"') return out;
      if (static_cast<unsigned char>(c) < 0x20) return std::nullopt;
      if (c != '\\') {
        out.push_back(c);
        continue;
      }
      if (pos_ >= s_.size()) return std::nullopt;
      const char e = s_[pos_++];
      switch (e) {
        case '"': out.push_back('"'); break;
        case '\\': out.push_back('\\'); break;
        case '/': out.push_back('/'); break;
        case 'b': out.push_back('\b'); break;
        case 'f': out.push_back('\f'); break;
        case 'n': out.push_back('\n'); break;
        case 'r': out.push_back('\r'); break;
        case 't': out.push_back('\t'); break;
        case 'u': {
          if (pos_ + 4 > s_.size()) return std::nullopt;
          const std::string hex(s_.substr(pos_, 4));
          char* end = nullptr;
          const long cp = std::strtol(hex.c_str(), &end, 16);
          if (end != hex.c_str() + 4) return std::nullopt;
          pos_ += 4;
          out.push_back(cp < 0x80 ? static_cast<char>(cp) : '?');
          break;
        }
        default: return std::nullopt;
      }
    }
    return std::nullopt;
  }

  std::optional<Json> number() {
    const std::size_t start = pos_;
    if (pos_ < s_.size() && s_[pos_] == '-') ++pos_;
    const auto digits = [&] {
      const std::size_t d = pos_;
      while (pos_ < s_.size() && s_[pos_] >= '0' && s_[pos_] <= '9') ++pos_;
      return pos_ > d;
    };
    if (!digits()) return std::nullopt;
    if (pos_ < s_.size() && s_[pos_] == '.') {
      ++pos_;
      if (!digits()) return std::nullopt;
    }
    if (pos_ < s_.size() && (s_[pos_] == 'e' || s_[pos_] == 'E')) {
      ++pos_;
      if (pos_ < s_.size() && (s_[pos_] == '+' || s_[pos_] == '-')) ++pos_;
      if (!digits()) return std::nullopt;
    }
    Json j;
    j.kind = Json::Kind::kNumber;
    j.number = std::strtod(std::string(s_.substr(start, pos_ - start)).c_str(), nullptr);
    return j;
  }

  std::optional<Json> value() {
    if (++depth_ > 64) return std::nullopt;
    skip_ws();
    std::optional<Json> result;
    if (pos_ >= s_.size()) return std::nullopt;
    const char c = s_[pos_];
    Json j;
    if (c == '{') {
      ++pos_;
      j.kind = Json::Kind::kObject;
      if (!eat('}')) {
        do {
          auto k = string();
          if (!k || !eat(':')) return std::nullopt;
          auto v = value();
          if (!v) return std::nullopt;
          j.members.emplace_back(std::move(*k), std::move(*v));
        } while (eat(','));
        if (!eat('}')) return std::nullopt;
      }
      result = std::move(j);
    } else if (c == '[') {
      ++pos_;
      j.kind = Json::Kind::kArray;
      if (!eat(']')) {
        do {
          auto v = value();
          if (!v) return std::nullopt;
          j.items.push_back(std::move(*v));
        } while (eat(','));
        if (!eat(']')) return std::nullopt;
      }
      result = std::move(j);
    } else if (c == '"') {
      auto s = string();
      if (!s) return std::nullopt;
      j.kind = Json::Kind::kString;
      j.text = std::move(*s);
      result = std::move(j);
    } else if (literal("true") || literal("false")) {
      j.kind = Json::Kind::kBool;
      j.boolean = s_[pos_ - 1] == 'e' && s_[pos_ - 2] == 'u';
      result = std::move(j);
    } else if (literal("null")) {
      result = std::move(j);
    } else {
      result = number();
    }
    --depth_;
    return result;
  }

  std::string_view s_;
  std::size_t pos_ = 0;
  int depth_ = 0;
};

}  // namespace

std::optional<Json> parse_json(std::string_view text) { return Parser(text).document(); }

}  // namespace tetcut::test
