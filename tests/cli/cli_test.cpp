// The `tetcut` executable, run as a user runs it, on files written into a temporary directory:
// exit codes, messages and --json output of check, info and convert (design: the command line);
// refine, cut and run in commands_cli_test.cpp.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli_fixture.hpp"
#include "core/random.hpp"
#include "run_process.hpp"
#include "tetcut/box_mesh.hpp"
#include "tetcut/canonical_hash.hpp"
#include "tetcut/io.hpp"

namespace tetcut::test {
namespace {

// One positive tet, in Gmsh 2.2 ASCII.
constexpr const char* kOneTetMsh =
    "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
    "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n"
    "$Elements\n1\n1 4 2 0 1 1 2 3 4\n$EndElements\n";

// Two positive tets sharing only vertex 1: conformal, but the vertex's shell is two components
// (its link is two disjoint triangles), so the mesh is not a manifold (I5).
constexpr const char* kBowtieMsh =
    "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
    "$Nodes\n7\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 0 -1 0\n6 -1 0 0\n7 0 0 -1\n$EndNodes\n"
    "$Elements\n2\n1 4 2 0 1 1 2 3 4\n2 4 2 0 1 1 5 6 7\n$EndElements\n";

std::size_t count_violations_named(const Json& report, const std::string& id) {
  std::size_t n = 0;
  for (const Json& item : report.value("violations", Json::array())) {
    if (item.value("id", "") == id) ++n;
  }
  return n;
}

// ---- usage ----------------------------------------------------------------------------------

TEST_F(Cli, VersionAndHelpExitZeroOnStdout) {
  const ProcessResult version = tetcut({"--version"});
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_TRUE(version.out.starts_with("tetcut ")) << version.out;

  const ProcessResult help = tetcut({"--help"});
  EXPECT_EQ(help.exit_code, 0);
  for (const char* command : {"info", "check", "convert"}) {
    EXPECT_NE(help.out.find(command), std::string::npos) << command;
  }
  const ProcessResult help_check = tetcut({"help", "check"});
  EXPECT_EQ(help_check.exit_code, 0);
  EXPECT_NE(help_check.out.find("--level"), std::string::npos);
  const ProcessResult check_help = tetcut({"check", "--help"});
  EXPECT_EQ(check_help.exit_code, 0);
  EXPECT_EQ(check_help.out, help_check.out);
}

TEST_F(Cli, BadUsageExitsTwoWithTheUsage) {
  const std::string box = write_box("box.msh", 1, 1, 1);
  const std::vector<std::vector<std::string>> bad = {
      {},
      {"frobnicate"},
      {"--frobnicate"},
      {"help", "frobnicate"},
      {"check"},
      {"check", box, box},
      {"check", box, "--bogus"},
      {"check", box, "--level"},
      {"check", box, "--level", "medium"},
      {"check", box, "--json=yes"},
      {"check", box, "--min-radius-ratio", "0.5x"},
      {"check", box, "--min-radius-ratio", "nan"},
      {"check", box, "--min-radius-ratio", "2"},
      {"info"},
      {"info", box, "--level", "full"},
      {"convert", box},
      {"convert", box, box, box},
      {"convert", box, box, "--format", "stl"},
      {"stats", "extra"},
      {"stats", "--mesh", "kidney"},
      {"stats", "--check", "none"},
      {"stats", "--json"},
  };
  for (const auto& args : bad) {
    const ProcessResult r = tetcut(args);
    std::string joined;
    for (const auto& a : args) joined += a + " ";
    EXPECT_TRUE(r.exited) << joined;
    EXPECT_EQ(r.exit_code, 2) << joined;
    EXPECT_TRUE(r.err.starts_with("tetcut")) << joined << ": " << r.err;
    EXPECT_NE(r.err.find("usage: tetcut"), std::string::npos) << joined << ": " << r.err;
  }
}

TEST_F(Cli, StatsWithoutItsCorpusNamesTheMissingScenario) {
  const ProcessResult r = tetcut({"stats", "--corpus", path("no-corpus")});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("no-corpus/scenarios/paper/cylinder.scn"), std::string::npos) << r.err;
}

// ---- a valid mesh ---------------------------------------------------------------------------

TEST_F(Cli, CheckAcceptsAValidBoxAtEveryLevel) {
  const std::string box = write_box("box.msh", 2, 3, 4);
  for (const char* level : {"local", "full", "exact"}) {
    const ProcessResult r = tetcut({"check", box, "--level", level});
    EXPECT_TRUE(r.exited);
    EXPECT_EQ(r.exit_code, 0) << level << "\n" << r.out << r.err;
    EXPECT_NE(r.out.find("valid at level " + std::string(level)), std::string::npos) << r.out;

    const Json report = tetcut_json({"check", box, "--level", level, "--json"}, 0);
    ASSERT_TRUE(report.contains("valid"));
    EXPECT_TRUE(report.at("valid").get<bool>());
    EXPECT_EQ(report.at("level_run").get<std::string>(), level);
    EXPECT_TRUE(report.at("violations").empty());
    EXPECT_TRUE(report.at("engine").at("built").get<bool>());
    EXPECT_EQ(report.at("tets").get<double>(), 6 * 2 * 3 * 4);
    EXPECT_NEAR(report.at("volume").get<double>(), 1.0, 1e-12);
  }
}

TEST_F(Cli, InfoReportsCountsVolumeQualityAndHashOfABox) {
  constexpr std::uint32_t nx = 2, ny = 3, nz = 4;
  const std::string box = write_box("box.msh", nx, ny, nz);
  const Json info = tetcut_json({"info", box, "--json"}, 0);
  for (const char* key : {"vertices", "tets", "boundary_faces", "volume", "min_radius_ratio",
                          "mean_radius_ratio", "min_dihedral_deg", "radius_ratio_histogram",
                          "bounding_box", "manifold", "hash"}) {
    EXPECT_TRUE(info.contains(key)) << key;
  }
  if (::testing::Test::HasFailure()) return;
  EXPECT_EQ(info.at("vertices").get<double>(), (nx + 1) * (ny + 1) * (nz + 1));
  EXPECT_EQ(info.at("tets").get<double>(), 6 * nx * ny * nz);
  EXPECT_EQ(info.at("boundary_faces").get<double>(), 2 * 2 * (nx * ny + ny * nz + nx * nz));
  EXPECT_NEAR(info.at("volume").get<double>(), 1.0, 1e-12);
  const double min_rr = info.at("min_radius_ratio").get<double>();
  EXPECT_GT(min_rr, 0.0);
  EXPECT_LE(min_rr, info.at("mean_radius_ratio").get<double>());
  EXPECT_LE(info.at("mean_radius_ratio").get<double>(), 1.0);
  EXPECT_GT(info.at("min_dihedral_deg").get<double>(), 0.0);
  double histogram_total = 0;
  for (const Json& bin : info.at("radius_ratio_histogram")) histogram_total += bin.get<double>();
  EXPECT_EQ(info.at("radius_ratio_histogram").size(), 10u);
  EXPECT_EQ(histogram_total, 6 * nx * ny * nz);
  const Json& bbox = info.at("bounding_box");
  ASSERT_EQ(bbox.at("min").size(), 3u);
  ASSERT_EQ(bbox.at("max").size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(bbox.at("min")[i].get<double>(), 0.0);
    EXPECT_EQ(bbox.at("max")[i].get<double>(), 1.0);
  }
  EXPECT_EQ(info.at("manifold").is_boolean(), true);
  EXPECT_TRUE(info.at("manifold").get<bool>());
  const std::string hash = info.at("hash").get<std::string>();
  EXPECT_EQ(hash, hash_to_hex(canonical_hash(make_box_mesh(nx, ny, nz))));
  EXPECT_EQ(hash.size(), 16u);

  // Deterministic, text and all.
  EXPECT_EQ(tetcut({"info", box, "--json"}).out, tetcut({"info", box, "--json"}).out);
  const ProcessResult text = tetcut({"info", box});
  EXPECT_EQ(text.exit_code, 0);
  EXPECT_NE(text.out.find(hash), std::string::npos) << text.out;
}

TEST_F(Cli, JsonStaysValidWhateverTheFileName) {
  const std::string odd = write_box("we\"ird\\na\tme \xff.msh", 1, 1, 1);
  const Json info = tetcut_json({"info", odd, "--json"}, 0);
  ASSERT_TRUE(info.contains("file"));
  EXPECT_NE(info.at("file").get<std::string>().find("we\"ird\\na\tme "), std::string::npos);
  const Json report = tetcut_json({"check", odd, "--json"}, 0);
  EXPECT_TRUE(report.contains("valid"));
}

TEST_F(Cli, QualityFloorAboveTheMeshsWorstTetIsAnI7Violation) {
  const std::string box = write_box("box.msh", 2, 2, 2);
  EXPECT_EQ(tetcut({"check", box, "--min-radius-ratio", "0.01"}).exit_code, 0);
  const Json report = tetcut_json({"check", box, "--min-radius-ratio", "0.99", "--json"}, 1);
  EXPECT_EQ(count_violations_named(report, "I7"), 1u) << "violations name I7";
}

// ---- a non-manifold mesh --------------------------------------------------------------------

TEST_F(Cli, CheckNamesTheSingularVertexOfTwoTetsSharingOnlyAVertex) {
  const std::string bowtie = write("bowtie.msh", kBowtieMsh);
  const ProcessResult r = tetcut({"check", bowtie});
  EXPECT_TRUE(r.exited);
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("I5"), std::string::npos) << r.out;

