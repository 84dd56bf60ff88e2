#include "edit/training_job.h"

#include <chrono>
#include <cstdio>

namespace mgp {

TrainingJob::~TrainingJob() {
    cancel();
    join();
}

void TrainingJob::join() {
    if (thread_.joinable()) thread_.join();
}

std::string TrainingJob::start(const Clip& clip, const gp::TrainOptions& options, const std::string& sourceFile) {
    if (running_.load()) return "a training run is already in progress";
    if (clip.format == ClipFormat::kBvh) return "BVH clips are view-only: training on BVH is not supported yet";
    if (clip.frameCount() < 3) return "expected at least 3 frames to train on, found " + std::to_string(clip.frameCount());
    join();
    cancel_.store(false);
    running_.store(true);
    {
        std::lock_guard<std::mutex> lock(mutex_);
        progress_ = {};
        progress_.running = true;
        progress_.total = options.outerIterations;
        progress_.kernel = gp::kernelKindName(options.kind);
        result_.reset();
        message_.clear();
        started_ = std::chrono::steady_clock::now();
    }
    thread_ = std::thread(&TrainingJob::run, this, clip, options, sourceFile);
    return "";
}

void TrainingJob::cancel() { cancel_.store(true); }

TrainingProgress TrainingJob::progress() const {
    std::lock_guard<std::mutex> lock(mutex_);
    TrainingProgress p = progress_;
    if (p.running)
        p.elapsedSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
    return p;
}

gp::ModelVersionPtr TrainingJob::take() {
    std::lock_guard<std::mutex> lock(mutex_);
    gp::ModelVersionPtr r = std::move(result_);
    result_.reset();
    return r;
}

std::string TrainingJob::message() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return message_;
}

void TrainingJob::run(Clip clip, gp::TrainOptions options, std::string sourceFile) {
    const auto t0 = std::chrono::steady_clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
    std::string msg;
    gp::ModelVersionPtr version;
    try {
        gp::TrainResult res = gp::trainOnClip(std::move(clip), options, [&](const gp::IterationLog& e) {
            std::lock_guard<std::mutex> lock(mutex_);
            progress_.iteration = e.iter;
            progress_.objective = e.L;
            progress_.elapsedSeconds = elapsed();
            if (e.iter > 0) progress_.etaSeconds = progress_.elapsedSeconds / e.iter * (progress_.total - e.iter);
        }, &cancel_);
        if (res.cancelled) {
            msg = "training cancelled after " + std::to_string(res.log.size()) + " iterations";
        } else {
            res.model.sourceFile = sourceFile;
            version = gp::ModelVersion::make(std::move(res.model));
            char buf[160];
            std::snprintf(buf, sizeof buf, "trained %s: %zu iterations in %.1f s%s", gp::kernelKindName(options.kind),
                          res.log.size(), elapsed(), res.converged ? " (converged)" : "");
            msg = buf;
        }
    } catch (const std::exception& e) {
        msg = std::string("training failed: ") + e.what();
    }
    {
        std::lock_guard<std::mutex> lock(mutex_);
        result_ = version;
        message_ = msg;
        progress_.running = false;
        progress_.elapsedSeconds = elapsed();
    }
    running_.store(false);
}

}  // namespace mgp
