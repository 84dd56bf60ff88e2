// Editor UI tests (label `gl`): the whole editor (ImGui + viewport + panels) runs on the
// offscreen EGL context with input fed exactly like a --script run, no display.
//
//  - drag: a scripted mouse drag of the right-foot handle upward by ≥ 15 cm, then a few idle
//    frames (the editor keeps refining while the mouse holds still) and the release; the foot's
//    FK position on the current frame must be within 0.5 cm of the dragged target (the target
//    itself is the ray/plane point under the mouse, read from the document);
//  - golden: the latent map and the timeline panels (crops of the window) against goldens with a
//    tolerance (see kTolerance below);
//  - fuzz: several hundred random input events on a real clip with a model: no crash, and the pose,
//    camera, readout and latent point stay finite.
// The model is the committed fixture (tests/fixtures/walk35_fas_m100_t3.model), never trained here.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>

#include "editor_harness.h"
#include "gl_test_paths.h"
#include "io/parse_error.h"
#include "render/gl_context.h"
#include "render/png_capture.h"
#include "skeleton/forward_kinematics.h"
#include "ui/input/gui_script.h"
#include "ui/shell/editor_app.h"

#include "skip.h"
#include "stb_image_include.h"

using namespace mgp;
namespace fs = std::filesystem;

namespace {

using test::kGoldenDir;
using test::kOutDir;

using test::Harness;
using test::makeHarness;
constexpr int kW = test::kGuiWidth, kH = test::kGuiHeight;

bool finite(const Pose& p) {
    if (!p.rootCm.allFinite()) return false;
    for (const auto& a : p.anglesDeg)
        if (!a.allFinite()) return false;
    return true;
}

render::Image crop(const render::Image& img, int x, int y, int w, int h) {
    render::Image out;
    out.width = w;
    out.height = h;
    out.rgba.resize(std::size_t(w) * h * 4);
    for (int r = 0; r < h; ++r)
        std::copy_n(&img.rgba[(std::size_t(y + r) * img.width + x) * 4], w * 4, &out.rgba[std::size_t(r) * w * 4]);
    return out;
}

// Golden compare. Tolerance: a pixel matches when every channel is within 8/255; at least 99 %
// of the pixels must match. Looser than the renderer goldens (2/255, 99.9 %) because these
// panels also draw a variance texture computed on this CPU (libm's exp differs in the last bits
// between CPUs) and text; a real regression (panel missing, wrong layout, wrong colours) changes
// far more.
// The model is loaded from the committed fixture, so the same latent layout is drawn on every
// CPU and build; what remains is the rasteriser's and the variance grid's last-bit noise.
void compareGolden(const std::string& name, const render::Image& actual) {
    constexpr int kTolerance = 8;
    constexpr double kMinMatching = 0.99;
    const std::string path = kGoldenDir + "/" + name + ".png";
    const char* upd = std::getenv("MOTIONGP_UPDATE_GOLDENS");
    if (upd && std::string(upd) == "1") {
        render::writePng(actual, path);
        MESSAGE("updated golden " << path);
        return;
    }
    fs::create_directories(kOutDir);
    int w = 0, h = 0, n = 0;
    stbi_uc* golden = stbi_load(path.c_str(), &w, &h, &n, 4);
    if (!golden) {
        render::writePng(actual, kOutDir + "/" + name + ".actual.png");
        FAIL("missing golden " << path << " (MOTIONGP_UPDATE_GOLDENS=1 ctest --test-dir build -L gl)");
        return;
    }
    REQUIRE(w == actual.width);
    REQUIRE(h == actual.height);
    long matching = 0;
    for (long p = 0; p < long(w) * h; ++p) {
        int m = 0;
        for (int c = 0; c < 4; ++c) m = std::max(m, std::abs(int(actual.rgba[p * 4 + c]) - int(golden[p * 4 + c])));
        matching += m <= kTolerance;
    }
    stbi_image_free(golden);
    const double fraction = double(matching) / (double(w) * h);
    INFO(name << ": " << fraction * 100 << " % of pixels within " << kTolerance << "/255 (need " << kMinMatching * 100
              << " %)");
    if (fraction < kMinMatching)
        render::writePng(actual, kOutDir + "/" + name + ".actual.png");
    else
        fs::remove(kOutDir + "/" + name + ".actual.png");
    CHECK(fraction >= kMinMatching);
}

}  // namespace

