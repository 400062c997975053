// The fixture of the command-line tests: a temporary directory per test, files written into it,
// and the built `tetcut` run there as a user runs it.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "run_process.hpp"
#include "tetcut/box_mesh.hpp"
#include "tetcut/io.hpp"

namespace tetcut::test {

namespace fs = std::filesystem;

// tetcut's JSON as nlohmann-json reads it (strictly: a parse error is "not JSON").
using Json = nlohmann::json;

inline std::optional<Json> parse_json(std::string_view text) {
  Json value = Json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (value.is_discarded()) return std::nullopt;
  return value;
}

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("tetcut_cli_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  std::string write(const std::string& name, const std::string& contents) const {
    const std::string p = path(name);
    std::ofstream(p, std::ios::binary) << contents;
    return p;
  }

  std::string write_box(const std::string& name, std::uint32_t nx, std::uint32_t ny,
                        std::uint32_t nz) const {
    const std::string p = path(name);
    const WriteResult w = write_mesh(p, make_box_mesh(nx, ny, nz));
    EXPECT_TRUE(w.ok) << w.error;
    return p;
  }

  ProcessResult tetcut(const std::vector<std::string>& args) const {
    return run_process(TETCUT_EXE, args, dir_.string());
  }

  // `tetcut convert INPUT OUTPUT [options...]` with `output` = {file name in the test's
  // directory, options...}: the convert tests' table rows.
  ProcessResult convert(const std::string& input, const std::vector<std::string>& output) const {
    std::vector<std::string> args = {"convert", input, path(output.at(0))};
    args.insert(args.end(), output.begin() + 1, output.end());
    return tetcut(args);
  }

  // Runs tetcut with --json and parses its stdout.
  Json tetcut_json(const std::vector<std::string>& args, int expected_exit) const {
    const ProcessResult r = tetcut(args);
    EXPECT_TRUE(r.exited) << "signal " << r.signal;
    EXPECT_EQ(r.exit_code, expected_exit) << r.err;
    const auto json = parse_json(r.out);
    EXPECT_TRUE(json.has_value()) << "not JSON:\n" << r.out;
    return json.value_or(Json{});
  }

  fs::path dir_;
};

// "tetcut: FILE:LINE: reason", on a single line.
inline void expect_file_line_message(const ProcessResult& r, const std::string& file) {
  EXPECT_TRUE(r.exited) << "signal " << r.signal;
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  const std::string prefix = "tetcut: " + file + ":";
  ASSERT_TRUE(r.err.starts_with(prefix)) << r.err;
  std::size_t i = prefix.size();
  const std::size_t digits_start = i;
  while (i < r.err.size() && std::isdigit(static_cast<unsigned char>(r.err[i]))) ++i;
  EXPECT_GT(i, digits_start) << "no line number: " << r.err;
  EXPECT_EQ(r.err.substr(i, 2), ": ") << r.err;
  EXPECT_GT(r.err.size(), i + 3) << "no reason: " << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "not one line: " << r.err;
}

}  // namespace tetcut::test
