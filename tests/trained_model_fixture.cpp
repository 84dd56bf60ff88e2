#include "trained_model_fixture.h"

#include <mutex>

#include "gp/trainer.h"
#include "io/clip_loader.h"
#include "test_support.h"

namespace mgp::test {

gp::ModelVersionPtr walkModel35() {
    static std::once_flag once;
    static gp::ModelVersionPtr model;
    std::call_once(once, [] {
        gp::TrainOptions options;
        options.kind = gp::KernelKind::kFas;
        options.activeSize = 100;
        options.outerIterations = 3;
        model = gp::ModelVersion::make(gp::trainOnClip(loadClip(mocap("asf_amc/35_01.amc")), options).model);
    });
    return model;
}

LearnedIkRequest requestAtFrame(const gp::ModelVersion& version, int frame, int maxIterations) {
    LearnedIkRequest req;
    req.start = version.model->clip.frames[frame];
    req.startX = latentStartForFrame(version, frame);
    req.maxIterations = maxIterations;
    return req;
}

}  // namespace mgp::test
