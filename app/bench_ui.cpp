// `motiongp bench --only ui`: editor frame time at 1280×720 on the offscreen context (llvmpipe
// here), the whole UI (ImGui panels, viewport without MSAA, latent map) while dragging the right
// foot with live learned IK. Drags are released between rounds, so adaptive updates and the
// latent-map recomputation (a 160×160 σ² image on a worker thread) run during later rounds. A
// second pass of the same drags reports where the time goes (drag_profile_seconds); a third
// alternates rounds with and without onion skins and motion trails (overlays).
#include <GL/gl.h>

#include <filesystem>
#include <functional>

#include "bench_registry.h"
#include "render/gl_context.h"
#include "render/scene_builder.h"
#include "render/skeleton_renderer.h"
#include "ui/shell/editor_app.h"

namespace mgp::app {

namespace {

nlohmann::json benchUi(const BenchContext& ctx) {
    constexpr int kW = 1280, kH = 720;
    render::OffscreenContext gl(kW, kH);
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
    ui::InputState in;
    auto frame = [&] {
        app.frame(in, 1.0 / 60.0, kW, kH);
        glFinish();
    };
    for (int i = 0; i < 3; ++i) frame();
    app.waitIdle();
    for (int i = 0; i < 3; ++i) frame();
    app.state().doc.setFrame(99 % app.state().doc.frameCount());
    frame();

    std::vector<double> idle, drag;
    for (int i = 0; i < 30; ++i) idle.push_back(secondsOf(frame));
    const int rounds = ctx.quick ? 2 : std::max(3, ctx.repeats);
    // Drags the right foot up 30 px and back in 1.5 px steps (0.25–0.5 cm per event at this zoom),
    // like a hand on a mouse, `count` times; `perFrame` runs after each drag frame.
    auto dragRounds = [&](const std::function<void(double)>& perFrame, int count) {
        for (int r = 0; r < count; ++r) {
            float x, y;
            if (!app.handleScreenPosition(Effector::kRFoot, x, y)) break;
            in.mouseX = x;
            in.mouseY = y;
            frame();
            in.mouseDown[0] = true;
            frame();
            for (int k = 0; k < 40; ++k) {
                in.mouseY += k < 20 ? -1.5f : 1.5f;
                perFrame(secondsOf(frame));
            }
            in.mouseDown[0] = false;
            frame();
        }
        app.waitIdle();
    };
    dragRounds([&](double seconds) { drag.push_back(seconds); }, rounds);
    const int dragFrames = static_cast<int>(drag.size());
    // The same drags with onion skins (2 before, 2 after, 10 frames apart) and trails of both feet
    // and the right hand over ±30 frames, alternating with rounds without them (A B A B, as the
    // machine's load drifts): what the overlays cost a dragging frame.
    std::vector<double> dragPlain, dragOverlays;
    auto setOverlays = [&](bool on) {
        ui::EditorState& s = app.state();
        s.showOnionSkin = on;
        s.onionSkin = {2, 2, 10};
        for (render::TrailPart p : {render::TrailPart::kLFoot, render::TrailPart::kRFoot, render::TrailPart::kRHand})
            s.trails[static_cast<int>(p)] = on;
    };
    for (int r = 0; r < rounds; ++r)
        for (bool on : {false, true}) {
            setOverlays(on);
            dragRounds([&](double seconds) { (on ? dragOverlays : dragPlain).push_back(seconds); }, 1);
        }
    setOverlays(false);
    // The same drags again with every phase ending in glFinish (ui/shell/frame_profile.h): where a
    // dragging frame's time goes. The stalls make these frames a little longer than the above.
    ui::FrameProfile& profile = app.state().profile;
    profile.measure = true;
    std::vector<double> pFrame, pSolve, pScene, pRender, pUpload, pRest;
    dragRounds(
        [&](double seconds) {
            pFrame.push_back(seconds);
            pSolve.push_back(profile.solveSeconds);
            pScene.push_back(profile.sceneSeconds);
            pRender.push_back(profile.imguiRenderSeconds);
            pUpload.push_back(profile.latentUploadSeconds);
            pRest.push_back(seconds - profile.solveSeconds - profile.sceneSeconds - profile.imguiRenderSeconds -
                            profile.latentUploadSeconds);
        },
        rounds);
    profile.measure = false;
    // For comparison: the 3-D scene alone (no MSAA) at the viewport's size, i.e. the part of a
    // UI frame that is the renderer's, not the editor's.
    std::vector<double> sceneOnly;
    {
        render::SceneRenderer renderer(1);
        render::ClipSceneOptions so;
        so.frameIndex = app.state().doc.frame();
        so.editedPose = app.state().doc.currentPose();
        so.caption = false;
        const render::Scene scene = render::buildClipScene(app.state().doc.clip(), so);
        for (int i = 0; i < 30; ++i)
            sceneOnly.push_back(secondsOf([&] {
                renderer.draw(scene, app.state().camera, kW - 380, kH - 123, 0);
                glFinish();
            }));
    }
    const render::GlInfo info = render::currentGlInfo();
    nlohmann::json j;
    j["width"] = kW;
    j["height"] = kH;
    j["renderer"] = info.renderer;
    j["clip"] = real ? "35_01" : "synthetic";
    j["model"] = {{"kernel", "fas"}, {"M", M}, {"T", 3}};
    j["idle_frame_seconds"] = summarizeSeconds(idle);
    j["drag_frame_seconds"] = summarizeSeconds(drag);
    j["drag_frames"] = dragFrames;
    j["overlays"] = {{"onion_skin", "2:2:10"},
                     {"trails", {"lfoot", "rfoot", "rhand"}},
                     {"trail_frames_each_side", 30},
                     {"drag_frame_seconds_without", summarizeSeconds(dragPlain)},
                     {"drag_frame_seconds_with", summarizeSeconds(dragOverlays)}};
    j["scene_only_seconds"] = summarizeSeconds(sceneOnly);
    j["scene_only_size"] = {kW - 380, kH - 123};
    j["drag_profile_seconds"] = {
        {"frame", summarizeSeconds(pFrame)},          {"ik_solve", summarizeSeconds(pSolve)},
        {"scene_draw", summarizeSeconds(pScene)},     {"imgui_render", summarizeSeconds(pRender)},
        {"latent_upload", summarizeSeconds(pUpload)}, {"panels_and_rest", summarizeSeconds(pRest)}};
    j["adaptive_updates"] = app.state().doc.adaptiveUpdates();
    j["latent_map_texels"] = 160 * 160;
    j["target_seconds"] = 0.016;
    return j;
}

const BenchRegistration uiBench("ui", "Editor frame time at 1280x720 while dragging (offscreen, whole UI)", benchUi);

}  // namespace
}  // namespace mgp::app
