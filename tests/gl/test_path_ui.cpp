// Path editing UI tests (label `gl`): the offscreen editor on 35_01 with a small trained model, a
// right-foot path edit around frame 110 started through the document, then
//  - mouse: hover key 2 (frame 103), press, move up 40 px over several frames, release: the key's
//    offset rises (y > 5 cm), the edited path follows, the key ends under the mouse, no effector
//    drag or camera orbit happened; a second drag cancelled with Esc restores the offset;
//  - look: after a regeneration of the left foot's path, the window shows the edited path (blue), its
//    keys, the captured path (grey) and the before ghost (violet); the screenshot is written to
//    build/tests/gl/out/path_ui.png and the test counts pixels of each colour in the viewport;
//  - panel: the Path panel drawn on its own (380×180, build/tests/gl/out/path_panel.png), its
//    buttons clicked with the mouse: Edit path, Displacement, Before ghost, Add key, Done.
#include <doctest/doctest.h>

#include <GL/gl.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <cmath>
#include <filesystem>

#include "gui_harness.h"
#include "render/png_capture.h"
#include "ui/panels/path_panel.h"
#include "ui/panels/viewport_panel.h"

using namespace mgp;
using namespace mgp::test;

namespace {

constexpr int kFrame = 109;  // frame 110, 1-based: default keys 89, 103, 117, 131
constexpr int kKey = 1;      // the key at frame 103

// Starts a foot's path edit at frame 110 and draws a few frames so the viewport knows it.
void beginFootPath(Harness& h, Effector foot) {
    EditorDocument& doc = h.app->state().doc;
    doc.setFrame(kFrame);
    REQUIRE(doc.beginPathEdit(foot) == "");
    REQUIRE(doc.paths().edit()->keyFrames == std::vector<int>{88, 102, 116, 130});
    h.frame(3);
}

// Moves the mouse onto key `key` and checks the viewport reports it hovered (no handle).
void hoverKey(Harness& h, int key) {
    float x = 0, y = 0;
    REQUIRE(ui::pathKeyWindowPosition(h.app->state(), key, x, y));
    h.input.mouseX = x;
    h.input.mouseY = y;
    h.frame(2);
    REQUIRE(h.app->state().hoveredHandle == -1);
    REQUIRE(h.app->state().hoveredKey == key);
}

// Pixels of the viewport (left of the right column, below the hint line, above the timeline)
// for which pred(r, g, b) holds.
template <class Pred>
long countViewport(const render::Image& img, Pred pred) {
    long n = 0;
    for (int y = 45; y < img.height - 110; ++y)
        for (int x = 0; x < img.width - 380; ++x) {
            const unsigned char* p = &img.rgba[(std::size_t(y) * img.width + x) * 4];
            n += pred(int(p[0]), int(p[1]), int(p[2]));
        }
    return n;
}
// Lit colours are shaded, so each element is recognised by its hue rather than an exact value.
bool violet(int r, int g, int b) { return b > g + 25 && r > g + 15; }                   // before ghost
bool blue(int r, int g, int b) { return b > r + 90 && b > g + 40; }                     // edited path
bool red(int r, int g, int b) { return r > 220 && g < 120 && b < 100 && r > g + 130; }  // selected key
long differing(const render::Image& a, const render::Image& b) {
    long n = 0;
    for (int y = 45; y < a.height - 110; ++y)
        for (int x = 0; x < a.width - 380; ++x) {
            const std::size_t i = (std::size_t(y) * a.width + x) * 4;
            n += std::abs(a.rgba[i] - b.rgba[i]) + std::abs(a.rgba[i + 1] - b.rgba[i + 1]) +
                     std::abs(a.rgba[i + 2] - b.rgba[i + 2]) >
                 30;
        }
    return n;
}

}  // namespace

