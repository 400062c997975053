// The haptic stress harness (docs/mechanics.md, "Snapshots for other threads"): a cutting thread
// runs the gated sweep on the bundled liver as fast as it goes, each cut followed by the model's
// and the surface's update, one explicit step and a publish (SnapshotPublisher); a haptic thread
// reads the latest frame every millisecond and a render thread every 1/60 s, both checking each
// frame whole (its checksum is the one published with it) and its sequence never going back.
//
// Reported: the readers' wait for a frame (the lease: the time latest() takes) and read time
// (the checksum over the whole frame, which a real haptic loop would not need), the haptic loop's
// period jitter (how late each wake-up is against its schedule: std::this_thread::sleep_until on
// steady_clock, default SCHED_OTHER scheduling, no real-time priority, timer slack 1 ns), and the
// cutter's time per sweep with the readers against without them (runs alternated, the median of
// each). Timings are meaningful from Release. Exit 1 on a torn or backward frame, 2 on bad arguments.
//
//   haptic_stress [--rounds N] [--sweeps N] [--json FILE]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "bench_meshes.hpp"
#include "gated_sweep.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/mechanics/periodic_reader.hpp"
#include "tetcut/mechanics/reaction_force.hpp"
#include "tetcut/mechanics/rendered_surface.hpp"
#include "tetcut/mechanics/snapshot.hpp"
#include "tetcut/mechanics/tensor_mass.hpp"
#include "tetcut/percentile.hpp"

