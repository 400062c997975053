// A round trip through every format keeps every bit of the mesh, hence its canonical hash.
#include <bit>
#include <cmath>

#include "core/random.hpp"
#include "io_test_support.hpp"
#include "tetcut/box_mesh.hpp"
#include "tetcut/canonical_hash.hpp"
#include "tetcut/mesh_builder.hpp"

namespace tetcut {
namespace {

using test::identical;

struct FormatCase {
  MeshFormat format;
  const char* file;
};

constexpr FormatCase kFormats[] = {
    {MeshFormat::kMsh22, "m22.msh"}, {MeshFormat::kMsh41, "m41.msh"}, {MeshFormat::kVtu, "m.vtu"},
    {MeshFormat::kVtk, "m.vtk"},     {MeshFormat::kMedit, "m.mesh"},  {MeshFormat::kTetgen, "m.node"},
};

// Coordinates made of random bit patterns (every finite double is fair, denormals and -0.0
// included): a writer that loses one bit fails.
RawMesh random_bits_mesh(std::uint64_t seed) {
  RawMesh mesh = make_box_mesh(2, 2, 1);
  SplitMix64 rng(seed);
  for (Vec3& p : mesh.positions) {
    for (double* c : {&p.x, &p.y, &p.z}) {
      do {
        *c = std::bit_cast<double>(rng.next());
      } while (!std::isfinite(*c));
    }
  }
  mesh.positions[0] = {-0.0, 5e-324, 1.7976931348623157e308};
  return mesh;
}

// `mesh` written to a file of every text format and read back: the same bits, the same hash,
// nothing to say about it. Every format that does not is named in the result.
::testing::AssertionResult every_format_keeps(const RawMesh& mesh) {
  test::ScratchDir dir;
  std::string failures;
  for (const FormatCase& f : kFormats) {
    const std::string path = dir.file(f.file);
    if (!write_mesh_as(path, mesh, f.format).ok) {
      failures += std::string("\n") + f.file + ": not written";
      continue;
    }
    const ReadResult back = read_mesh(path);
    if (!back.mesh) {
      failures += std::string("\n") + f.file + ": not read back: " + test::describe(back);
      continue;
    }
    if (!identical(mesh, *back.mesh)) failures += std::string("\n") + f.file + ": not the same bits";
    if (canonical_hash(mesh) != canonical_hash(*back.mesh)) failures += std::string("\n") + f.file + ": another hash";
    if (!back.notices.empty()) failures += std::string("\n") + f.file + ": notices: " + test::describe(back);
  }
  if (failures.empty()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << failures;
}

TEST(RoundTrip, EveryFormatKeepsBoxMeshAndHashThroughFiles) {
  EXPECT_TRUE(every_format_keeps(make_box_mesh(3, 2, 2, {-1.5, 0.25, 10}, {3, 0.1, 1e-3})));
}

TEST(RoundTrip, EveryFormatKeepsRandomBitCoordinates) {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    EXPECT_TRUE(every_format_keeps(random_bits_mesh(seed)));
  }
}

TEST(RoundTrip, InMemoryFormattersAndReadersAgree) {
  const RawMesh mesh = random_bits_mesh(42);
  EXPECT_TRUE(identical(mesh, *read_msh(format_msh22(mesh), "a.msh").mesh));
  EXPECT_TRUE(identical(mesh, *read_msh(format_msh41(mesh), "a.msh").mesh));
  EXPECT_TRUE(identical(mesh, *read_vtu(format_vtu(mesh), "a.vtu").mesh));
  EXPECT_TRUE(identical(mesh, *read_vtk(format_vtk(mesh), "a.vtk").mesh));
  EXPECT_TRUE(identical(mesh, *read_medit(format_medit(mesh), "a.mesh").mesh));
  EXPECT_TRUE(identical(
      mesh, *read_tetgen(format_tetgen_node(mesh), "a.node", format_tetgen_ele(mesh), "a.ele").mesh));
}

TEST(RoundTrip, EmptyMeshRoundTripsInEveryFormat) {
  test::ScratchDir dir;
  const RawMesh empty;
  for (const FormatCase& f : kFormats) {
    SCOPED_TRACE(f.file);
    ASSERT_TRUE(write_mesh_as(dir.file(f.file), empty, f.format).ok);
    const ReadResult back = read_mesh(dir.file(f.file));
    ASSERT_TRUE(back.mesh.has_value()) << test::describe(back);
    EXPECT_TRUE(back.mesh->positions.empty());
    EXPECT_TRUE(back.mesh->tets.empty());
  }
}

TEST(RoundTrip, TetMeshIsWrittenThroughItsRawForm) {
  test::ScratchDir dir;
  const BuildResult built = build_mesh(make_box_mesh(2, 2, 2));
  ASSERT_TRUE(built.ok());
  for (const char* name : {"t.msh", "t.vtu", "t.vtk", "t.mesh", "t.ele"}) {
    SCOPED_TRACE(name);
    ASSERT_TRUE(write_mesh(dir.file(name), *built.mesh).ok);
    const ReadResult back = read_mesh(dir.file(name));
    ASSERT_TRUE(back.mesh.has_value()) << test::describe(back);
    EXPECT_EQ(canonical_hash(*built.mesh), canonical_hash(*back.mesh));
  }
}

TEST(RoundTrip, ExtensionPicksTheFormatCaseInsensitively) {
  test::ScratchDir dir;
  const RawMesh mesh = test::two_tets();
  ASSERT_TRUE(write_mesh(dir.file("UPPER.VTK"), mesh).ok);
  std::string text;
  ASSERT_FALSE(read_file(dir.file("UPPER.VTK"), text).has_value());
  EXPECT_EQ(text.rfind("# vtk DataFile", 0), 0u);
  EXPECT_TRUE(identical(mesh, *read_mesh(dir.file("UPPER.VTK")).mesh));
  // A .msh written as 4.1 is recognised by its header.
  ASSERT_TRUE(write_mesh_as(dir.file("v41.msh"), mesh, MeshFormat::kMsh41).ok);
  EXPECT_TRUE(identical(mesh, *read_mesh(dir.file("v41.msh")).mesh));
  // Writing x.ele writes the pair; either name reads it back.
  ASSERT_TRUE(write_mesh(dir.file("pair.ele"), mesh).ok);
  EXPECT_TRUE(std::filesystem::exists(dir.file("pair.node")));
  EXPECT_TRUE(identical(mesh, *read_mesh(dir.file("pair.ele")).mesh));
  EXPECT_TRUE(identical(mesh, *read_mesh(dir.file("pair.node")).mesh));
}

TEST(RoundTrip, BinaryAndCompressedWritersKeepEveryBit) {
  test::ScratchDir dir;
  struct BinaryCase {
    MeshFormat format;
    Compression compression;
    const char* file;
  };
  constexpr BinaryCase kCases[] = {
      {MeshFormat::kMsh22, Compression::kNone, "b22.msh"}, {MeshFormat::kMsh41, Compression::kNone, "b41.msh"},
      {MeshFormat::kVtk, Compression::kNone, "b.vtk"},     {MeshFormat::kVtu, Compression::kNone, "b.vtu"},
      {MeshFormat::kVtu, Compression::kZlib, "z.vtu"},     {MeshFormat::kVtu, Compression::kLzma, "x.vtu"},
  };
  // A mesh large enough for several 32 KiB compressed blocks per array.
  const RawMesh mesh = random_bits_mesh(7);
  const RawMesh big = make_box_mesh(12, 12, 12);
  for (const BinaryCase& c : kCases) {
    for (const RawMesh* m : {&mesh, &big}) {
      SCOPED_TRACE(c.file);
      const std::string path = dir.file(c.file);
      ASSERT_TRUE(write_mesh_as(path, *m, c.format, WriteOptions{.binary = true, .compression = c.compression}).ok);
      const ReadResult back = read_mesh(path);
      ASSERT_TRUE(back.mesh.has_value()) << test::describe(back);
      EXPECT_TRUE(identical(*m, *back.mesh));
    }
  }
  const WriteResult medit = write_mesh_as(dir.file("m.mesh"), mesh, MeshFormat::kMedit, WriteOptions{.binary = true});
  EXPECT_FALSE(medit.ok);
  EXPECT_NE(medit.error.find("written as text only"), std::string::npos) << medit.error;
  const WriteResult gmsh = write_mesh_as(dir.file("m.msh"), mesh, MeshFormat::kMsh22, WriteOptions{.compression = Compression::kZlib});
  EXPECT_FALSE(gmsh.ok);
  EXPECT_FALSE(std::filesystem::exists(dir.file("m.msh")));
}

TEST(RoundTrip, UnknownExtensionIsAnErrorForReadAndWrite) {
  test::ScratchDir dir;
  const WriteResult w = write_mesh(dir.file("mesh.xyz"), test::two_tets());
  EXPECT_FALSE(w.ok);
  EXPECT_NE(w.error.find("unknown extension"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir.file("mesh.xyz")));
  // Read: the content is looked at first; content no reader knows is an error naming both.
  ASSERT_TRUE(write_file_atomically(dir.file("mesh.xyz"), "1 2 3\n").ok);
  const ReadResult r = read_mesh(dir.file("mesh.xyz"));
  ASSERT_TRUE(r.error.has_value());
  EXPECT_NE(r.error->reason.find("unknown extension '.xyz'"), std::string::npos) << r.error->reason;
  EXPECT_NE(r.error->reason.find("text starting '1 2 3'"), std::string::npos) << r.error->reason;
  EXPECT_FALSE(read_mesh(dir.file("no_extension")).mesh.has_value());
}

TEST(RoundTrip, MissingFileIsAnErrorNamingTheFile) {
  const ReadResult r = read_mesh("/nonexistent/dir/mesh.msh");
  ASSERT_TRUE(r.error.has_value());
  EXPECT_EQ(r.error->file, "/nonexistent/dir/mesh.msh");
  EXPECT_NE(r.error->message().find("cannot open"), std::string::npos);
}

}  // namespace
}  // namespace tetcut
