#pragma once
// The Table 1 protocol ("convergence precision", docs/maths.md §14): FASGPLVM vs SGPLVM on real
// CMU clips, same preprocessing, M, initial values, IVM, SCG counts and tolerances, reported at
// the paper's iteration counts scaled by itersScale. Both use the corrected, gauge-fixed
// objective; `literal` adds a run of each with the paper-literal eq. 5 (c = N, no gauge). For
// every run: (a) the paper's raw max |Δparam| at T, (b) the scale-free max |Δ ln param|, (c)
// |ΔL_GP| over Step 6 with the active set held fixed, (d) ‖∇L_GP‖∞ after Step 6, (e) the
// active-set overlap, and the control with the active set frozen from T − 5 on. Whatever comes
// out is reported; nothing is tuned to any published figure.
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "eval/clip_segments.h"
#include "eval/protocol_runs.h"
#include "gp/train/trainer.h"

namespace mgp {

struct Table1Clip {
    std::string kind;
    int paperFrames = 0;      // the paper's clip length, which the choice approximates
    int paperIterations = 0;  // the paper's T for this clip
    std::vector<ClipSegment> segments;
    std::string why;
};

// The full protocol's clips (the CMU set, ../shared/mocap) and the quick ones (the shipped
// clips in assets/mocap, short stretches: a smoke run, not the protocol).
const std::vector<Table1Clip>& table1Clips();
const std::vector<Table1Clip>& table1QuickClips();

// A clip the paper never used (`table1 --clip FILE[:A:B]`), run at T iterations.
Table1Clip table1ClipFromSpec(const std::string& spec, int iterations);

struct Table1Settings {
    std::vector<Table1Clip> clips = table1Clips();
    double itersScale = 1.0;  // T = max(3, round(itersScale · paper T))
    bool literal = false;
    bool quick = false;  // only reported: the caller chose the clips and sizes
    int runs = 1;        // repeated, perturbed runs per cell (eval/protocol_runs.h)
    double startNoise = kRunStartNoise;
    int workers = 1;  // runs trained at once (each Step 8 then single-threaded)
    // The training options of every run; kind, outerIterations and paperLiteral are set per run.
    gp::TrainOptions train = table1TrainOptions();

    // The protocol's options: the paper's model (no temporal prior), no early stop.
    static gp::TrainOptions table1TrainOptions();
    // Throws std::invalid_argument naming the first bad field.
    void validate() const;
};

// One progress line ("kick fas iter 3/5"), for a terminal; may be empty.
using ProgressFn = std::function<void(const std::string&)>;

// The report iteration count of a clip.
int table1Iterations(int paperIterations, double itersScale);

// One model's run: the trajectory, the quantities (a)–(e) at T and the frozen-set control.
nlohmann::json table1Run(const gp::TrainingData& data, const gp::TrainOptions& options, int T, const std::string& label,
                         const ProgressFn& progress);

// The whole table: {"settings", "reductions", "rows", "claims"}. With one run a row holds "fas"
// and "sgplvm" (table1Run each); with K runs it holds "runs" (K of those pairs) and "spread"
// (mean ± sd per model and quantity). "claims": the paper's Table 1 claims judged over every
// (clip, run) pair (eval/claim_test.h). The settings are the ones used.
nlohmann::json runTable1(const std::string& mocapDir, const Table1Settings& settings, const ProgressFn& progress);

}  // namespace mgp
