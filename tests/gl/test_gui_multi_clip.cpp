// A model of several clips in the editor (label `gl`, offscreen): the open clip, when it is any of
// the model's clips, opens without a question and becomes the model's working clip; otherwise the
// question comes and "Open with its clip" opens the first clip. A tiny model trained here (two
// kicks of subject 10, 20 rows each, M = 15, T = 1) keeps the test cheap.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>
#include <unistd.h>

#include "editor_app.h"
#include "editor_harness.h"
#include "gp/model_file.h"
#include "gp/trainer.h"
#include "input_state.h"
#include "io/clip_loader.h"

using namespace mgp;
using test::tapKey;
namespace key = ui::key;

namespace {
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
