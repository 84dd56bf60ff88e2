// Where am I in the data (label `gl`, offscreen): after a learned drag the readout names the
// captured frame nearest to the pose, and its ghost shows that captured pose at the current root.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "editor_harness.h"
#include "gl_test_paths.h"
#include "render/png_capture.h"
#include "skeleton/forward_kinematics.h"
#include "ui/input/gui_script.h"
#include "ui/input/script_player.h"
#include "ui/panels/viewport_panel.h"
#include "ui/shell/editor_app.h"

using namespace mgp;

namespace {
using test::kOutDir;

int greenGhosts(const render::Scene& scene) {
    int n = 0;
    for (const render::Figure& f : scene.figures) n += f.ghost && f.ghostTint.g > 0.8f && f.ghostTint.r < 0.5f;
    return n;
}
}  // namespace

TEST_CASE("gui: the readout names the nearest captured frame and its ghost shows it at the current root") {
    auto h = test::makeHarness(false);
    if (!h) return;
    ui::EditorState& s = h->app->state();
    EditorDocument& doc = s.doc;
    doc.setFrame(99);
    h->frame(2);
    CHECK(doc.readout().nearest.row == -1);  // no solve yet

    ui::GuiScript script;
    script.add(0, "hover", {"rhand"});
    script.add(2, "down", {"left"});
    for (int k = 0; k < 6; ++k) script.add(4 + k, "moveby", {"-5", "-4"});
    script.add(14, "up", {"left"});
    ui::ScriptPlayer player(script);
    std::vector<std::string> shots;
    for (int i = 0; i <= 16; ++i) {
        player.apply(i, h->input, *h->app, shots);
        h->frame();
    }
    h->app->waitIdle();
    const SolveReadout& r = doc.readout();
    REQUIRE(r.valid);
    REQUIRE(r.learned);
    REQUIRE(r.nearest.row >= 0);
    CHECK(r.nearest.row < doc.frameCount());
    CHECK(r.nearestClip == "35_01");
    CHECK(r.nearest.rmsDeg >= 0.0);

    h->frame(2);
    CHECK(greenGhosts(h->app->viewport().lastScene()) == 0);  // off by default
    s.showNearestGhost = true;
    h->frame(2);
    const render::Scene& scene = h->app->viewport().lastScene();
    REQUIRE(greenGhosts(scene) == 1);
    const render::Figure* ghost = nullptr;
    for (const render::Figure& f : scene.figures)
        if (f.ghost && f.ghostTint.g > 0.8f) ghost = &f;
    REQUIRE(ghost != nullptr);
    // Laid over the current pose's root: the root joint is where the current root is.
    FkState fk;
    forwardKinematics(doc.clip().skeleton, doc.currentPose(), fk);
    REQUIRE(!ghost->joints.empty());
    const glm::vec3 root = ghost->joints.front().centreCm;
    CHECK(std::abs(root.x - float(fk.jointCm[0].x())) < 1e-3f);
    CHECK(std::abs(root.y - float(fk.jointCm[0].y())) < 1e-3f);
    CHECK(std::abs(root.z - float(fk.jointCm[0].z())) < 1e-3f);
    std::filesystem::create_directories(kOutDir);
    render::writePng(h->app->capture(test::kGuiWidth, test::kGuiHeight), kOutDir + "/nearest_ghost.png");
}
