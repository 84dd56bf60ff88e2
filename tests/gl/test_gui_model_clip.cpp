// Opening a model trained on another clip than the open one asks first (label `gl`, offscreen):
// Cancel keeps the clip, "Open with its clip" replaces it (after the unsaved-changes question
// when there are edits), and a model of the open clip opens without a question.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>

#include "editor_harness.h"
#include "test_paths.h"
#include "ui/input/input_state.h"
#include "ui/shell/editor_app.h"

using namespace mgp;
using test::tapKey;
namespace key = ui::key;

namespace {
std::string kickModelPath() { return std::string(MOTIONGP_TEST_FIXTURES) + "/kick10_03_fas_m100_t3.model"; }

// Opens the kick model (trained on 10_03) and answers its question with `answer` (Enter: open
// with its clip, Esc: cancel); the question must be up first and gone after.
void openKickModelAnswering(test::Harness& h, int answer) {
    REQUIRE(h.app->runAction({"open-model", kickModelPath()}) == "");
    h.frame(2);
    REQUIRE(h.app->askingAboutModelClip());
    tapKey(h, answer);
    h.frame(2);
    CHECK_FALSE(h.app->askingAboutModelClip());
}
}  // namespace

TEST_CASE("gui: a model of another clip asks before replacing the open clip") {
    auto h = test::makeHarness(false, false);  // 35_01 open, no model
    if (!h) return;
    EditorDocument& doc = h->app->state().doc;
    REQUIRE(doc.clip().name == "35_01");

    // Cancel (Esc): nothing changes.
    openKickModelAnswering(*h, key::kEscape);
    CHECK(doc.clip().name == "35_01");
    CHECK(doc.frameCount() == 358);
    CHECK_FALSE(doc.hasModel());

    // Unsaved edits, then Open with its clip (Enter): the unsaved-changes question comes next,
    // and cancelling it still keeps the clip and the edit.
    doc.setFrame(40);
    REQUIRE(doc.pastePose(doc.clip().frames[10]) == "");
    REQUIRE(h->app->dirty());
    openKickModelAnswering(*h, key::kEnter);
    REQUIRE(h->app->askingAboutUnsavedChanges());
    tapKey(*h, key::kEscape);
    h->frame(1);
    CHECK(doc.clip().name == "35_01");
    CHECK(doc.isEdited(40));
    CHECK_FALSE(doc.hasModel());

    // Without edits (a fresh editor on 35_01), Enter opens the model with its clip.
    h->restartApp();
    REQUIRE(h->app->openClip(test::mocapDir() + "/asf_amc/35_01.amc") == "");
    h->frame(2);
    EditorDocument& fresh = h->app->state().doc;
    REQUIRE_FALSE(h->app->dirty());
    openKickModelAnswering(*h, key::kEnter);
    CHECK_FALSE(h->app->askingAboutUnsavedChanges());
    REQUIRE(fresh.hasModel());
    CHECK(fresh.clip().name == "10_03");
    CHECK(fresh.frameCount() == fresh.model()->model->clip.frameCount());
}

TEST_CASE("gui: the Enter that opens a model in the file dialog does not also answer the question") {
    auto h = test::makeHarness(false, false);
    if (!h) return;
    REQUIRE(h->app->runAction({"open-model"}) == "");  // no PATH: the Open dialog
    h->frame(2);
    REQUIRE(h->app->fileDialog().isOpen());
    const std::string path = kickModelPath();
    h->input.chars.assign(path.begin(), path.end());
    h->frame(2);
    REQUIRE(std::string(h->app->fileDialog().typedPath()) == path);
    tapKey(*h, key::kEnter);
    h->frame(3);
    CHECK_FALSE(h->app->fileDialog().isOpen());
    REQUIRE(h->app->askingAboutModelClip());  // still asking: that Enter was the dialog's
    CHECK(h->app->state().doc.clip().name == "35_01");
    CHECK_FALSE(h->app->state().doc.hasModel());
    tapKey(*h, key::kEscape);
    h->frame(2);
    CHECK_FALSE(h->app->askingAboutModelClip());
    CHECK(h->app->state().doc.clip().name == "35_01");
}

TEST_CASE("gui: a model of the open clip opens without a question") {
    auto h = test::makeHarness(false, false);
    if (!h) return;
    REQUIRE(h->app->runAction({"open-model", test::fixtureModelPath()}) == "");
    CHECK(h->app->state().doc.hasModel());
    h->frame(2);
    CHECK_FALSE(h->app->askingAboutModelClip());
    CHECK(h->app->state().doc.clip().name == "35_01");
}

TEST_CASE("gui: a file dialog opens in the folder of the last file a dialog gave") {
    auto h = test::makeHarness(false, false);
    if (!h) return;
    REQUIRE(h->app->runAction({"open-model"}) == "");
    h->frame(2);
    REQUIRE(h->app->fileDialog().isOpen());
    const std::string path = test::fixtureModelPath();
    h->input.chars.assign(path.begin(), path.end());
    h->frame(2);
    tapKey(*h, key::kEnter);
    h->frame(3);
    REQUIRE(h->app->state().doc.hasModel());
    // Another dialog, another purpose: it starts where that model was, not in the data folder.
    REQUIRE(h->app->runAction({"open"}) == "");
    h->frame(2);
    REQUIRE(h->app->fileDialog().isOpen());
    CHECK(std::filesystem::equivalent(h->app->fileDialog().folder(), std::filesystem::path(path).parent_path()));
    tapKey(*h, key::kEscape);
}
