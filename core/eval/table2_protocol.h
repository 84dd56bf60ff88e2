#pragma once
// The Table 2 protocol (editing range in cm, docs/maths.md §14): 2×2 SGPLVM/FASGPLVM ×
// static/adaptive on the Table 1 clips and the paper's edits, judged by the model-independent
// naturalness tests against a reference set R of real frames; plus the learned IK's poses
// against the plain IK's (nearest-pose RMS, eval/nearest_pose.h) and the same edit by span
// regeneration (eval/span_range.h). Whatever comes out is reported.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "eval/clip_segments.h"
#include "eval/naturalness.h"
#include "eval/table1_protocol.h"

namespace mgp {

struct Table2Row {
    std::string kind;
    std::vector<ClipSegment> training;
    int frame = 1;  // the edited frame, 1-based in the training clip
    Effector effector = Effector::kRFoot;
    double direction = 1.0;  // +1 raise, −1 lower
    std::string edit;
    std::vector<ClipSegment> reference;  // the other trials of R, one group each
    std::string why;
};

// The full protocol's rows (the CMU set) and the quick ones (shipped clips, short stretches).
const std::vector<Table2Row>& table2Rows();
const std::vector<Table2Row>& table2QuickRows();

struct Table2Settings {
    std::vector<Table2Row> rows = table2Rows();
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

// The whole table: {"settings", "reductions", "rows"}. The settings are the ones used.
nlohmann::json runTable2(const std::string& mocapDir, const Table2Settings& settings, const ProgressFn& progress);

}  // namespace mgp
