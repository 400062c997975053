#include "tetcut/harness/engine_fuzz.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <stdexcept>

#include "core/random.hpp"
#include "tetcut/harness/engine_regression.hpp"

namespace tetcut::harness {

namespace fs = std::filesystem;

std::vector<std::uint8_t> mutate(const std::vector<std::uint8_t>& input, const std::vector<std::vector<std::uint8_t>>& seeds,
                                 std::uint64_t& random_state) {
  SplitMix64 random(random_state);
  std::vector<std::uint8_t> out = input;
  if (out.size() < 2) out.resize(2, 0);
  const std::uint32_t mutations = 1 + random.below(4);
  for (std::uint32_t m = 0; m < mutations; ++m) {
    // Index 0 is the version byte: never touched.
    const auto body = static_cast<std::uint32_t>(out.size() - 1);
    const std::uint32_t at = 1 + random.below(body);
    switch (random.below(6)) {
      case 0:
        out[at] = static_cast<std::uint8_t>(out[at] ^ (1u << random.below(8)));
        break;
      case 1:
        out[at] = static_cast<std::uint8_t>(random.below(256));
        break;
      case 2:
        out.insert(out.begin() + at, static_cast<std::uint8_t>(random.below(256)));
        break;
      case 3:
        if (out.size() > 2) out.erase(out.begin() + at);
        break;
      case 4: {  // a span of the input copied over another place in it
        const std::uint32_t length = 1 + random.below(std::min<std::uint32_t>(body, 16));
        const std::uint32_t from = 1 + random.below(body);
        for (std::uint32_t i = 0; i < length && from + i < out.size() && at + i < out.size(); ++i) {
          out[at + i] = out[from + i];
        }
        break;
      }
      default: {  // the tail of another seed after this input's head
        const std::vector<std::uint8_t>& other = seeds[random.below(static_cast<std::uint32_t>(seeds.size()))];
        if (other.size() > 2) {
          const std::uint32_t cut = 2 + random.below(static_cast<std::uint32_t>(other.size() - 2));
          out.resize(at);
          out.insert(out.end(), other.begin() + cut, other.end());
        }
        break;
      }
    }
  }
  if (out.size() > kMaxEngineInputSize) out.resize(kMaxEngineInputSize);
  random_state = random.next();
  return out;
}

std::vector<std::vector<std::uint8_t>> load_engine_seeds(const std::string& corpus_dir, EngineTarget target) {
  const fs::path dir = fs::path(corpus_dir) / "fuzz" / "engines" / std::string(target_name(target));
  std::vector<fs::path> paths;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    if (entry.is_regular_file() && entry.path().filename().string().front() != '.') paths.push_back(entry.path());
  }
  std::sort(paths.begin(), paths.end());
  if (paths.empty()) throw std::runtime_error(dir.string() + ": no seed inputs");
  std::vector<std::vector<std::uint8_t>> seeds;
  for (const fs::path& path : paths) {
    std::ifstream in(path, std::ios::binary);
    seeds.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  return seeds;
}

EngineFuzzResult fuzz_engine(const AdapterInfo& adapter, const EngineFuzzOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<FuzzMesh> meshes = load_fuzz_meshes(options.corpus_dir);
  const std::vector<std::vector<std::uint8_t>> seeds = load_engine_seeds(options.corpus_dir, options.target);
  const std::string target(target_name(options.target));
  std::uint64_t random_state = options.seed;
  std::set<std::string> seen;
  EngineFuzzResult result;
  for (std::uint64_t run = 0; run < options.runs; ++run) {
    const std::vector<std::uint8_t> input =
        run < seeds.size() ? seeds[run] : mutate(seeds[random_state % seeds.size()], seeds, random_state);
    EnginePlan plan = decode_engine_input(input, options.target, meshes);
    if (plan.operations.empty()) continue;
    ++result.runs;
    const PlanCheck check = check_plan(adapter, plan, options.check);
    const std::string signature = signature_of(check);
    if (signature.empty()) continue;
    ++result.failing;
    if (!seen.insert(signature).second) continue;
    EngineFinding finding;
    finding.run = run;
    finding.signature = signature;
    finding.first_operation = check.failed_operation_name;
    finding.operations = plan.operations.size();
    // What follows the failing operation played no part in it.
    if (check.failed_operation && *check.failed_operation > 0 && *check.failed_operation <= plan.operations.size()) {
      plan.operations.resize(*check.failed_operation);
    }
    const Minimized minimized = minimize_plan(adapter, plan, signature, options.check);
    finding.minimized_operations = minimized.plan.operations.size();
    finding.minimize_checks = minimized.checks;
    const std::string dir =
        options.regressions_dir.empty() ? "" : (fs::path(options.regressions_dir) / adapter.name / target).string();
    const std::string header = "A finding of `tetcut check-engine --fuzz " + target + "` on adapter '" + adapter.name +
                               "', input " + std::to_string(run) + " of seed " + std::to_string(options.seed) +
                               ",\nminimized from " + std::to_string(finding.operations) + " operations to " +
                               std::to_string(finding.minimized_operations) +
                               ". tests/harness/engine_regressions_test.cpp replays it: it must still\n"
                               "fail on that engine with this signature, and tetcut must pass it.\n"
                               "engine: " + adapter.name + "\nsignature: " + signature;
    finding.scenario = scenario_text(minimized.plan, dir.empty() ? fs::current_path().string() : dir, header);
    if (!dir.empty()) {
      finding.path = write_regression(dir, regression_name(signature, minimized.plan, finding.scenario), finding.scenario);
    }
    result.findings.push_back(std::move(finding));
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace tetcut::harness
