// The action table (ui/actions/editor_actions.h) against what it drives: docs/guide.md's table, the
// script parser, strict arguments, shortcuts, menus' enabled state and panel requests.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "editor_harness.h"
#include "io/parse_error.h"
#include "test_paths.h"
#include "ui/actions/editor_actions.h"

using namespace mgp;
using test::tapKey;

namespace {
std::string guideSection() {
    std::ifstream f(std::string(MOTIONGP_GOLDEN_DIR) + "/../../docs/guide.md");
    std::stringstream ss;
    ss << f.rdbuf();
    const std::string text = ss.str();
    const std::string begin = "<!-- action-table:begin -->\n", end = "<!-- action-table:end -->";
    const auto b = text.find(begin), e = text.find(end);
    if (b == std::string::npos || e == std::string::npos || e < b) return "(no action-table markers in docs/guide.md)";
    return text.substr(b + begin.size(), e - b - begin.size());
}

}  // namespace

TEST_CASE("gui actions: the guide's action table is the one the editor runs") {
    const std::string expected = ui::ActionTable::editor().markdownTable();
    const std::string found = guideSection();
    if (found != expected) {
        std::filesystem::create_directories(MOTIONGP_GL_OUT_DIR);
        const std::string out = std::string(MOTIONGP_GL_OUT_DIR) + "/guide_action_table.md";
        std::ofstream(out) << expected;
        FAIL("docs/guide.md's action table differs from ui/actions/editor_actions.cpp; the generated table is in "
             << out);
    }
}

TEST_CASE("gui actions: names are unique, every action has a summary, chords have a shortcut text") {
    std::set<std::string> names;
    for (const ui::EditorAction& a : ui::ActionTable::editor().actions()) {
        INFO(a.name);
        CHECK(names.insert(a.name).second);
        CHECK(!a.summary.empty());
        CHECK(a.run);
        if (!a.chords.empty()) CHECK(!a.shortcut.empty());
    }
    CHECK(ui::ActionTable::editor().find("undo") != nullptr);
    CHECK(ui::ActionTable::editor().find("explode") == nullptr);
}

TEST_CASE("gui actions: scripts parse action names from the table and refuse missing arguments") {
    CHECK_NOTHROW(ui::GuiScript::parse("1 action regenerate\n2 action demo-clip\n3 action frame 4\n"));
    CHECK_THROWS_WITH_AS(ui::GuiScript::parse("1 action frame\n", "s.txt"),
                         "s.txt:1: expected an argument after 'frame', found none", ParseError);
    CHECK_THROWS_AS(ui::GuiScript::parse("1 action explode\n"), ParseError);
    CHECK_THROWS_AS(ui::GuiScript::parse("1.5 move 1 2\n"), ParseError);
    CHECK_THROWS_AS(ui::GuiScript::parse("1 move 12abc 5\n"), ParseError);
    CHECK_THROWS_AS(ui::GuiScript::parse("1 hover key:2x\n"), ParseError);
    CHECK_NOTHROW(ui::GuiScript::parse("1 hover dot:10_02:41\n2 action model-clip 10_02 41\n"));
    CHECK_THROWS_AS(ui::GuiScript::parse("1 hover dot:10_02\n"), ParseError);
    CHECK_THROWS_AS(ui::GuiScript::parse("1 hover dot::4\n"), ParseError);
    CHECK_THROWS_AS(ui::GuiScript::parse("1 hover dot:10_02:0\n"), ParseError);
    CHECK_THROWS_AS(ui::GuiScript::parse("1 key F1x\n"), ParseError);
}

TEST_CASE("gui actions: numeric arguments are parsed strictly, with a clear message") {
    auto h = test::makeHarness(false, false);
    if (!h) return;
    EditorDocument& doc = h->app->state().doc;
    doc.setFrame(5);
    CHECK(h->app->runAction({"frame", "12abc"}) == "expected a frame number N (an integer), found '12abc'");
    CHECK(doc.frame() == 5);
    CHECK(h->app->runAction({"frame", "12"}) == "");
    CHECK(doc.frame() == 11);
    CHECK(h->app->runAction({"train", "fas", "30x"}) == "expected the active set size M (an integer), found '30x'");
    CHECK(h->app->runAction({"train", "gp"}) == "expected fas or sgplvm, found 'gp'");
    CHECK(!h->app->state().training.running());
    CHECK(h->app->runAction({"regenerate", "1e3"}) == "expected the iteration count (an integer), found '1e3'");
    CHECK(h->app->runAction({"path-offset", "1", "2", "x", "4"}) ==
          "expected an offset in cm (a finite number), found 'x'");
    CHECK(h->app->runAction({"compare", "ghost"}) == "expected none, plain or model, found 'ghost'");
    CHECK(h->app->runAction({"compare", "plain"}) == "");
    CHECK(doc.compareMode() == CompareMode::kPlainIk);
    CHECK(h->app->runAction({"explode"}) == "unknown action 'explode'");

    // The script player puts the line before the action's message.
    const auto errors = h->play(ui::GuiScript::parse("1 action frame 7\n2 action regenerate 5q\n"));
    REQUIRE(errors.size() == 1);
    CHECK(errors[0] == "line 2: expected the iteration count (an integer), found '5q'");
    CHECK(doc.frame() == 6);
}

TEST_CASE("gui actions: shortcuts run the table's actions, and respect its enabled predicates") {
    auto h = test::makeHarness(false, false);
    if (!h) return;
    EditorDocument& doc = h->app->state().doc;
    doc.setFrame(10);
    tapKey(*h, ui::key::kRight, {ui::key::kLeftShift});
    CHECK(doc.frame() == 20);
    tapKey(*h, ui::key::kLeft, {ui::key::kLeftShift});
    CHECK(doc.frame() == 10);
    tapKey(*h, ui::key::kEnd);
    CHECK(doc.frame() == doc.frameCount() - 1);
    // Ctrl+R with no path edit is disabled: nothing happens, nothing is said.
    const long posts = h->app->state().messages.postCount();
    tapKey(*h, 'R', {ui::key::kLeftCtrl});
    CHECK(h->app->state().messages.postCount() == posts);
    // Ctrl+Z is run while disabled so that the user hears why.
    tapKey(*h, 'Z', {ui::key::kLeftCtrl});
    REQUIRE(h->app->state().messages.current() != nullptr);
    CHECK(h->app->state().messages.current()->text == "nothing to undo");
    CHECK(!ui::ActionTable::editor().enabled("undo", *h->app));
}

TEST_CASE("gui actions: a panel's request runs its action once, in the same frame") {
    auto h = test::makeHarness(false, false);
    if (!h) return;
    ui::EditorState& s = h->app->state();
    s.doc.setFrame(3);
    s.request("next-frame");
    s.request("next-frame");
    h->frame(1);
    CHECK(s.doc.frame() == 5);
    CHECK(s.requests.empty());
    h->frame(1);
    CHECK(s.doc.frame() == 5);
}
