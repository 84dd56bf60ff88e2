// `motiongp bench [--only NAME] [--repeats N] [--quick] [--json]`: runs the registered sections.
#include <algorithm>
#include <chrono>
#include <iostream>
#include <thread>

#include "bench_registry.h"
#include "cli_common.h"
#include "command_registry.h"
#include "io/data_paths.h"

namespace mgp::app {

std::vector<BenchSection>& benchTable() {
    static std::vector<BenchSection> table;
    return table;
}

double secondsOf(const std::function<void()>& fn) {
    const auto t0 = std::chrono::steady_clock::now();
    fn();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

nlohmann::json summarizeSeconds(std::vector<double> s) {
    if (s.empty()) return {{"n", 0}};
    std::sort(s.begin(), s.end());
    auto quantile = [&](double q) {
        const std::size_t i = std::min(s.size() - 1, static_cast<std::size_t>(q * (s.size() - 1) + 0.5));
        return s[i];
    };
    return {{"median", quantile(0.5)}, {"p99", quantile(0.99)}, {"min", s.front()}, {"max", s.back()}, {"n", s.size()}};
}

namespace {

const CommandRegistration benchCommand(
    "bench", "Measure speed (medians over repeats) and print JSON", [](CLI::App& sub) -> CommandRunner {
        auto only = std::make_shared<std::vector<std::string>>();
        auto repeats = std::make_shared<int>(5);
        auto quick = std::make_shared<bool>(false);
        auto json = std::make_shared<bool>(false);
        sub.add_option("--only", *only, "Run only these sections")->delimiter(',');
        sub.add_option("--repeats", *repeats, "Repeats per measurement")->check(CLI::Range(1, 1000));
        sub.add_flag("--quick", *quick, "Smaller sizes (a smoke test, not a measurement)");
        sub.add_flag("--json", *json, "Print one JSON object");
        return [=]() {
            BenchContext ctx;
            ctx.repeats = *repeats;
            ctx.quick = *quick;
            if (auto dir = findMocapFolder(globalOptions().dataDir, globalOptions().exeDir)) ctx.mocapDir = *dir;
            for (const std::string& name : *only)
                if (std::none_of(benchTable().begin(), benchTable().end(),
                                 [&](const BenchSection& s) { return s.name == name; })) {
                    std::string known;
                    for (const auto& s : benchTable()) known += (known.empty() ? "" : ", ") + s.name;
                    throw UsageError("expected --only among {" + known + "}, found '" + name + "'");
                }
            nlohmann::json out;
            out["machine"] = {{"hardware_threads", std::thread::hardware_concurrency()},
                              {"repeats", ctx.repeats},
                              {"quick", ctx.quick}};
            nlohmann::json sections = nlohmann::json::object();
            for (const BenchSection& s : benchTable()) {
                if (!only->empty() && std::find(only->begin(), only->end(), s.name) == only->end()) continue;
                std::cerr << "bench: " << s.name << " ..." << std::endl;
                sections[s.name] = s.run(ctx);
            }
            out["sections"] = sections;
            if (*json)
                printJson(out);
            else
                std::cout << out.dump(2) << std::endl;
            return 0;
        };
    });

}  // namespace
}  // namespace mgp::app
