#pragma once
// The editing-range sweep of docs/maths.md §14: target c(δ) = p_e(y_t) + δ·u for δ = 0, 1, 2, …
// cm, each solved with the learned IK warm-started from δ − 1, judged by the naturalness tests.
// A test's range is the largest δ such that every δ' ≤ δ passes it (−1: δ = 0 already fails);
// the combined range needs every test. With `adaptive`, the adaptive update (docs/maths.md §11)
// runs after each δ ≥ 1 while every δ' ≤ δ has passed all tests, and the next δ uses the new
// model version. The sweep stops at maxDeltaCm or once every test has failed (all ranges are then
// known). δ = 0 is the captured frame re-solved, not an edit, so the adaptive arm never learns it
// (docs/maths.md §14.2).
//
// With `editorDrag` each δ is solved as the editor's drag solves it (ik/constrained_ik.h, the
// drag's defaults): the target exact, the feet in ground contact on the frame pinned where they
// stand, the floor, locality around the captured pose and the root rotation held near it.
#include <string>
#include <vector>

#include "eval/naturalness.h"
#include "gp/model_version.h"

namespace mgp {

struct EditingStep {
    int deltaCm = 0;
    double residualCm = 0.0;
    double lik = 0.0;
    bool reach = false;
    NaturalnessVerdict verdict;
    bool accepted = false;      // reach and every naturalness test
    bool updatedModel = false;  // an adaptive update was applied after this step
    Eigen::VectorXd poseDeg;    // the solved pose vector (degrees, skeleton/pose_layout.h)
};

struct EditingRange {
    int combined = -1, reach = -1, ranges = -1, nearest = -1, density = -1, continuity = -1;
    int adaptiveUpdates = 0;
    std::vector<EditingStep> steps;
    // The tests that fail first, at δ = combined + 1 ("reach", "joint ranges", "nearest real
    // pose", "density", "continuity"); empty when the sweep reached maxDeltaCm.
    std::vector<std::string> binding() const;
};

struct EditingRangeJob {
    gp::ModelVersionPtr version;
    int frame = 0;  // clip frame (0-based)
    Effector effector = Effector::kRFoot;
    Eigen::Vector3d direction = Eigen::Vector3d::UnitY();
    const NaturalnessTests* tests = nullptr;
    bool adaptive = false;
    int maxDeltaCm = 80;
    int ikIterations = 500;
    int adaptiveScgIterations = 100;  // SCG iterations of each adaptive update
    bool editorDrag = false;
    EditingRange run() const;
};

}  // namespace mgp
