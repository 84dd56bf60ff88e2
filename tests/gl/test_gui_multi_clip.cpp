// A model of several clips in the editor (label `gl`, offscreen): the open clip, when it is any of
// the model's clips, opens without a question and becomes the model's working clip; otherwise the
// question comes and "Open with its clip" opens the first clip. A tiny model trained here (two
// kicks of subject 10, 20 rows each, M = 15, T = 1) keeps the test cheap. The latent map colours
// the dots by clip with a legend, and clicking a dot of the other clip opens that clip there
// (after the unsaved-changes question when there are edits).
#include <doctest/doctest.h>

#include <unistd.h>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>

#include "editor_harness.h"
#include "gl_test_paths.h"
#include "gp/model_file.h"
#include "gp/train/trainer.h"
#include "io/clip_loader.h"
#include "ui/shell/editor_app.h"

using namespace mgp;
using test::tapKey;
namespace key = ui::key;

namespace {

// Runs `action`, which must ask about unsaved changes first, and answers Cancel (Escape).
void askThenCancel(test::Harness& h, const std::vector<std::string>& action) {
    REQUIRE(h.app->runAction(action) == "");
    h.frame(2);
    CHECK(h.app->askingAboutUnsavedChanges());
    tapKey(h, key::kEscape);
    h.frame(1);
    CHECK_FALSE(h.app->askingAboutUnsavedChanges());
}
std::string twoKickModel() {
    const std::string dir =
        (std::filesystem::temp_directory_path() / ("motiongp_gui_multi_clip_" + std::to_string(::getpid()))).string();
    std::filesystem::create_directories(dir);
    const std::string path = dir + "/two_kicks.model";
    Clip a = loadClip(test::mocapDir() + "/asf_amc/10_02.amc");
    Clip b = loadClip(test::mocapDir() + "/asf_amc/10_03.amc");
    unwrapClip(a);
    unwrapClip(b);
    std::vector<int> frames;
    for (int t = 0; t < 60; t += 3) frames.push_back(t);
    gp::TrainOptions o;
    o.activeSize = 15;
    o.outerIterations = 1;
    o.scgIterations = 10;
    o.pointIterations = 10;
    gp::TrainResult r = gp::train(gp::trainingDataFromClips({&a, &b}, {frames, frames}), o);
    r.model.clip = a;
    r.model.sourceFile = "10_02.amc";
    r.model.moreClips.push_back({"10_03.amc", "", b});
    gp::saveModel(path, r.model);
    return path;
}
}  // namespace

TEST_CASE("gui: a multi-clip model opens on whichever of its clips is open") {
    auto h = test::makeHarness(false, false);  // 35_01 open, no model
    if (!h) return;
    const std::string model = twoKickModel();
    REQUIRE(h->app->openClip(test::mocapDir() + "/asf_amc/10_03.amc") == "");
    h->frame(2);
    REQUIRE(h->app->runAction({"open-model", model}) == "");
    h->frame(3);  // the latent map and the Model panel draw the model
    CHECK_FALSE(h->app->askingAboutModelClip());
    EditorDocument& doc = h->app->state().doc;
    REQUIRE(doc.hasModel());
    CHECK(doc.clip().name == "10_03");
    const gp::GpModel& m = *doc.model()->model;
    CHECK(m.clip.name == "10_03");  // the working (primary) clip is the open one
    CHECK(m.clipName(1) == "10_02");
    CHECK(m.rowClip(25) == 0);  // rows follow their clip
    CHECK(m.rowClip(5) == 1);
    doc.setFrame(30);
    h->frame(2);
    CHECK(doc.currentLatent().allFinite());

    // Another clip open: the question comes; Enter opens the model's first clip.
    REQUIRE(h->app->openClip(test::mocapDir() + "/asf_amc/35_01.amc") == "");
    h->frame(2);
    REQUIRE(h->app->runAction({"open-model", model}) == "");
    h->frame(2);
    REQUIRE(h->app->askingAboutModelClip());
    tapKey(*h, key::kEnter);
    h->frame(3);
    CHECK_FALSE(h->app->askingAboutModelClip());
    EditorDocument& after = h->app->state().doc;
    REQUIRE(after.hasModel());
    CHECK(after.clip().name == "10_02");
    CHECK(after.model()->model->clip.name == "10_02");
    std::filesystem::remove_all(std::filesystem::path(model).parent_path());
}

