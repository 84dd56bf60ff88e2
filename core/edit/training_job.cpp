#include "edit/training_job.h"

#include <chrono>
#include <cstdio>
#include <utility>

namespace mgp {
namespace {

// Whether a running training publishes after iteration `iter`, `sinceLast` seconds after its last
// publication (`count` so far).
bool publishDue(const PublishPolicy& policy, int iter, double sinceLast, int count) {
    if (!policy.enabled || iter < policy.firstIterations) return false;
    return count == 0 || sinceLast >= policy.everySeconds;
}

}  // namespace

TrainingJob::TrainingJob()
    : worker_(
          WorkerPolicy::kLatestRequest, [this](Request& r, const std::atomic<bool>& cancel) { return run(r, cancel); },
          "training failed: ") {}

std::string TrainingJob::start(const Clip& clip, const gp::TrainOptions& options, const std::string& sourceFile) {
    if (clip.frameCount() < 3)
        return "expected at least 3 frames to train on, found " + std::to_string(clip.frameCount());
    if (worker_.busy()) return "a training run is already in progress";  // before copying the clip
    gp::TrainingClip one;
    one.clip = clip;
    unwrapClip(one.clip);  // the model's clip must match its (unwrapped) training rows
    one.path = sourceFile;
    one.frames =
        gp::trainingFrames(clip.frameCount(), clip.restFrame, gp::FrameSelection{}, clip.name);  // all but a rest frame
    std::vector<gp::TrainingClip> clips;
    clips.push_back(std::move(one));
    return startRequest(Request{std::move(clips), gp::FrameSelection{}, options});
}

std::string TrainingJob::start(std::vector<gp::TrainingClip> clips, const gp::FrameSelection& selection,
                               const gp::TrainOptions& options) {
    if (clips.empty()) return "expected at least one clip to train on";
    return startRequest(Request{std::move(clips), selection, options});
}

std::string TrainingJob::startRequest(Request request) {
    static const char* const kBusy = "a training run is already in progress";
    if (worker_.busy()) return kBusy;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        progress_ = {};
        refinement_.reset();
        progress_.running = true;
        progress_.total = request.options.outerIterations;
        progress_.kernel = gp::kernelKindName(request.options.kind);
        started_ = std::chrono::steady_clock::now();
    }
    if (!worker_.startIfIdle(std::move(request))) return kBusy;
    return "";
}

TrainingProgress TrainingJob::progress() const {
    std::lock_guard<std::mutex> lock(mutex_);
    TrainingProgress p = progress_;
    if (p.running)
        p.elapsedSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
    return p;
}

gp::ModelVersionPtr TrainingJob::take() {
    std::optional<gp::ModelVersionPtr> r = worker_.take();
    if (r) {
        std::lock_guard<std::mutex> lock(mutex_);
        refinement_.reset();  // superseded by the final model
    }
    return r ? std::move(*r) : nullptr;
}

gp::ModelVersionPtr TrainingJob::takeRefinement() {
    std::lock_guard<std::mutex> lock(mutex_);
    return std::exchange(refinement_, nullptr);
}

JobOutcome<gp::ModelVersionPtr> TrainingJob::run(Request& request, const std::atomic<bool>& cancel) {
    const auto t0 = std::chrono::steady_clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
    // The progress ends "not running" however the run ends, a thrown error included.
    struct Finish {
        TrainingJob& job;
        const decltype(elapsed)& seconds;
        ~Finish() {
            std::lock_guard<std::mutex> lock(job.mutex_);
            job.progress_.running = false;
            job.progress_.elapsedSeconds = seconds();
        }
    } finish{*this, elapsed};
    const gp::TrainOptions& options = request.options;
    const PublishPolicy policy = policy_;
    double lastPublished = 0.0;
    int published = 0;
    gp::TrainControl control;
    control.cancel = &cancel;
    control.afterIteration = [&](const gp::Trainer& trainer) {
        const gp::IterationLog& e = trainer.log().back();
        {
            std::lock_guard<std::mutex> lock(mutex_);
            progress_.iteration = e.iter;
            progress_.objective = e.L;
            progress_.elapsedSeconds = elapsed();
            if (e.iter > 0) progress_.etaSeconds = progress_.elapsedSeconds / e.iter * (progress_.total - e.iter);
        }
        // The last iteration's model is the final one (take()); earlier ones are published by the policy.
        const bool last = e.iter >= options.outerIterations;
        const bool due = publishDue(policy, e.iter, elapsed() - lastPublished, published);
        if (last || !due || cancel.load()) return;
        gp::GpModel snapshot = gp::snapshotModel(trainer);
        gp::attachTrainingClips(snapshot, request.clips, request.selection);
        gp::ModelVersionPtr version = gp::ModelVersion::make(std::move(snapshot));
        lastPublished = elapsed();
        std::lock_guard<std::mutex> lock(mutex_);
        refinement_ = std::move(version);
        progress_.published = ++published;
        progress_.publishedIteration = e.iter;
        progress_.publishedObjective = e.L;
    };
    gp::TrainResult res = gp::train(gp::trainingDataOf(request.clips), options, control);
    if (res.cancelled)
        return {std::nullopt, "training cancelled after " + std::to_string(res.log.size()) + " iterations"};
    gp::attachTrainingClips(res.model, std::move(request.clips), request.selection);
    char buf[160];
    std::snprintf(buf, sizeof buf, "trained %s: %zu iterations in %.1f s%s", gp::kernelKindName(options.kind),
                  res.log.size(), elapsed(), res.converged ? " (converged)" : "");
    return {gp::ModelVersion::make(std::move(res.model)), buf};
}

}  // namespace mgp
