// Whatever the bytes, a reader returns a mesh or an error: randomly mutated valid files (seeded)
// never crash a reader, and every mesh it returns is well formed.
#include <cmath>
#include <functional>

#include "core/random.hpp"
#include "io_test_support.hpp"
#include "tetcut/box_mesh.hpp"

namespace tetcut {
namespace {

std::string mutate(const std::string& base, SplitMix64& rng) {
  std::string s = base;
  const int edits = 1 + static_cast<int>(rng.below(4));
  static constexpr const char* kInserts[] = {"-", "9999999999999", "nan", "\n", "$", "<", ">", "\"",
                                             "=", "e999", "0", " ", "\r\n", "/>", "-1", "_"};
  for (int e = 0; e < edits && !s.empty(); ++e) {
    const auto size = static_cast<std::uint32_t>(s.size());
    const std::uint32_t at = rng.below(size);
    switch (rng.below(6)) {
      case 0: s[at] = static_cast<char>(rng.below(256)); break;
      case 1: s.erase(at, 1 + rng.below(16)); break;
      case 2: s.insert(at, kInserts[rng.below(16)]); break;
      case 3: s.resize(at); break;  // truncation
      case 4: {
        const std::uint32_t len = 1 + rng.below(32);
        s.insert(rng.below(size), s.substr(at, len));  // duplicated range
        break;
      }
      default: s[at] = static_cast<char>('0' + rng.below(10)); break;
    }
  }
  return s;
}

bool well_formed(const ReadResult& r) {
  if (r.mesh.has_value() == r.error.has_value()) return false;
  if (!r.mesh) return !r.error->reason.empty();
  for (const Vec3& p : r.mesh->positions) {
    if (!is_finite(p)) return false;
  }
  for (const auto& tet : r.mesh->tets) {
    for (std::uint32_t v : tet) {
      if (v >= r.mesh->positions.size()) return false;
    }
  }
  return true;
}

using Reader = std::function<ReadResult(const std::string&)>;

void fuzz(const Reader& read, const std::string& base, std::uint64_t seed, int iterations) {
  SplitMix64 rng(seed);
  ASSERT_TRUE(read(base).mesh.has_value());
  for (int i = 0; i < iterations; ++i) {
    const std::string input = mutate(base, rng);
    ASSERT_TRUE(well_formed(read(input))) << "iteration " << i;
  }
}

std::string corpus_text(const std::string& name) {
  std::string text;
  EXPECT_FALSE(read_file(test::corpus_file(name), text).has_value());
  return text;
}

constexpr int kIterations = 1500;
const RawMesh kBox = make_box_mesh(1, 1, 2);

TEST(Robustness, MutatedMshNeverCrashes) {
  const Reader read = [](const std::string& t) { return read_msh(t, "f.msh"); };
  ASSERT_NO_FATAL_FAILURE(fuzz(read, format_msh22(kBox), 1, kIterations));
  ASSERT_NO_FATAL_FAILURE(fuzz(read, format_msh41(kBox), 2, kIterations));
  ASSERT_NO_FATAL_FAILURE(fuzz(read, corpus_text("two_tets_msh22_quirks.msh"), 3, kIterations));
  ASSERT_NO_FATAL_FAILURE(fuzz(read, corpus_text("two_tets_msh41_quirks.msh"), 4, kIterations));
  ASSERT_NO_FATAL_FAILURE(fuzz(read, corpus_text("two_tets_msh10.msh"), 5, kIterations));
}

TEST(Robustness, MutatedVtkAndVtuNeverCrash) {
  const Reader vtk = [](const std::string& t) { return read_vtk(t, "f.vtk"); };
  const Reader vtu = [](const std::string& t) { return read_vtu(t, "f.vtu"); };
  ASSERT_NO_FATAL_FAILURE(fuzz(vtk, format_vtk(kBox), 6, kIterations));
  ASSERT_NO_FATAL_FAILURE(fuzz(vtk, corpus_text("two_tets_v51.vtk"), 7, kIterations));
  ASSERT_NO_FATAL_FAILURE(fuzz(vtu, format_vtu(kBox), 8, kIterations));
  ASSERT_NO_FATAL_FAILURE(fuzz(vtu, corpus_text("two_tets_binary_uint64.vtu"), 9, kIterations));
  ASSERT_NO_FATAL_FAILURE(fuzz(vtu, corpus_text("two_tets_appended_raw.vtu"), 10, kIterations));
  ASSERT_NO_FATAL_FAILURE(fuzz(vtu, corpus_text("two_tets_appended_base64.vtu"), 11, kIterations));
}

TEST(Robustness, MutatedBinaryAndCompressedFilesNeverCrash) {
  const Reader msh = [](const std::string& t) { return read_msh(t, "f.msh"); };
  const Reader vtk = [](const std::string& t) { return read_vtk(t, "f.vtk"); };
  const Reader vtu = [](const std::string& t) { return read_vtu(t, "f.vtu"); };
  ASSERT_NO_FATAL_FAILURE(fuzz(msh, format_msh22_binary(kBox), 21, kIterations));
  ASSERT_NO_FATAL_FAILURE(fuzz(msh, format_msh41_binary(kBox), 22, kIterations));
  ASSERT_NO_FATAL_FAILURE(fuzz(msh, corpus_text("binary/two_tets_msh41_binary_be.msh"), 23, kIterations));
  ASSERT_NO_FATAL_FAILURE(fuzz(vtk, format_vtk_binary(kBox), 24, kIterations));
  ASSERT_NO_FATAL_FAILURE(fuzz(vtk, corpus_text("binary/two_tets_binary_v3.vtk"), 25, kIterations));
  ASSERT_NO_FATAL_FAILURE(fuzz(vtu, format_vtu_binary(kBox, Compression::kZlib), 26, kIterations));
  ASSERT_NO_FATAL_FAILURE(fuzz(vtu, corpus_text("binary/vtu_be_u64_b64_lzma.vtu"), 27, kIterations));
  ASSERT_NO_FATAL_FAILURE(fuzz(vtu, corpus_text("binary/vtu_le_u32_inline_zlib.vtu"), 28, kIterations));
}

TEST(Robustness, MutatedMeditAndTetgenNeverCrash) {
  const Reader medit = [](const std::string& t) { return read_medit(t, "f.mesh"); };
  ASSERT_NO_FATAL_FAILURE(fuzz(medit, format_medit(kBox), 12, kIterations));
  ASSERT_NO_FATAL_FAILURE(fuzz(medit, corpus_text("two_tets_quirks.mesh"), 13, kIterations));
  const std::string ele = format_tetgen_ele(kBox);
  const std::string node = format_tetgen_node(kBox);
  ASSERT_NO_FATAL_FAILURE(fuzz([&](const std::string& t) { return read_tetgen(t, "f.node", ele, "f.ele"); }, node, 14, kIterations));
  ASSERT_NO_FATAL_FAILURE(fuzz([&](const std::string& t) { return read_tetgen(node, "f.node", t, "f.ele"); }, ele, 15, kIterations));
}

TEST(Robustness, MutatedSurfacesNeverCrash) {
  const auto check = [](const SurfaceReadResult& r, std::size_t& accepted) {
    if (r.surface.has_value() == r.error.has_value()) return false;
    if (!r.surface) return true;
    ++accepted;
    for (const auto& tri : r.surface->triangles) {
      for (std::uint32_t v : tri) {
        if (v >= r.surface->positions.size()) return false;
      }
    }
    return true;
  };
  std::size_t accepted = 0;
  SplitMix64 rng(16);
  const std::string off = corpus_text("cube_quads.off");
  const std::string obj = corpus_text("cube_quads.obj");
  const std::string stl = corpus_text("tetra.stl");
  const std::string stlb = corpus_text("tetra_binary.stl");
  for (int i = 0; i < kIterations; ++i) {
    ASSERT_TRUE(check(read_off(mutate(off, rng), "f.off"), accepted)) << i;
    ASSERT_TRUE(check(read_obj(mutate(obj, rng), "f.obj"), accepted)) << i;
    ASSERT_TRUE(check(read_stl(mutate(stl, rng), "f.stl"), accepted)) << i;
    ASSERT_TRUE(check(read_stl(mutate(stlb, rng), "f.stl"), accepted)) << i;
  }
  EXPECT_GT(accepted, 0u);  // the mutations are not all fatal: both paths are exercised
}

}  // namespace
}  // namespace tetcut
