#pragma once
// `motiongp bench` sections register themselves here (app/bench_<name>.cpp), like the verbs.
// A section measures with repeats and reports medians (and p99 where it matters) as JSON.
// Timed unit tests are not used anywhere: speed is measured only through this command.
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace mgp::app {

struct BenchContext {
    std::string mocapDir;  // the CMU folder ("" if none was found)
    int repeats = 5;       // --repeats
    bool quick = false;    // --quick: smaller sizes, for smoke tests
};

struct BenchSection {
    std::string name;
    std::string description;
    std::function<nlohmann::json(const BenchContext&)> run;
};

std::vector<BenchSection>& benchTable();

struct BenchRegistration {
    BenchRegistration(std::string name, std::string description,
                      std::function<nlohmann::json(const BenchContext&)> run) {
        benchTable().push_back({std::move(name), std::move(description), std::move(run)});
    }
};

// Timing helpers: seconds of one call, and summary statistics of samples.
double secondsOf(const std::function<void()>& fn);
nlohmann::json summarizeSeconds(std::vector<double> samples);  // {"median", "p99", "min", "n"}

}  // namespace mgp::app
