#include "editor_harness.h"

#include <doctest/doctest.h>

#include <filesystem>
#include <vector>

#include "skip.h"
#include "test_paths.h"
#include "ui/input/script_player.h"

namespace mgp::test {

namespace fs = std::filesystem;

const std::string& mocapDir() {
    static const std::string dir = MOTIONGP_TEST_MOCAP;
    return dir;
}

std::string fixtureModelPath() { return std::string(MOTIONGP_TEST_FIXTURES) + "/walk35_fas_m100_t3.model"; }

void Harness::frame(int n) {
    for (int i = 0; i < n; ++i, ++frameNo) app->frame(input, 1.0 / 60.0, kGuiWidth, kGuiHeight);
}

std::vector<std::string> Harness::play(const ui::GuiScript& script) {
    ui::ScriptPlayer player(script);
    std::vector<std::string> shots;
    for (int i = 0; i <= script.lastFrame() + 2; ++i) {
        player.apply(i, input, *app, shots);
        frame();
    }
    return player.errors();
}

void Harness::restartApp(ui::EditorOptions options, bool editorFont) {
    app.reset();
    input = ui::InputState{};
    options.builtinFont = !editorFont;
    app = std::make_unique<ui::EditorApp>(options);
}

std::unique_ptr<Harness> makeHarness(bool llvmpipeOnly, bool withModel) {
    auto h = std::make_unique<Harness>();
    try {
        h->ctx = std::make_unique<render::OffscreenContext>(kGuiWidth, kGuiHeight);
    } catch (const render::RenderError& e) {
        MGP_MARK_SKIPPED("no offscreen GL context: " << e.what());
        return nullptr;
    }
    if (llvmpipeOnly && !render::currentGlInfo().isLlvmpipe()) {
        MGP_MARK_SKIPPED("goldens are made with Mesa llvmpipe");
        return nullptr;
    }
    h->restartApp();
    REQUIRE(h->app->openClip(mocapDir() + "/asf_amc/35_01.amc") == "");
    h->frame(2);
    if (withModel) {
        REQUIRE(h->app->runAction({"open-model", fixtureModelPath()}) == "");
        h->app->waitIdle();
        REQUIRE(h->app->state().doc.hasModel());
        h->frame(2);
        h->app->waitIdle();
        h->frame(2);
    }
    return h;
}

void tapKey(Harness& h, int k, std::initializer_list<int> mods) {
    for (int m : mods) h.input.setKey(m, true);
    h.input.setKey(k, true);
    h.input.setKey(k, false);
    for (int m : mods) h.input.setKey(m, false);
    h.frame(3);
}

void answerUnsaved(Harness& h, const std::string& button) {
    h.frame(2);  // the modal is drawn and its buttons recorded
    REQUIRE(h.app->askingAboutUnsavedChanges());
    const auto& b = h.app->state().controls.at("unsaved: " + button);
    clickAt(h, (b.x0 + b.x1) / 2, (b.y0 + b.y1) / 2);
}

void clickAt(Harness& h, float x, float y) {
    ui::GuiScript script;
    script.add(0, "move", {std::to_string(x), std::to_string(y)});
    script.add(2, "down", {"left"});
    script.add(4, "up", {"left"});
    ui::ScriptPlayer player(script);
    std::vector<std::string> shots;
    for (int i = 0; i <= 6; ++i) {
        player.apply(i, h.input, *h.app, shots);
        h.frame();
    }
}

}  // namespace mgp::test
