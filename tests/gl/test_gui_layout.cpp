// The editor's layout in a small window (label `gl`, offscreen): at 1024×600 every panel's main
// controls are drawn wholly inside what their window shows, with no scrolling: Train, Open and
// Save model; the latent map; the timeline track; the IK readout's falloff; the Path tab's
// Regenerate. Read from the rectangles the panels record (EditorState::controls).
#include <doctest/doctest.h>
#include <imgui.h>

#include <imgui_internal.h>

#include <filesystem>
#include <string>
#include <utility>

#include "editor_harness.h"
#include "skeleton/forward_kinematics.h"
#include "skip.h"
#include "test_paths.h"
#include "ui/input/gui_script.h"
#include "ui/panels/timeline_panel.h"
#include "ui/panels/viewport_panel.h"
#include "ui/shell/editor_app.h"
#include "ui/shell/imgui_setup.h"

using namespace mgp;

namespace {

void frames(test::Harness& h, int w, int hgt, int n) {
    for (int i = 0; i < n; ++i) h.app->frame(h.input, 1.0 / 60.0, w, hgt);
}

void checkControl(const ui::EditorState& s, const char* name, int w, int h) {
    INFO("control " << name);
    const auto it = s.controls.find(name);
    REQUIRE(it != s.controls.end());
    const ui::EditorState::ControlRect& r = it->second;
    INFO("rect " << r.x0 << "," << r.y0 << " .. " << r.x1 << "," << r.y1);
    CHECK(r.visible);
    CHECK(r.x0 >= 0.0f);
    CHECK(r.y0 >= 0.0f);
    CHECK(r.x1 <= float(w));
    CHECK(r.y1 <= float(h));
    CHECK(r.x1 - r.x0 >= 8.0f);
    CHECK(r.y1 - r.y0 >= 8.0f);
}

// The editor with its own font, DejaVu Sans, as a user sees it (the harness draws with ImGui's
// narrower built-in font), on the walk with the committed model; false (the test is reported
// skipped, with the reason) without the font.
bool withEditorFont(test::Harness& h) {
    std::error_code ec;
    if (!std::filesystem::exists(ui::kEditorFontPath, ec)) {
        MGP_MARK_SKIPPED("the editor's font is not installed (" << ui::kEditorFontPath << ", fonts-dejavu-core)");
        return false;
    }
    h.restartApp({}, true);
    REQUIRE(h.app->openClip(test::mocapDir() + "/asf_amc/35_01.amc") == "");
    h.frame(2);
    REQUIRE(h.app->runAction({"open-model", test::fixtureModelPath()}) == "");
    h.app->waitIdle();
    h.frame(2);
    return true;
}

}  // namespace

TEST_CASE("gui layout: at 1024x600 every panel's main controls are visible without scrolling") {
    auto h = test::makeHarness(false);
    if (!h) return;
    constexpr int W = 1024, H = 600;
    ui::EditorState& s = h->app->state();
    s.controls.clear();
    frames(*h, W, H, 3);
    for (const char* name : {"Train", "Open model", "Save model", "latent map", "timeline track", "drag falloff"})
        checkControl(s, name, W, H);
    const auto& map = s.controls.at("latent map");
    CHECK(map.x1 - map.x0 >= 110.0f);  // still a usable map
    // The Path tab comes forward with a path edit: Regenerate in view.
    REQUIRE(s.doc.beginPathEdit(Effector::kRFoot) == "");
    frames(*h, W, H, 3);
    checkControl(s, "Regenerate", W, H);
}

TEST_CASE("gui layout: at 1280x800 the panels keep their sizes (the goldens' layout)") {
    auto h = test::makeHarness(false);
    if (!h) return;
    ui::EditorState& s = h->app->state();
    frames(*h, 1280, 800, 2);
    CHECK(s.viewportWidth == 1280 - 380);
    const auto& train = s.controls.at("Train");
    CHECK(train.visible);
    CHECK(train.x0 >= 900.0f);
}