namespace {
// Opens 10_03 and the two-kick model (10_03 becomes its working clip) and lets the map settle.
void openTwoKicks(test::Harness& h, const std::string& model) {
    REQUIRE(h.app->openClip(test::mocapDir() + "/asf_amc/10_03.amc") == "");
    h.frame(2);
    REQUIRE(h.app->runAction({"open-model", model}) == "");
    for (int i = 0; i < 10 && !h.app->latentMapUpToDate(); ++i) {
        h.app->waitIdle();
        h.frame();
    }
    h.frame(2);
    REQUIRE(h.app->latentMapUpToDate());
}

// The training frame (0-based) of clip 10_02 whose dot is farthest from every other dot, so a
// click there picks it; its window pixel in x, y.
int loneDotOf1002(test::Harness& h, float& x, float& y) {
    int best = -1;
    float bestD2 = -1.0f;
    for (int f = 0; f < 60; f += 3) {
        float fx = 0, fy = 0;
        REQUIRE(h.app->latentDotScreenPosition("10_02", f, fx, fy));
        float nearest = 1e30f;
        for (const char* clip : {"10_02", "10_03"})
            for (int g = 0; g < 60; g += 3) {
                float gx = 0, gy = 0;
                if ((clip == std::string("10_02") && g == f) || !h.app->latentDotScreenPosition(clip, g, gx, gy))
                    continue;
                nearest = std::min(nearest, (gx - fx) * (gx - fx) + (gy - fy) * (gy - fy));
            }
        if (nearest > bestD2) bestD2 = nearest, best = f, x = fx, y = fy;
    }
    INFO("the lone 10_02 dot is " << std::sqrt(bestD2) << " px from the next");
    CHECK(bestD2 >= 9.0f);  // a click there reaches it (hover picks within 7 px, the nearest)
    return best;
}

}  // namespace

TEST_CASE("gui: the latent map of a two-clip model colours its dots by clip, with a legend") {
    auto h = test::makeHarness(false, false);
    if (!h) return;
    const std::string model = twoKickModel();
    openTwoKicks(*h, model);
    const ui::EditorState& s = h->app->state();
    // One legend line per clip, "NAME #RRGGBB", the open clip marked.
    std::istringstream lines(s.clipLegend);
    std::string name, colour, open;
    std::map<std::string, std::string> colours;
    std::string openClip;
    std::string line;
    while (std::getline(lines, line)) {
        std::istringstream in(line);
        in >> name >> colour;
        open.clear();
        in >> open;
        colours[name] = colour;
        if (open == "(open)") openClip = name;
    }
    REQUIRE(colours.size() == 2);
    CHECK(openClip == "10_03");
    REQUIRE(colours.count("10_02") == 1);
    CHECK(colours["10_02"] != colours["10_03"]);
    // The swatches are drawn in those colours.
    const render::Image img = h->app->capture(test::kGuiWidth, test::kGuiHeight);
    for (const auto& entry : colours) {
        // Named copies: clang before 16 cannot capture a structured binding in INFO's lambda.
        const std::string& clip = entry.first;
        const std::string& hex = entry.second;
        const auto& r = s.controls.at("clip legend " + clip);
        REQUIRE(r.visible);
        const int px = int((r.x0 + r.x1) / 2), py = int((r.y0 + r.y1) / 2);
        const std::uint8_t* p = &img.rgba[4 * (std::size_t(py) * std::size_t(img.width) + std::size_t(px))];
        char seen[8];
        std::snprintf(seen, sizeof seen, "#%02X%02X%02X", p[0], p[1], p[2]);
        INFO(clip << " swatch at " << px << "," << py);
        CHECK(std::string(seen) == hex);
    }
    // A single-clip model has no legend.
    REQUIRE(h->app->openClip(test::mocapDir() + "/asf_amc/35_01.amc") == "");
    REQUIRE(h->app->runAction({"open-model", test::fixtureModelPath()}) == "");
    h->frame(3);
    CHECK(s.clipLegend.empty());
    std::filesystem::remove_all(std::filesystem::path(model).parent_path());
}

