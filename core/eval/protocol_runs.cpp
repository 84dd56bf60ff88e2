#include "eval/protocol_runs.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <memory>
#include <mutex>
#include <stdexcept>

#include "util/parallel_for.h"

namespace mgp {

std::vector<int> runFrames(int frameCount, int run, int runs, int anchor) {
    std::vector<int> kept;
    kept.reserve(frameCount);
    const int dropped = 1 + run % (kRunDropPeriod - 1);
    for (int f = 0; f < frameCount; ++f) {
        const int phase = ((f - anchor) % kRunDropPeriod + kRunDropPeriod) % kRunDropPeriod;
        if (runs <= 1 || phase != dropped) kept.push_back(f);
    }
    return kept;
}

double runStartNoise(int runs, double startNoise) { return runs <= 1 ? 0.0 : startNoise; }

std::string runLabel(const std::string& kind, int run, int runs) {
    return runs > 1 ? kind + " run " + std::to_string(run + 1) + "/" + std::to_string(runs) : kind;
}

void validateRunSettings(int runs, double startNoise, int workers) {
    if (runs < 1 || runs > 50) throw std::invalid_argument("expected 1 to 50 runs, found " + std::to_string(runs));
    if (!(startNoise >= 0.0) || !std::isfinite(startNoise))
        throw std::invalid_argument("expected a start noise ≥ 0, found " + std::to_string(startNoise));
    if (workers < 1) throw std::invalid_argument("expected at least one worker, found " + std::to_string(workers));
}

std::string describeRunPerturbation(int runs, double startNoise) {
    if (runs <= 1) return "one run: every frame, the paper's start";
    char buf[320];
    std::snprintf(
        buf, sizeof buf,
        "%d runs; run r drops the frames f with (f - anchor) mod %d = 1 + (r mod %d) (one in ten; the anchor "
        "is Table 2's edited frame, frame 1 in Table 1) and adds N(0, %.3g^2) seeded with r to the whitened-PCA start",
        runs, kRunDropPeriod, kRunDropPeriod - 1, startNoise);
    return buf;
}

void forEachJob(int jobs, int workers, const std::function<void(int job)>& job) {
    std::atomic<int> next{0};
    parallelFor(std::clamp(workers, 1, std::max(1, jobs)), [&](int) {
        for (int j = next++; j < jobs; j = next++) job(j);
    });
}

std::function<void(const std::string&)> lockedProgress(std::function<void(const std::string&)> progress) {
    auto lock = std::make_shared<std::mutex>();
    return [lock, progress = std::move(progress)](const std::string& line) {
        const std::lock_guard<std::mutex> guard(*lock);
        if (progress) progress(line);
    };
}

}  // namespace mgp