TEST_CASE("gui: script parser accepts the documented verbs and reports file:line on errors") {
    const auto s = ui::GuiScript::parse(
        "# drag\n5 hover rfoot\n7 down left  # press\n9 moveby 0 -20\n"
        "11 up left\n12 key SPACE\n13 keydown shift\n14 wheel -1\n"
        "15 action frame 10\n16 action screenshot a.png\n");
    CHECK(s.events().size() == 9);
    CHECK(s.lastFrame() == 16);
    CHECK(s.events()[1].verb == "down");
    CHECK_THROWS_WITH_AS(ui::GuiScript::parse("1 move 10\n", "s.txt"),
                         "s.txt:1: expected two pixel coordinates, found 1 arguments", ParseError);
    CHECK_THROWS_WITH_AS(ui::GuiScript::parse("\nx move 1 2\n", "s.txt"),
                         "s.txt:2: expected a frame number ≥ 0 first, found 'x'", ParseError);
    CHECK_THROWS_AS(ui::GuiScript::parse("1 key NOPE\n"), ParseError);
    CHECK_THROWS_AS(ui::GuiScript::parse("1 action explode\n"), ParseError);
}

TEST_CASE("gui: dragging the right foot up by 15+ cm leaves it within 0.5 cm of the target (FK)") {
    auto h = makeHarness(false);
    if (!h) return;
    EditorDocument& doc = h->app->state().doc;
    doc.setFrame(99);  // frame 100
    h->frame(2);
    const Eigen::Vector3d start = doc.effectorPosition(Effector::kRFoot);

    ui::GuiScript script;
    script.add(0, "hover", {"rfoot"});
    script.add(2, "down", {"left"});
    for (int k = 0; k < 12; ++k) script.add(4 + k, "moveby", {"0", "-8"});
    script.add(16 + 10, "up", {"left"});  // ten idle frames holding still, then release
    ui::ScriptPlayer player(script);
    std::vector<std::string> shots;
    bool sawDrag = false;
    for (int i = 0; i <= 30; ++i) {
        player.apply(i, h->input, *h->app, shots);
        h->frame();
        sawDrag |= doc.dragging();
    }
    CHECK(player.errors().empty());
    REQUIRE(sawDrag);
    CHECK_FALSE(doc.dragging());
    REQUIRE(doc.isEdited(99));
    const Eigen::Vector3d target = doc.dragTarget();
    INFO("start " << start.transpose() << "  target " << target.transpose());
    CHECK(target.y() - start.y() >= 15.0);
    FkState fk;
    forwardKinematics(doc.clip().skeleton, doc.currentPose(), fk);
    const Eigen::Vector3d foot = effectorCm(doc.clip().skeleton, fk, Effector::kRFoot);
    INFO("foot " << foot.transpose() << "  residual " << (foot - target).norm() << " cm");
    CHECK((foot - target).norm() <= 0.5);
    CHECK(doc.readout().valid);
    CHECK(doc.readout().learned);
    CHECK(doc.readout().reached);
    // The accepted pose went to the adaptive worker; the UI never waited for it.
    doc.waitIdle();
    CHECK(doc.models().updates() >= 1);
}