TEST_CASE("gui: clicking a dot of the model's other clip opens that clip at that frame, the model staying") {
    auto h = test::makeHarness(false, false);
    if (!h) return;
    const std::string model = twoKickModel();
    openTwoKicks(*h, model);
    EditorDocument& doc = h->app->state().doc;
    const gp::GpModel* before = doc.model()->model.get();
    const int rows = before->N();
    float x = 0, y = 0;
    const int frame = loneDotOf1002(*h, x, y);
    REQUIRE(frame >= 0);
    test::clickAt(*h, x, y);
    CHECK_FALSE(h->app->askingAboutUnsavedChanges());  // nothing unsaved: no question
    CHECK(doc.clip().name == "10_02");
    CHECK(doc.frame() == frame);
    REQUIRE(doc.hasModel());
    const gp::GpModel& m = *doc.model()->model;
    CHECK(m.N() == rows);  // the same model, relabelled
    CHECK(m.clip.name == "10_02");
    CHECK(m.clipName(1) == "10_03");
    CHECK(h->app->state().messages.latestText().find("10_02 frame " + std::to_string(frame + 1)) != std::string::npos);
    CHECK_FALSE(h->app->dirty());
    h->frame(3);
    CHECK(h->app->state().clipLegend.find("10_02 #") == 0);
    CHECK(h->app->state().clipLegend.find("(open)") < h->app->state().clipLegend.find("10_03"));
    // The action behind the click names what is wrong with a bad clip or frame, and changes nothing.
    CHECK(h->app->runAction({"model-clip", "10_09"}) == "the model has no clip '10_09'; its clips: 10_02, 10_03");
    CHECK(h->app->runAction({"model-clip", "10_03", "9999"}) == "expected a frame in 1..362 of 10_03, found 9999");
    CHECK(doc.clip().name == "10_02");
    // Back to 10_03 by the action: frame counted within that clip.
    REQUIRE(h->app->runAction({"model-clip", "10_03", "7"}) == "");
    CHECK(doc.clip().name == "10_03");
    CHECK(doc.frame() == 6);
    std::filesystem::remove_all(std::filesystem::path(model).parent_path());
}

TEST_CASE("gui: with unsaved edits, clicking another clip's dot asks first and Cancel keeps the clip and edits") {
    auto h = test::makeHarness(false, false);
    if (!h) return;
    const std::string model = twoKickModel();
    openTwoKicks(*h, model);
    EditorDocument& doc = h->app->state().doc;
    doc.setFrame(40);
    REQUIRE(doc.pastePose(doc.clip().frames[10]) == "");
    REQUIRE(h->app->dirty());
    h->frame(2);
    float x = 0, y = 0;
    REQUIRE(loneDotOf1002(*h, x, y) >= 0);
    test::clickAt(*h, x, y);
    REQUIRE(h->app->askingAboutUnsavedChanges());
    CHECK(doc.clip().name == "10_03");  // nothing happens before the answer
    tapKey(*h, key::kEscape);
    h->frame(1);
    CHECK_FALSE(h->app->askingAboutUnsavedChanges());
    CHECK(doc.clip().name == "10_03");
    CHECK(doc.isEdited(40));
    CHECK(doc.model()->model->clip.name == "10_03");
    CHECK(h->app->dirty());
    std::filesystem::remove_all(std::filesystem::path(model).parent_path());
}

