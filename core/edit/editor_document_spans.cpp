// EditorDocument's span edits (editor_document.h, sections "path editing" and "keys and
// in-betweening"): path regeneration and fill between keys, solved on background workers and
// applied as one undo step each.
#include "edit/editor_document.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "edit/held_effectors.h"
#include "edit/regeneration_step.h"
#include "ik/locality.h"
#include "skeleton/pose_layout.h"

namespace mgp {

// ---- path editing --------------------------------------------------------------------------

std::string EditorDocument::beginPathEdit(Effector e) { return paths_.begin(e, frame_); }

std::string EditorDocument::startRegenerate(int maxIterations) {
    const std::optional<PathEdit>& path = paths_.edit();
    if (!path) return "no path is being edited";
    const gp::ModelVersionPtr v = model();
    if (!v) return "regeneration needs a model: train one or open one first";
    const Clip& mc = v->model->clip;
    if (mc.frameCount() != frameCount() || mc.skeleton.jointCount() != clip().skeleton.jointCount())
        return "expected a model trained on this clip, found one trained on " + mc.name;
    finishRunningFalloff();
    pollRegenerate();  // never drop a finished result nobody took yet
    cancelDrag();
    MotionEditJob job;
    job.version = v;
    job.effector = path->effector;
    job.keyFrames = path->keyFrames;
    job.keyOffsetsCm = path->keyOffsetsCm;
    job.mode = path->mode;
    job.maxIterations = maxIterations;
    job.pins = pinnedEffectors();  // a pin holds its effector at the captured position on every frame of the span
    job.contacts = std::make_shared<const ContactSet>(store_.contacts());  // the user may have switched some off
    job.spanWeights.locality = kDefaultSpanLocality * bodyStiffness_;
    // The path is re-solved from the capture, but what earlier gestures placed on its inner frames
    // (held effectors, edit/held_effectors.h) stays where the edited motion has it
    // (EditBase::placedFrames); pins and planted feet are held as before.
    job.heldPlaced = heldRuns(store_, path->keyFrames.front() + 1, path->keyFrames.back() - 1, path->effector);
    if (!job.heldPlaced.empty()) {
        auto base = std::make_shared<EditBase>();
        base->frames = mc.frames;
        base->placedFrames.reserve(static_cast<std::size_t>(frameCount()));
        for (int t = 0; t < frameCount(); ++t) base->placedFrames.push_back(store_.pose(t));
        job.base = std::move(base);
    }
    return regenerate_.start(std::move(job));
}

std::string EditorDocument::pollRegenerate(std::string* error) {
    if (regenerate_.running()) return "";
    std::optional<MotionEditJob> job = regenerate_.take();
    if (!job) {
        if (error) *error = regenerate_.takeMessage();
        return std::exchange(falloffSkipped_, std::string());
    }
    // A drag's falloff joins the drag's own undo step when that step is still the latest.
    if (const long stepId = std::exchange(falloffStepId_, 0); stepId != 0) {
        EditStep* top = history_.topUndoWithId(stepId);
        if (!top) return "";  // undone or superseded: drop the falloff
        mergeFalloff(*job, store_, *top);
        applyFrames(top->after);
        ++revision_;
        return falloffSummary(*job, spreadFalloff_, spreadRadius_, top->label);
    }
    lastRegenerateQuality_ = job->quality;  // the Path panel's report: path regenerations only
    lastRegenerateKeys_ = job->keys;
    EditStep step = regenerationStep(*job, store_);
    if (models_.hasModel())
        for (AdaptiveSample& sample : movedKeySamples(*job)) {
            const auto it = step.after.find(sample.clipFrame);
            if (it == step.after.end() || !it->second) continue;  // a moved key is always a regenerated frame
            if (const long seq = teach(std::move(sample), it->second->pose, it->second->moved); seq > 0)
                step.samples.push_back(seq);
        }
    applyFrames(step.after);
    pushStep(std::move(step));
    return regenerationSummary(*job, models_.updating());
}

// ---- keys and in-betweening ----------------------------------------------------------------

void EditorDocument::toggleKey(int frame) {
    if (!hasClip() || frame < 0 || frame >= frameCount()) return;
    if (!keys_.erase(frame)) keys_.insert(frame);
    ++revision_;
}

std::string EditorDocument::restoreKeys(std::set<int> keys) {
    for (int k : keys)
        if (k < 0 || k >= frameCount())
            return "expected key frames in 1.." + std::to_string(frameCount()) + ", found " + std::to_string(k + 1);
    keys_ = std::move(keys);
    ++revision_;
    return "";
}

std::optional<InbetweenGap> EditorDocument::keyGapAt(int frame) const {
    auto after = keys_.upper_bound(frame);
    if (after == keys_.begin() || after == keys_.end()) return std::nullopt;
    const int a = *std::prev(after), b = *after;
    if (a + 1 >= b) return std::nullopt;
    return InbetweenGap{a, b};
}

std::vector<InbetweenGap> EditorDocument::keyGapsIn(int first, int last) const {
    std::vector<InbetweenGap> gaps;
    for (auto k = keys_.lower_bound(first); k != keys_.end() && std::next(k) != keys_.end() && *std::next(k) <= last;
         ++k)
        if (*k + 1 < *std::next(k)) gaps.push_back({*k, *std::next(k)});
    return gaps;
}

std::string EditorDocument::startFill(InbetweenMethod method, std::optional<std::pair<int, int>> range) {
    const gp::ModelVersionPtr v = model();
    if (!v) return "fill between keys needs a model: train one or open one first";
    std::vector<InbetweenGap> gaps;
    if (range) {
        gaps = keyGapsIn(range->first, range->second);
        if (gaps.empty())
            return "expected two keys with frames between inside frames " + std::to_string(range->first + 1) + "-" +
                   std::to_string(range->second + 1) + " (K marks a key)";
    } else if (const std::optional<InbetweenGap> gap = keyGapAt(frame_)) {
        gaps = {*gap};
    } else {
        return "expected a key before the playhead and one after it with frames between (K marks a key)";
    }
    finishRunningFalloff();  // a drag's spread finishes first (it is part of the drag)
    pollRegenerate();        // never drop a finished result nobody took yet
    if (regenerating()) return "a regeneration is running: wait for it or cancel it";
    cancelDrag();
    InbetweenJob job;
    job.version = v;
    job.clip = clip();
    // The capture the clip is a take of, judged on the unedited clip (edited frames would hide it):
    // its frames in the gap are never read, whatever was edited.
    job.sameCapture = gp::findCapture(*v->model, clip());
    for (int t = 0; t < frameCount(); ++t)
        job.clip.frames[static_cast<std::size_t>(t)] = poseAt(t);  // the edited motion
    job.gaps = std::move(gaps);
    job.method = method;
    if (const std::string problem = job.validate(); !problem.empty()) return problem;
    if (!fill_.startIfIdle(std::move(job))) return "a fill is already running";
    return "";
}

std::string EditorDocument::pollFill(std::string* error) {
    if (fill_.busy()) return "";
    std::optional<InbetweenJob> job = fill_.take();
    if (!job) {
        if (error) *error = fill_.takeMessage();
        return "";
    }
    const int first = job->gaps.front().a, last = job->gaps.back().b;
    // The keys or the frames between changed while it ran (nothing should, drags wait): the result
    // belongs to another motion, so it is dropped rather than pasted over the change.
    for (int t = first; t <= last; ++t)
        if (!posesIdentical(poseAt(t), job->clip.frames[static_cast<std::size_t>(t)])) {
            if (error) *error = "the motion between the keys changed while filling: fill again";
            return "";
        }
    EditStep step;
    step.label = "fill frames " + std::to_string(first + 2) + "-" + std::to_string(last);
    double seconds = 0.0, held = 0.0;
    for (std::size_t g = 0; g < job->gaps.size(); ++g) {
        for (int t = job->gaps[g].a + 1; t < job->gaps[g].b; ++t) {
            const std::size_t i = static_cast<std::size_t>(t);
            step.after[t] = EditRecord{job->frames[i], i < job->x.size() ? job->x[i] : Eigen::VectorXd(), {}};
        }
        seconds += job->reports[g].seconds;
        held = std::max(held, job->reports[g].maxHeldResidualCm);
    }
    step.before = store_.current(step.after);
    applyFrames(step.after);
    pushStep(std::move(step));
    const InbetweenJob::GapReport& r = job->reports.front();
    const std::size_t n = job->gaps.size();
    char summary[240];
    if (r.sourceClip.empty())
        std::snprintf(summary, sizeof summary, "filled frames %d-%d, %zu gap%s (%s)", first + 2, last, n,
                      n == 1 ? "" : "s", inbetweenMethodName(job->method));
    else if (n == 1)
        std::snprintf(summary, sizeof summary,
                      "filled frames %d-%d from %s frames %d-%d in %.2f s (feet held within %.2f cm)", first + 2, last,
                      r.sourceClip.c_str(), r.sourceFirst + 1, r.sourceLast + 1, seconds, held);
    else
        std::snprintf(summary, sizeof summary, "filled frames %d-%d, %zu gaps, in %.2f s (feet held within %.2f cm)",
                      first + 2, last, n, seconds, held);
    return summary;
}

}  // namespace mgp
