#include <gtest/gtest.h>

#include "tetcut/scenario/scenario.hpp"

namespace tetcut::scenario {
namespace {

TEST(ScenarioParse, ReadsEveryOperation) {
  const ParseResult r = parse(
      "# a comment\n"
      "mesh box.msh\n"
      "diameter 0.5   # trailing comment\n"
      "strategy neighbours\n"
      "cut 0.5,0.5,0.5\r\n"
      "sweep 0,0,0 1,1,1 0.1\n"
      "remove 0.2,0.2,0.2\n"
      "compact\n"
      "check exact\n"
      "expect hash 0123456789abcdef\n"
      "expect tets 12\n"
      "expect unresolved 0\n"
      "expect components 2\n",
      "t.scn", ".");
  ASSERT_TRUE(r.scenario) << r.error;
  const std::vector<Op>& ops = r.scenario->ops;
  ASSERT_EQ(ops.size(), 12u);
  EXPECT_EQ(ops[0].kind, OpKind::kMesh);
  EXPECT_EQ(ops[0].line, 2u);
  EXPECT_EQ(ops[3].kind, OpKind::kCut);
  EXPECT_EQ(ops[3].a, (Vec3{0.5, 0.5, 0.5}));
  EXPECT_EQ(ops[4].kind, OpKind::kSweep);
  EXPECT_EQ(ops[4].step, 0.1);
  EXPECT_EQ(ops[7].text, "exact");
  EXPECT_EQ(ops[8].text, "0123456789abcdef");
  EXPECT_EQ(ops[11].count, 2u);
}

TEST(ScenarioParse, NamesTheLineAndTheReason) {
  struct Case {
    const char* text;
    const char* expected;
  };
  for (const Case& c : {Case{"mesh a.msh\ncut 1,2\n", "t.scn:2: expected: cut X,Y,Z"},
                        Case{"diameter -1\n", "t.scn:1: tool diameter must be a positive"},
                        Case{"diameter nan\n", "t.scn:1: diameter must be a finite number"},
                        Case{"\n\nfly 1,2,3\n", "t.scn:3: unknown operation 'fly'"},
                        Case{"sweep 0,0,0 1,0,0 0\n", "t.scn:1: expected: sweep"},
                        Case{"sweep 0,0,0 1e9,0,0 1e-3\n", "t.scn:1: sweep of more than"},
                        Case{"expect hash XYZ\n", "t.scn:1: a hash is 16 lowercase hex digits"},
                        Case{"strategy magic\n", "t.scn:1: strategy must be"},
                        Case{"check everything\n", "t.scn:1: check level must be"}}) {
    const ParseResult r = parse(c.text, "t.scn", ".");
    EXPECT_FALSE(r.scenario) << c.text;
    EXPECT_EQ(r.error.rfind(c.expected, 0), 0u) << "got: " << r.error;
  }
}

TEST(ScenarioRun, AnOperationBeforeAnyMeshIsAnError) {
  const ParseResult p = parse("cut 0,0,0\n", "t.scn", ".");
  ASSERT_TRUE(p.scenario);
  const RunResult r = run(*p.scenario);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.failed_line, 1u);
}

TEST(ScenarioRun, AWrongExpectationFailsAtItsLine) {
  const ParseResult p = parse("mesh ../meshes/cylinder.msh\nexpect tets 1\n", "t.scn", TETCUT_CORPUS_DIR "/scenarios");
  ASSERT_TRUE(p.scenario) << p.error;
  const RunResult r = run(*p.scenario);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.failed_line, 2u);
  EXPECT_NE(r.error.find("expected 1 tets"), std::string::npos) << r.error;
}

}  // namespace
}  // namespace tetcut::scenario
