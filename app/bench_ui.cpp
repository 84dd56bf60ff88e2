// `motiongp bench --only ui`: editor frame time at 1280×720 on the offscreen context (llvmpipe
// here), the whole UI (ImGui panels, viewport without MSAA, latent map) while dragging the right
// foot with live learned IK. Drags are released between rounds, so adaptive updates and the
// latent-map recomputation (a 160×160 σ² image on a worker thread) run during later rounds. A
// second pass of the same drags reports where the time goes (drag_profile_seconds); a third
// alternates rounds with and without onion skins and motion trails (overlays).
#include <GL/gl.h>

#include <cstdlib>
#include <filesystem>
#include <functional>

#include "bench_registry.h"
#include "render/gl_context.h"
#include "render/motion_overlays.h"
#include "render/scene_builder.h"
#include "render/skeleton_renderer.h"
#include "ui/shell/editor_app.h"
#include "util/thread_priority.h"

namespace mgp::app {

namespace {

constexpr int kUiBenchWidth = 1280, kUiBenchHeight = 720;

// Drives the editor like a user: frames at 1/60 s with one input state, and drags of the right foot.
class UiBenchDriver {
public:
    explicit UiBenchDriver(ui::EditorApp& app) : app_(app) {}

    // One frame, finished on the GPU so its time is the whole frame's.
    void frame() {
        app_.frame(in_, 1.0 / 60.0, kUiBenchWidth, kUiBenchHeight);
        glFinish();
    }
    double timedFrame() {
        return secondsOf([&] { frame(); });
    }

    // Drags the right foot up 30 px and back in 1.5 px steps (0.25–0.5 cm per event at this zoom),
    // like a hand on a mouse, `count` times; `perFrame` runs after each drag frame.
    void dragRounds(const std::function<void(double)>& perFrame, int count) {
        for (int r = 0; r < count; ++r) {
            float x, y;
            if (!app_.handleScreenPosition(Effector::kRFoot, x, y)) break;
            in_.mouseX = x;
            in_.mouseY = y;
            frame();
            in_.mouseDown[0] = true;
            frame();
            for (int k = 0; k < 40; ++k) {
                in_.mouseY += k < 20 ? -1.5f : 1.5f;
                perFrame(timedFrame());
            }
            in_.mouseDown[0] = false;
            frame();
        }
        app_.waitIdle();
    }

