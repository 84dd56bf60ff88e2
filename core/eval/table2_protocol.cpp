#include "eval/table2_protocol.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "eval/claim_test.h"
#include "eval/editing_range.h"
#include "eval/nearest_pose.h"
#include "eval/span_range.h"
#include "ik/learned_ik.h"
#include "ik/plain_ik.h"

namespace mgp {

const std::vector<Table2Row>& table2Rows() {
    static const std::vector<Table2Row> r = {
        {"kick",
         {{"10_03", 1, 362}},
         206,
         Effector::kRFoot,
         Eigen::Vector3d::UnitY(),
         "raise right foot",
         {{"10_01", 1, 801}, {"10_02", 1, 590}},
         "Table 1's kick clip; R = the other kicks of subject 10"},
        {"run",
         {{"09_01", 1, 148}, {"09_02", 1, 130}},
         124,
         Effector::kLHand,
         Eigen::Vector3d::UnitY(),
         "raise left hand",
         {{"09_03", 1, 128}},
         "Table 1's run clip (09_01 + 09_02); R = the third run of subject 09"},
        {"jump",
         {{"16_02", 1, 466}, {"16_01", 1, 70}},
         385,
         Effector::kRFoot,
         Eigen::Vector3d::UnitY(),
         "raise right foot",
         {{"16_01", 71, 322}},
         "no AMC run-and-jump: Table 1's jump clip; R = the unused rest of jump 16_01"},
        {"box",
         {{"13_17", 1001, 1452}},
         162,
         Effector::kRHand,
         -Eigen::Vector3d::UnitY(),
         "lower right hand",
         {{"13_17", 1, 990}, {"13_17", 1463, 4840}},
         "Table 1's box stretch; R = the rest of the only boxing trial, 10 frames kept apart"},
        {"forward_jump",
         {{"16_06", 21, 387}},
         256,
         Effector::kHead,
         -Eigen::Vector3d::UnitY(),
         "lower head",
         {{"16_05", 1, 295}},
         "Table 1's forward-jump clip; R = the other forward jump of subject 16"},
    };
    return r;
}

const std::vector<Table2Row>& table2QuickRows() {
    static const std::vector<Table2Row> r = {
        {"kick",
         {{"10_03", 151, 270}},
         56,
         Effector::kRFoot,
         Eigen::Vector3d::UnitY(),
         "raise right foot",
         {{"10_02", 1, 590}},
         "quick: Table 1's quick kick stretch (frame 206 of 10_03); R = the other shipped kick 10_02"},
        {"jump",
         {{"16_01", 1, 120}},
         60,
         Effector::kRFoot,
         Eigen::Vector3d::UnitY(),
         "raise right foot",
         {{"16_01", 131, 322}},
         "quick: Table 1's quick jump stretch; R = the rest of 16_01, 10 frames kept apart"},
    };
    return r;
}

Table2Row table2RowFromSpec(const std::string& clipSpec, const std::string& editSpec, int frame,
                            const std::vector<std::string>& referenceSpecs, int clipFrames) {
    Table2Row row;
    row.training = {parseClipSpec(clipSpec)};
    row.kind = std::filesystem::path(row.training[0].trial).stem().string();
    // EFF:dx,dy,dz
    const std::size_t colon = editSpec.find(':');
    double v[3] = {0, 0, 0};
    char tail = 0;
    if (colon == std::string::npos || !parseEffector(editSpec.substr(0, colon), row.effector) ||
        std::sscanf(editSpec.c_str() + colon + 1, "%lf,%lf,%lf%c", &v[0], &v[1], &v[2], &tail) != 3)
        throw std::invalid_argument(
            "expected --edit EFFECTOR:dx,dy,dz (lhand, rhand, lfoot, rfoot or head; a direction in "
            "world axes, Y up), found '" +
            editSpec + "'");
    const Eigen::Vector3d u(v[0], v[1], v[2]);
    if (!u.allFinite() || !std::isfinite(u.norm()) || u.norm() < 1e-9)
        throw std::invalid_argument("expected a non-zero, finite edit direction, found '" + editSpec + "'");
    row.direction = u.normalized();
    char buf[160];
    std::snprintf(buf, sizeof buf, "move %s along (%.3g, %.3g, %.3g)", effectorName(row.effector), row.direction.x(),
                  row.direction.y(), row.direction.z());
    row.edit = buf;
    if (frame < 0 || frame > clipFrames)
        throw std::invalid_argument("expected --frame within 1.." + std::to_string(clipFrames) + " of " + clipSpec +
                                    ", found " + std::to_string(frame));
    row.frame = frame == 0 ? (clipFrames + 1) / 2 : frame;
    for (const std::string& r : referenceSpecs) row.reference.push_back(parseClipSpec(r));
    row.why = "--clip " + clipSpec + " frame " + std::to_string(row.frame) + ": a clip the paper never used; R = " +
              (referenceSpecs.empty() ? std::string("the clip itself without the edited frame ± 10")
                                      : std::to_string(referenceSpecs.size()) +
                                            " reference clip(s) and the clip without the edited frame ± 10");
    return row;
}

void Table2Settings::validate() const {
    auto atLeast = [](int v, int lo, const char* name) {
        if (v < lo)
            throw std::invalid_argument(std::string("expected ") + name + " ≥ " + std::to_string(lo) + ", found " +
                                        std::to_string(v));
    };
    atLeast(outerIterations, 1, "outer iterations");
    atLeast(activeSize, 2, "active set size");
    atLeast(maxDeltaCm, 1, "largest displacement (cm)");
    atLeast(ikIterations, 1, "IK iterations");
    atLeast(adaptiveScgIterations, 1, "adaptive SCG iterations");
    if (rows.empty()) throw std::invalid_argument("expected at least one Table 2 row, found none");
    validateRunSettings(runs, startNoise, workers);
}

std::vector<ReferenceFrame> table2Reference(const Clip& clip, int frame, const std::vector<Clip>& refClips) {
    // R = the other trials (preferred) ∪ the training clip without the edited frame ±10
    // (the fallback), as docs/maths.md §14.4 has it. Other trials alone reject poses the captured
    // clip itself holds (its own frames fall outside their joint ranges), so both sources of real
    // frames are used; the training clip is its own group for the leave-one-clip-out threshold.
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
        out.name += (out.name.empty() ? "" : "+") + s.trial + "[" + std::to_string(s.first) + ":" +
                    (s.last == 0 ? "end" : std::to_string(s.last)) + "]";
    unwrapClip(out);
    return out;
}

// A model trained on `frames` of the clip (a repeated run's subset) whose clip is the whole capture,
// so that the edited frame, the span's keys and the feet's contacts are the captured ones.
gp::ModelVersionPtr trainOn(const Clip& clip, const std::vector<int>& frames, gp::KernelKind kind, int active,
                            int iters, double startNoise, unsigned seed, int threads) {
    gp::TrainOptions options;
    options.startNoise = startNoise;
    options.startSeed = seed;
    options.threads = threads;
    options.prior = gp::LatentPrior::kNone;  // the paper's model, whatever the editor's default
    options.kind = kind;
    options.activeSize = active;
    options.outerIterations = iters;
    gp::TrainResult trained = gp::train(gp::trainingDataFromClip(clip, frames), options);
    trained.model.clip = clip;
    return gp::ModelVersion::make(std::move(trained.model));
}

double secondsSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Why a sweep stopped: at δ = range + 1, each failing test with the numbers it judged.
nlohmann::json bindingDetail(const EditingRange& r, const Skeleton& sk, const NaturalnessTests& tests) {
    const int at = r.combined + 1;
    if (at < 0 || at >= static_cast<int>(r.steps.size())) return nullptr;
    const EditingStep& s = r.steps[at];
    const PoseLayout layout(sk);
    nlohmann::json out{{"delta", at}, {"tests", r.binding()}};
    if (!s.reach) out["reach"] = {{"residual_cm", s.residualCm}, {"limit_cm", 0.5}};
    if (!s.verdict.ranges && s.verdict.worstRangeDof >= 0) {
        const int k = s.verdict.worstRangeDof;
        const auto [lo, hi] = tests.rangeBounds(k);
        out["joint_ranges"] = {{"dof", layout.dofName(sk, k)},
                               {"violations", s.verdict.rangeViolations},
                               {"value_deg", s.poseDeg[k]},
                               {"allowed_deg", {lo, hi}},
                               {"at_delta_0_deg", r.steps[0].poseDeg[k]}};
    }
    if (!s.verdict.nearest) out["nearest_real_pose"] = {{"d_nn_cm", s.verdict.dNN}, {"tau_cm", tests.nnThreshold()}};
    if (!s.verdict.density)
        out["density"] = {{"log_density", s.verdict.logDensity}, {"threshold", tests.densityThreshold()}};
    if (!s.verdict.continuity && s.verdict.maxStepDof >= 0)
        out["continuity"] = {
            {"dof", layout.dofName(sk, s.verdict.maxStepDof)}, {"step_deg", s.verdict.maxStepDeg}, {"limit_deg", 15.0}};
    return out;
}

nlohmann::json rangeJson(const EditingRange& r, double seconds, const Skeleton& sk, const NaturalnessTests& tests) {
    const PoseLayout layout(sk);
    auto dofName = [&](int dof) { return dof < 0 ? nlohmann::json(nullptr) : nlohmann::json(layout.dofName(sk, dof)); };
    nlohmann::json steps = nlohmann::json::array();
    for (const EditingStep& s : r.steps)
        steps.push_back({{"delta", s.deltaCm},
                         {"residual_cm", s.residualCm},
                         {"L_IK", s.lik},
                         {"reach", s.reach},
                         {"ranges", s.verdict.ranges},
                         {"worst_range_dof", dofName(s.verdict.worstRangeDof)},
                         {"worst_range_excess_deg", s.verdict.worstRangeExcessDeg},
                         {"d_nn_cm", s.verdict.dNN},
                         {"nearest", s.verdict.nearest},
                         {"log_density", s.verdict.logDensity},
                         {"density", s.verdict.density},
                         {"max_step_deg", s.verdict.maxStepDeg},
                         {"max_step_dof", dofName(s.verdict.maxStepDof)},
                         {"continuity", s.verdict.continuity},
                         {"model_updated", s.updatedModel}});
    return {{"steps", steps},
            {"combined", r.combined},
            {"binding", r.binding()},
            {"binding_detail", bindingDetail(r, sk, tests)},
            {"reach", r.reach},
            {"joint_ranges", r.ranges},
            {"nearest_real_pose", r.nearest},
            {"density", r.density},
            {"continuity", r.continuity},
            {"adaptive_updates", r.adaptiveUpdates},
            {"steps_solved", r.steps.size()},
            {"seconds", seconds}};
}

// The naturalness tests compare the 22 model bones and whole pose vectors: every clip of a row
// must have those bones and `like`'s pose layout (the same DOFs in the same order).
void requireJudgeableSkeleton(const Clip& clip, const Clip& like) {
    for (const char* bone : modelBoneNames())
        if (clip.skeleton.findBone(bone) < 0)
            throw std::invalid_argument(
                std::string("expected a skeleton with the 22 model bones the naturalness tests compare "
                            "(a CMU ASF skeleton, or a BVH naming them), found ") +
                clip.name + " without '" + bone + "'");
    const PoseLayout a(clip.skeleton), b(like.skeleton);
    bool same = a.size() == b.size();
    for (int k = 0; same && k < a.size(); ++k) same = a.dofName(clip.skeleton, k) == b.dofName(like.skeleton, k);
    if (!same)
        throw std::invalid_argument("expected reference clips with " + like.name + "'s pose layout (" +
                                    std::to_string(b.size()) + " DOFs), found " + clip.name + " with another (" +
                                    std::to_string(a.size()) + " DOFs)");
}

// The smallest R the density test can be fitted on (its PPCA has 15 components, 5 held-out folds).
constexpr int kMinReferenceFrames = 60;

// The cells of a row, by their key: the paper's four, then this product's two.
const std::vector<std::string>& table2Cells() {
    static const std::vector<std::string> c = {"sgplvm_static", "sgplvm_adaptive", "fas_static",
                                               "fas_adaptive",  "fas_static_span", "fas_static_drag"};
    return c;
}

// The edited frame as captured, judged by R (which leaves it out): a test that refuses the real
// frame itself cannot be what bounds an edit of it.
nlohmann::json capturedVerdictJson(const Clip& clip, int frame, const NaturalnessTests& tests) {
    const PoseLayout layout(clip.skeleton);
    const NaturalnessVerdict v = tests.judge(clip.skeleton, poseMatrix(clip).row(frame).transpose(), nullptr);
    nlohmann::json out{{"ranges", v.ranges},
                       {"nearest", v.nearest},
                       {"density", v.density},
                       {"d_nn_cm", v.dNN},
                       {"log_density", v.logDensity}};
    if (v.worstRangeDof >= 0) {
        out["worst_range_dof"] = layout.dofName(clip.skeleton, v.worstRangeDof);
        out["worst_range_excess_deg"] = v.worstRangeExcessDeg;
    }
    return out;
}

// One (row, run): both kernels trained on the run's frames, every cell swept.
nlohmann::json table2Job(const Table2Row& row, const Clip& clip, int frame, const std::vector<int>& joins,
                         const NaturalnessTests& tests, const Table2Settings& s, int run, const ProgressFn& say) {
    const std::vector<int> kept = runFrames(clip.frameCount(), run, s.runs, frame);
    // Every run keeps the edited frame; its model's clip is the whole capture (trainOn).
    const int threads = s.workers > 1 ? 1 : 0;
    const std::string tag = runLabel(row.kind, run, s.runs);
    nlohmann::json out{{"run", run}, {"frames_trained", kept.size()}};
    auto sweep = [&](const gp::ModelVersionPtr& model, bool adaptive, bool editorDrag) {
        EditingRangeJob job;
        job.version = model;
        job.frame = frame;
        job.effector = row.effector;
        job.direction = row.direction;
        job.tests = &tests;
        job.adaptive = adaptive;
        job.editorDrag = editorDrag;
        job.maxDeltaCm = s.maxDeltaCm;
        job.ikIterations = s.ikIterations;
        job.adaptiveScgIterations = s.adaptiveScgIterations;
        const auto s0 = std::chrono::steady_clock::now();
        const EditingRange r = job.run();
        return std::make_pair(r, rangeJson(r, secondsSince(s0), clip.skeleton, tests));
    };
    gp::ModelVersionPtr fasModel;
    EditingRange fasStatic;
    for (gp::KernelKind kind : {gp::KernelKind::kSgplvm, gp::KernelKind::kFas}) {
        const std::string name = gp::kernelKindName(kind);
        if (say) say(tag + " " + name + " ...");
        const auto t0 = std::chrono::steady_clock::now();
        const gp::ModelVersionPtr model =
            trainOn(clip, kept, kind, s.activeSize, s.outerIterations, runStartNoise(s.runs, s.startNoise),
                    static_cast<unsigned>(run), threads);
        out[name + "_training_seconds"] = secondsSince(t0);
        for (bool adaptive : {false, true}) {
            auto [r, json] = sweep(model, adaptive, false);
            out[name + (adaptive ? "_adaptive" : "_static")] = std::move(json);
            if (kind == gp::KernelKind::kFas && !adaptive) fasStatic = std::move(r);
        }
        if (kind == gp::KernelKind::kFas) fasModel = model;
    }
    out["fas_static_drag"] = sweep(fasModel, false, true).second;
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
        plain.constraints = {{row.effector, origin + row.direction * delta, false}};
        plain.solve();
        const Eigen::VectorXd plainPose = PoseLayout(clip.skeleton).extract(plain.pose);
        compare.push_back(
            {{"delta_cm", delta},
             {"learned",
              {{"residual_cm", learned.residualCm}, {"nn_rms_deg", nearestPoseRmsDeg(learned.poseDeg, candidates)}}},
             {"plain",
              {{"residual_cm", plain.results[0].residualCm},
               {"nn_rms_deg", nearestPoseRmsDeg(plainPose, candidates)}}}});
    }
    out["learned_vs_plain"] = compare;
    {
        const auto s0 = std::chrono::steady_clock::now();
        SpanRangeJob span;
        span.version = fasModel;
        span.frame = frame;
        span.joins = joins;
        span.effector = row.effector;
        span.direction = row.direction;
        span.tests = &tests;
        span.maxDeltaCm = s.maxDeltaCm;
        out["fas_static_span"] = span.run();
        out["fas_static_span"]["seconds"] = secondsSince(s0);
        // The span reports the first test that failed, or that none did up to the sweep's end.
        nlohmann::json& spanCell = out["fas_static_span"];
        const bool stopped = spanCell.contains("combined") && spanCell["combined"].get<int>() < s.maxDeltaCm;
        spanCell["binding"] = stopped ? nlohmann::json::array({spanCell["first_failure"]}) : nlohmann::json::array();
    }
    return out;
}