TEST_CASE("gui path: dragging a path key up with the mouse raises its offset and moves the edited path") {
    auto h = makeHarness(false);
    if (!h) return;
    beginFootPath(*h, Effector::kRFoot);
    ui::EditorState& s = h->app->state();
    EditorDocument& doc = s.doc;
    // The right foot is planted over frames 89–131 of 35_01, so every key starts under the foot's
    // handle (which wins the pick): lift key 2 clear of it first, as the panel's offset would.
    REQUIRE(doc.paths().setKeyOffset(kKey, Eigen::Vector3d(0, 15, 0)) == "");
    h->frame(2);
    const std::vector<Eigen::Vector3d> before = doc.paths().targets();
    const Eigen::Vector3d offsetBefore = doc.paths().edit()->keyOffsetsCm[kKey];
    const float yaw = s.camera.yawDeg, pitch = s.camera.pitchDeg;

    hoverKey(*h, kKey);
    h->input.mouseDown[0] = true;
    h->frame(2);
    for (int i = 0; i < 5; ++i) {
        h->input.mouseY -= 8.0f;
        h->frame();
    }
    h->input.mouseDown[0] = false;
    h->frame(2);

    const Eigen::Vector3d offset = doc.paths().edit()->keyOffsetsCm[kKey];
    INFO("offset before " << offsetBefore.transpose() << "  after " << offset.transpose());
    CHECK(offset.y() - offsetBefore.y() > 5.0);
    CHECK((offset - offsetBefore).norm() < 60.0);  // 40 px is not a metre
    CHECK(s.selectedKey == kKey);
    // The key followed the mouse (camera-facing plane: it projects back under the cursor).
    float kx = 0, ky = 0;
    REQUIRE(ui::pathKeyWindowPosition(s, kKey, kx, ky));
    CHECK(std::abs(kx - h->input.mouseX) < 2.0f);
    CHECK(std::abs(ky - h->input.mouseY) < 2.0f);
    // The edited path moved at the key's frame and not at the fixed first key.
    const std::vector<Eigen::Vector3d> after = doc.paths().targets();
    REQUIRE(after.size() == before.size());
    const std::size_t at = std::size_t(102 - 88);
    CHECK(after[at].y() - before[at].y() > 5.0);
    CHECK((after.front() - before.front()).norm() < 1e-9);
    // A key drag is neither an effector drag nor a camera orbit.
    CHECK_FALSE(doc.dragging());
    CHECK(doc.edits().empty());
    CHECK(s.camera.yawDeg == yaw);
    CHECK(s.camera.pitchDeg == pitch);

    // A second drag cancelled with Esc puts the key back.
    hoverKey(*h, kKey);
    h->input.mouseDown[0] = true;
    h->frame(2);
    h->input.mouseX += 30.0f;
    h->frame();
    CHECK((doc.paths().edit()->keyOffsetsCm[kKey] - offset).norm() > 1.0);
    h->input.keys[ui::key::kEscape] = true;
    h->frame();
    h->input.keys[ui::key::kEscape] = false;
    h->input.mouseDown[0] = false;
    h->frame(2);
    CHECK((doc.paths().edit()->keyOffsetsCm[kKey] - offset).norm() < 1e-9);
    doc.waitIdle();
}

TEST_CASE("gui path: the viewport shows the edited path, its keys, the captured path and the before ghost") {
    auto h = makeHarness(false);
    if (!h) return;
    beginFootPath(*h, Effector::kLFoot);  // the left foot swings over these frames: a long path
    ui::EditorState& s = h->app->state();
    EditorDocument& doc = s.doc;
    REQUIRE(doc.paths().setKeyOffset(1, Eigen::Vector3d(0, 20, 0)) == "");
    REQUIRE(doc.paths().setKeyOffset(2, Eigen::Vector3d(0, 20, 0)) == "");
    REQUIRE(doc.startRegenerate() == "");
    doc.waitIdle();
    std::string err;
    doc.pollRegenerate(&err);
    REQUIRE(err == "");
    REQUIRE(doc.isEdited(kFrame));
    REQUIRE(doc.beforeGhost().has_value());
    doc.waitIdle();  // the adaptive updates the regeneration posted: nothing changes between shots
    s.showCapturedPath = true;
    s.showBeforeGhost = true;
    s.selectedKey = 1;
    s.setStatus("path ui");
    h->frame(3);
    const render::Image img = h->app->capture(kW, kH);
    std::filesystem::create_directories(kOutDir);
    render::writePng(img, kOutDir + "/path_ui.png");

    // Each element is on screen, in its own colour: switching it off removes those pixels.
    auto shot = [&] {
        h->frame(3);
        return h->app->capture(kW, kH);
    };
    s.showCapturedPath = false;
    const render::Image noCaptured = shot();
    s.showCapturedPath = true;
    s.showBeforeGhost = false;
    const render::Image noGhost = shot();
    s.showBeforeGhost = true;
    s.selectedKey = -1;
    const render::Image noSelection = shot();
    s.selectedKey = 1;
    doc.paths().end();
    const render::Image noPath = shot();
    const long ghost = countViewport(img, violet), ghostOff = countViewport(noGhost, violet);
    const long path = countViewport(img, blue), pathOff = countViewport(noPath, blue);
    const long key = countViewport(img, red), keyOff = countViewport(noSelection, red);
    const long captured = differing(img, noCaptured);
    MESSAGE("pixels on / off: before ghost " << ghost << " / " << ghostOff << ", edited path " << path << " / "
                                             << pathOff << ", selected key " << key << " / " << keyOff
                                             << "; captured path changes " << captured);
    CHECK(ghost > 1000);
    CHECK(ghostOff < ghost / 10);
    CHECK(path - pathOff > 150);
    CHECK(key - keyOff > 20);
    CHECK(captured > 100);
    doc.waitIdle();
}