    // Onion skins (2 before, 2 after, 10 frames apart) and trails of both feet and the right hand.
    void setOverlays(bool on) {
        ui::EditorState& s = app_.state();
        s.showOnionSkin = on;
        s.onionSkin = {2, 2, 10};
        for (render::TrailPart p : {render::TrailPart::kLFoot, render::TrailPart::kRFoot, render::TrailPart::kRHand})
            s.trails[static_cast<int>(p)] = on;
    }

private:
    ui::EditorApp& app_;
    ui::InputState in_;
};

// Every sample the bench takes, in seconds.
struct UiBenchSamples {
    std::vector<double> idle, drag;
    std::vector<double> dragPlain, dragOverlays;
    long overlayLayerDraws = 0;  // how often the still overlays' layer was drawn in those rounds
    std::vector<double> pFrame, pSolve, pScene, pRender, pUpload, pRest;  // the profiled drags' phases
    std::vector<double> sceneOnly, sceneOnlyOverlays;
};

// The same drags with onion skins (2 before, 2 after, 10 frames apart) and trails of both feet
// and the right hand over ±30 frames, alternating with rounds without them (A B A B, as the
// machine's load drifts): what the overlays cost a dragging frame.
void measureOverlayDrags(UiBenchDriver& d, const ui::ViewportPanel& viewport, int rounds, UiBenchSamples& t) {
    const long layerDrawsBefore = viewport.overlayLayerDraws();
    for (int r = 0; r < rounds; ++r)
        for (bool on : {false, true}) {
            d.setOverlays(on);
            d.dragRounds([&](double seconds) { (on ? t.dragOverlays : t.dragPlain).push_back(seconds); }, 1);
        }
    d.setOverlays(false);
    t.overlayLayerDraws = viewport.overlayLayerDraws() - layerDrawsBefore;
}

// The same drags again with every phase ending in glFinish (ui/shell/frame_profile.h): where a
// dragging frame's time goes. The stalls make these frames a little longer than the above.
void profileDrags(UiBenchDriver& d, ui::FrameProfile& profile, int rounds, UiBenchSamples& t) {
    profile.measure = true;
    d.dragRounds(
        [&](double seconds) {
            t.pFrame.push_back(seconds);
            t.pSolve.push_back(profile.solveSeconds);
            t.pScene.push_back(profile.sceneSeconds);
            t.pRender.push_back(profile.imguiRenderSeconds);
            t.pUpload.push_back(profile.latentUploadSeconds);
            t.pRest.push_back(seconds - profile.solveSeconds - profile.sceneSeconds - profile.imguiRenderSeconds -
                              profile.latentUploadSeconds);
        },
        rounds);
    profile.measure = false;
}

// For comparison: the 3-D scene alone (no MSAA) at the viewport's size, i.e. the part of a
// UI frame that is the renderer's, not the editor's; alternately without and with the overlays
// of the drags above, their trails cut at the current frame as the viewport cuts them (the still
// overlays' layer is drawn once, then laid in).
void timeSceneOnly(ui::EditorApp& app, UiBenchSamples& t) {
    render::SceneRenderer renderer(1);
    render::ClipSceneOptions so;
    so.frameIndex = app.state().doc.frame();
    so.editedPose = app.state().doc.currentPose();
    so.caption = false;
    const render::Scene plain = render::buildClipScene(app.state().doc.clip(), so);
    so.onion = render::OnionSkin{2, 2, 10};
    so.trails = {render::TrailPart::kLFoot, render::TrailPart::kRFoot, render::TrailPart::kRHand};
    render::Scene overlays = render::buildClipScene(app.state().doc.clip(), so);
    overlays.paths = render::splitEachForPosing(overlays.paths);
    for (int i = 0; i < 60; ++i) {
        const bool with = i % 2 == 1;
        (with ? t.sceneOnlyOverlays : t.sceneOnly).push_back(secondsOf([&] {
            renderer.draw(with ? overlays : plain, app.state().camera, kUiBenchWidth - 380, kUiBenchHeight - 123, 0);
            glFinish();
        }));
    }
}

nlohmann::json uiBenchJson(ui::EditorApp& app, bool real, int M, const UiBenchSamples& t, int dragFrames) {
    constexpr int kW = kUiBenchWidth, kH = kUiBenchHeight;
    const render::GlInfo info = render::currentGlInfo();
    nlohmann::json j;
    j["width"] = kW;
    j["height"] = kH;
    j["renderer"] = info.renderer;
    j["clip"] = real ? "35_01" : "synthetic";
    j["model"] = {{"kernel", "fas"}, {"M", M}, {"T", 3}};
    j["idle_frame_seconds"] = summarizeSeconds(t.idle);
    j["drag_frame_seconds"] = summarizeSeconds(t.drag);
    j["drag_frames"] = dragFrames;
    j["overlays"] = {{"onion_skin", "2:2:10"},
                     {"trails", {"lfoot", "rfoot", "rhand"}},
                     {"trail_frames_each_side", 30},
                     {"drag_frame_seconds_without", summarizeSeconds(t.dragPlain)},
                     {"drag_frame_seconds_with", summarizeSeconds(t.dragOverlays)},
                     {"still_layer_draws", t.overlayLayerDraws},
                     {"frames_with", t.dragOverlays.size()}};
    j["scene_only_seconds"] = summarizeSeconds(t.sceneOnly);
    j["scene_only_seconds_with_overlays"] = summarizeSeconds(t.sceneOnlyOverlays);
    j["scene_only_size"] = {kW - 380, kH - 123};
    j["drag_profile_seconds"] = {
        {"frame", summarizeSeconds(t.pFrame)},          {"ik_solve", summarizeSeconds(t.pSolve)},
        {"scene_draw", summarizeSeconds(t.pScene)},     {"imgui_render", summarizeSeconds(t.pRender)},
        {"latent_upload", summarizeSeconds(t.pUpload)}, {"panels_and_rest", summarizeSeconds(t.pRest)}};
    j["adaptive_updates"] = app.state().doc.models().updates();
    j["latent_map_texels"] = 160 * 160;
    j["target_seconds"] = 0.016;
    j["background_workers_yield"] = backgroundWorkersYield();
    return j;
}

nlohmann::json benchUi(const BenchContext& ctx) {
    render::OffscreenContext gl(kUiBenchWidth, kUiBenchHeight);
    // As the editor runs (app/cmd_gui.cpp); MOTIONGP_BENCH_WORKERS_AT_UI_PRIORITY=1 measures without.
    const bool yield = std::getenv("MOTIONGP_BENCH_WORKERS_AT_UI_PRIORITY") == nullptr;
    setBackgroundWorkersYield(yield);
    ui::EditorApp app;
    const std::string amc = ctx.mocapDir + "/asf_amc/35_01.amc";
    const bool real = !ctx.mocapDir.empty() && std::filesystem::exists(amc);
    if (real)
        app.openClip(amc);
    else
        app.openSyntheticClip("bench");
    const int M = ctx.quick ? 100 : 200;
    app.runAction({"train", "fas", std::to_string(M), "3"});
    app.waitIdle();
    UiBenchDriver d(app);
    for (int i = 0; i < 3; ++i) d.frame();
    app.waitIdle();
    for (int i = 0; i < 3; ++i) d.frame();
    app.state().doc.setFrame(99 % app.state().doc.frameCount());
    d.frame();

    UiBenchSamples t;
    for (int i = 0; i < 30; ++i) t.idle.push_back(d.timedFrame());
    const int rounds = ctx.quick ? 2 : std::max(3, ctx.repeats);
    d.dragRounds([&](double seconds) { t.drag.push_back(seconds); }, rounds);
    const int dragFrames = static_cast<int>(t.drag.size());
    measureOverlayDrags(d, app.viewport(), rounds, t);
    profileDrags(d, app.state().profile, rounds, t);
    timeSceneOnly(app, t);
    nlohmann::json out = uiBenchJson(app, real, M, t, dragFrames);
    setBackgroundWorkersYield(false);  // the benches after this one run as batch work
    return out;
}

const BenchRegistration uiBench("ui", "Editor frame time at 1280x720 while dragging (offscreen, whole UI)", benchUi);

}  // namespace
}  // namespace mgp::app