TEST_CASE("gui layout: a 2x content scale (HiDPI) doubles fonts and panel sizes and keeps the controls in view") {
    auto h = test::makeHarness(false, false);
    if (!h) return;
    frames(*h, 1280, 800, 2);
    const float frameH1 = ImGui::GetFrameHeight();
    const float trainH1 = h->app->state().controls.at("Train").y1 - h->app->state().controls.at("Train").y0;
    ui::EditorOptions o;
    o.uiScale = 2.0f;
    h->restartApp(o);
    REQUIRE(h->app->openClip(test::mocapDir() + "/asf_amc/35_01.amc") == "");
    CHECK(h->app->uiScale() == 2.0f);
    frames(*h, 1280, 800, 3);
    const ui::EditorState& s = h->app->state();
    CHECK(ImGui::GetFrameHeight() == doctest::Approx(2.0f * frameH1).epsilon(0.05));
    const auto& train = s.controls.at("Train");
    CHECK(train.y1 - train.y0 == doctest::Approx(2.0f * trainH1).epsilon(0.05));
    CHECK(s.viewportWidth < 1280 - 380);  // the right column grew
    for (const char* name : {"Train", "Open model", "timeline track", "drag falloff"}) checkControl(s, name, 1280, 800);
}

TEST_CASE("gui layout: dragging the splitters resizes the panels, and the next editor remembers it") {
    auto h = test::makeHarness(false, false);
    if (!h) return;
    const std::string dir = std::string(MOTIONGP_GL_OUT_DIR) + "/layout_prefs";
    const std::string file = dir + "/layout.json";
    std::filesystem::remove_all(dir);
    ui::EditorOptions o;
    o.layoutFile = file;
    h->restartApp(o);
    REQUIRE(h->app->openClip(test::mocapDir() + "/asf_amc/35_01.amc") == "");
    frames(*h, 1280, 800, 3);
    ui::EditorState& s = h->app->state();
    REQUIRE(s.viewportWidth == 900);
    const int viewportH = s.viewportHeight;

    // Right column: grab the boundary at x = 900 and pull it 100 px to the left.
    auto drag = [&](float x, float y, float dx, float dy) {
        h->input.mouseX = x;
        h->input.mouseY = y;
        frames(*h, 1280, 800, 2);
        h->input.setButton(0, true);
        frames(*h, 1280, 800, 2);
        for (int i = 0; i < 4; ++i) {
            h->input.mouseX += dx / 4;
            h->input.mouseY += dy / 4;
            frames(*h, 1280, 800, 1);
        }
        h->input.setButton(0, false);
        frames(*h, 1280, 800, 3);
    };
    drag(900.0f, 400.0f, -100.0f, 0.0f);
    CHECK(s.viewportWidth == 800);
    // Timeline: its top edge up by 60 px.
    drag(400.0f, s.viewportY + float(s.viewportHeight), 0.0f, -60.0f);
    CHECK(s.viewportHeight == viewportH - 60);
    REQUIRE(std::filesystem::exists(file));

    h->restartApp(o);
    REQUIRE(h->app->openClip(test::mocapDir() + "/asf_amc/35_01.amc") == "");
    frames(*h, 1280, 800, 3);
    CHECK(h->app->state().viewportWidth == 800);
    CHECK(h->app->state().viewportHeight == viewportH - 60);
}