  const Json report = tetcut_json({"check", bowtie, "--json"}, 1);
  EXPECT_FALSE(report.at("valid").get<bool>());
  EXPECT_EQ(count_violations_named(report, "I5"), 1u);
  for (const Json& v : report.at("violations")) {
    if (v.at("id").get<std::string>() != "I5") continue;
    EXPECT_GE(v.at("count").get<double>(), 1);
    ASSERT_FALSE(v.at("vertices").empty());
    EXPECT_EQ(v.at("vertices")[0].get<double>(), 0) << "the shared vertex is input vertex 0";
  }
}

TEST_F(Cli, LocalLevelFallsBackToFullWithANoteWhenTheEngineCannotBuild) {
  const std::string bowtie = write("bowtie.msh", kBowtieMsh);
  const Json report = tetcut_json({"check", bowtie, "--level", "local", "--json"}, 1);
  EXPECT_EQ(report.at("level").get<std::string>(), "local");
  EXPECT_EQ(report.at("level_run").get<std::string>(), "full");
  EXPECT_EQ(report.at("notes").size(), 1u);
  EXPECT_EQ(count_violations_named(report, "I5"), 1u);
}

TEST_F(Cli, InfoDescribesANonManifoldMeshInsteadOfRefusingIt) {
  const std::string bowtie = write("bowtie.msh", kBowtieMsh);
  const Json info = tetcut_json({"info", bowtie, "--json"}, 0);
  EXPECT_EQ(info.at("tets").get<double>(), 2);
  EXPECT_EQ(info.at("vertices").get<double>(), 7);
  EXPECT_EQ(info.at("boundary_faces").get<double>(), 8);
  EXPECT_FALSE(info.at("manifold").get<bool>());
}

