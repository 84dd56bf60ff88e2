// bench section "fk": one FK pass and one effector Jacobian on a real clip.
#include "bench_registry.h"
#include "io/clip_loader.h"
#include "skeleton/forward_kinematics.h"
#include "skeleton/synthetic_clip.h"

namespace mgp::app {
namespace {

const BenchRegistration fkBench("fk", "Forward kinematics and effector Jacobian per call", [](const BenchContext& ctx) {
    const Clip clip = ctx.mocapDir.empty() ? makeSyntheticWalk() : loadClip(ctx.mocapDir + "/asf_amc/35_01.amc");
    const PoseLayout layout(clip.skeleton);
    FkState fk;
    Eigen::Matrix<double, 3, Eigen::Dynamic> jac(3, layout.size());
    const int calls = ctx.quick ? 1000 : 20000;
    std::vector<double> fkSamples, jacSamples;
    volatile double sink = 0.0;
    for (int r = 0; r < ctx.repeats; ++r) {
        fkSamples.push_back(secondsOf([&] {
                                for (int i = 0; i < calls; ++i)
                                    forwardKinematics(clip.skeleton, clip.frames[i % clip.frameCount()], fk);
                                sink = sink + fk.jointCm[1].x();
                            }) /
                            calls);
        forwardKinematics(clip.skeleton, clip.frames[0], fk);
        jacSamples.push_back(secondsOf([&] {
                                 for (int i = 0; i < calls; ++i)
                                     effectorJacobian(clip.skeleton, layout, fk, clip.frames[0], Effector::kRFoot, jac);
                                 sink = sink + jac(0, 0);
                             }) /
                             calls);
    }
    return nlohmann::json{{"clip", clip.name},
                          {"fk_seconds", summarizeSeconds(fkSamples)},
                          {"jacobian_seconds", summarizeSeconds(jacSamples)}};
});

}  // namespace
}  // namespace mgp::app