TEST_CASE("gui layout: the range legend never covers the character, at 1280x800, 1024x600 and 800x500") {
    auto h = test::makeHarness(false);
    if (!h) return;
    ui::EditorState& s = h->app->state();
    s.doc.setFrame(60);
    // Not a structured binding: clang 14 cannot capture one in CAPTURE's lambda.
    for (const std::pair<int, int>& size : {std::pair{1280, 800}, std::pair{1024, 600}, std::pair{800, 500}}) {
        const int W = size.first, H = size.second;
        CAPTURE(W);
        s.cameraNeedsFraming = true;  // framed for this window, as a resize and F would
        frames(*h, W, H, 4);
        const auto legend = s.controls.find("range legend");
        REQUIRE(legend != s.controls.end());
        const ui::EditorState::ControlRect& r = legend->second;
        INFO("legend " << r.x0 << "," << r.y0 << " .. " << r.x1 << "," << r.y1);
        CHECK(r.x0 >= 0.0f);
        CHECK(r.y0 >= 0.0f);
        CHECK(r.x1 <= float(W));
        CHECK(r.y1 <= float(H));
        // Every joint and bone end of the shown pose lies outside the legend's box.
        const Skeleton& sk = s.doc.clip().skeleton;
        FkState fk;
        forwardKinematics(sk, s.doc.currentPose(), fk);
        int inView = 0;
        for (int j = 0; j < sk.jointCount(); ++j)
            for (const Eigen::Vector3d& p : {fk.jointCm[j], boneEndCm(sk, fk, j)}) {
                float x, y;
                if (!ui::viewportWindowPosition(s, p, x, y)) continue;
                ++inView;
                CHECK_FALSE((x > r.x0 && x < r.x1 && y > r.y0 && y < r.y1));
            }
        CHECK(inView > sk.jointCount());
    }
}

TEST_CASE("gui layout: after a drag the whole IK readout is in view at 1280x800, and the main controls at every size") {
    auto h = test::makeHarness(false);
    if (!h || !withEditorFont(*h)) return;
    ui::EditorState& s = h->app->state();
    s.doc.setFrame(76);  // frame 77: both feet planted, three targets
    frames(*h, 1280, 800, 2);
    // A real drag of the right hand: the readout then lists its three targets, the verdict, the
    // centre of mass, the nearest frame and the solver's diagnostic, its last line.
    std::string script = "0 hover rhand\n2 down left\n";
    for (int k = 0; k < 5; ++k) script += std::to_string(4 + 2 * k) + " moveby 0 -12\n";
    script += "16 up left\n";
    REQUIRE(h->play(ui::GuiScript::parse(script)).empty());
    h->app->waitIdle();
    REQUIRE(s.doc.readout().valid);
    CHECK(s.doc.readout().constraints.size() == 3);
    // A 60-pixel raise leaves the training range: the longest verdict.
    REQUIRE(s.doc.shownPoseVerdict().has_value());
    CHECK(s.doc.shownPoseVerdict()->shown().judgement == PoseJudgement::kUnlikeCapture);
    for (const std::pair<int, int>& size : {std::pair{1280, 800}, std::pair{1024, 600}, std::pair{800, 500}}) {
        const int W = size.first, H = size.second;
        CAPTURE(W);
        s.controls.clear();
        frames(*h, W, H, 3);
        // Train, Open and Save on one line in view (Save was below the fold at 800x500), the status line
        // (it was gone at 1024x600), the timeline and the readout's first control.
        for (const char* name : {"Train", "Open model", "Save model", "status line", "timeline track", "drag falloff"})
            checkControl(s, name, W, H);
        CHECK(s.controls.at("Save model").y0 == doctest::Approx(s.controls.at("Train").y0));
        // The right column's controls stay out of the viewport, and inside the window.
        for (const char* name : {"Train", "Open model", "Save model", "latent map", "drag falloff", "body stiffness"}) {
            INFO("control " << name);
            CHECK(s.controls.at(name).x0 >= s.viewportX + float(s.viewportWidth));
            CHECK(s.controls.at(name).x1 <= float(W));
        }
    }
    // At 1280x800 the readout's last line is in view without scrolling.
    s.controls.clear();
    frames(*h, 1280, 800, 3);
    checkControl(s, "readout end", 1280, 800);
}

