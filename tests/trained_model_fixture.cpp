#include "trained_model_fixture.h"

#include <mutex>

#include "gp/model_file.h"
#include "test_paths.h"

namespace mgp::test {

std::string walkModelPath() { return std::string(MOTIONGP_TEST_FIXTURES) + "/walk35_fas_m100_t3.model"; }

gp::ModelVersionPtr walkModel35() {
    static std::once_flag once;
    static gp::ModelVersionPtr model;
    std::call_once(once, [] { model = gp::ModelVersion::make(gp::loadModel(walkModelPath())); });
    return model;
}

gp::ModelVersionPtr kickModel1003() {
    static std::once_flag once;
    static gp::ModelVersionPtr model;
    std::call_once(once, [] {
        model =
            gp::ModelVersion::make(gp::loadModel(std::string(MOTIONGP_TEST_FIXTURES) + "/kick10_03_fas_m100_t3.model"));
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
