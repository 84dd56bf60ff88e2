// `motiongp table2 [--iters T] [--active M] [--max-delta CM] [--runs K] [--clip FILE[:A:B] --edit
// EFF:dx,dy,dz [--frame F] [--reference FILE[:A:B]]…] [--threads N] [--quick] [--json]`: the
// paper's Table 2 (editing range in cm) under the protocol of docs/maths.md §14, run by
// eval/table2_protocol.h; this file only reads the options and prints the table.
#include <algorithm>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <thread>

#include "cli_common.h"
#include "command_registry.h"
#include "eval/table2_protocol.h"
#include "io/data_paths.h"

namespace mgp::app {
namespace {

struct Table2Options {
    int iters = 10, active = 200, maxDelta = 80, runs = 1, frame = 0, threads = 0;
    bool quick = false, json = false;
    std::vector<std::string> clips, references;
    std::string edit;
};

// The row of each --clip, all with the one --edit, --frame and --references.
std::vector<Table2Row> rowsFromClips(const Table2Options& o) {
    if (o.edit.empty()) throw UsageError("expected --edit EFFECTOR:dx,dy,dz with --clip, found none");
    std::vector<Table2Row> rows;
    try {
        for (const std::string& spec : o.clips) {
            TrialCache cache;
            const int frames = joinSegments("", {parseClipSpec(spec)}, cache).frameCount();
            rows.push_back(table2RowFromSpec(spec, o.edit, o.frame, o.references, frames));
        }
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    return rows;
}

std::string rangeCell(const nlohmann::json& r) {
    std::ostringstream s;
    if (!r.contains("combined")) return "-";
    s << r["combined"];
    if (r.contains("reach"))
        s << " (" << r["reach"] << "/" << r["joint_ranges"] << "/" << r["nearest_real_pose"] << "/" << r["density"]
          << "/" << r["continuity"] << ")";
    return s.str();
}

std::string bindingCell(const nlohmann::json& r) {
    std::string s;
    if (r.contains("binding"))
        for (const auto& b : r["binding"]) s += (s.empty() ? "" : "+") + b.get<std::string>();
    return s.empty() ? "none" : s;
}

void printTable(const nlohmann::json& out, int runs) {
    const auto& cells = out["settings"]["cells"];
    std::cout << std::left << std::setw(14) << "motion" << std::setw(22) << "edit";
    for (const auto& c : cells) std::cout << std::setw(runs == 1 ? 26 : 16) << c.get<std::string>();
    std::cout << "\n";
    for (const auto& e : out["rows"]) {
        std::cout << std::setw(14) << e["kind"].get<std::string>() << std::setw(22)
                  << e["edit"].get<std::string>().substr(0, 21);
        for (const auto& c : cells) {
            const std::string key = c.get<std::string>();
            if (runs == 1) {
                std::cout << std::setw(26) << (e.contains(key) ? rangeCell(e[key]) : std::string("-"));
            } else {
                char buf[64] = "-";
                if (e["spread"].contains(key))
                    std::snprintf(buf, sizeof buf, "%.1f ± %.1f", e["spread"][key]["mean"].get<double>(),
                                  e["spread"][key]["sd"].get<double>());
                std::cout << std::setw(16) << buf;
            }
        }
        std::cout << "\n";
        if (runs == 1) {
            std::cout << std::setw(36) << "  binding at range + 1 cm:";
            for (const auto& c : cells) {
                const std::string key = c.get<std::string>();
                std::cout << std::setw(26) << (e.contains(key) ? bindingCell(e[key]) : std::string("-"));
            }
            std::cout << "\n";
        }
    }
    if (runs == 1)
        std::cout << "(combined (reach/ranges/NN/density/continuity); -1: fails at δ = 0. Learned vs plain IK: see "
                     "--json.)\n";
    else
        std::cout << "(combined range, mean ± sd over " << runs
                  << " runs; each run's cells and binding tests: see --json.)\n";
}

int runTable2Command(Table2Options o) {
    Table2Settings settings;
    if (o.quick) {  // the shipped clips, small sizes: well under a minute
        settings.rows = table2QuickRows();
        o.iters = std::min(o.iters, 2);
        o.active = std::min(o.active, 100);
        o.maxDelta = std::min(o.maxDelta, 30);
    }
    if (!o.clips.empty())
        settings.rows = rowsFromClips(o);
    else if (!o.edit.empty() || !o.references.empty() || o.frame != 0)
        throw UsageError("expected --clip with --edit, --frame or --reference, found no --clip");
    settings.outerIterations = o.iters;
    settings.activeSize = o.active;
    settings.maxDeltaCm = o.maxDelta;
    settings.quick = o.quick;
    settings.runs = o.runs;
    settings.workers =
        o.runs > 1 ? (o.threads > 0 ? o.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency())))
                   : 1;
    try {
        settings.validate();
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    const auto dir = !o.clips.empty() ? std::optional<std::string>(globalOptions().dataDir)
                     : o.quick && globalOptions().dataDir.empty()
                         ? findShippedMocapFolder(globalOptions().exeDir)
                         : findMocapFolder(globalOptions().dataDir, globalOptions().exeDir);
    if (!dir)
        throw UsageError(o.quick ? "expected the shipped clips (assets/mocap) or --data, found neither"
                                 : "expected the CMU mocap folder (--data or $MOTIONGP_DATA), found none");
    const nlohmann::json out =
        runTable2(*dir, settings, [](const std::string& line) { std::cerr << "table2: " << line << std::endl; });
    if (o.json) {
        printJson(out);
        return 0;
    }
    const nlohmann::json& st = out["settings"];
    std::cout << "Table 2 — editing range (cm), δ in 1 cm steps up to " << st["max_delta_cm"]
              << "; T = " << st["outer_iterations"] << ", M = " << st["active"]
              << (o.quick ? " (quick: shipped clips)" : "") << "; " << st["perturbation"].get<std::string>() << "\n";
    printTable(out, settings.runs);
    printClaims(out["claims"]);
    return 0;
}

const CommandRegistration table2Command(
    "table2", "Editing range (paper Table 2) with model-independent naturalness tests",
    [](CLI::App& sub) -> CommandRunner {
        auto o = std::make_shared<Table2Options>();
        sub.add_option("--iters", o->iters, "Outer training iterations per model (default 10)")
            ->check(CLI::Range(1, 1000));
        sub.add_option("--active", o->active, "Active set size M (default 200)")->check(CLI::Range(2, 100000));
        sub.add_option("--max-delta", o->maxDelta, "Largest displacement in cm (default 80)")
            ->check(CLI::Range(1, 1000));
        sub.add_option("--runs", o->runs,
                       "Repeat every cell over K perturbed runs (docs/maths.md §14.5); report mean ± sd and a verdict "
                       "per claim (default 1)")
            ->check(CLI::Range(1, 50));
        sub.add_option("--clip", o->clips,
                       "Run on this clip instead of the paper's (a skeleton with the 22 CMU model bones: ASF/AMC, or a "
                       "BVH naming them; FILE:A:B keeps frames A..B); repeatable");
        sub.add_option(
            "--edit", o->edit,
            "With --clip: the edit, EFFECTOR:dx,dy,dz (lhand, rhand, lfoot, rfoot, head; a world direction, Y up)");
        sub.add_option("--frame", o->frame,
                       "With --clip: the edited frame, 1-based within the clip's A..B (default: the middle frame)")
            ->check(CLI::Range(1, 10000000));
        sub.add_option("--reference", o->references,
                       "With --clip: other real clips of the motion for R (FILE[:A:B]); repeatable");
        sub.add_option("--threads", o->threads,
                       "With --runs K: runs at once (default: all cores; results do not depend on it)")
            ->check(CLI::Range(0, 256));
        sub.add_flag("--quick", o->quick,
                     "Smoke run on the shipped clips (2 rows of 120 frames): T ≤ 2, M ≤ 100, δ ≤ 30");
        sub.add_flag("--json", o->json, "Print one JSON object");
        return [o]() { return runTable2Command(*o); };
    });

}  // namespace
}  // namespace mgp::app