namespace {

// The Path panel alone, drawn with the editor's ImGui context (fonts, style, GL backend) in frames
// of our own: the app lays out its fixed windows, and the panel is meant for a ~380×180 tab.
struct PanelDriver {
    Harness& h;
    static constexpr float kPanelW = 380.0f, kPanelH = 180.0f;

    // One frame at mouse (mx, my) (window pixels); returns the item the mouse was over (0: none).
    // Hovering needs no pixels: `draw` false skips llvmpipe, most of a frame's cost.
    ImGuiID frame(float mx, float my, bool down, bool draw = true) {
        ImGuiIO& io = ImGui::GetIO();
        io.DisplaySize = ImVec2(kPanelW, kPanelH);
        io.DeltaTime = 1.0f / 60.0f;
        io.MousePos = ImVec2(mx, my);
        io.MouseDown[0] = down;
        ImGui_ImplOpenGL3_NewFrame();
        ImGui::NewFrame();
        ImGui::SetNextWindowPos(ImVec2(0, 0));
        ImGui::SetNextWindowSize(ImVec2(kPanelW, kPanelH));
        ImGui::Begin("Path", nullptr,
                     ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoSavedSettings);
        ui::drawPathPanel(h.app->state());
        ImGui::End();
        ImGui::Render();
        if (!draw) return ImGui::GetCurrentContext()->HoveredId;
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, int(kPanelW), int(kPanelH));
        glClearColor(0.1f, 0.1f, 0.11f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        return ImGui::GetCurrentContext()->HoveredId;
    }
    // A frame that only asks what the mouse at (mx, my) hovers.
    ImGuiID hover(float mx, float my) { return frame(mx, my, false, false); }
    // The ID a top-level panel item gets from its label.
    ImGuiID idOf(const char* label) {
        ImGui_ImplOpenGL3_NewFrame();
        ImGui::NewFrame();
        ImGui::Begin("Path");
        const ImGuiID id = ImGui::GetID(label);
        ImGui::End();
        ImGui::EndFrame();
        return id;
    }
    // Clicks the top-level item labelled `label`, found by sweeping the mouse over the panel;
    // false if no pixel hovers it (absent or disabled).
    bool click(const char* label) {
        const ImGuiID id = idOf(label);
        for (float y = 4; y < kPanelH; y += 5)
            for (float x = 4; x < kPanelW; x += 6)
                if (hover(x, y) == id) {
                    frame(x, y, true);
                    frame(x, y, true);
                    frame(x, y, false);
                    frame(-1, -1, false);
                    return true;
                }
        return false;
    }
};

}  // namespace

TEST_CASE("gui path panel: Edit path, mode, ghost switch and Done drive the document") {
    auto h = makeHarness(false, false);  // no model: Regenerate is disabled
    if (!h) return;
    ui::EditorState& s = h->app->state();
    EditorDocument& doc = s.doc;
    doc.setFrame(kFrame);
    s.selected = Effector::kLHand;
    PanelDriver p{*h};
    p.frame(-1, -1, false);
    CHECK_FALSE(p.click("Done"));  // no path yet
    REQUIRE(p.click("Edit path"));
    REQUIRE(doc.paths().edit().has_value());
    CHECK(doc.paths().edit()->effector == Effector::kLHand);
    CHECK(doc.paths().edit()->keyFrames == std::vector<int>{88, 102, 116, 130});
    CHECK(doc.paths().edit()->mode == PathMode::kDisplacement);  // the default
    REQUIRE(p.click("displacement"));
    CHECK(doc.paths().edit()->mode == PathMode::kDirect);
    REQUIRE(p.click("displacement"));
    CHECK(doc.paths().edit()->mode == PathMode::kDisplacement);
    CHECK_FALSE(s.showBeforeGhost);
    REQUIRE(p.click("before"));
    CHECK(s.showBeforeGhost);
    p.click("Regenerate");  // disabled without a model: a click does nothing
    CHECK_FALSE(doc.regenerating());
    CHECK(s.messages.latestText().find("regenerating") == std::string::npos);
    doc.setFrame(95);
    REQUIRE(p.click("Add key at current frame"));
    CHECK(doc.paths().edit()->keyFrames == std::vector<int>{88, 95, 102, 116, 130});
    REQUIRE(doc.paths().setKeyOffset(2, Eigen::Vector3d(1.5, 12.0, -3.0)) == "");
    s.selectedKey = 2;
    p.frame(-1, -1, false);
    p.frame(-1, -1, false);
    std::filesystem::create_directories(kOutDir);
    render::writePng(render::readFramebuffer(int(p.kPanelW), int(p.kPanelH)), kOutDir + "/path_panel.png");
    REQUIRE(p.click("Done"));
    CHECK_FALSE(doc.paths().edit().has_value());
}

