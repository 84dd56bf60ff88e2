#pragma once
// TrainingJob: trains a model from one clip or several clips of one skeleton on a background thread, one outer
// iteration at a time, with progress, an ETA and cancellation (docs/architecture.md §4: the app never blocks the UI on
// training). The UI polls progress() every frame and takes the finished model once. The thread,
// the cancel flag and the take-once model are a BackgroundWorker's (core/util/background_worker.h),
// one run at a time. No GL or ImGui here.
#include <chrono>
#include <mutex>
#include <string>
#include <vector>

#include "gp/model_version.h"
#include "gp/train/trainer.h"
#include "gp/train/training_clips.h"
#include "skeleton/clip.h"
#include "util/background_worker.h"

namespace mgp {

struct TrainingProgress {
    bool running = false;
    int iteration = 0;     // outer iterations done
    int total = 0;         // T
    double objective = 0;  // L_GP after the last iteration
    double elapsedSeconds = 0;
    double etaSeconds = -1;  // < 0 until one iteration has finished (an upper bound: Step 9 may stop early)
    std::string kernel;      // "fas" | "sgplvm"
    // Models published while the run goes on (docs/maths.md §23): how many, and
    // the outer iteration and L_GP of the latest.
    int published = 0;
    int publishedIteration = 0;
    double publishedObjective = 0;
};

// When a running training publishes the model as it stands: first after `firstIterations` outer
// iterations, then again once `everySeconds` have passed since the last publication. The defaults
// are docs/maths.md §23's measured choice.
struct PublishPolicy {
    int firstIterations = 3;
    double everySeconds = 4.0;
    bool enabled = true;
};

class TrainingJob {
public:
    TrainingJob();
    ~TrainingJob() = default;  // the worker cancels and joins
    TrainingJob(const TrainingJob&) = delete;
    TrainingJob& operator=(const TrainingJob&) = delete;

    // Starts training on every frame of `clip` (ASF/AMC or synthetic). Returns "" or why not
    // (a job is running, fewer than 3 frames).
    std::string start(const Clip& clip, const gp::TrainOptions& options, const std::string& sourceFile = "");
    // Starts training on clips checked by gp::prepareTrainingClips (the first becomes the model's
    // primary clip; `selection` is recorded in the model's settings). "" or why not.
    std::string start(std::vector<gp::TrainingClip> clips, const gp::FrameSelection& selection,
                      const gp::TrainOptions& options);
    void cancel() { worker_.cancel(); }
    bool running() const { return worker_.busy(); }
    TrainingProgress progress() const;
    // The finished model, once (null while running, after a cancel, or when already taken).
    gp::ModelVersionPtr take();
    // The latest model published while the run goes on, once (null when there is none newer than
    // the last one taken). A finished run's final model comes from take(), never from here.
    gp::ModelVersionPtr takeRefinement();
    // For the next start() (tests: publish after every iteration).
    void setPublishPolicy(const PublishPolicy& policy) { policy_ = policy; }
    // "" or the last job's outcome ("cancelled after 3 iterations", an error message, ...).
    std::string message() const { return worker_.message(); }
    void join() { worker_.waitIdle(); }

private:
    struct Request {
        std::vector<gp::TrainingClip> clips;
        gp::FrameSelection selection;
        gp::TrainOptions options;
    };
    std::string startRequest(Request request);
    JobOutcome<gp::ModelVersionPtr> run(Request& request, const std::atomic<bool>& cancel);
    mutable std::mutex mutex_;  // guards progress_, started_ and refinement_
    TrainingProgress progress_;
    gp::ModelVersionPtr refinement_;
    PublishPolicy policy_;  // read by the worker: changed only between runs
    std::chrono::steady_clock::time_point started_;
    BackgroundWorker<Request, gp::ModelVersionPtr> worker_;  // last: joined before the members above go
};

}  // namespace mgp
