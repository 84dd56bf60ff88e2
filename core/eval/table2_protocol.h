#pragma once
// The Table 2 protocol (editing range in cm, docs/maths.md §14): 2×2 SGPLVM/FASGPLVM ×
// static/adaptive on the Table 1 clips and the paper's edits, judged by the model-independent
// naturalness tests against a reference set R of real frames; plus the learned IK's poses
// against the plain IK's (nearest-pose RMS, eval/nearest_pose.h) and the same edit by span
// regeneration (eval/span_range.h) and by the editor's drag solve (EditingRangeJob::editorDrag).
// With K runs (eval/protocol_runs.h) every cell is repeated and the paper's Table 2 claims are
// judged over the (row, run) pairs. Whatever comes out is reported.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "eval/clip_segments.h"
#include "eval/naturalness.h"
#include "eval/protocol_runs.h"
#include "eval/table1_protocol.h"

namespace mgp {

struct Table2Row {
    std::string kind;
    std::vector<ClipSegment> training;
    int frame = 1;  // the edited frame, 1-based in the training clip
    Effector effector = Effector::kRFoot;
    Eigen::Vector3d direction = Eigen::Vector3d::UnitY();  // unit: the edit's direction in world space
    std::string edit;
    std::vector<ClipSegment> reference;  // the other trials of R, one group each
    std::string why;
};

// The full protocol's rows (the CMU set) and the quick ones (shipped clips, short stretches).
const std::vector<Table2Row>& table2Rows();
const std::vector<Table2Row>& table2QuickRows();

// A row on a clip the paper never used: `table2 --clip FILE[:A:B] --edit EFF:dx,dy,dz [--frame F]
// [--reference FILE[:A:B]]…`. frame: 1-based in the clip (0: its middle frame); the edit's vector
// gives the direction (any length but zero). R: the references, plus the clip without F ± 10.
// Throws std::invalid_argument naming what was expected and found.
Table2Row table2RowFromSpec(const std::string& clipSpec, const std::string& editSpec, int frame,
                            const std::vector<std::string>& referenceSpecs, int clipFrames);

struct Table2Settings {
    std::vector<Table2Row> rows = table2Rows();
    int runs = 1;  // repeated, perturbed runs per cell (eval/protocol_runs.h)
    double startNoise = kRunStartNoise;
    int workers = 1;  // (row, run) jobs at once
    int outerIterations = 10;
    int activeSize = 200;
    int maxDeltaCm = 80;
    int ikIterations = 500;
    int adaptiveScgIterations = 100;
    bool quick = false;  // only reported: the caller chose the rows and sizes
    // Throws std::invalid_argument naming the first bad field.
    void validate() const;
};

// The reference frames of a row: the training clip without the edited frame ±10 (group 0) and
// every frame of each reference clip (group g + 1).
std::vector<ReferenceFrame> table2Reference(const Clip& training, int frame0, const std::vector<Clip>& referenceClips);

// The whole table: {"settings", "reductions", "rows", "claims"}. With one run a row holds its
// cells (sgplvm_static … fas_static_drag); with K runs it holds "runs" (K of those) and "spread"
// (mean ± sd of every cell's ranges). Every cell names its binding tests. The settings are the
// ones used.
nlohmann::json runTable2(const std::string& mocapDir, const Table2Settings& settings, const ProgressFn& progress);

}  // namespace mgp
