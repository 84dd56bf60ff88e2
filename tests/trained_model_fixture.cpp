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
        Clip clip = loadClip(mocap("asf_amc/35_01.amc"));
        unwrapClip(clip);
        const Eigen::MatrixXd poses = poseMatrix(clip);
        std::vector<int> frames(clip.frameCount());
        for (int t = 0; t < clip.frameCount(); ++t) frames[t] = t;
        gp::TrainOptions options;
        options.kind = gp::KernelKind::kFas;
        options.activeSize = 100;
        options.outerIterations = 3;
        gp::TrainResult result = gp::train(gp::prepareTrainingData(poses, frames), options);
        result.model.clip = std::move(clip);
        model = gp::ModelVersion::make(std::move(result.model));
    });
    return model;
}

}  // namespace mgp::test
