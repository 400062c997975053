// Writes go through a temporary file and a rename: a failed write leaves no trace.
#include <fstream>

#include "io_test_support.hpp"

namespace tetcut {
namespace {

std::size_t entries(const std::filesystem::path& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++n;
  return n;
}

TEST(AtomicWrite, WritesTheContentsAndLeavesNoTemporary) {
  test::ScratchDir dir;
  ASSERT_TRUE(write_file_atomically(dir.file("a.txt"), "hello\n").ok);
  std::string text;
  ASSERT_FALSE(read_file(dir.file("a.txt"), text).has_value());
  EXPECT_EQ(text, "hello\n");
  EXPECT_EQ(entries(dir.path()), 1u);
}

TEST(AtomicWrite, ReplacesAnExistingFile) {
  test::ScratchDir dir;
  ASSERT_TRUE(write_file_atomically(dir.file("a.txt"), "old contents, longer").ok);
  ASSERT_TRUE(write_file_atomically(dir.file("a.txt"), "new").ok);
  std::string text;
  ASSERT_FALSE(read_file(dir.file("a.txt"), text).has_value());
  EXPECT_EQ(text, "new");
}

TEST(AtomicWrite, MissingDirectoryFailsWithThePath) {
  test::ScratchDir dir;
  const std::string path = dir.file("no/such/dir/a.msh");
  const WriteResult r = write_mesh(path, test::two_tets());
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find(path), std::string::npos);
  EXPECT_EQ(entries(dir.path()), 0u);
}

TEST(AtomicWrite, FailedRenameRemovesTheTemporaryAndKeepsTheTarget) {
  test::ScratchDir dir;
  // The target is a non-empty directory: rename onto it fails after the temporary is written.
  const std::string target = dir.file("target.msh");
  std::filesystem::create_directories(target + "/inside");
  const WriteResult r = write_mesh(target, test::two_tets());
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(std::filesystem::is_directory(target + "/inside"));
  EXPECT_EQ(entries(dir.path()), 1u);  // just the directory: no temporary left behind
}

}  // namespace
}  // namespace tetcut
