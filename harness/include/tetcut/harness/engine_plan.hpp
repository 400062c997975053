// What the harness asks an engine to do: a mesh and a sequence of operations that any engine can
// carry out through engine.h (cuts by a ball or a capsule, the removal of the tet holding a
// point). Made from a scenario file, whose engine-neutral lines it keeps, or from a seeded
// random sweep across a mesh.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tetcut/raw_mesh.hpp"
#include "tetcut/vec3.hpp"

namespace tetcut::harness {

struct EngineOperation {
  enum class Kind : std::uint8_t { kCut, kRemoveAt };
  Kind kind = Kind::kCut;
  Vec3 a;                 // the ball's centre, the capsule's start, the point whose tet goes
  std::optional<Vec3> b;  // a capsule's end
  double diameter = 0.0;  // the tool's, for a cut
  std::string name;       // "cut 3 at (x, y, z)", "FILE:LINE: remove at (x, y, z)"
};

struct EnginePlan {
  std::string name;       // the scenario file, or "sweep MESH seed S"
  std::string mesh_path;  // where the mesh was read (a finding's scenario names it)
  RawMesh mesh;
  std::vector<EngineOperation> operations;
  // The scenario lines no engine interface carries (tetcut's own parameters, undo, expectations),
  // each "FILE:LINE: skipped: why": reported, so that nobody takes the plan for the scenario.
  std::vector<std::string> notes;
};

// The plan of a scenario file: its one mesh, its diameter lines, its cuts and sweeps (ball and
// swept) and removals. Lines that tune tetcut alone (strategy, improve, ...) and expectations of
// tetcut's own answers (hash, tets) are noted and skipped; a scenario that takes back, renumbers
// or protects tissue (undo, compact, uncuttable) or loads a second mesh is refused, since what
// follows those lines means something else without them. Throws std::runtime_error("FILE:LINE:
// reason") for a file it cannot use.
EnginePlan plan_from_scenario(const std::string& path);

// A seeded random sweep across `mesh`: a chord through its bounding box's middle third in a
// random direction, one ball every half diameter, `cuts` of them, with a tool diameter of
// `diameter_in_edges` times the mesh's median edge length. Same seed, same plan.
EnginePlan random_sweep_plan(const std::string& mesh_name, RawMesh mesh, std::uint64_t seed, std::uint32_t cuts,
                             double diameter_in_edges = 1.0);

// "(x, y, z)" with 6 significant digits: how operation names show points.
std::string point_text(const Vec3& p);

// The median length of the tets' edges (an edge counted once per tet holding it); 1 for no tet.
double median_edge_length(const RawMesh& mesh);

struct MeshBox {
  Vec3 low, high;
};
MeshBox bounding_box(const RawMesh& mesh);

}  // namespace tetcut::harness
