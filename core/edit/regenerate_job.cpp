#include "edit/regenerate_job.h"

#include <utility>

namespace mgp {

RegenerateJob::~RegenerateJob() {
    cancel();
    join();
}

std::string RegenerateJob::start(MotionEditJob job) {
    if (running_.load()) return "a regeneration is already running";
    if (const std::string problem = job.validate(); !problem.empty()) return problem;
    join();
    {
        std::lock_guard<std::mutex> lock(mutex_);
        result_.reset();
        message_.clear();
    }
    cancel_ = false;
    done_ = 0;
    total_ = std::max(0, job.keyFrames.back() - job.keyFrames.front() - 1);
    running_ = true;
    thread_ = std::thread([this, job = std::move(job)]() mutable {
        job.framesDone = &done_;
        job.cancel = &cancel_;
        std::string message;
        try {
            job.run();
            if (job.cancelled) message = "regeneration cancelled";
        } catch (const std::exception& e) {
            message = std::string("regeneration failed: ") + e.what();
        }
        job.framesDone = nullptr;
        job.cancel = nullptr;
        {
            std::lock_guard<std::mutex> lock(mutex_);
            message_ = message;
            if (message.empty()) result_ = std::move(job);
        }
        running_ = false;
    });
    return "";
}

void RegenerateJob::cancel() { cancel_ = true; }

std::optional<MotionEditJob> RegenerateJob::take() {
    if (running_.load()) return std::nullopt;
    std::lock_guard<std::mutex> lock(mutex_);
    std::optional<MotionEditJob> out = std::move(result_);
    result_.reset();
    return out;
}

std::string RegenerateJob::takeMessage() {
    std::lock_guard<std::mutex> lock(mutex_);
    return std::exchange(message_, std::string());
}

void RegenerateJob::join() {
    if (thread_.joinable()) thread_.join();
}

}  // namespace mgp