// ---- malformed input ------------------------------------------------------------------------

TEST_F(Cli, MalformedFilesAreRefusedWithFileLineAndReason) {
  const std::string header = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"empty.msh", ""},
      {"truncated.msh", std::string(kOneTetMsh).substr(0, 60)},
      {"garbage.msh", "hello world\n\x01\x02\x03 not a mesh\n"},
      {"nan.msh", header + "$Nodes\n4\n1 0 0 0\n2 nan 0 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n"
                           "$Elements\n1\n1 4 2 0 1 1 2 3 4\n$EndElements\n"},
      {"out_of_range.msh", header + "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n"
                                    "$Elements\n1\n1 4 2 0 1 1 2 3 99\n$EndElements\n"},
      {"absurd_nodes.msh", header + "$Nodes\n99999999999999999\n1 0 0 0\n$EndNodes\n"},
      {"absurd_elements.msh",
       header + "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n"
                "$Elements\n4000000000\n1 4 2 0 1 1 2 3 4\n$EndElements\n"},
      {"negative_count.msh", header + "$Nodes\n-4\n$EndNodes\n"},
  };
  for (const auto& [name, contents] : cases) {
    SCOPED_TRACE(name);
    const std::string file = write(name, contents);
    expect_file_line_message(tetcut({"check", file}), file);
    expect_file_line_message(tetcut({"info", file, "--json"}), file);
    expect_file_line_message(tetcut({"convert", file, path("out.msh")}), file);
    EXPECT_FALSE(fs::exists(path("out.msh")));
  }
}

TEST_F(Cli, MissingFileIsRefusedNamingIt) {
  const std::string missing = path("missing.msh");
  const ProcessResult r = tetcut({"check", missing});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(r.err.starts_with("tetcut: " + missing)) << r.err;
}

