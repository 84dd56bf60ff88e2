// Model ▸ Train on clips… in the editor (label `gl`, offscreen): the modal lists the open clip and
// the other clips of its skeleton beside it, a click ticks a second kick, Train (clicked) trains a
// tiny model (two kicks of subject 10, frames 1..60 every 3rd of each: N = 40, M = 15, T = 1) off
// the UI thread, and the model is installed with the open clip primary and both clips on the
// latent map's legend. Esc closes the modal without changes; an open BVH clip offers its own
// hierarchy only and trains a BVH model; the script action names what is wrong, and Add file ticks a clip from
// elsewhere.
#include <doctest/doctest.h>

#include <unistd.h>
#include <filesystem>
#include <string>
#include <vector>

#include "editor_harness.h"
#include "gp/train/pca_init.h"
#include "ui/shell/editor_app.h"

using namespace mgp;
using test::tapKey;
namespace key = ui::key;

namespace {
// A left click at the centre of the control `name` as last drawn (its left end for a check box).
void clickControl(test::Harness& h, const std::string& name, bool leftEnd = false) {
    const auto& controls = h.app->state().controls;
    REQUIRE(controls.count(name) == 1);
    const auto& r = controls.at(name);
    REQUIRE(r.visible);
    test::clickAt(h, leftEnd ? r.x0 + 6.0f : (r.x0 + r.x1) / 2, (r.y0 + r.y1) / 2);
}

// The Model panel's options for a tiny run: M active, T = 1, 10 SCG and point iterations.
void tinyTraining(test::Harness& h, int M) {
    gp::TrainOptions& o = h.app->state().trainOptions;
    o.activeSize = M;
    o.outerIterations = 1;
    o.scgIterations = 10;
    o.pointIterations = 10;
}

// Until the run has ended and the latent map shows its model.
void waitForTraining(test::Harness& h) {
    h.app->waitIdle();
    for (int i = 0; i < 10 && !h.app->latentMapUpToDate(); ++i) {
        h.app->waitIdle();
        h.frame();
    }
}
}  // namespace

TEST_CASE("gui: Train on clips lists the kicks of subject 10, trains two into one model and shows both") {
    auto h = test::makeHarness(false, false);
    if (!h) return;
    REQUIRE(h->app->openClip(test::mocapDir() + "/asf_amc/10_03.amc") == "");
    h->frame(2);
    REQUIRE(h->app->runAction({"train-clips"}) == "");
    h->frame(3);
    const ui::TrainClipsWindow& w = h->app->trainClipsWindow();
    REQUIRE(w.shown());
    CHECK(h->app->popupOpen());
    const std::vector<TrainingCandidate>& list = w.candidates();
    REQUIRE(list.size() == 7u);  // 10_03 (open), 10_02, and five clips of other subjects, refused
    CHECK(list[0].name == "10_03");
    CHECK(w.checked(0));
    CHECK(list[1].name == "10_02");
    CHECK_FALSE(w.checked(1));
    for (std::size_t i = 2; i < list.size(); ++i) CHECK_FALSE(list[i].usable);

    clickControl(*h, "train clips: 10_02", true);
    REQUIRE(w.checked(1));
    // A tiny run: the dialog's range and the Model panel's options.
    h->app->trainClipsWindow().selection() = {1, 60, 3};
    tinyTraining(*h, 15);
    h->frame(2);
    CHECK(w.totalRows() == 40);
    clickControl(*h, "train clips: Train");
    CHECK_FALSE(w.shown());
    waitForTraining(*h);
    h->frame(2);
    const EditorDocument& doc = h->app->state().doc;
    REQUIRE(doc.hasModel());
    const gp::GpModel& m = *doc.model()->model;
    CHECK(m.clipCount() == 2);
    CHECK(m.clip.name == "10_03");  // the open clip is the primary one
    CHECK(m.clipName(1) == "10_02");
    CHECK(m.N() == 40);
    CHECK(doc.clip().name == "10_03");
    const std::string& legend = h->app->state().clipLegend;
    CHECK(legend.find("10_03 #") != std::string::npos);
    CHECK(legend.find("10_02 #") != std::string::npos);
    CHECK(legend.find("(open)") != std::string::npos);

    // Esc closes the modal; nothing changes.
    const gp::GpModel* before = doc.model()->model.get();
    REQUIRE(h->app->runAction({"train-clips"}) == "");
    h->frame(3);
    REQUIRE(h->app->popupOpen());
    tapKey(*h, key::kEscape);
    h->frame(2);
    CHECK_FALSE(w.shown());
    CHECK_FALSE(h->app->popupOpen());
    CHECK(doc.model()->model.get() == before);
    CHECK_FALSE(h->app->state().training.running());
}

