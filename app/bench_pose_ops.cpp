// bench section "pose_ops": paste, mirror and rotate joint spread over time (EditorDocument::
// setCurrentPose: an additive layer over t−r..t+r re-solved under the learned prior with contacts
// held, r = a quarter second, widened for large changes), on standing frames of clips nobody
// tuned on. Each operation runs on the captured motion, as the editor runs it (a document with the
// model, adaptive updates off):
//  - paste: the pose of the frame 180 frames away (before t if there is room, else after);
//  - mirror: the frame's pose mirrored left/right;
//  - rotate: the right knee bent 30° further, then the same with the learned prior following.
// Reported per operation: the worst one-frame jump of a hand or foot over the span, in excess of
// the capture's jump on the same frames (the bar: ≤ 1 cm), the edited frames, the worst distance
// of a planted foot from its captured place (≤ 1 cm), the worst of a planted heel's (its ankle,
// on the frames the heel is down, the operation's own frame included; ≤ 1 cm), and the wall time.
#include "bench_clip_range.h"
#include "bench_registry.h"
#include "edit/editor_document.h"
#include "edit/joint_rotation.h"
#include "edit/mirror_edit.h"
#include "gp/train/trainer.h"
#include "motion/pose_layer.h"
#include "skeleton/forward_kinematics.h"

