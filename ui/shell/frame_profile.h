#pragma once
// Where one editor frame's time goes (`motiongp bench --only ui`). Each phase adds its wall time
// to its slot. With `measure` on, a phase ends with glFinish, so the GPU work it queued (llvmpipe
// rasterising on the CPU) is charged to it and not to whoever next waits on the driver; that
// stalls the pipeline, so it is off in normal use and the slots then hold CPU-side times only.
#include <chrono>

namespace mgp::ui {

struct FrameProfile {
    bool measure = false;
    double solveSeconds = 0.0;         // learned IK: dragTo / refine in the viewport
    double sceneSeconds = 0.0;         // the 3-D scene into the viewport's texture (0 when not redrawn)
    double latentUploadSeconds = 0.0;  // a new σ² image uploaded, the latent map's static layer redrawn
    double imguiRenderSeconds = 0.0;   // the viewport's blit and the panels' draw lists, to the window
    void beginFrame() { solveSeconds = sceneSeconds = latentUploadSeconds = imguiRenderSeconds = 0.0; }
};

// Adds the scope's wall time to one slot of a FrameProfile (after glFinish when measuring).
class PhaseTimer {
public:
    PhaseTimer(const FrameProfile& profile, double& slot)
        : measure_(profile.measure), slot_(slot), start_(std::chrono::steady_clock::now()) {}
    ~PhaseTimer();
    PhaseTimer(const PhaseTimer&) = delete;
    PhaseTimer& operator=(const PhaseTimer&) = delete;

private:
    bool measure_;
    double& slot_;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace mgp::ui