TEST_CASE("gui path: key handles stay at least 12 px across when the camera moves away, and can be grabbed") {
    auto h = makeHarness(false);
    if (!h) return;
    beginFootPath(*h, Effector::kLFoot);  // the left foot swings here: its keys lie apart
    ui::EditorState& s = h->app->state();
    s.followCharacter = false;
    for (const float zoom : {1.0f, 3.0f}) {
        CAPTURE(zoom);
        if (zoom > 1.0f) s.camera.distanceCm *= zoom;
        h->frame(2);
        const render::Scene& scene = h->app->viewport().lastScene();
        REQUIRE_FALSE(scene.paths.empty());
        const render::Path& edited = scene.paths.back();
        REQUIRE(edited.keysCm.size() == 4);
        // The screen radius of each key: its centre and a point one radius away across the view.
        const glm::mat4 view = s.camera.view();
        const glm::vec3 right(view[0][0], view[1][0], view[2][0]);
        for (std::size_t k = 0; k < edited.keysCm.size(); ++k) {
            glm::vec3 c, e;
            REQUIRE(s.camera.project(edited.keysCm[k], s.viewportWidth, s.viewportHeight, c));
            REQUIRE(s.camera.project(edited.keysCm[k] + right * edited.keyRadiusCm(), s.viewportWidth, s.viewportHeight,
                                     e));
            CHECK(glm::length(glm::vec2(e - c)) >= 5.9f);  // 6 px in radius (perspective rounds a little)
        }
        // The mouse 4 px off a key's centre still hovers it.
        float x = 0, y = 0;
        REQUIRE(ui::pathKeyWindowPosition(s, 3, x, y));
        h->input.mouseX = x + 4.0f;
        h->input.mouseY = y;
        h->frame(2);
        CHECK(s.hoveredKey == 3);
    }
}

TEST_CASE("gui path: keys stacked under a planted foot, the one picked in the list is the one the mouse drags") {
    auto h = makeHarness(false);
    if (!h) return;
    beginFootPath(*h, Effector::kRFoot);
    ui::EditorState& s = h->app->state();
    EditorDocument& doc = s.doc;
    // The right foot is planted over frames 89-131: keys 3 and 4 (frames 117, 131) lie within a
    // centimetre or two of each other, under the foot's handle.
    float x3 = 0, y3 = 0, x4 = 0, y4 = 0;
    REQUIRE(ui::pathKeyWindowPosition(s, 2, x3, y3));
    REQUIRE(ui::pathKeyWindowPosition(s, 3, x4, y4));
    CHECK(std::hypot(x3 - x4, y3 - y4) < 6.0f);
    h->input.mouseX = x3;
    h->input.mouseY = y3;
    h->frame(2);
    CHECK(s.hoveredKey != 2);  // the handle or the key nearest in time wins without a pick
    // Picked in the list (the Path tab's "#" column), key 3 is the one under the mouse there...
    s.selectedKey = s.listPickedKey = 2;
    h->frame(2);
    REQUIRE(s.hoveredKey == 2);
    CHECK(s.hoveredHandle == -1);
    // ... and a drag moves it, not key 4 nor the foot.
    const Eigen::Vector3d before3 = doc.paths().edit()->keyOffsetsCm[2], before4 = doc.paths().edit()->keyOffsetsCm[3];
    h->input.mouseDown[0] = true;
    h->frame(2);
    for (int i = 0; i < 4; ++i) {
        h->input.mouseY -= 8.0f;
        h->frame();
    }
    h->input.mouseDown[0] = false;
    h->frame(2);
    CHECK(doc.paths().edit()->keyOffsetsCm[2].y() - before3.y() > 5.0);
    CHECK((doc.paths().edit()->keyOffsetsCm[3] - before4).norm() < 1e-9);
    CHECK_FALSE(doc.dragging());
    CHECK(doc.edits().empty());
    CHECK(s.listPickedKey == 2);  // dragging the picked key keeps the pick
    // A press elsewhere in the viewport (an orbit) ends the pick: the foot's handle is its own again.
    h->input.mouseX = 30.0f;
    h->input.mouseY = 300.0f;
    h->frame(2);
    h->input.mouseDown[0] = true;
    h->frame(2);
    h->input.mouseDown[0] = false;
    h->frame(2);
    CHECK(s.listPickedKey == -1);
    doc.waitIdle();
}
