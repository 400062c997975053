// The replay driver: a main() that runs files through a fuzz target's LLVMFuzzerTestOneInput, so
// that every build (GCC, Release, ASan+UBSan) replays the seed corpus and every minimized
// regression in ctest without libFuzzer (style: fmt's fuzz build).
//
//   <target> [-flag ...] PATH...
// Each PATH is a file, or a folder whose files (not sub-folders) are run in name order, so a
// failure always happens on the same input. Arguments starting with '-' are libFuzzer flags and
// are ignored, so one command line (`<target> -runs=0 corpus/`) replays with either build; a
// target's LLVMFuzzerInitialize, when it has one, sees them first, as libFuzzer calls it.
// A failing input aborts inside the target; the driver prints each input's name first so that
// the log names it.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <system_error>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);
// Optional, as in libFuzzer: a target that defines it reads its own arguments first (the
// sequence targets' -engine=LIB).
extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) __attribute__((weak));

namespace {

namespace fs = std::filesystem;

bool run_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    std::fprintf(stderr, "replay: cannot open %s\n", path.c_str());
    return false;
  }
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::fprintf(stderr, "replay: %s (%zu bytes)\n", path.c_str(), bytes.size());
  // A copy in a buffer of exactly the input's size, so that ASan sees any read past its end
  // (as libFuzzer's own copy does).
  std::vector<std::uint8_t> data(bytes.begin(), bytes.end());
  LLVMFuzzerTestOneInput(data.empty() ? nullptr : data.data(), data.size());
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (LLVMFuzzerInitialize != nullptr) LLVMFuzzerInitialize(&argc, &argv);
  std::size_t inputs = 0;
  bool ok = true;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.starts_with("-")) continue;
    const fs::path path(arg);
    std::error_code ec;
    if (fs::is_directory(path, ec)) {
      std::vector<fs::path> files;
      for (const fs::directory_entry& entry : fs::directory_iterator(path, ec))
        if (entry.is_regular_file()) files.push_back(entry.path());
      if (ec) {
        std::fprintf(stderr, "replay: cannot list %s: %s\n", path.c_str(), ec.message().c_str());
        ok = false;
        continue;
      }
      std::sort(files.begin(), files.end());
      for (const fs::path& file : files) {
        ok = run_file(file) && ok;
        ++inputs;
      }
    } else if (fs::is_regular_file(path, ec)) {
      ok = run_file(path) && ok;
      ++inputs;
    } else {
      std::fprintf(stderr, "replay: no such file or folder: %s\n", path.c_str());
      ok = false;
    }
  }
  std::fprintf(stderr, "replay: %zu inputs, %s\n", inputs, ok ? "all passed" : "some could not be read");
  return ok ? 0 : 1;
}
