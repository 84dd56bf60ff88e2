// `motiongp table2 [--iters T] [--active M] [--max-delta CM] [--quick] [--json]`: the paper's
// Table 2 (editing range in cm) under the protocol of docs/maths.md §14, run by
// eval/table2_protocol.h; this file only reads the options and prints the table.
#include <iomanip>
#include <iostream>
#include <sstream>

#include "cli_common.h"
#include "command_registry.h"
#include "eval/table2_protocol.h"
#include "io/data_paths.h"

namespace mgp::app {
namespace {

int runTable2Command(int iters, int active, int maxDelta, bool quick, bool json) {
    Table2Settings settings;
    if (quick) {  // the shipped clips, small sizes: well under a minute
        settings.rows = table2QuickRows();
        iters = std::min(iters, 2);
        active = std::min(active, 100);
        maxDelta = std::min(maxDelta, 30);
    }
    settings.outerIterations = iters;
    settings.activeSize = active;
    settings.maxDeltaCm = maxDelta;
    settings.quick = quick;
    const auto dir = quick && globalOptions().dataDir.empty() ? findShippedMocapFolder(globalOptions().exeDir)
                                                              : findMocapFolder(globalOptions().dataDir, globalOptions().exeDir);
    if (!dir)
        throw UsageError(quick ? "expected the shipped clips (assets/mocap) or --data, found neither"
                               : "expected the CMU mocap folder (--data or $MOTIONGP_DATA), found none");
    const nlohmann::json out =
        runTable2(*dir, settings, [](const std::string& line) { std::cerr << "table2: " << line << std::endl; });
    if (json) {
        printJson(out);
        return 0;
    }
    const nlohmann::json& st = out["settings"];
    std::cout << "Table 2 — editing range (cm), δ in 1 cm steps up to " << st["max_delta_cm"] << "; T = " << st["outer_iterations"]
              << ", M = " << st["active"] << (quick ? " (quick: shipped clips)" : "")
              << "; combined range (reach/ranges/NN/density/continuity)\n";
    std::cout << std::left << std::setw(14) << "motion" << std::setw(20) << "edit" << std::setw(24) << "SGPLVM static"
              << std::setw(24) << "SGPLVM adaptive" << std::setw(24) << "FAS static" << std::setw(24) << "FAS adaptive"
              << "FAS static span\n";
    for (const auto& e : out["rows"]) {
        auto cell = [&](const char* key) {
            const auto& r = e[key];
            std::ostringstream s;
            s << r["combined"] << " (" << r["reach"] << "/" << r["joint_ranges"] << "/" << r["nearest_real_pose"] << "/" << r["density"]
              << "/" << r["continuity"] << ")";
            return s.str();
        };
        std::cout << std::setw(14) << e["kind"].get<std::string>() << std::setw(20) << e["edit"].get<std::string>() << std::setw(24)
                  << cell("sgplvm_static") << std::setw(24) << cell("sgplvm_adaptive") << std::setw(24) << cell("fas_static")
                  << std::setw(24) << cell("fas_adaptive")
                  << (e["fas_static_span"].contains("combined") ? e["fas_static_span"]["combined"].dump() : std::string("-")) << "\n";
    }
    std::cout << "(-1: fails at δ = 0. Learned vs plain IK closeness to real poses: see --json. FAS static span: the same\n"
                 " edit made by span regeneration over keys f−21, f, f+21, with the span's smoothness bar; see --json.)\n";
    return 0;
}

const CommandRegistration table2Command("table2", "Editing range (paper Table 2) with model-independent naturalness tests",
                              [](CLI::App& sub) -> CommandRunner {
    auto iters = std::make_shared<int>(10), active = std::make_shared<int>(200), maxDelta = std::make_shared<int>(80);
    auto quick = std::make_shared<bool>(false), json = std::make_shared<bool>(false);
    sub.add_option("--iters", *iters, "Outer training iterations per model (default 10)")->check(CLI::Range(1, 1000));
    sub.add_option("--active", *active, "Active set size M (default 200)")->check(CLI::Range(2, 100000));
    sub.add_option("--max-delta", *maxDelta, "Largest displacement in cm (default 80)")->check(CLI::Range(1, 1000));
    sub.add_flag("--quick", *quick, "Smoke run on the shipped clips (2 rows of 120 frames): T ≤ 2, M ≤ 100, δ ≤ 30");
    sub.add_flag("--json", *json, "Print one JSON object");
    return [=]() { return runTable2Command(*iters, *active, *maxDelta, *quick, *json); };
});

}  // namespace
}  // namespace mgp::app
