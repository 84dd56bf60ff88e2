#pragma once
// Repeated runs of a protocol (docs/maths.md §14.5). A single run of Table 1 or 2 is chaotic in
// its last bits, so `--runs K` repeats every cell K times under a stated perturbation:
//  - the frames: run r trains on every frame but one in ten, dropping the frames f with
//    (f − anchor) mod 10 = 1 + (r mod 9), so the anchor (Table 2's edited frame) is always kept
//    and runs 0..8 drop different tenths;
//  - the start: N(0, startNoise²) on the whitened-PCA latent points, seeded with the run index
//    (gp::TrainOptions::startNoise).
// One run (K = 1) is the protocol itself: every frame, the paper's start.
#include <functional>
#include <string>
#include <vector>

namespace mgp {

constexpr int kRunDropPeriod = 10;
constexpr double kRunStartNoise = 0.05;

// The frames (0-based, ascending) run `run` of `runs` keeps out of frameCount.
std::vector<int> runFrames(int frameCount, int run, int runs, int anchor);
// The perturbation in one sentence, for the protocols' "settings".
std::string describeRunPerturbation(int runs, double startNoise);
// The latent start noise of a run (0 when runs = 1).
double runStartNoise(int runs, double startNoise);
// "kick" for one run, "kick run 2/5" for one of several: a progress line's subject.
std::string runLabel(const std::string& kind, int run, int runs);
// Throws std::invalid_argument naming the first bad value: runs in 1..50, a finite noise ≥ 0, at
// least one worker (both protocols' settings).
void validateRunSettings(int runs, double startNoise, int workers);

// job(j) for j in [0, jobs), spread over `workers` threads (≤ 1: the calling thread alone); each
// job's result must not depend on the thread or the order. Exceptions reach the caller.
void forEachJob(int jobs, int workers, const std::function<void(int job)>& job);
// `progress` (may be empty) made safe to call from several jobs at once: one line at a time.
std::function<void(const std::string&)> lockedProgress(std::function<void(const std::string&)> progress);

}  // namespace mgp
