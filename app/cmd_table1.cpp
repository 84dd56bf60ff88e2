// `motiongp table1 [--quick | --iters-scale F] [--runs K] [--clip FILE[:A:B] [--iters T]] [--scg-iters S]
// [--active M] [--literal] [--threads N] [--json]`:
// the paper's Table 1 ("convergence precision") under the protocol of docs/maths.md §14, run by
// eval/table1_protocol.h; this file only reads the options and prints the table.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <thread>

#include "cli_common.h"
#include "command_registry.h"
#include "eval/table1_protocol.h"
#include "io/data_paths.h"

namespace mgp::app {
namespace {

void printSingleRuns(const nlohmann::json& rows, bool literal) {
    std::printf("%-13s %-34s %5s %4s | %-14s %10s %10s %10s %10s %6s | %10s %10s\n", "kind", "clips", "N", "T", "model",
                "(a) raw", "(b) log", "(c) |dL|", "(d) |g|inf", "(e) ov", "frozen raw", "frozen log");
    std::vector<std::string> models = {"fas", "sgplvm"};
    if (literal) {
        models.push_back("fas_literal");
        models.push_back("sgplvm_literal");
    }
    for (const auto& r : rows)
        for (const auto& m : models) {
            const auto& x = r[m];
            std::printf("%-13s %-34s %5d %4d | %-14s %10.4g %10.4g %10.4g %10.4g %6.3f | %10.4g %10.4g\n",
                        r["kind"].get<std::string>().c_str(), r["clips"].get<std::string>().c_str(), r["N"].get<int>(),
                        r["T_report"].get<int>(), m.c_str(), x["raw_max_delta"].get<double>(),
                        x["log_max_delta"].get<double>(), x["abs_delta_L_fixed_active"].get<double>(),
                        x["grad_inf"].get<double>(), x["active_overlap"].get<double>(),
                        x.value("frozen_raw_max_delta", std::nan("")), x.value("frozen_log_max_delta", std::nan("")));
        }
}

std::string meanSd(const nlohmann::json& spread, const char* key) {
    if (!spread.contains(key)) return "-";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.3g ± %.2g", spread[key]["mean"].get<double>(), spread[key]["sd"].get<double>());
    return buf;
}

void printSpreads(const nlohmann::json& rows, int runs) {
    std::printf("mean ± sd over %d runs per cell\n", runs);
    std::printf("%-13s %4s | %-7s %-18s %-18s %-18s %-16s %-18s\n", "kind", "T", "model", "(a) raw", "(b) log",
                "(e) overlap", "frozen (b)", "alpha");
    for (const auto& r : rows)
        for (const char* m : {"fas", "sgplvm"}) {
            const auto& x = r["spread"][m];
            std::printf("%-13s %4d | %-7s %-18s %-18s %-18s %-16s %-18s\n", r["kind"].get<std::string>().c_str(),
                        r["T_report"].get<int>(), m, meanSd(x, "raw_max_delta").c_str(),
                        meanSd(x, "log_max_delta").c_str(), meanSd(x, "active_overlap").c_str(),
                        meanSd(x, "frozen_log_max_delta").c_str(), meanSd(x, "alpha").c_str());
        }
}

const CommandRegistration table1Command(
    "table1", "Reproduce the paper's Table 1 (convergence precision, FASGPLVM vs SGPLVM)",
    [](CLI::App& sub) -> CommandRunner {
        struct Opts {
            double itersScale = 1.0;
            bool quick = false, literal = false, json = false;
            int scgIters = 100, threads = 0, active = 200, runs = 1, iters = 58;
            std::vector<std::string> clips;
        };
        auto o = std::make_shared<Opts>();
        sub.add_flag("--quick", o->quick,
                     "Smoke run on the shipped clips (3 × 120 frames): iteration scale ≤ 0.1 (T = 5..7), ≤ 30 SCG "
                     "iterations, M ≤ 60");
        sub.add_option("--iters-scale", o->itersScale, "Scale the paper's iteration counts (default 1)");
        sub.add_option("--scg-iters", o->scgIters, "SCG iterations per Step 6 (default 100)");
        sub.add_option("--active", o->active, "Active set size M (default 200, the paper's)");
        sub.add_flag("--literal", o->literal, "Also run the paper-literal eq. 5 (c = N, no gauge)");
        sub.add_option("--runs", o->runs,
                       "Repeat every cell over K perturbed runs (docs/maths.md §14.5); report mean ± sd and a verdict "
                       "per claim (default 1)");
        sub.add_option(
            "--clip", o->clips,
            "Run on this clip instead of the paper's (AMC, BVH or glTF; FILE:A:B keeps frames A..B); repeatable");
        sub.add_option(
            "--iters", o->iters,
            "Outer iterations on a --clip before --iters-scale (default 58, the mean of the paper's T; T ≥ 3)");
        sub.add_option(
            "--threads", o->threads,
            "Threads: for Step 8, or with --runs K for runs at once (default: all cores; results do not depend on it)");
        sub.add_flag("--json", o->json, "Print one JSON object");
        return [o]() {
            if (o->quick) {  // the shipped clips, small sizes: well under a minute
                o->itersScale = std::min(o->itersScale, 0.1);
                o->scgIters = std::min(o->scgIters, 30);
                o->active = std::min(o->active, 60);
            }
            if (!(o->itersScale > 0.0) || o->itersScale > 1.0)
                throw UsageError("expected --iters-scale in (0, 1], found " + std::to_string(o->itersScale));
            if (o->scgIters < 1) throw UsageError("expected --scg-iters ≥ 1, found " + std::to_string(o->scgIters));
            if (o->active < 1) throw UsageError("expected --active ≥ 1, found " + std::to_string(o->active));
            if (o->iters < 1) throw UsageError("expected --iters ≥ 1, found " + std::to_string(o->iters));
            if (o->threads < 0) throw UsageError("expected --threads ≥ 0, found " + std::to_string(o->threads));
            Table1Settings settings;
            if (o->quick) settings.clips = table1QuickClips();
            if (!o->clips.empty()) {
                settings.clips.clear();
                try {
                    for (const std::string& spec : o->clips)
                        settings.clips.push_back(table1ClipFromSpec(spec, o->iters));
                } catch (const std::invalid_argument& e) {
                    throw UsageError(e.what());
                }
            }
            settings.runs = o->runs;
            settings.workers =
                o->runs > 1 ? (o->threads > 0 ? o->threads : std::max(1u, std::thread::hardware_concurrency())) : 1;
            settings.itersScale = o->itersScale;
            settings.literal = o->literal;
            settings.quick = o->quick;
            settings.train.activeSize = o->active;
            settings.train.scgIterations = o->scgIters;
            settings.train.threads = o->threads;
            try {
                settings.validate();
            } catch (const std::invalid_argument& e) {
                throw UsageError(e.what());
            }
            const bool ownClips = !o->clips.empty();
            const auto dir = ownClips ? std::optional<std::string>(globalOptions().dataDir)
                             : o->quick && globalOptions().dataDir.empty()
                                 ? findShippedMocapFolder(globalOptions().exeDir)
                                 : findMocapFolder(globalOptions().dataDir, globalOptions().exeDir);
            if (!dir)
                throw UsageError(
                    o->quick ? "expected the shipped clips (assets/mocap) or --data, found neither"
                             : "expected a mocap folder (--data, $MOTIONGP_DATA or ../shared/mocap), found none");
            const auto t0 = std::chrono::steady_clock::now();
            nlohmann::json out = runTable1(*dir, settings, [](const std::string& line) {
                std::cerr << "\rtable1: " << line << "   " << std::flush;
            });
            const nlohmann::json& rows = out["rows"];
            const nlohmann::json& reductions = out["reductions"];
            std::cerr << "\n";
            out["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            if (o->json) {
                printJson(out);
                return 0;
            }
            for (const auto& r : reductions) std::cout << "reduction: " << r.get<std::string>() << "\n";
            if (settings.runs == 1)
                printSingleRuns(rows, settings.literal);
            else
                printSpreads(rows, settings.runs);
            printClaims(out["claims"]);
            std::cout << "total " << out["seconds"].get<double>() << " s\n";
            return 0;
        };
    });

}  // namespace
}  // namespace mgp::app