// A cell's combined range in one run, or NaN when the cell did not run (a span that does not fit).
double cellRange(const nlohmann::json& run, const std::string& cell) {
    return run.contains(cell) && run[cell].contains("combined") ? run[cell]["combined"].get<double>() : std::nan("");
}

// The paper's Table 2 claims, and this product's columns on the same yardstick, over every
// (row, run) pair.
nlohmann::json table2Claims(const std::vector<std::string>& kinds,
                            const std::vector<std::vector<nlohmann::json>>& runs) {
    auto differences = [&](const std::string& better, const std::string& than) {
        std::vector<std::vector<double>> d(runs.size());
        for (std::size_t r = 0; r < runs.size(); ++r)
            for (const auto& run : runs[r]) {
                const double v = cellRange(run, better) - cellRange(run, than);
                if (!std::isnan(v)) d[r].push_back(v);
            }
        return d;
    };
    nlohmann::json claims = nlohmann::json::array();
    claims.push_back(claimJson(
        "the adaptive FASGPLVM extends the editing range over the static SGPLVM (the paper's Table 2)",
        "range FAS adaptive - range SGPLVM static (cm)", kinds, differences("fas_adaptive", "sgplvm_static")));
    claims.push_back(claimJson("the FASGPLVM kernel alone extends the range (both static)",
                               "range FAS static - range SGPLVM static (cm)", kinds,
                               differences("fas_static", "sgplvm_static")));
    claims.push_back(claimJson("the adaptive active set extends FASGPLVM's range",
                               "range FAS adaptive - range FAS static (cm)", kinds,
                               differences("fas_adaptive", "fas_static")));
    claims.push_back(claimJson("beyond the paper: span regeneration extends the range over the adaptive FASGPLVM",
                               "range span - range FAS adaptive (cm)", kinds,
                               differences("fas_static_span", "fas_adaptive")));
    claims.push_back(claimJson("beyond the paper: the editor's drag solve extends the range over the adaptive FASGPLVM",
                               "range editor drag - range FAS adaptive (cm)", kinds,
                               differences("fas_static_drag", "fas_adaptive")));
    return claims;
}

}  // namespace

