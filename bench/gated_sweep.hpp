// The gated cautery sweep on the bundled liver (~16k tets): the cuts whose per-cut times and
// instruction count the gate bounds (cut_bench, cut_instructions), and that the peers replay
// (bench/peers/). One definition, so that every figure quoted beside the gate's is of these cuts.
#pragma once

#include <vector>

#include "tetcut/vec3.hpp"

namespace tetcut::bench {

// The tool's diameter on the bundled liver (mm): finer meshes scale it with their edge length.
inline constexpr double kGatedToolDiameter = 8.0;

// Tool centres: passes across the organ in the plane x = 95 mm, every 4 mm from y = 40 to 180,
// at 7 heights z = 60, 75, ..., 150 (the paths of corpus/scenarios/liver-resection.scn, thinned):
// 252 cuts.
inline std::vector<Vec3> gated_sweep_centres() {
  std::vector<Vec3> c;
  for (double z = 60; z <= 150; z += 15)
    for (double y = 40; y <= 180; y += 4) c.push_back({95, y, z});
  return c;
}

// The same passes as strokes of the swept tool (Cutter::cut_segment): each pass's consecutive
// centres joined by a capsule, 4 mm long: 7 passes of 35, 245 cuts.
struct Stroke {
  Vec3 from, to;
};
inline std::vector<Stroke> gated_strokes() {
  std::vector<Stroke> s;
  for (double z = 60; z <= 150; z += 15)
    for (double y = 40; y + 4 <= 180; y += 4) s.push_back({{95, y, z}, {95, y + 4, z}});
  return s;
}

}  // namespace tetcut::bench
