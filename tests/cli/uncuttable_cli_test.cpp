// `--keep-label L` (tetcut cut, tetcut simulate) and the scenario's `uncuttable` line: a labelled
// vessel through a box, swept down to by a cautery, as the user runs it. The files that come out
// are read back and measured, owing the engine nothing: the vessel's labelled volume is what it
// was, and tissue around it went; the same sweep without the option takes part of the vessel.
#include <algorithm>
#include <cmath>

#include "cli_fixture.hpp"

namespace tetcut::test {
namespace {

constexpr std::uint32_t kVessel = 2;

double volume(const RawMesh& m, std::size_t t) {
  const auto& v = m.tets[t];
  const Vec3 a = m.positions[v[0]];
  return dot(m.positions[v[1]] - a, cross(m.positions[v[2]] - a, m.positions[v[3]] - a)) / 6.0;
}

// Total volume, and the volume labelled kVessel.
std::pair<double, double> volumes(const RawMesh& m) {
  double total = 0, vessel = 0;
  for (std::size_t t = 0; t < m.tets.size(); ++t) {
    total += volume(m, t);
    if (m.labels.at(t) == kVessel) vessel += volume(m, t);
  }
  return {total, vessel};
}

class KeepLabel : public Cli {
 protected:
  // A 6^3 box, label 1, with a vessel (label 2) along x: the tets whose centroid lies within
  // 0.2 of y = z = 0.5.
  std::string write_vessel_box(const std::string& name) {
    RawMesh box = make_box_mesh(6, 6, 6);
    box.labels.resize(box.tets.size(), 1);
    for (std::size_t t = 0; t < box.tets.size(); ++t) {
      Vec3 c{};
      for (std::uint32_t v : box.tets[t]) c = c + 0.25 * box.positions[v];
      if (std::hypot(c.y - 0.5, c.z - 0.5) < 0.2) box.labels[t] = kVessel;
    }
    before_ = volumes(box);
    const std::string p = path(name);
    const WriteResult w = write_mesh(p, box);
    EXPECT_TRUE(w.ok) << w.error;
    return p;
  }
  RawMesh read_back(const std::string& name) {
    ReadResult r = read_mesh(path(name));
    EXPECT_TRUE(r.mesh.has_value());
    EXPECT_TRUE(r.mesh && r.mesh->labelled());
    return r.mesh ? std::move(*r.mesh) : RawMesh{};
  }
  // Down onto the vessel from the top face.
  std::vector<std::string> sweep_args(const std::string& in, const std::string& out) {
    return {"cut", in, "--diameter", "0.3", "--from", "0.1,0.5,0.72", "--to", "0.9,0.5,0.72", "--step", "0.1", "--out", out};
  }
  std::pair<double, double> before_;
};

TEST_F(KeepLabel, CutLeavesTheLabelledVesselAndTakesTheTissueAboveIt) {
  const std::string in = write_vessel_box("vessel.msh");
  ASSERT_GT(before_.second, 0.05);
  std::vector<std::string> args = sweep_args(in, path("kept.msh"));
  args.insert(args.end(), {"--keep-label", "2"});
  const ProcessResult kept = tetcut(args);
  ASSERT_EQ(kept.exit_code, 0) << kept.out << kept.err;
  const auto [total, vessel] = volumes(read_back("kept.msh"));
  EXPECT_NEAR(vessel, before_.second, 1e-12);
  EXPECT_LT(total, before_.first - 0.02);

  const ProcessResult taken = tetcut(sweep_args(in, path("taken.msh")));
  ASSERT_EQ(taken.exit_code, 0) << taken.out << taken.err;
  EXPECT_LT(volumes(read_back("taken.msh")).second, before_.second - 0.01);
}

TEST_F(KeepLabel, TheScenarioLineDoesWhatTheOptionDoes) {
  write_vessel_box("vessel.msh");
  const std::string scn = write("keep.scn",
                                "mesh vessel.msh\ndiameter 0.3\nuncuttable 2\n"
                                "sweep 0.1,0.5,0.72 0.9,0.5,0.72 0.1\ncheck full\n");
  const ProcessResult r = tetcut({"run", scn, "--out", path("run.msh")});
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  std::vector<std::string> args = sweep_args(path("vessel.msh"), path("cut.msh"));
  args.insert(args.end(), {"--keep-label", "2"});
  ASSERT_EQ(tetcut(args).exit_code, 0);
  const RawMesh a = read_back("run.msh"), b = read_back("cut.msh");
  EXPECT_EQ(a.tets, b.tets);
  EXPECT_EQ(a.labels, b.labels);
}

TEST_F(KeepLabel, BadLabelsAndUnlabelledMeshesAreRefusedWithAMessage) {
  const std::string in = write_vessel_box("vessel.msh");
  std::vector<std::string> args = sweep_args(in, path("out.msh"));
  args.insert(args.end(), {"--keep-label", "two"});
  ProcessResult r = tetcut(args);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--keep-label"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(path("out.msh")));

  const std::string plain = write_box("plain.vtu", 3, 3, 3);
  args = sweep_args(plain, path("out.msh"));
  args.insert(args.end(), {"--keep-label", "2"});
  r = tetcut(args);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("labels"), std::string::npos) << r.err;

  const std::string scn = write("bad.scn", "mesh vessel.msh\nuncuttable 2 x\n");
  r = tetcut({"run", scn});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("bad.scn:2:"), std::string::npos) << r.err;
}

TEST_F(KeepLabel, SimulateTakesTheOptionAndRefusesItWithoutLabels) {
  const std::string in = write_vessel_box("vessel.msh");
  const std::vector<std::string> args = {"simulate", in, "--diameter", "0.3", "--sweep", "0.1,0.5,0.72", "0.9,0.5,0.72",
                                         "0.2", "--unit", "0.01", "--steps", "1", "--keep-label", "2"};
  const ProcessResult r = tetcut(args);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  std::vector<std::string> plain_args = args;
  plain_args[1] = write_box("plain.vtu", 3, 3, 3);
  const ProcessResult plain = tetcut(plain_args);
  EXPECT_EQ(plain.exit_code, 2);
  EXPECT_NE(plain.err.find("has no labels"), std::string::npos) << plain.err;
}

}  // namespace
}  // namespace tetcut::test