TEST_F(Cli, RandomBytesNeverCrashTheCommandLine) {
  SplitMix64 rng(20240601);
  const std::string seeds[] = {kOneTetMsh, kBowtieMsh};
  for (int i = 0; i < 200; ++i) {
    std::string bytes;
    if (i % 2 == 0) {
      // Pure noise, sometimes only printable (to get past the first tokenizer checks).
      const std::uint32_t n = rng.below(400);
      const bool printable = rng.below(2) == 0;
      for (std::uint32_t k = 0; k < n; ++k) {
        bytes.push_back(printable ? static_cast<char>(" \n0123456789.-e$"[rng.below(16)])
                                  : static_cast<char>(rng.below(256)));
      }
    } else {
      // A valid file with a few bytes replaced, inserted or removed: reaches the deep paths.
      bytes = seeds[rng.below(2)];
      const std::uint32_t edits = 1 + rng.below(4);
      for (std::uint32_t e = 0; e < edits && !bytes.empty(); ++e) {
        const std::uint32_t at = rng.below(static_cast<std::uint32_t>(bytes.size()));
        const char c = static_cast<char>("0123456789 -\n9$."[rng.below(16)]);
        switch (rng.below(3)) {
          case 0: bytes[at] = c; break;
          case 1: bytes.insert(bytes.begin() + at, c); break;
          default: bytes.erase(at, 1); break;
        }
      }
    }
    // Noise goes to every reader; the mutated Gmsh files to the Gmsh one.
    static constexpr const char* kExtensions[] = {".msh", ".vtk", ".vtu", ".mesh", ".node"};
    const std::string file =
        write(std::string("random") + (i % 2 == 0 ? kExtensions[(i / 2) % 5] : ".msh"), bytes);
    const ProcessResult r = tetcut({"check", file, "--json"});
    ASSERT_TRUE(r.exited) << "killed by signal " << r.signal << " on input " << i << ":\n"
                          << bytes;
    ASSERT_TRUE(r.exit_code == 0 || r.exit_code == 1 || r.exit_code == 2)
        << "exit " << r.exit_code << " on input " << i << ":\n" << bytes << "\n" << r.err;
    if (r.exit_code != 2) {
      EXPECT_TRUE(parse_json(r.out).has_value()) << r.out;
    }
    if (i % 4 == 1) {
      const ProcessResult info = tetcut({"info", file});
      ASSERT_TRUE(info.exited) << "info killed by signal " << info.signal << ":\n" << bytes;
      EXPECT_TRUE(info.exit_code == 0 || info.exit_code == 2) << info.exit_code;
    }
  }
}

// ---- convert --------------------------------------------------------------------------------

TEST_F(Cli, ConvertKeepsTheCanonicalHashAndPrintsIt) {
  const std::string box = write_box("box.msh", 2, 2, 1);
  const std::string copy = path("copy.msh");
  const ProcessResult r = tetcut({"convert", box, copy});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const std::string hash = hash_to_hex(canonical_hash(make_box_mesh(2, 2, 1)));
  EXPECT_NE(r.out.find(hash), std::string::npos) << r.out;
  ASSERT_TRUE(fs::exists(copy));
  const Json info = tetcut_json({"info", copy, "--json"}, 0);
  EXPECT_EQ(info.at("hash").get<std::string>(), hash);
}

TEST_F(Cli, ConvertRoundTripsThroughEveryFormatKeepingTheHash) {
  const std::string box = write_box("box.msh", 2, 1, 2);
  const std::string hash = hash_to_hex(canonical_hash(make_box_mesh(2, 1, 2)));
  const std::vector<std::vector<std::string>> outputs = {
      {"a.vtu"}, {"a.vtk"}, {"a.mesh"}, {"a.node"}, {"a41.msh", "--format", "msh41"}};
  for (const auto& output : outputs) {
    SCOPED_TRACE(output[0]);
    const ProcessResult r = convert(box, output);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    // And back, so the reader of each format is exercised by the command line too.
    const std::string back = path("back_" + output[0] + ".msh");
    ASSERT_EQ(tetcut({"convert", path(output[0]), back}).exit_code, 0);
    const Json info = tetcut_json({"info", back, "--json"}, 0);
    EXPECT_EQ(info.at("hash").get<std::string>(), hash);
  }
}

TEST_F(Cli, ConvertRefusesAnUnwritableOrUnknownOutputWithoutLeavingAFile) {
  const std::string box = write_box("box.msh", 1, 1, 1);
  const ProcessResult unknown = tetcut({"convert", box, path("out.unknownformat")});
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_TRUE(unknown.err.starts_with("tetcut: ")) << unknown.err;
  EXPECT_FALSE(fs::exists(path("out.unknownformat")));
  const ProcessResult nodir = tetcut({"convert", box, path("no/such/dir/out.msh")});
  EXPECT_EQ(nodir.exit_code, 2);
  EXPECT_NE(nodir.err.find("no/such/dir"), std::string::npos) << nodir.err;
}

}  // namespace
}  // namespace tetcut::test
