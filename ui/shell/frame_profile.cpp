#include "ui/shell/frame_profile.h"

#include <GL/gl.h>

namespace mgp::ui {

PhaseTimer::~PhaseTimer() {
    if (measure_) glFinish();
    slot_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

}  // namespace mgp::ui
