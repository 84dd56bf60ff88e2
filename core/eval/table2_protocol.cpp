#include "eval/table2_protocol.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "eval/editing_range.h"
#include "eval/nearest_pose.h"
#include "eval/span_range.h"
#include "ik/learned_ik.h"
#include "ik/plain_ik.h"

namespace mgp {

const std::vector<Table2Row>& table2Rows() {
    static const std::vector<Table2Row> r = {
        {"kick", {{"10_03", 1, 362}}, 206, Effector::kRFoot, +1, "raise right foot", {{"10_01", 1, 801}, {"10_02", 1, 590}},
         "Table 1's kick clip; R = the other kicks of subject 10"},
        {"run", {{"09_01", 1, 148}, {"09_02", 1, 130}}, 124, Effector::kLHand, +1, "raise left hand", {{"09_03", 1, 128}},
         "Table 1's run clip (09_01 + 09_02); R = the third run of subject 09"},
        {"jump", {{"16_02", 1, 466}, {"16_01", 1, 70}}, 385, Effector::kRFoot, +1, "raise right foot", {{"16_01", 71, 322}},
         "no AMC run-and-jump: Table 1's jump clip; R = the unused rest of jump 16_01"},
        {"box", {{"13_17", 1001, 1452}}, 162, Effector::kRHand, -1, "lower right hand", {{"13_17", 1, 990}, {"13_17", 1463, 4840}},
         "Table 1's box stretch; R = the rest of the only boxing trial, 10 frames kept apart"},
        {"forward_jump", {{"16_06", 21, 387}}, 256, Effector::kHead, -1, "lower head", {{"16_05", 1, 295}},
         "Table 1's forward-jump clip; R = the other forward jump of subject 16"},
    };
    return r;
}

const std::vector<Table2Row>& table2QuickRows() {
    static const std::vector<Table2Row> r = {
        {"kick", {{"10_03", 151, 270}}, 56, Effector::kRFoot, +1, "raise right foot", {{"10_02", 1, 590}},
         "quick: Table 1's quick kick stretch (frame 206 of 10_03); R = the other shipped kick 10_02"},
        {"jump", {{"16_01", 1, 120}}, 60, Effector::kRFoot, +1, "raise right foot", {{"16_01", 131, 322}},
         "quick: Table 1's quick jump stretch; R = the rest of 16_01, 10 frames kept apart"},
    };
    return r;
}

void Table2Settings::validate() const {
    auto atLeast = [](int v, int lo, const char* name) {
        if (v < lo)
            throw std::invalid_argument(std::string("expected ") + name + " ≥ " + std::to_string(lo) + ", found " + std::to_string(v));
    };
    atLeast(outerIterations, 1, "outer iterations");
    atLeast(activeSize, 2, "active set size");
    atLeast(maxDeltaCm, 1, "largest displacement (cm)");
    atLeast(ikIterations, 1, "IK iterations");
    atLeast(adaptiveScgIterations, 1, "adaptive SCG iterations");
    if (rows.empty()) throw std::invalid_argument("expected at least one Table 2 row, found none");
}

std::vector<ReferenceFrame> table2Reference(const Clip& clip, int frame, const std::vector<Clip>& refClips) {
    // R = the other trials (preferred by §14) ∪ the training clip without the edited frame ±10
    // (the fallback). Other trials alone reject poses the captured clip itself holds (its own
    // frames fall outside their joint ranges), so both sources of real frames are used; the
    // training clip is its own group for the leave-one-clip-out threshold.
    std::vector<ReferenceFrame> ref;
    for (int t = 0; t < clip.frameCount(); ++t)
        if (std::abs(t - frame) > 10) ref.push_back({&clip, t, 0});
    for (std::size_t g = 0; g < refClips.size(); ++g)
        for (int t = 0; t < refClips[g].frameCount(); ++t) ref.push_back({&refClips[g], t, static_cast<int>(g) + 1});
    return ref;
}

namespace {

Clip namedClip(const std::string& dir, const std::vector<ClipSegment>& spans, TrialCache& cache) {
    Clip out = joinSegments(dir, spans, cache);
    out.name.clear();
    for (const ClipSegment& s : spans)
        out.name += (out.name.empty() ? "" : "+") + s.trial + "[" + std::to_string(s.first) + ":" + std::to_string(s.last) + "]";
    unwrapClip(out);
    return out;
}

gp::ModelVersionPtr trainOn(const Clip& clip, gp::KernelKind kind, int active, int iters) {
    gp::TrainOptions options;
    options.prior = gp::LatentPrior::kNone;  // the paper's model, whatever the editor's default
    options.kind = kind;
    options.activeSize = active;
    options.outerIterations = iters;
    return gp::ModelVersion::make(gp::trainOnClip(clip, options).model);
}

double secondsSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

nlohmann::json rangeJson(const EditingRange& r, double seconds) {
    nlohmann::json steps = nlohmann::json::array();
    for (const EditingStep& s : r.steps)
        steps.push_back({{"delta", s.deltaCm}, {"residual_cm", s.residualCm}, {"L_IK", s.lik}, {"reach", s.reach},
                         {"ranges", s.verdict.ranges}, {"worst_range_dof", s.verdict.worstRangeDof},
                         {"worst_range_excess_deg", s.verdict.worstRangeExcessDeg}, {"d_nn_cm", s.verdict.dNN},
                         {"nearest", s.verdict.nearest}, {"log_density", s.verdict.logDensity}, {"density", s.verdict.density},
                         {"max_step_deg", s.verdict.maxStepDeg}, {"max_step_dof", s.verdict.maxStepDof},
                         {"continuity", s.verdict.continuity}, {"model_updated", s.updatedModel}});
    return {{"steps", steps}, {"combined", r.combined}, {"reach", r.reach}, {"joint_ranges", r.ranges}, {"nearest_real_pose", r.nearest},
            {"density", r.density}, {"continuity", r.continuity}, {"adaptive_updates", r.adaptiveUpdates},
            {"steps_solved", r.steps.size()}, {"seconds", seconds}};
}

}  // namespace

nlohmann::json runTable2(const std::string& dir, const Table2Settings& s, const ProgressFn& progress) {
    s.validate();
    nlohmann::json out;
    out["settings"] = {{"outer_iterations", s.outerIterations}, {"active", s.activeSize}, {"max_delta_cm", s.maxDeltaCm},
                       {"lambda", LearnedIkRequest{}.lambda}, {"ik_iterations", s.ikIterations},
                       {"adaptive_scg_iterations", s.adaptiveScgIterations}, {"quick", s.quick}, {"mocap_dir", dir}};
    nlohmann::json reductions = nlohmann::json::array({"outer iterations T = " + std::to_string(s.outerIterations) +
                                                       " per model instead of the paper's 46-71 (time); models are trained once per row and kernel"});
    if (s.quick) reductions.push_back("quick: short stretches of the shipped clips, not the protocol's clips");
    out["reductions"] = reductions;
    TrialCache cache;
    nlohmann::json table = nlohmann::json::array();
    for (const Table2Row& row : s.rows) {
        if (progress) progress(row.kind + " ...");
        const Clip clip = namedClip(dir, row.training, cache);
        std::vector<Clip> refClips;
        for (const ClipSegment& seg : row.reference) refClips.push_back(namedClip(dir, {seg}, cache));
        const int frame = row.frame - 1;
        if (frame < 0 || frame >= clip.frameCount())
            throw std::invalid_argument("expected the edited frame within 1.." + std::to_string(clip.frameCount()) + " of " +
                                        clip.name + ", found " + std::to_string(row.frame));
        const std::vector<ReferenceFrame> ref = table2Reference(clip, frame, refClips);
        const NaturalnessTests tests(ref, row.effector);
        const int otherTrialFrames =
            tests.size() - static_cast<int>(std::count_if(ref.begin(), ref.end(), [](const ReferenceFrame& f) { return f.group == 0; }));
        nlohmann::json entry{{"kind", row.kind}, {"clip", clip.name}, {"frames", clip.frameCount()}, {"edited_frame", row.frame},
                             {"edit", row.edit}, {"why", row.why},
                             {"reference", "other trials: " + std::to_string(otherTrialFrames) + " frames, plus the training clip without frames " +
                                               std::to_string(row.frame - 10) + ".." + std::to_string(row.frame + 10)},
                             {"reference_frames", tests.size()},
                             {"tau_nn_cm", tests.nnThreshold()}, {"density_threshold", tests.densityThreshold()}};
        EditingRange fasStatic;
        gp::ModelVersionPtr fasModel;
        for (gp::KernelKind kind : {gp::KernelKind::kSgplvm, gp::KernelKind::kFas}) {
            const auto t0 = std::chrono::steady_clock::now();
            const gp::ModelVersionPtr model = trainOn(clip, kind, s.activeSize, s.outerIterations);
            if (kind == gp::KernelKind::kFas) fasModel = model;
            entry[std::string(gp::kernelKindName(kind)) + "_training_seconds"] = secondsSince(t0);
            for (bool adaptive : {false, true}) {
                EditingRangeJob job;
                job.version = model;
                job.frame = frame;
                job.effector = row.effector;
                job.direction = Eigen::Vector3d(0, row.direction, 0);
                job.tests = &tests;
                job.adaptive = adaptive;
                job.maxDeltaCm = s.maxDeltaCm;
                job.ikIterations = s.ikIterations;
                job.adaptiveScgIterations = s.adaptiveScgIterations;
                const auto s0 = std::chrono::steady_clock::now();
                const EditingRange r = job.run();
                entry[std::string(gp::kernelKindName(kind)) + (adaptive ? "_adaptive" : "_static")] = rangeJson(r, secondsSince(s0));
                if (kind == gp::KernelKind::kFas && !adaptive) fasStatic = r;
            }
        }
        // Learned (FAS static) against plain IK: closeness to real poses (R) at a few displacements.
        const Eigen::MatrixXd candidates = tests.referencePoses();
        nlohmann::json compare = nlohmann::json::array();
        const Eigen::Vector3d origin = effectorCm(clip.skeleton, clip.frames[frame], row.effector);
        for (int delta : {10, 20, 30}) {
            if (delta > s.maxDeltaCm || delta >= static_cast<int>(fasStatic.steps.size())) continue;
            const EditingStep& learned = fasStatic.steps[delta];
            PlainIkJob plain;
            plain.skeleton = &clip.skeleton;
            plain.start = clip.frames[frame];
            plain.constraints = {{row.effector, origin + Eigen::Vector3d(0, row.direction * delta, 0), false}};
            plain.solve();
            const Eigen::VectorXd plainPose = PoseLayout(clip.skeleton).extract(plain.pose);
            compare.push_back({{"delta_cm", delta},
                               {"learned", {{"residual_cm", learned.residualCm}, {"nn_rms_deg", nearestPoseRmsDeg(learned.poseDeg, candidates)}}},
                               {"plain", {{"residual_cm", plain.results[0].residualCm}, {"nn_rms_deg", nearestPoseRmsDeg(plainPose, candidates)}}}});
        }
        entry["learned_vs_plain"] = compare;
        {
            const auto s0 = std::chrono::steady_clock::now();
            SpanRangeJob span;
            span.version = fasModel;
            span.frame = frame;
            span.effector = row.effector;
            span.direction = row.direction;
            span.tests = &tests;
            span.maxDeltaCm = s.maxDeltaCm;
            entry["fas_static_span"] = span.run();
            entry["fas_static_span"]["seconds"] = secondsSince(s0);
        }
        table.push_back(entry);
    }
    out["rows"] = table;
    return out;
}

}  // namespace mgp
