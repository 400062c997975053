// The table of `tetcut` subcommands and their help texts.
#include <array>
#include <ostream>

#include "command.hpp"

namespace tetcut::cli {

namespace {

constexpr std::string_view kCheckHelp =
    "Runs the independent invariant checker (I1-I9) on a mesh file and names every violated\n"
    "invariant with its count, its first offending tets and vertices, and a detail line.\n"
    "\n"
    "The file is checked from its raw arrays, so a non-manifold or inverted mesh is diagnosed\n"
    "rather than refused. If the engine can also build its mesh from the file, that mesh is\n"
    "checked too (adjacency I2 and bookkeeping I8), and a refusal by the engine is reported.\n"
    "\n"
    "  --level full    (default) every invariant, O(n)\n"
    "  --level exact   full, plus the geometric tests (boundary self-intersection, exact)\n"
    "  --level local   builds the engine mesh and runs the local checker as if one operation\n"
    "                  had just replaced every tet by itself, so that the code path run after\n"
    "                  each cut is exercised on the whole file; if the engine cannot build the\n"
    "                  mesh, falls back to the full check of the raw arrays (with a note)\n"
    "  --min-radius-ratio R   I7: a tet with radius ratio below R (0..1) is a violation\n"
    "  --json          the report as JSON on stdout\n"
    "\n"
    "exit: 0 valid, 1 an invariant is violated, 2 unreadable input or bad usage\n";

constexpr std::string_view kInfoHelp =
    "Prints counts, boundary, volume, quality statistics (radius ratio min/mean/histogram,\n"
    "minimum dihedral angle), bounding box, manifold status and the canonical hash of a mesh.\n"
    "\n"
    "  --json   as JSON (quality values are null when there are no tets): keys vertices,\n"
    "           tets, boundary_faces, volume, min_radius_ratio,\n"
    "           mean_radius_ratio, min_dihedral_deg, mean_min_dihedral_deg,\n"
    "           radius_ratio_histogram, bounding_box, manifold, oriented, hash, ...\n"
    "\n"
    "`manifold` is true when the full checker finds no violation of I1, I3, I5 or I6;\n"
    "`oriented` when it finds none of I4.\n"
    "\n"
    "exit: 0, 2 unreadable input or bad usage\n";

constexpr std::string_view kConvertHelp =
    "Converts a mesh between the supported formats, chosen by file extension, and prints the\n"
    "canonical hash of the mesh (identical for IN and OUT when the round trip is faithful).\n"
    "IN may be any format tetcut reads (ASCII, binary or compressed; see the README).\n"
    "The output is written to a temporary file and renamed: a failure leaves no partial file.\n"
    "\n"
    "  --format F       the output format, for when the extension is not enough: msh22 (the\n"
    "                   default for .msh) or msh41; also vtu, vtk, medit, tetgen\n"
    "  --binary         binary output: Gmsh binary MSH, legacy VTK BINARY, VTU appended raw\n"
    "                   data (medit and TetGen are text only)\n"
    "  --compress C     VTU only, binary: zlib (vtkZLibDataCompressor) or lzma (xz)\n"
    "  --reorient       turn every negatively oriented tet positive (two vertices swapped), as\n"
    "                   the mesh builder does on request; for meshes from tools whose convention\n"
    "                   is the opposite of tetcut's\n"
    "\n"
    "exit: 0, 2 unreadable input, unwritable output, a mesh --reorient cannot build, or bad usage\n";

constexpr std::string_view kGenHelp =
    "Generates a mesh: cylinder, sheet, box (TetGen), surface FILE (any closed .off/.stl/.obj\n"
    "surface, or a VTK POLYDATA surface .vtk/.vtp, through TetGen), liver (CGAL Mesh_3).\n"
    "Prints the canonical hash.\n"
    "\n"
    "exit: 0, 2 bad parameters or unwritable output\n";

constexpr std::string_view kRepairHelp =
    "Makes a non-manifold or inverted mesh manifold and positively oriented with the smallest\n"
    "change it can, and reports what it changed.\n"
    "\n"
    "exit: 0, 1 the mesh could not be repaired, 2 unreadable input or bad usage\n";

constexpr std::string_view kRefineHelp =
    "Refines a mesh locally by edge splitting (paper 3.2) and checks the result.\n"
    "\n"
    "  --uniform                 split every edge once (8 times the tets)\n"
    "  --random-edges N --seed S split N edges picked at random\n"
    "  --ball X,Y,Z,R            the paper's loop around a tool of radius R:\n"
    "      --dref D              split edges longer than D (default 1.5 x tool diameter)\n"
    "      --p P                 also split shell edges longer than P x |e| (default 1.5)\n"
    "      --max-iterations N    bound on the loop (default 8)\n"
    "  --strategy templates|bisection   the 10 split configurations, or sequential bisection\n"
    "  --report R.json           summary: iterations, edges_split, tets_created,\n"
    "                            min_radius_ratio, hash\n"
    "\n"
    "exit: 0, 1 the result violates an invariant or a split was refused, 2 bad input or usage\n";

constexpr std::string_view kRemoveHelp =
    "Removes tetrahedra without breaking the manifold (paper 3.3-3.7) and prints the paper's\n"
    "statistics (Tables 1 and 2). --at X,Y,Z (several separated by ';' or as further arguments)\n"
    "removes the tet containing each point in turn; --random N|all --seed S requests tets on the\n"
    "current boundary one at a time, as a cautery meets them. --check every: local checker after\n"
    "every request and full check at the end; end (default): full check at the end; none.\n"
    "The report's summary: requested, removed, unresolved, direct, vertex_singularities,\n"
    "edge_singularities, resolved_by_neighbours, resolved_by_refinement, mean_cardinality,\n"
    "tets_left, hash.\n"
    "\n"
    "exit: 0, 1 an invariant broke, 2 unreadable input or bad usage\n";

constexpr std::string_view kCutHelp =
    "A cautery sweep: one cut every STEP from --from to --to with a tool of the given diameter,\n"
    "each cut refined then removed without breaking the manifold (paper 3.1-3.7).\n"
    "\n"
    "  --strategy basic|neighbours|combined|wide   removal strategy (default combined)\n"
    "  --split templates|bisection            refinement (default templates)\n"
    "  --dref-factor F --p P --depth N        the paper's parameters (1.5, 1.5, 10)\n"
    "  --check every|end|none   local check after every cut (default), full check at the end\n"
    "  --out M                  the final mesh\n"
    "  --report R.json          `cuts` (time in microseconds and counts per cut) and `summary`\n"
    "                           (cuts, first_us, p50_us, p90_us, p99_us, max_us (over all\n"
    "                           cuts, the first included), tets_removed,\n"
    "                           tets_created, unresolved, min_radius_ratio, hash)\n"
    "  --frames DIR             a .vtu snapshot after every cut, for ParaView\n"
    "\n"
    "exit: 0, 1 an invariant broke, 2 bad input or usage\n";

constexpr std::string_view kStatsHelp =
    "Redoes the paper's experiment (section 3.6): five meshes of its kinds (cylinder, sheet, coarse\n"
    "liver, finer liver, locally refined liver), each cut by the cautery scenario in\n"
    "CORPUS/scenarios/paper/ with the combined strategy, and prints Tables 1 and 2 with the paper's\n"
    "figures and the difference beside ours. Then compares the strategies (basic, neighbours,\n"
    "combined; templates and bisection) on one of those scenarios, and runs the liver resection\n"
    "(CORPUS/scenarios/liver-resection.scn) for the report's plots and pictures.\n"
    "\n"
    "  --corpus DIR        the corpus folder (default: corpus, as from the repository's root)\n"
    "  --mesh NAME         the strategy comparison's mesh (default liver-refined)\n"
    "  --check every|end   the local checker after every cut (default) or the full one at the end\n"
    "  --json FILE         everything as JSON: keys table1, table2 (one row per mesh, with paper\n"
    "                      and diff), strategies (one row per strategy), resection\n"
    "  --html FILE         a self-contained HTML report: tables, latency plot, quality\n"
    "                      histograms, the liver before and after the resection as SVG\n"
    "  --pictures DIR      the report's pictures as DIR/latency-plot.svg, quality-histogram.svg,\n"
    "                      liver-before.svg and liver-after.svg (DIR must exist)\n"
    "\n"
    "Only the times (p50_us, p99_us, cut_us) vary between runs; every other figure is\n"
    "deterministic.\n"
    "\n"
    "exit: 0 done, 1 a scenario failed a check or the combined strategy left a tet unresolved,\n"
    "2 unusable corpus or bad usage\n";

constexpr std::string_view kRunHelp =
    "Runs a scenario file: one operation a line (mesh, diameter, strategy, cut, sweep, remove,\n"
    "compact, check, expect hash|tets|unresolved|components), tets and tools addressed by points\n"
    "so that scenarios survive changes of internal ids. See corpus/scenarios/ and\n"
    "tools/scenario/include/tetcut/scenario/scenario.hpp.\n"
    "\n"
    "  --check every|end|none   local check after every operation (default)\n"
    "  --out M  --report R.json as for tetcut cut\n"
    "\n"
    "exit: 0 passed, 1 a check or expectation failed (its line is named), 2 unusable input\n";

constexpr std::string_view kReplayHelp =
    "Decodes an input of a sequence fuzz target (removal_sequence, cut_sequence) into a scenario,\n"
    "prints it, and runs it through the target's own entry point with every check the target\n"
    "makes (local check after every operation, full checks, every request resolved under the\n"
    "combined strategy, rolled back cuts leaving the mesh as it was). Names the first failing\n"
    "operation and its scenario line, then says whether the scenario alone reproduces it under\n"
    "`tetcut run` (the input of `tetcut minimize`).\n"
    "\n"
    "  --target NAME         removal_sequence or cut_sequence\n"
    "  --scenario-out FILE   also write the scenario (mesh paths relative to FILE's folder)\n"
    "\n"
    "exit: 0 the input passes, 1 an operation fails, 2 unreadable input, not the target's\n"
    "input version, or bad usage\n";

constexpr std::string_view kMinimizeHelp =
    "Shrinks a failing scenario (one `tetcut run` exits 1 on) while it keeps failing with the\n"
    "same kind of error (an invariant by its id, an expectation by its kind, a failed cut):\n"
    "deletes operations (ddmin: chunks, then single lines), turns sweeps into single cuts and\n"
    "rounds coordinates. Every candidate is a full run. Writes OUT atomically.\n"
    "\n"
    "  -o OUT           the minimized scenario (mesh paths relative to its folder)\n"
    "  --max-runs N     stop after N runs of candidates (default 2000)\n"
    "\n"
    "exit: 0 written, 2 the scenario does not fail (or does not parse), unwritable OUT, or bad\n"
    "usage\n";

constexpr std::array kCommands = {
    CommandInfo{"info", "tetcut info MESH [--json]",
                "counts, boundary, quality statistics, manifold status, hash", kInfoHelp,
                &cmd_info},
    CommandInfo{"check",
                "tetcut check MESH [--level local|full|exact] [--min-radius-ratio R] [--json]",
                "runs the invariant checker, names each violated invariant", kCheckHelp,
                &cmd_check},
    CommandInfo{"convert", "tetcut convert IN OUT [--format F] [--binary] [--compress zlib|lzma] [--reorient]",
                "converts between the supported formats",
                kConvertHelp, &cmd_convert},
    CommandInfo{"gen", "tetcut gen KIND [OPTIONS] -o OUT",
                "generates a mesh (cylinder, sheet, box, surface, liver)", kGenHelp, &cmd_gen},
    CommandInfo{"repair", "tetcut repair IN -o OUT",
                "makes a mesh manifold and positively oriented", kRepairHelp, &cmd_repair},
    CommandInfo{"refine",
                "tetcut refine MESH (--uniform | --random-edges N --seed S | --ball X,Y,Z,R [--dref D] [--p P]) "
                "[--strategy templates|bisection] -o OUT [--report R.json]",
                "refines by edge splitting (10 configurations or bisection)", kRefineHelp, &cmd_refine},
    CommandInfo{"remove",
                "tetcut remove MESH (--at X,Y,Z ... | --random N|all --seed S) [--strategy basic|neighbours|combined|wide] "
                "[--check every|end|none] -o OUT [--report R.json]",
                "removes tetrahedra without breaking the manifold (paper 3.3-3.7)", kRemoveHelp, &cmd_remove},
    CommandInfo{"cut",
                "tetcut cut MESH --diameter D --from X,Y,Z --to X,Y,Z --step S [--strategy S] "
                "[--check every|end|none] [--out M] [--report R.json] [--frames DIR]",
                "a cautery sweep, one cut per step", kCutHelp, &cmd_cut},
    CommandInfo{"run", "tetcut run SCENARIO [--check every|end|none] [--out M] [--report R.json]",
                "runs a scenario file", kRunHelp, &cmd_run},
    CommandInfo{"stats",
                "tetcut stats [--corpus DIR] [--mesh NAME] [--check every|end] [--json FILE] [--html FILE] "
                "[--pictures DIR]",
                "the paper's Tables 1 and 2, a strategy comparison and an HTML report", kStatsHelp, &cmd_stats},
    CommandInfo{"replay", "tetcut replay INPUT --target NAME [--scenario-out FILE]",
                "decodes a fuzz input into a scenario and runs it", kReplayHelp, &cmd_replay},
    CommandInfo{"minimize", "tetcut minimize SCENARIO -o OUT [--max-runs N]",
                "shrinks a failing scenario while it still fails", kMinimizeHelp, &cmd_minimize},
};

}  // namespace

std::span<const CommandInfo> commands() { return kCommands; }

const CommandInfo* find_command(std::string_view name) {
  for (const CommandInfo& c : kCommands) {
    if (c.name == name) return &c;
  }
  return nullptr;
}

int usage_error(std::string_view command, std::string_view message, std::ostream& err) {
  err << "tetcut: " << command << ": " << message << '\n';
  if (const CommandInfo* info = find_command(command)) {
    err << "usage: " << info->synopsis << '\n';
  }
  return kExitBadInput;
}

}  // namespace tetcut::cli