namespace {

using namespace tetcut;
using Clock = std::chrono::steady_clock;
using mechanics::SnapshotPublisher;
using ReaderFigures = mechanics::PeriodicReader::Figures;

// The cutting thread's work: `sweeps` times the gated sweep on a fresh copy of the liver, each
// cut applied, stepped and published. Returns the seconds it took.
double cut_and_publish(SnapshotPublisher& publisher, int sweeps) {
  double seconds = 0;
  for (int s = 0; s < sweeps; ++s) {
    TetMesh mesh = bench::corpus_mesh("liver.msh");
    Cutter cutter(mesh, {.tool_diameter = bench::kGatedToolDiameter});
    mechanics::ModelParams params;
    params.gravity = {0, 0, -9.81};
    mechanics::TensorMassModel model(mesh, params);
    model.fix_where(mesh, [](const Vec3& x) { return x.x > 150; });
    mechanics::RenderedSurface surface(mesh);
    const double dt = 0.5 * model.stable_time_step(mesh).dt;
    std::vector<Vec3> forces;
    ChangeLog log;
    log.reserve(4096);
    publisher.publish(mesh, model, surface, nullptr, true, {});
    const Clock::time_point start = Clock::now();
    for (const Vec3& centre : bench::gated_sweep_centres()) {
      log.clear();
      if (cutter.cut(centre, &log).ok) {
        model.apply(mesh, log);
        surface.apply(mesh, log);
      }
      model.step(dt);
      // The tool's reaction: the elastic forces on the vertices within the tool (paper 4).
      const Vec3 reaction = mechanics::reaction_force(mesh, model, centre, centre, bench::kGatedToolDiameter / 2, forces);
      publisher.publish(mesh, model, surface, &log, true, reaction);
    }
    seconds += std::chrono::duration<double>(Clock::now() - start).count();
  }
  return seconds;
}

// Each round's figures after the earlier rounds'.
void append(ReaderFigures& all, const ReaderFigures& round) {
  all.wait_us.insert(all.wait_us.end(), round.wait_us.begin(), round.wait_us.end());
  all.read_us.insert(all.read_us.end(), round.read_us.begin(), round.read_us.end());
  all.late_us.insert(all.late_us.end(), round.late_us.begin(), round.late_us.end());
  all.reads += round.reads;
  all.torn += round.torn;
  all.backwards += round.backwards;
}

std::string figures_json(const char* name, std::vector<double> v) {
  char text[256];
  std::snprintf(text, sizeof text, "\"%s\": {\"p50\": %.3f, \"p99\": %.3f, \"max\": %.3f, \"n\": %zu}", name,
                v.empty() ? 0.0 : percentile(v, 0.5), v.empty() ? 0.0 : percentile(v, 0.99),
                v.empty() ? 0.0 : *std::max_element(v.begin(), v.end()), v.size());
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  int rounds = 3, sweeps = 1;
  std::string json;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--rounds" && i + 1 < argc) {
      rounds = std::atoi(argv[++i]);
    } else if (a == "--sweeps" && i + 1 < argc) {
      sweeps = std::atoi(argv[++i]);
    } else if (a == "--json" && i + 1 < argc) {
      json = argv[++i];
    } else {
      std::fprintf(stderr, "usage: haptic_stress [--rounds N] [--sweeps N] [--json FILE]\n");
      return 2;
    }
  }
  if (rounds < 1 || sweeps < 1) {
    std::fprintf(stderr, "haptic_stress: --rounds and --sweeps must be at least 1\n");
    return 2;
  }
  std::vector<double> alone_s, read_s;
  ReaderFigures haptic, render;
  std::uint64_t publishes = 0, skipped = 0;
  for (int round = 0; round < rounds; ++round) {
    {
      SnapshotPublisher publisher({.readers = 2, .checksums = true});
      alone_s.push_back(cut_and_publish(publisher, sweeps));
    }
    SnapshotPublisher publisher({.readers = 2, .checksums = true});
    mechanics::PeriodicReader h(publisher, {.period = std::chrono::microseconds(1000)});
    mechanics::PeriodicReader r(publisher, {.period = std::chrono::microseconds(16667)});
    read_s.push_back(cut_and_publish(publisher, sweeps));
    append(haptic, h.stop());
    append(render, r.stop());
    publishes += publisher.stats().publishes;
    skipped += publisher.stats().skipped;
  }
  const double cuts = static_cast<double>(bench::gated_sweep_centres().size()) * sweeps;
  const double alone = percentile(alone_s, 0.5), with = percentile(read_s, 0.5);
  std::printf("cutter (cut + update + step + publish): %.1f us a cut alone, %.1f us with the readers: %+.1f %%\n",
              1e6 * alone / cuts, 1e6 * with / cuts, 100.0 * (with / alone - 1.0));
  auto line = [](const char* who, const ReaderFigures& f) {
    std::printf("%s: %zu reads, wait p50 %.3f us p99 %.3f us max %.3f us; read p50 %.1f us p99 %.1f us; "
                "late p50 %.1f us p99 %.1f us max %.1f us; %llu torn, %llu backwards\n",
                who, static_cast<std::size_t>(f.reads), percentile(f.wait_us, 0.5), percentile(f.wait_us, 0.99),
                *std::max_element(f.wait_us.begin(), f.wait_us.end()), percentile(f.read_us, 0.5),
                percentile(f.read_us, 0.99), percentile(f.late_us, 0.5), percentile(f.late_us, 0.99),
                *std::max_element(f.late_us.begin(), f.late_us.end()), static_cast<unsigned long long>(f.torn),
                static_cast<unsigned long long>(f.backwards));
  };
  if (haptic.wait_us.empty() || render.wait_us.empty()) {
    std::fprintf(stderr, "haptic_stress: a reader read nothing: the run was too short\n");
    return 1;
  }
  line("haptic (1 kHz)", haptic);
  line("render (60 Hz)", render);
  std::printf("%llu publishes, %llu skipped; %u hardware threads\n", static_cast<unsigned long long>(publishes),
              static_cast<unsigned long long>(skipped), std::thread::hardware_concurrency());
  if (!json.empty()) {
    std::ofstream out(json + ".tmp");
    out << "{\"cut_alone_us\": " << 1e6 * alone / cuts << ", \"cut_with_readers_us\": " << 1e6 * with / cuts
        << ", \"haptic\": {" << figures_json("wait_us", haptic.wait_us) << ", " << figures_json("read_us", haptic.read_us)
        << ", " << figures_json("late_us", haptic.late_us) << "}, \"render\": {" << figures_json("wait_us", render.wait_us)
        << ", " << figures_json("read_us", render.read_us) << ", " << figures_json("late_us", render.late_us)
        << "}, \"torn\": " << haptic.torn + render.torn << ", \"backwards\": " << haptic.backwards + render.backwards
        << ", \"hardware_threads\": " << std::thread::hardware_concurrency() << "}\n";
    out.close();
    std::rename((json + ".tmp").c_str(), json.c_str());
  }
  return haptic.torn + render.torn + haptic.backwards + render.backwards == 0 ? 0 : 1;
}
