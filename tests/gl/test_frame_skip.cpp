// A UI frame that would draw the pixels of the previous one is not rasterised again
// (ui/shell/frame_signature.h): the signature sees every part of the draw data, the images it shows by
// reference, and nothing else; the editor skips exactly the frames whose signature repeats, and
// the window still shows the same picture.
#include <doctest/doctest.h>
#include <imgui.h>

#include "editor_harness.h"
#include "render/png_capture.h"
#include "ui/shell/frame_signature.h"

using namespace mgp;

namespace {

// One draw list with a quad's worth of vertices and indices and one draw command.
struct OneList {
    ImDrawList list{nullptr};
    ImDrawList* lists[1] = {&list};
    ImDrawData data;

    OneList() {
        for (int i = 0; i < 4; ++i)
            list.VtxBuffer.push_back(ImDrawVert{ImVec2(float(i), 2.0f * float(i)), ImVec2(0.5f, 0.5f), 0xff336699u});
        for (ImDrawIdx i : {0, 1, 2, 0, 2, 3}) list.IdxBuffer.push_back(i);
        ImDrawCmd cmd;
        cmd.ClipRect = ImVec4(0, 0, 100, 50);
        cmd.TextureId = reinterpret_cast<ImTextureID>(std::uintptr_t(7));
        cmd.ElemCount = 6;
        list.CmdBuffer.push_back(cmd);
        data.Valid = true;
        data.CmdLists = lists;
        data.CmdListsCount = 1;
        data.DisplaySize = ImVec2(100, 50);
        data.FramebufferScale = ImVec2(1, 1);
    }
    std::uint64_t signature(std::int64_t imageVersion = 0) const { return ui::frameSignature(data, {imageVersion}); }
};

}  // namespace

TEST_CASE(
    "frame signature: equal draw data match, and a vertex, an index, a clip rectangle, a texture or an image version "
    "differ") {
    const OneList a, b;
    CHECK(a.signature() == b.signature());
    const std::uint64_t base = a.signature();
    {
        OneList c;
        c.list.VtxBuffer[2].col = 0xff336698u;  // one colour bit
        CHECK(c.signature() != base);
    }
    {
        OneList c;
        c.list.VtxBuffer[3].pos.y += 1.0f;
        CHECK(c.signature() != base);
    }
    {
        OneList c;
        c.list.IdxBuffer[5] = 1;
        CHECK(c.signature() != base);
    }
    {
        OneList c;
        c.list.CmdBuffer[0].ClipRect.z = 99.0f;
        CHECK(c.signature() != base);
    }
    {
        OneList c;
        c.list.CmdBuffer[0].TextureId = reinterpret_cast<ImTextureID>(std::uintptr_t(8));
        CHECK(c.signature() != base);
    }
    {
        OneList c;
        c.list.CmdBuffer[0].ElemCount = 3;
        CHECK(c.signature() != base);
    }
    {
        OneList c;
        c.data.DisplaySize.x = 101.0f;
        CHECK(c.signature() != base);
    }
    CHECK(a.signature(1) != base);  // the same vertices over a new picture in a texture
    {
        OneList c;
        c.data.CmdListsCount = 0;  // nothing drawn is not the same as the quad
        CHECK(c.signature() != base);
    }
}

TEST_CASE("gui frames: a frame that repeats the last one is not drawn, the picture stays, and any change draws again") {
    auto h = mgp::test::makeHarness(false);
    if (!h) return;
    h->frame(30);  // settle: the model's latent map arrives, hover states settle
    h->app->waitIdle();
    h->frame(5);
    // Nothing moves: the next frames repeat the last one.
    h->frame();
    CHECK_FALSE(h->app->frameDrawn());
    const render::Image still = h->app->capture(mgp::test::kGuiWidth, mgp::test::kGuiHeight);
    h->app->requestRedraw();
    h->frame();
    CHECK(h->app->frameDrawn());
    const render::Image redrawn = h->app->capture(mgp::test::kGuiWidth, mgp::test::kGuiHeight);
    CHECK(still.rgba == redrawn.rgba);  // the skipped frames left exactly the picture a draw makes
    h->frame();
    CHECK_FALSE(h->app->frameDrawn());
    // A new frame of the clip: the viewport, the timeline and the latent map's dot move.
    const int before = h->app->state().doc.frame();
    h->app->runAction({"frame", std::to_string(before + 10)});
    h->frame();
    CHECK(h->app->frameDrawn());
    const render::Image moved = h->app->capture(mgp::test::kGuiWidth, mgp::test::kGuiHeight);
    CHECK(moved.rgba != still.rgba);
    // The mouse over the menu bar: ImGui's hover highlight alone is a change.
    h->frame(3);
    h->input.mouseX = 20.0f;
    h->input.mouseY = 8.0f;
    h->frame();
    CHECK(h->app->frameDrawn());
}
