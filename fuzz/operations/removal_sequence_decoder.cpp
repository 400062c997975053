#include "operations/removal_sequence_decoder.hpp"

#include <algorithm>
#include <vector>

#include "operations/sequence_session.hpp"
#include "remove/removal.hpp"

namespace tetcut::fuzz::removal_sequence {
namespace {

// max_operation_size: the most tets of a set. Version 2's few operations: most of an input's
// time is in the requests themselves once the mesh is small.
constexpr VersionedLimits kLimits{{24, 16, 6}, {8, 8, 4}};

enum class Op : std::uint8_t { kStrategy, kRemoveBoundary, kRemoveAny, kRemovePoint, kRemoveSet, kLast = kRemoveSet };

Vec3 centroid(const TetMesh& mesh, TetId t) {
  const auto v = mesh.tet(t);
  return 0.25 * (mesh.position(v[0]) + mesh.position(v[1]) + mesh.position(v[2]) + mesh.position(v[3]));
}

TetId consume_boundary_tet(const TetMesh& mesh, FuzzedDataProvider& input) {
  return consume_live_tet_where(mesh, input, [&](TetId t) { return mesh.boundary_face_count(t) > 0; });
}

void request(SequenceSession& session, const Vec3& p, const std::string& name) {
  const std::uint32_t line = session.recorder().add("remove " + format_point(p));
  const OperationOutcome outcome = session.remove_at(p, name, line);
  if (outcome.rolled_back)
    session.recorder().replace(line, "# remove " + format_point(p) + "   rolled back (" + outcome.reason +
                                         "): the mesh is as before");
}

// A boundary tet and its face neighbours breadth first (face order), up to `size` tets: a patch
// a cautery would meet at once. Their centroids are taken before the first request, as a
// simulator's selection would be; a later request whose tet went with an earlier one's set
// finds another tet there, or none.
void request_set(SequenceSession& session, FuzzedDataProvider& input, std::uint32_t max_size) {
  const TetMesh& mesh = session.mesh();
  const TetId seed = consume_boundary_tet(mesh, input);
  const std::uint32_t size = input.ConsumeIntegralInRange<std::uint32_t>(2, max_size);
  std::vector<TetId> set;
  if (seed.valid()) set.push_back(seed);
  for (std::size_t i = 0; i < set.size() && set.size() < size; ++i)
    for (int f = 0; f < 4 && set.size() < size; ++f) {
      const FaceRef n = mesh.neighbour(set[i], f);
      if (n.valid() && std::find(set.begin(), set.end(), n.tet) == set.end()) set.push_back(n.tet);
    }
  std::vector<Vec3> points;
  for (TetId t : set) points.push_back(centroid(mesh, t));
  for (std::size_t i = 0; i < points.size(); ++i)
    request(session, points[i], "remove set " + std::to_string(i + 1) + "/" + std::to_string(points.size()));
}

void body(std::uint8_t version, FuzzedDataProvider& input, ScenarioRecorder& recorder) {
  const SequenceLimits& limits = kLimits.of(version);
  const SequenceStart start = start_sequence("removal_sequence", version, input, recorder);
  SequenceSession& session = start.session;
  const BundledMesh& bundled = start.bundled;
  CutParams params = session.cutter().params();
  const double quantum = coordinate_quantum(bundled.box.diagonal(), 3);
  const Vec3 margin = 0.1 * (bundled.box.hi - bundled.box.lo);
  run_operations(start, input, limits, [&] {
    const Op op = static_cast<Op>(input.ConsumeIntegralInRange<std::uint8_t>(0, static_cast<std::uint8_t>(Op::kLast)));
    const TetMesh& mesh = session.mesh();
    switch (op) {
      case Op::kStrategy:
        params.strategy = consume_strategy(version, input);
        session.set_param("strategy", to_string(params.strategy), params);
        if (version >= kSequenceVersionReadings) {  // paper 3.5's two readings
          params.neighbour_set = input.ConsumeBool() ? NeighbourSetChoice::kFirst : NeighbourSetChoice::kSmallest;
          session.set_param("neighbour_set", to_string(params.neighbour_set), params);
        }
        break;
      case Op::kRemoveBoundary:
      case Op::kRemoveAny: {
        const TetId t = op == Op::kRemoveBoundary ? consume_boundary_tet(mesh, input) : consume_live_tet(mesh, input);
        if (t.valid()) request(session, centroid(mesh, t), op == Op::kRemoveBoundary ? "remove boundary" : "remove any");
        break;
      }
      case Op::kRemovePoint: {
        const Vec3 lo = bundled.box.lo - margin, span = (bundled.box.hi + margin) - lo;
        const Vec3 p{round_to(lo.x + span.x * consume_unit(input), quantum),
                     round_to(lo.y + span.y * consume_unit(input), quantum),
                     round_to(lo.z + span.z * consume_unit(input), quantum)};
        request(session, p, "remove point");
        break;
      }
      case Op::kRemoveSet: request_set(session, input, limits.max_operation_size); break;
    }
  });
}

}  // namespace

SequenceResult run(const std::uint8_t* data, std::size_t size, const SequenceOptions& options) {
  return run_sequence(data, size, options, body);
}

}  // namespace tetcut::fuzz::removal_sequence