TEST_CASE(
    "gui: a model trained here and never saved is asked about on every path that drops it, even after a clip switch") {
    // The user's sequence: a model trained in the editor (here: the opened model replaced by a copy,
    // as a finished training installs one), click the other clip's dot, answer "Don't save"; the
    // model stays, still unsaved, so opening a BVH clip, quitting or opening the demo clip asks
    // again. Once the model is saved to a file, opening a clip asks nothing.
    auto h = test::makeHarness(false, false);
    if (!h) return;
    const std::string model = twoKickModel();
    openTwoKicks(*h, model);
    EditorDocument& doc = h->app->state().doc;
    CHECK_FALSE(h->app->dirty());
    CHECK_FALSE(h->app->modelUnsaved());
    doc.setModel(gp::ModelVersion::make(gp::GpModel(*doc.model()->model)), false);
    CHECK(h->app->modelUnsaved());
    h->frame(2);
    float x = 0, y = 0;
    REQUIRE(loneDotOf1002(*h, x, y) >= 0);
    test::clickAt(*h, x, y);
    REQUIRE(h->app->askingAboutUnsavedChanges());
    test::answerUnsaved(*h, "Don't save");
    h->frame(2);
    CHECK_FALSE(h->app->askingAboutUnsavedChanges());
    REQUIRE(doc.clip().name == "10_02");  // switched, the model staying
    CHECK(h->app->modelUnsaved());
    CHECK(h->app->dirty());
    // Every way of dropping it asks first (File > Open and Open model ask before their dialogs; a
    // model file of the open clip would replace this one; a script's `open PATH`; a new training,
    // whose model would replace it), and Cancel keeps it.
    const std::string bvh = test::mocapDir() + "/bvh/02_03.bvh";
    const std::vector<std::vector<std::string>> drops = {
        {"open"}, {"open", bvh}, {"open-model"}, {"open-model", model}, {"demo-clip"}, {"train"}, {"quit"}};
    for (const std::vector<std::string>& action : drops) {
        INFO(action.front());
        askThenCancel(*h, action);
        CHECK(doc.clip().name == "10_02");
        CHECK(doc.hasModel());
        CHECK(h->app->modelUnsaved());
        CHECK_FALSE(h->app->fileDialog().isOpen());
        CHECK_FALSE(h->app->quitRequested());
        CHECK_FALSE(h->app->state().training.running());
    }
    // Saved to a file, the model is safe: opening the demo clip no longer asks.
    const std::string saved = std::filesystem::path(model).parent_path().string() + "/saved.model";
    REQUIRE(h->app->runAction({"save-model", saved}) == "");
    CHECK_FALSE(h->app->modelUnsaved());
    CHECK_FALSE(h->app->dirty());
    REQUIRE(h->app->runAction({"demo-clip"}) == "");
    h->frame(2);
    CHECK_FALSE(h->app->askingAboutUnsavedChanges());
    CHECK(doc.clip().name == "synthetic_walk");
    std::filesystem::remove_all(std::filesystem::path(model).parent_path());
}

TEST_CASE("gui: a compare model no session holds is asked about before anything drops or replaces it") {
    // A compare model as a finished compare training installs one; every path that would drop it
    // (opening a clip, a model, the demo clip, quitting) or replace it (a new compare training)
    // asks first, and Cancel keeps it. Saved in a session, a new compare training asks nothing.
    auto h = test::makeHarness(false);
    if (!h) return;
    EditorDocument& doc = h->app->state().doc;
    CHECK_FALSE(h->app->dirty());
    doc.setCompareModel(gp::ModelVersion::make(gp::GpModel(*doc.model()->model)));
    const gp::ModelVersionPtr compare = doc.compareModel();
    CHECK(h->app->compareModelUnsaved());
    CHECK(h->app->dirty());
    const std::string bvh = test::mocapDir() + "/bvh/02_03.bvh";
    const std::vector<std::vector<std::string>> drops = {
        {"open", bvh}, {"open-model", test::fixtureModelPath()}, {"demo-clip"}, {"train-compare"}, {"quit"}};
    for (const std::vector<std::string>& action : drops) {
        INFO(action.front());
        askThenCancel(*h, action);
        CHECK(doc.compareModel() == compare);
        CHECK_FALSE(h->app->state().compareTraining.running());
        CHECK_FALSE(h->app->quitRequested());
    }
    const std::string dir = test::kOutDir + "/compare_model_session";
    std::filesystem::create_directories(dir);
    REQUIRE(h->app->runAction({"save-session", dir + "/with_compare.mgsession"}) == "");
    CHECK_FALSE(h->app->compareModelUnsaved());
    CHECK_FALSE(h->app->dirty());
    REQUIRE(h->app->runAction({"train-compare"}) == "");
    h->frame(1);
    CHECK_FALSE(h->app->askingAboutUnsavedChanges());
    CHECK(h->app->state().compareTraining.running());
    h->app->state().compareTraining.cancel();
    h->app->waitIdle();
    std::filesystem::remove_all(dir);
}