nlohmann::json runTable2(const std::string& dir, const Table2Settings& s, const ProgressFn& progress) {
    s.validate();
    nlohmann::json out;
    out["settings"] = {{"outer_iterations", s.outerIterations},
                       {"active", s.activeSize},
                       {"max_delta_cm", s.maxDeltaCm},
                       {"lambda", LearnedIkRequest{}.lambda},
                       {"ik_iterations", s.ikIterations},
                       {"adaptive_scg_iterations", s.adaptiveScgIterations},
                       {"quick", s.quick},
                       {"mocap_dir", dir},
                       {"runs", s.runs},
                       {"perturbation", describeRunPerturbation(s.runs, s.startNoise)},
                       {"cells", table2Cells()}};
    nlohmann::json reductions = nlohmann::json::array(
        {"outer iterations T = " + std::to_string(s.outerIterations) +
         " per model instead of the paper's 46-71 (time); models are trained once per row, run and kernel"});
    if (s.quick) reductions.push_back("quick: short stretches of the shipped clips, not the protocol's clips");
    out["reductions"] = reductions;
    // Clips and R are read once per row (R is the same yardstick for every run of a row).
    TrialCache cache;
    struct RowData {
        Clip clip;
        std::vector<Clip> refClips;
        int frame = 0;
        std::vector<int> joins;  // first frame of every segment after the first
        std::unique_ptr<NaturalnessTests> tests;
    };
    std::vector<RowData> data(s.rows.size());
    for (std::size_t r = 0; r < s.rows.size(); ++r) {
        const Table2Row& row = s.rows[r];
        RowData& d = data[r];
        d.clip = namedClip(dir, row.training, cache);
        for (std::size_t k = 0, at = 0; k + 1 < row.training.size(); ++k) {
            at += row.training[k].last - row.training[k].first + 1;
            d.joins.push_back(static_cast<int>(at));
        }
        for (const ClipSegment& seg : row.reference) d.refClips.push_back(namedClip(dir, {seg}, cache));
        d.frame = row.frame - 1;
        if (d.frame < 0 || d.frame >= d.clip.frameCount())
            throw std::invalid_argument("expected the edited frame within 1.." + std::to_string(d.clip.frameCount()) +
                                        " of " + d.clip.name + ", found " + std::to_string(row.frame));
        requireJudgeableSkeleton(d.clip, d.clip);
        for (const Clip& c : d.refClips) requireJudgeableSkeleton(c, d.clip);
        const std::vector<ReferenceFrame> ref = table2Reference(d.clip, d.frame, d.refClips);
        if (static_cast<int>(ref.size()) < kMinReferenceFrames)
            throw std::invalid_argument("expected at least " + std::to_string(kMinReferenceFrames) +
                                        " reference frames (R: " + d.clip.name +
                                        " without the edited frame ± 10, and the references), found " +
                                        std::to_string(ref.size()) + "; give a longer clip or --reference");
        d.tests = std::make_unique<NaturalnessTests>(ref, row.effector);
    }
    const int jobs = static_cast<int>(s.rows.size()) * s.runs;
    std::vector<nlohmann::json> results(jobs);
    const ProgressFn say = lockedProgress(progress);
    forEachJob(jobs, s.workers, [&](int j) {
        const int r = j / s.runs, run = j % s.runs;
        results[j] = table2Job(s.rows[r], data[r].clip, data[r].frame, data[r].joins, *data[r].tests, s, run, say);
    });
    nlohmann::json table = nlohmann::json::array();
    std::vector<std::string> kinds;
    std::vector<std::vector<nlohmann::json>> byRow;
    for (std::size_t r = 0; r < s.rows.size(); ++r) {
        const Table2Row& row = s.rows[r];
        const RowData& d = data[r];
        const NaturalnessTests& tests = *d.tests;
        int otherTrialFrames = 0;  // R holds every frame of each reference clip
        for (const Clip& c : d.refClips) otherTrialFrames += c.frameCount();
        nlohmann::json entry{{"kind", row.kind},
                             {"clip", d.clip.name},
                             {"frames", d.clip.frameCount()},
                             {"edited_frame", row.frame},
                             {"edit", row.edit},
                             {"why", row.why},
                             {"direction", {row.direction.x(), row.direction.y(), row.direction.z()}},
                             {"reference", "other trials: " + std::to_string(otherTrialFrames) +
                                               " frames, plus the training clip without frames " +
                                               std::to_string(row.frame - 10) + ".." + std::to_string(row.frame + 10)},
                             {"reference_frames", tests.size()},
                             {"tau_nn_cm", tests.nnThreshold()},
                             {"density_threshold", tests.densityThreshold()},
                             {"captured_frame", capturedVerdictJson(d.clip, d.frame, tests)}};
        std::vector<nlohmann::json> runs(results.begin() + r * s.runs, results.begin() + (r + 1) * s.runs);
        if (s.runs == 1) {
            for (auto& [key, value] : runs[0].items())
                if (key != "run" && key != "frames_trained") entry[key] = value;
        } else {
            nlohmann::json spread;
            for (const std::string& cell : table2Cells()) {
                std::vector<double> v;
                for (const auto& run : runs)
                    if (!std::isnan(cellRange(run, cell))) v.push_back(cellRange(run, cell));
                if (!v.empty()) spread[cell] = spreadJson(spreadOf(v));
            }
            entry["runs"] = runs;
            entry["spread"] = spread;
        }
        table.push_back(entry);
        kinds.push_back(row.kind);
        byRow.push_back(std::move(runs));
    }
    out["rows"] = table;
    out["claims"] = table2Claims(kinds, byRow);
    return out;
}

}  // namespace mgp
