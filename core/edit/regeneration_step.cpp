#include "edit/regeneration_step.h"

#include <algorithm>
#include <cstdio>

#include "edit/held_effectors.h"

namespace mgp {

FrameEdits regeneratedFrames(const MotionEditJob& job) {
    FrameEdits out;
    for (std::size_t i = 0; i < job.solvedFrames.size(); ++i) {
        const int t = job.solvedFrames[i];
        // The effector the gesture placed, and those it held there because earlier ones placed them.
        std::vector<Effector> placed;
        if (job.placesEffector) placed.push_back(job.effector);
        for (const ContactInterval& c : job.heldPlaced)
            if (t >= c.first && t <= c.last) placed.push_back(c.foot);
        out[t] = EditRecord{job.frames[t], job.results[i].x, withHeld({}, placed)};
    }
    return out;
}

EditStep regenerationStep(const MotionEditJob& job, const ClipEdits& edits) {
    EditStep step;
    char label[96];
    std::snprintf(label, sizeof label, "regenerate %s, frames %d-%d", effectorName(job.effector),
                  job.keyFrames.front() + 2, job.keyFrames.back());
    step.label = label;
    step.after = regeneratedFrames(job);
    step.before = edits.current(step.after);
    return step;
}

void mergeFalloff(const MotionEditJob& job, const ClipEdits& edits, EditStep& dragStep) {
    for (auto& [frame, record] : regeneratedFrames(job)) {
        if (job.heldPose && frame == job.heldPose->frame) continue;  // held: the drag's own record stays
        if (!dragStep.before.count(frame)) dragStep.before[frame] = edits.editAt(frame);
        dragStep.after[frame] = std::move(record);
    }
}

std::vector<AdaptiveSample> movedKeySamples(const MotionEditJob& job) {
    std::vector<AdaptiveSample> out;
    for (std::size_t k = 1; k + 1 < job.keyFrames.size(); ++k) {
        if (job.keyOffsetsCm[k].isZero()) continue;
        const int t = job.keyFrames[k];
        const auto it = std::find(job.solvedFrames.begin(), job.solvedFrames.end(), t);
        if (it == job.solvedFrames.end()) continue;
        const LearnedIkResult& r = job.results[static_cast<std::size_t>(it - job.solvedFrames.begin())];
        if (!r.x.allFinite() || !r.y.allFinite()) continue;
        out.push_back({r.x, r.y, t});
    }
    return out;
}

std::string regenerationSummary(const MotionEditJob& job, bool updateQueued) {
    const SpanQuality& q = job.quality;
    char summary[320];
    std::snprintf(
        summary, sizeof summary,
        "regenerated %zu frames, max residual %.3f cm; angle 2nd difference p95 %.1f° (captured %.1f°), max %.1f° "
        "(captured %.1f°); %zu contact(s) held%s",
        job.solvedFrames.size(), job.maxResidualCm, q.edited.p95Deg, q.captured.p95Deg, q.edited.maxDeg,
        q.captured.maxDeg, job.held.size() - static_cast<std::size_t>(job.placedRunsHeld),
        updateQueued ? " (adaptive update queued)" : "");
    std::string out = summary;
    if (job.placedRunsHeld > 0)
        out += "; " + std::to_string(job.placedRunsHeld) + " placed effector run(s) held where you put them";
    // A key the solve could not meet is said here too, not only in the Path panel's red rows.
    for (const MotionEditJob::KeyResult& k : job.keys) {
        if (k.reached) continue;
        char missed[96];
        std::snprintf(missed, sizeof missed, "; the key on frame %d missed its target by %.1f cm", k.frame + 1,
                      k.errorCm);
        out += missed;
    }
    return out;
}

std::string falloffSummary(const MotionEditJob& job, int falloffRadius, int spreadRadius,
                           const std::string& stepLabel) {
    std::string out = stepLabel + ": spread over frames " + std::to_string(job.keyFrames.front() + 2) + "-" +
                      std::to_string(job.keyFrames.back()) + " (falloff " + std::to_string(falloffRadius) + " frames";
    if (spreadRadius > falloffRadius)
        out += ", widened to " + std::to_string(spreadRadius) + " to keep the motion smooth";
    return out + ")";
}

}  // namespace mgp