namespace mgp::app {
namespace {

const BenchClipRange kPoseOpsClips[] = {
    {"asf_amc/124_03.amc", 1, 620},
    {"asf_amc/13_17.amc", 1, 1200},
};

// Frames with both feet planted, `margin` frames from either end, spread over the clip.
std::vector<int> poseOpsFrames(const Clip& clip, const ContactSet& contacts, int margin, int count) {
    std::vector<int> candidates;
    for (int t = margin; t + margin < clip.frameCount(); ++t)
        if (contacts.at(Effector::kLFoot, t) && contacts.at(Effector::kRFoot, t)) candidates.push_back(t);
    return spreadPicks(candidates, count, 60);
}

// The operation's spread measured against the capture over t−R−1..t+R+1, R the widest a pose
// change's layer can be (kLayerWidening falloff radii): frames it did not edit add nothing.
nlohmann::json measurePoseOp(const EditorDocument& doc, const ContactSet& contacts, int t, int radius, double seconds) {
    const Clip& clip = doc.clip();
    const Skeleton& sk = clip.skeleton;
    const int reach = kLayerWidening * radius + 1;
    const int first = std::max(0, t - reach), last = std::min(clip.frameCount() - 1, t + reach);
    double worstJump = 0.0, worstFoot = 0.0;
    int jumpFrame = -1;
    Effector jumpEffector = Effector::kLHand;
    for (Effector e : {Effector::kLHand, Effector::kRHand, Effector::kLFoot, Effector::kRFoot}) {
        for (int s = first; s < last; ++s) {
            const double edited = (effectorCm(sk, doc.poseAt(s + 1), e) - effectorCm(sk, doc.poseAt(s), e)).norm();
            const double captured = (effectorCm(sk, clip.frames[s + 1], e) - effectorCm(sk, clip.frames[s], e)).norm();
            if (edited - captured > worstJump) worstJump = edited - captured, jumpFrame = s + 1, jumpEffector = e;
        }
    }
    for (Effector foot : {Effector::kLFoot, Effector::kRFoot})
        for (int s = first; s <= last; ++s)
            if (contacts.at(foot, s) && s != t)  // frame t is the operation's own pose
                worstFoot = std::max(
                    worstFoot, (effectorCm(sk, doc.poseAt(s), foot) - effectorCm(sk, clip.frames[s], foot)).norm());
    // The heels (the ankles) on the frames their heel is down, the operation's own frame too: a
    // foot held by its ball alone could tip onto its toe there.
    double worstHeel = 0.0;
    FkState edited, captured;
    for (int s = first; s <= last; ++s) {
        forwardKinematics(sk, doc.poseAt(s), edited);
        forwardKinematics(sk, clip.frames[s], captured);
        for (Effector foot : {Effector::kLFoot, Effector::kRFoot})
            if (const FootContact* c = contacts.at(foot, s); c && c->heel.contains(s)) {
                const int ankle = sk.effectorSite(foot).joint;
                worstHeel = std::max(worstHeel, (edited.jointCm[ankle] - captured.jointCm[ankle]).norm());
            }
    }
    return {{"worst_jump_over_capture_cm", worstJump},
            {"worst_jump_frame", jumpFrame + 1},
            {"worst_jump_effector", effectorName(jumpEffector)},
            {"planted_feet_worst_cm", worstFoot},
            {"planted_heels_worst_cm", worstHeel},
            {"edited_frames", doc.edits().size()},
            {"seconds", seconds},
            {"meets", worstJump <= 1.0 && worstFoot <= 1.0 && worstHeel <= 1.0}};
}

// Runs `op` on frame t of a fresh document state (everything undone), waits for its spread.
nlohmann::json runOp(EditorDocument& doc, const ContactSet& contacts, int t, const std::function<std::string()>& op) {
    while (doc.canUndo()) doc.undo();
    doc.setFrame(t);
    std::string err;
    const double seconds = secondsOf([&] {
        err = op();
        doc.waitIdle();
    });
    const std::string summary = doc.pollRegenerate();
    if (!err.empty()) return {{"error", err}};
    nlohmann::json out = measurePoseOp(doc, contacts, t, doc.dragFalloff(), seconds);
    out["spread"] = summary;
    return out;
}

nlohmann::json runPoseOpsClip(const BenchContext& ctx, const BenchClipRange& spec, const gp::TrainOptions& options) {
    int first = 1;
    const Clip clip = loadClipRange(ctx.mocapDir, spec, first);
    const gp::ModelVersionPtr version = gp::ModelVersion::make(gp::trainOnClip(clip, options).model);
    EditorDocument doc;
    doc.setModel(version, true);
    doc.setAdaptiveEnabled(false);
    const Clip& trained = doc.clip();
    const ContactSet& contacts = doc.contacts();
    const int radius = doc.dragFalloff();
    const int knee = trained.skeleton.findBone("rtibia");
    nlohmann::json rows = nlohmann::json::array();
    int met = 0, total = 0;
    for (int t : poseOpsFrames(trained, contacts, radius + 2, ctx.quick ? 1 : 3)) {
        const int source = t >= 180 ? t - 180 : std::min(trained.frameCount() - 1, t + 180);
        nlohmann::json row = {{"frame", t + first}, {"paste_from", source + first}};
        row["paste"] = runOp(doc, contacts, t, [&] { return doc.pastePose(trained.frames[source]); });
        row["mirror"] = runOp(doc, contacts, t, [&] { return mirrorCurrentPose(doc); });
        for (const bool prior : {false, true}) {
            row[prior ? "rotate_knee_prior" : "rotate_knee"] = runOp(doc, contacts, t, [&] {
                JointRotation r;
                r.joint = knee;
                r.anglesDeg = trained.frames[t].anglesDeg[knee] + Eigen::Vector3d(30.0, 0.0, 0.0);
                r.followPrior = prior;
                return applyJointRotation(doc, r);
            });
        }
        for (const char* op : {"paste", "mirror", "rotate_knee", "rotate_knee_prior"}) {
            ++total;
            met += row[op].value("meets", false);
        }
        rows.push_back(std::move(row));
    }
    return {{"clip", spec.path},
            {"frames", std::to_string(first) + "-" + std::to_string(first + clip.frameCount() - 1)},
            {"falloff_frames", radius},
            {"cases", rows},
            {"meets", std::to_string(met) + "/" + std::to_string(total)}};
}

const BenchRegistration poseOpsBench(
    "pose_ops", "Paste, mirror and rotate joint spread on standing frames: jumps, planted feet, time",
    [](const BenchContext& ctx) {
        if (ctx.mocapDir.empty()) return nlohmann::json{{"skipped", "no CMU mocap folder"}};
        gp::TrainOptions options;
        options.outerIterations = 20;
        if (ctx.quick) options.activeSize = 100, options.outerIterations = 3;
        nlohmann::json out = nlohmann::json::array();
        const std::size_t clips = ctx.quick ? 1 : std::size(kPoseOpsClips);
        for (std::size_t c = 0; c < clips; ++c) out.push_back(runPoseOpsClip(ctx, kPoseOpsClips[c], options));
        return nlohmann::json{{"clips", out}};
    });

}  // namespace
}  // namespace mgp::app