TEST_CASE("gui layout: a long tooltip wraps and stays on screen at 800x500") {
    auto h = test::makeHarness(false, false);
    if (!h || !withEditorFont(*h)) return;
    ui::EditorState& s = h->app->state();
    constexpr int W = 800, H = 500;
    // A status message far wider than the timeline: shown ending in "...", whole in its tooltip.
    s.setStatus(std::string("a long message ") + std::string(300, 'x') + " the end", false);
    frames(*h, W, H, 2);
    REQUIRE(s.controls.count("status line"));
    const ui::EditorState::ControlRect line = s.controls.at("status line");
    CHECK(line.x1 <= s.viewportX + float(s.viewportWidth));
    h->input.mouseX = line.x1 - 4.0f;  // its right end, near the column's edge
    h->input.mouseY = 0.5f * (line.y0 + line.y1);
    frames(*h, W, H, 3);
    const ImGuiWindow* tip = nullptr;
    for (const ImGuiWindow* win : ImGui::GetCurrentContext()->Windows)
        if ((win->Flags & ImGuiWindowFlags_Tooltip) && win->Active) tip = win;
    REQUIRE(tip != nullptr);
    INFO("tooltip at " << tip->Pos.x << "," << tip->Pos.y << " size " << tip->Size.x << "x" << tip->Size.y);
    CHECK(tip->Pos.x >= 0.0f);
    CHECK(tip->Pos.y >= 0.0f);
    CHECK(tip->Pos.x + tip->Size.x <= float(W));
    CHECK(tip->Pos.y + tip->Size.y <= float(H));
    CHECK(tip->Size.y > 2.0f * ImGui::GetTextLineHeight());  // wrapped onto several lines
}

TEST_CASE("gui layout: with a path edited and regenerated, its span report and every key are in view at 1280x800") {
    auto h = test::makeHarness(false);
    if (!h || !withEditorFont(*h)) return;
    ui::EditorState& s = h->app->state();
    s.doc.setFrame(100);
    REQUIRE(s.doc.beginPathEdit(Effector::kRFoot) == "");
    REQUIRE(s.doc.paths().setKeyOffset(1, Eigen::Vector3d(0.0, 15.0, 0.0)) == "");
    // No report before the first regeneration.
    s.controls.clear();
    frames(*h, 1280, 800, 3);
    CHECK(s.controls.count("key table") == 1);
    CHECK(s.controls.count("span report") == 0);
    REQUIRE(s.doc.startRegenerate() == "");
    s.doc.waitIdle();
    frames(*h, 1280, 800, 2);
    s.doc.waitIdle();
    REQUIRE(s.doc.lastRegenerateQuality().has_value());
    s.controls.clear();
    frames(*h, 1280, 800, 3);  // the Path tab comes forward; the latent map gives it room
    REQUIRE(s.doc.paths().edit()->keyFrames.size() == 4);
    checkControl(s, "span report", 1280, 800);
    checkControl(s, "key table", 1280, 800);
    checkControl(s, "latent map", 1280, 800);
    const auto& map = s.controls.at("latent map");
    CHECK(map.x1 - map.x0 >= 110.0f);  // still a usable map
}

TEST_CASE("timeline labels: every second on a short clip, every few seconds where the numbers would overlap") {
    // 590 frames at 120 fps over 860 px (1.46 px per frame): a second is 175 px.
    CHECK(ui::timelineMajorStep(120.0, 860.0f / 589, 40.0f) == 120);
    // 4840 frames over the same width (0.18 px per frame): a second is 21 px, under a 40 px label,
    // so every 2 s (43 px).
    CHECK(ui::timelineMajorStep(120.0, 860.0f / 4839, 40.0f) == 240);
    CHECK(ui::timelineMajorStep(120.0, 860.0f / 4839, 60.0f) == 600);  // 5 s: 107 px
    CHECK(ui::timelineMajorStep(30.0, 0.001f, 40.0f) == 600 * 30);     // none fits: the widest
    CHECK(ui::timelineMajorStep(0.4, 10.0f, 40.0f) == 5);              // under one frame per second
    // Small ticks divide the labelled step, so every label sits on one.
    CHECK(ui::timelineMinorStep(120, 860.0f / 589) == 10);
    CHECK(ui::timelineMinorStep(600, 860.0f / 4839) == 50);
    CHECK(ui::timelineMinorStep(30, 1.4f) == 3);  // 30 fps: twelfths are no whole frame; tenths, 4.2 px
    CHECK(ui::timelineMinorStep(25, 2.0f) == 5);  // 25 fps: fifths
    CHECK(ui::timelineMinorStep(7, 0.1f) == 7);   // nothing finer is 4 px apart
}
