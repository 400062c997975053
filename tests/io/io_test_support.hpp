// Helpers shared by the io tests: the two-tet reference mesh of corpus/test-files, a scratch
// directory, and a comparison that checks every bit of a round trip.
#pragma once

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <string>

#include "tetcut/io.hpp"
#include "tetcut/raw_mesh.hpp"

namespace tetcut::test {

// A(0,0,0) B(1,0,0) C(0,1,0) D(0,0,1) E(1,1,1); tets ABCD and BCDE, both positive.
inline RawMesh two_tets() {
  RawMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
  m.tets = {{0, 1, 2, 3}, {1, 2, 3, 4}};
  return m;
}

inline std::string corpus_file(const std::string& name) {
  return std::string(TETCUT_CORPUS_DIR) + "/test-files/" + name;
}

// A fresh directory per test, removed afterwards.
class ScratchDir {
 public:
  ScratchDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() /
            ("tetcut_io_" + std::string(info->test_suite_name()) + "_" + info->name());
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() { std::filesystem::remove_all(path_); }
  [[nodiscard]] std::string file(const std::string& name) const { return (path_ / name).string(); }
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// Same vertex order, same tets, every coordinate bit for bit (so -0.0 stays -0.0).
inline ::testing::AssertionResult identical(const RawMesh& a, const RawMesh& b) {
  if (a.positions.size() != b.positions.size()) {
    return ::testing::AssertionFailure() << a.positions.size() << " vs " << b.positions.size() << " positions";
  }
  if (a.positions.size() > 0 &&
      std::memcmp(a.positions.data(), b.positions.data(), a.positions.size() * sizeof(Vec3)) != 0) {
    return ::testing::AssertionFailure() << "positions differ in some bit";
  }
  if (a.tets != b.tets) return ::testing::AssertionFailure() << "tets differ";
  return ::testing::AssertionSuccess();
}

inline std::string describe(const ReadResult& r) {
  return r.error ? r.error->message() : std::string("ok");
}

}  // namespace tetcut::test