TEST_CASE("gui: Train on clips on a BVH clip refuses other hierarchies and trains a BVH model") {
    auto h = test::makeHarness(false, false);
    if (!h) return;
    REQUIRE(h->app->openClip(test::mocapDir() + "/bvh/49_04.bvh") == "");
    h->frame(2);
    REQUIRE(h->app->runAction({"train-clips"}) == "");
    h->frame(3);
    const ui::TrainClipsWindow& w = h->app->trainClipsWindow();
    REQUIRE(w.shown());
    // 49_04 (open), then the two other cgspeed conventions beside it, refused: other hierarchies.
    REQUIRE(w.candidates().size() == 3u);
    CHECK(w.candidates()[0].usable);
    for (std::size_t i = 1; i < 3; ++i) CHECK(w.candidates()[i].reason.rfind("another skeleton (", 0) == 0);
    CHECK(h->app->runAction({"train-clips", "02_03"}).rfind("02_03 cannot train with 49_04: another skeleton (", 0) ==
          0);
    // The open clip alone, a tiny run: a BVH model (its own channels, d by eq. 4) is installed.
    h->app->trainClipsWindow().selection() = {2, 200, 4};
    tinyTraining(*h, 20);
    h->frame(2);
    CHECK(w.totalRows() == 50);
    clickControl(*h, "train clips: Train");
    waitForTraining(*h);
    const EditorDocument& doc = h->app->state().doc;
    REQUIRE(doc.hasModel());
    const gp::GpModel& m = *doc.model()->model;
    CHECK(m.clip.name == "49_04");
    CHECK(m.clip.skeleton.poseVector == PoseVectorKind::kChannels);
    CHECK(m.N() == 50);
    CHECK(m.latentDim() == gp::latentDimensionFor(m.D()));
}

TEST_CASE("gui: the train-clips action names what is wrong and trains nothing") {
    auto h = test::makeHarness(false, false);
    if (!h) return;
    REQUIRE(h->app->openClip(test::mocapDir() + "/asf_amc/10_03.amc") == "");
    h->frame(2);
    ui::EditorApp& app = *h->app;
    CHECK(app.runAction({"train-clips", "10_09"}) ==
          "no clip '10_09' beside the open clip (offered: 10_02; give a path to add another file)");
    CHECK(app.runAction({"train-clips", "16_01"})
              .rfind("16_01 cannot train with 10_03: another skeleton (16.asf): joint ", 0) == 0);
    CHECK(app.runAction({"train-clips", "10_02", "5"}) == "expected a frame range A:B or all, found '5'");
    CHECK(app.runAction({"train-clips", "10_02", "1:1"}) ==
          "expected at least 3 training frames after --frames/--step, found 2");
    CHECK(app.runAction({"train-clips", "10_02", "1:400"}) ==
          "expected --frames A:B with 1 ≤ A ≤ B ≤ 362 (10_03's frames counted from 1), found '1:400'");
    CHECK(app.runAction({"train-clips", test::mocapDir() + "/asf_amc/10_99.amc"}) ==
          "10_99 cannot train with 10_03: no such file");
    // Add file: a kick of subject 10 from another folder is ticked; a second file named like a
    // listed clip is refused (a model names its clips by file stem).
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("motiongp_gui_train_clips_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    fs::copy_file(test::mocapDir() + "/asf_amc/10.asf", dir / "10.asf", fs::copy_options::overwrite_existing);
    fs::copy_file(test::mocapDir() + "/asf_amc/10_02.amc", dir / "10_05.amc", fs::copy_options::overwrite_existing);
    fs::copy_file(test::mocapDir() + "/asf_amc/10_02.amc", dir / "10_02.amc", fs::copy_options::overwrite_existing);
    REQUIRE(app.runAction({"train-clips"}) == "");
    ui::TrainClipsWindow& w = app.trainClipsWindow();
    CHECK(w.addFile((dir / "10_05.amc").string()) == "");
    CHECK(w.candidates().back().name == "10_05");
    CHECK(w.checked(w.candidates().size() - 1));
    CHECK(w.addFile((dir / "10_02.amc").string()) ==
          "expected clips with distinct names (file stems), found 10_02 twice");
    fs::remove_all(dir);
    CHECK_FALSE(app.state().training.running());
    CHECK_FALSE(app.state().doc.hasModel());
    h->frame(3);
    REQUIRE(app.trainClipsWindow().shown());
    app.trainClipsWindow().close();
    h->frame(3);
    CHECK_FALSE(app.popupOpen());
}