TEST_CASE("gui golden: latent map and timeline panels") {
    // The map shows the committed fixture model (loaded, not trained here), so its picture does
    // not depend on this CPU's floating point.
    auto h = makeHarness(true);
    if (!h) return;
    h->app->state().doc.setFrame(59);
    h->app->state().setStatus("golden");  // the status line would name the model file
    h->frame(3);
    REQUIRE(h->app->latentMapUpToDate());
    const render::Image img = h->app->capture(kW, kH);
    fs::create_directories(kOutDir);
    render::writePng(img, kOutDir + "/ui_window.png");
    // Fixed layout (EditorApp::layout): right column 380 px wide; the latent map window starts
    // at menu height + 262 and is 356 px tall; the timeline is the bottom 104 px left of it.
    const int menuH = 19;  // ImGui's built-in font: frame height 13 + 2*3
    compareGolden("ui_latent_map", crop(img, kW - 380, menuH + 262, 380, 356));
    compareGolden("ui_timeline", crop(img, 0, kH - 104, kW - 380, 104));
}

TEST_CASE("gui: the latent map's static layer is drawn once per model version, not once per frame") {
    auto h = makeHarness(false);
    if (!h) return;
    EditorDocument& doc = h->app->state().doc;
    doc.setFrame(99);
    h->frame(3);
    REQUIRE(h->app->latentMapUpToDate());
    const int settled = h->app->latentMapLayerRenders();
    CHECK(settled >= 1);
    h->frame(5);
    CHECK(h->app->latentMapLayerRenders() == settled);  // nothing changed: no redraw

    // A drag moves the current latent point every frame but leaves the layer alone.
    ui::GuiScript script;
    script.add(0, "hover", {"rfoot"});
    script.add(2, "down", {"left"});
    for (int k = 0; k < 6; ++k) script.add(4 + k, "moveby", {"0", "-4"});
    script.add(12, "up", {"left"});
    ui::ScriptPlayer player(script);
    std::vector<std::string> shots;
    int dragFrames = 0;
    for (int i = 0; i <= 12; ++i) {
        player.apply(i, h->input, *h->app, shots);
        h->frame();
        if (!doc.dragging()) continue;
        ++dragFrames;
        CHECK(h->app->latentMapLayerRenders() == settled);
    }
    CHECK(dragFrames >= 6);
    // A new model (here: retrained) redraws it once its σ² image is in.
    h->app->waitIdle();
    h->frame();
    const int beforeTraining = h->app->latentMapLayerRenders();
    const gp::GpModel* oldModel = doc.model()->model.get();
    REQUIRE(h->app->runAction({"train", "fas", "50", "1"}).empty());
    // The drag's pose was taught to the model, which no file holds now: training asks first.
    test::answerUnsaved(*h, "Don't save");
    for (int i = 0; i < 20 && (doc.model()->model.get() == oldModel || !h->app->latentMapUpToDate()); ++i) {
        h->app->waitIdle();
        h->frame();
    }
    REQUIRE(doc.model()->model.get() != oldModel);
    REQUIRE(h->app->latentMapUpToDate());
    CHECK(h->app->latentMapLayerRenders() > beforeTraining);
}

