#pragma once
// The offscreen editor the UI tests drive (tests/gl/test_gui_*.cpp): an EGL context, an
// EditorApp on 35_01 from the shared mocap, optionally with a small model trained at test time
// (FASGPLVM, M = 100, T = 3: about a second), and the input a script or the test fills.
#include <doctest/doctest.h>

#include <filesystem>
#include <memory>
#include <string>

#include "editor_app.h"
#include "gl_context.h"
#include "input_state.h"

namespace mgp::test {

inline const std::string kMocap = MOTIONGP_TEST_MOCAP;
inline const std::string kGoldenDir = MOTIONGP_GOLDEN_DIR;
inline const std::string kOutDir = MOTIONGP_GL_OUT_DIR;
constexpr int kW = 1280, kH = 800;

struct Harness {
    std::unique_ptr<render::OffscreenContext> ctx;
    std::unique_ptr<ui::EditorApp> app;
    ui::InputState input;
    int frameNo = 0;

    void frame(int n = 1) {
        for (int i = 0; i < n; ++i, ++frameNo) app->frame(input, 1.0 / 60.0, kW, kH);
    }
};

// Offscreen editor on 35_01 with a small trained model, or nullptr (test skipped with a reason).
inline std::unique_ptr<Harness> makeHarness(bool llvmpipeOnly, bool train = true) {
    if (!std::filesystem::exists(kMocap + "/asf_amc/35_01.amc")) {
        MESSAGE("MOTIONGP_GL_SKIP: no CMU mocap folder at " << kMocap);
        return nullptr;
    }
    auto h = std::make_unique<Harness>();
    try {
        h->ctx = std::make_unique<render::OffscreenContext>(kW, kH);
    } catch (const render::RenderError& e) {
        MESSAGE("MOTIONGP_GL_SKIP: no offscreen GL context: " << e.what());
        return nullptr;
    }
    if (llvmpipeOnly && !render::currentGlInfo().isLlvmpipe()) {
        MESSAGE("MOTIONGP_GL_SKIP: goldens are made with Mesa llvmpipe");
        return nullptr;
    }
    ui::EditorOptions o;
    o.builtinFont = true;  // no dependence on system fonts
    h->app = std::make_unique<ui::EditorApp>(o);
    REQUIRE(h->app->openClip(kMocap + "/asf_amc/35_01.amc") == "");
    h->frame(2);
    if (train) {
        REQUIRE(h->app->runAction({"train", "fas", "100", "3"}) == "");
        h->app->waitIdle();
        REQUIRE(h->app->state().doc.hasModel());
        h->frame(2);
        h->app->waitIdle();
        h->frame(2);
    }
    return h;
}

}  // namespace mgp::test