TEST_CASE("gui: several hundred random input events on a real clip stay finite and do not crash") {
    auto h = makeHarness(false);
    if (!h) return;
    std::mt19937 rng(1234);
    std::uniform_real_distribution<float> ux(0.0f, float(kW)), uy(0.0f, float(kH)), step(-40.0f, 40.0f);
    const int keys[] = {ui::key::kSpace, ui::key::kLeft,   ui::key::kRight,    'F', 'P', ui::key::kHome,
                        ui::key::kEnd,   ui::key::kEscape, ui::key::kLeftShift};
    EditorDocument& doc = h->app->state().doc;
    int dragFrames = 0;
    for (int i = 0; i < 600; ++i) {
        ui::InputState& in = h->input;
        // Release one-shot keys from the previous event (not Shift, which is toggled).
        for (int k : keys)
            if (k != ui::key::kLeftShift) in.keys[k] = false;
        switch (rng() % 10) {
            case 0: in.mouseX = ux(rng), in.mouseY = uy(rng); break;
            case 1:
            case 2: in.mouseX += step(rng), in.mouseY += step(rng); break;
            case 3: in.mouseDown[rng() % 3] = true; break;
            case 4: in.mouseDown[rng() % 3] = false; break;
            case 5: in.wheel += float(int(rng() % 5) - 2); break;
            case 6: {
                const int k = keys[rng() % (sizeof keys / sizeof keys[0])];
                in.keys[k] = !in.keys[k];
                break;
            }
            case 7:
            case 8: {  // aim at a handle with the buttons up, to provoke drags
                float x, y;
                if (h->app->handleScreenPosition(static_cast<Effector>(rng() % kEffectorCount), x, y))
                    in.mouseX = x, in.mouseY = y;
                in.mouseDown.fill(false);
                break;
            }
            case 9: in.mouseDown[0] = true; break;
        }
        h->frame();
        dragFrames += doc.dragging();
        REQUIRE(finite(doc.currentPose()));
        const auto& cam = h->app->state().camera;
        REQUIRE(std::isfinite(cam.distanceCm));
        REQUIRE(std::isfinite(cam.targetCm.x + cam.targetCm.y + cam.targetCm.z));
        if (doc.readout().valid) {
            REQUIRE(std::isfinite(doc.readout().sigma2));
            REQUIRE(std::isfinite(doc.readout().lik));
            for (const auto& c : doc.readout().constraints) REQUIRE(std::isfinite(c.residualCm));
        }
        if (doc.hasModel()) REQUIRE(doc.currentLatent().allFinite());
    }
    for (const auto& [f, e] : doc.edits()) {
        (void)f;
        CHECK(finite(e.pose));
    }
    MESSAGE("random events: " << dragFrames << " frames inside an effector drag, " << doc.edits().size()
                              << " edited frames");
    CHECK(dragFrames > 0);  // the events did exercise the learned IK, not only the camera
    h->app->state().playing = false;
    doc.waitIdle();
}

TEST_CASE("gui verb: --offscreen --script runs the frames, writes the screenshots and exits 0 with no display") {
    const std::string dir = kOutDir + "/gui_cli";
    fs::create_directories(dir);
    fs::remove(dir + "/mid.png");
    fs::remove(dir + "/end.png");
    {
        std::ofstream s(dir + "/script.txt");
        s << "# scrub, play, pause, pin, shot\n2 key RIGHT\n4 key SPACE\n10 key SPACE\n12 action pin lfoot\n"
             "14 action screenshot "
          << dir << "/mid.png\n";
    }
    const std::string cmd = std::string("DISPLAY= ") + MOTIONGP_TEST_BINARY + " gui '" + test::mocapDir() +
                            "/asf_amc/35_01.amc' --offscreen --size 640x400 --script '" + dir +
                            "/script.txt' --screenshot '" + dir + "/end.png' > '" + dir + "/log.txt' 2>&1";
    const int rc = std::system(cmd.c_str());
    if (rc != 0) {
        std::ifstream log(dir + "/log.txt");
        const std::string text((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
        if (text.find("EGL") != std::string::npos) {
            MGP_SKIP("no offscreen GL context for `motiongp gui`: " << text);
        }
        FAIL("gui exited " << rc << ": " << text);
    }
    int w = 0, h = 0, n = 0;
    stbi_uc* img = stbi_load((dir + "/end.png").c_str(), &w, &h, &n, 4);
    REQUIRE(img);
    CHECK(w == 640);
    CHECK(h == 400);
    stbi_image_free(img);
    CHECK(fs::exists(dir + "/mid.png"));
    // A malformed script is one clear error with file:line.
    {
        std::ofstream s(dir + "/bad.txt");
        s << "1 move 10\n";
    }
    const std::string bad = std::string("DISPLAY= ") + MOTIONGP_TEST_BINARY + " gui --offscreen --script '" + dir +
                            "/bad.txt' > '" + dir + "/bad.log' 2>&1";
    CHECK(std::system(bad.c_str()) != 0);
    std::ifstream log(dir + "/bad.log");
    const std::string text((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
    CHECK(text.find("bad.txt:1: expected two pixel coordinates") != std::string::npos);
}
