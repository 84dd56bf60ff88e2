// View > Onion skins and View > Motion trails, driven through the editor offscreen with the
// committed walk model: the viewport's scene (plain data) holds the right ghosts and trails, the
// edited trail follows a drag while the captured one stays, and a session brings the settings back.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "editor_harness.h"
#include "skeleton/forward_kinematics.h"
#include "ui/input/gui_script.h"
#include "ui/shell/editor_app.h"
#include "ui/shell/editor_session.h"

using namespace mgp;
using test::makeHarness;

namespace {

int ghostCount(const render::Scene& scene) {
    int n = 0;
    for (const render::Figure& f : scene.figures) n += f.ghost;
    return n;
}

double overlayDistanceCm(const glm::vec3& a, const glm::vec3& b) { return static_cast<double>(glm::length(a - b)); }

// The scene's paths of the captured motion (unticked) and the edited trail's pieces (ticked).
std::vector<render::Path> trailPaths(const render::Scene& scene, bool edited) {
    std::vector<render::Path> out;
    for (const render::Path& p : scene.paths)
        if ((p.tickRadiusCm > 0.0f) == edited) out.push_back(p);
    return out;
}

// The edited trail as one polyline. The viewport cuts it at the current frame (the stretches
// before and after it are still overlays, render::splitForPosing), into pieces that share their
// end points; the live piece carries the current mark. `pieces` is how many there were.
render::Path joinedTrail(const render::Scene& scene, int& pieces) {
    const std::vector<render::Path> parts = trailPaths(scene, true);
    pieces = static_cast<int>(parts.size());
    render::Path joined;
    for (const render::Path& part : parts) {
        const bool sharesStart = !joined.pointsCm.empty() && !part.pointsCm.empty() &&
                                 overlayDistanceCm(joined.pointsCm.back(), part.pointsCm.front()) == 0.0;
        const int offset = static_cast<int>(joined.pointsCm.size()) - (sharesStart ? 1 : 0);
        if (part.currentPoint >= 0) joined.currentPoint = offset + part.currentPoint;
        joined.tickRadiusCm = part.tickRadiusCm;
        joined.pointsCm.insert(joined.pointsCm.end(), part.pointsCm.begin() + (sharesStart ? 1 : 0),
                               part.pointsCm.end());
    }
    return joined;
}

}  // namespace

TEST_CASE("gui overlays: onion skins show the frames around the current one, trails the edited and captured motion") {
    auto h = makeHarness(false);
    if (!h) return;
    ui::EditorState& s = h->app->state();
    EditorDocument& doc = s.doc;
    doc.setDragFalloff(10);
    doc.setFrame(60);
    h->frame(2);
    CHECK(ghostCount(h->app->viewport().lastScene()) == 0);  // off by default

    s.showOnionSkin = true;
    s.onionSkin = {2, 2, 5};
    h->frame(1);
    const render::Scene& onion = h->app->viewport().lastScene();
    REQUIRE(ghostCount(onion) == 4);
    // Drawn farthest first: frames 50, 55, 70, 65; the ghost of frame 55 is that frame's pose.
    FkState fk;
    forwardKinematics(doc.clip().skeleton, doc.poseAt(55), fk);
    const render::Figure pose55 = render::makeFigure(doc.clip().skeleton, fk);
    const render::Figure& ghost55 = onion.figures[2];
    REQUIRE(ghost55.ghost);
    REQUIRE(ghost55.bones.size() == pose55.bones.size());
    for (std::size_t b = 0; b < pose55.bones.size(); ++b)
        CHECK(overlayDistanceCm(ghost55.bones[b].endCm, pose55.bones[b].endCm) < 1e-3);
    CHECK(ghost55.ghostAlpha > onion.figures[1].ghostAlpha);  // nearer than frame 50's

    doc.setFrame(2);  // near the start only the ghosts after it
    h->frame(1);
    CHECK(ghostCount(h->app->viewport().lastScene()) == 2);
    s.onionSkin = {3, 1, 10};
    doc.setFrame(60);
    h->frame(1);
    CHECK(ghostCount(h->app->viewport().lastScene()) == 4);
    s.showOnionSkin = false;

    s.trails[static_cast<int>(render::TrailPart::kRHand)] = true;
    s.trailHalfSpan = 20;
    h->frame(1);
    {
        // Nothing edited: the captured trail would lie exactly under the edited one, so only that is
        // drawn, cut at the current frame: still before, live around it, still after.
        const render::Scene& scene = h->app->viewport().lastScene();
        CHECK(trailPaths(scene, false).empty());
        int pieces = 0;
        const render::Path edited = joinedTrail(scene, pieces);
        CHECK(pieces == 3);
        const std::vector<render::Path> parts = trailPaths(scene, true);
        REQUIRE(parts.size() == 3);
        CHECK(parts[0].stillOverlay);
        CHECK_FALSE(parts[1].stillOverlay);
        CHECK(parts[1].pointsCm.size() == 3);
        CHECK(parts[2].stillOverlay);
        REQUIRE(edited.pointsCm.size() == 41);
        CHECK(edited.currentPoint == 20);
        CHECK(edited.tickRadiusCm > 0.0f);
        for (int i = 0; i < 41; ++i) {
            const glm::vec3 captured =
                render::toGlm(effectorCm(doc.clip().skeleton, doc.clip().frames[40 + i], Effector::kRHand));
            CHECK(overlayDistanceCm(edited.pointsCm[static_cast<std::size_t>(i)], captured) < 1e-3);
        }
    }

    // Drag the right hand up on frame 60: its edited trail moves there and on the spread's
    // frames; the captured trail stays where the capture is.
    std::string script = "0 hover rhand\n2 down left\n";
    for (int k = 0; k < 8; ++k) script += std::to_string(4 + 2 * k) + " moveby 0 -6\n";
    script += "22 up left\n";
    REQUIRE(h->play(ui::GuiScript::parse(script)).empty());
    h->app->waitIdle();
    h->frame(2);
    REQUIRE(doc.isEdited(60));
    const render::Scene& after = h->app->viewport().lastScene();
    // The captured trail beneath where the edit moved the hand (one stretch, a still overlay), then
    // the edited trail.
    const std::vector<render::Path> capturedParts = trailPaths(after, false);
    REQUIRE(capturedParts.size() == 1);
    const render::Path& capturedPart = capturedParts[0];
    CHECK(capturedPart.stillOverlay);
    int pieces = 0;
    const render::Path edited = joinedTrail(after, pieces);
    CHECK(pieces == 3);
    REQUIRE(edited.pointsCm.size() == 41);
    auto capturedHand = [&](int f) {
        return render::toGlm(effectorCm(doc.clip().skeleton, doc.clip().frames[f], Effector::kRHand));
    };
    bool holdsFrame60 = false;
    for (const glm::vec3& p : capturedPart.pointsCm)
        holdsFrame60 = holdsFrame60 || overlayDistanceCm(p, capturedHand(60)) < 1e-3;
    CHECK(holdsFrame60);
    CHECK(capturedPart.pointsCm.size() < 41);  // frames 40.. outside the falloff agree and are left out
    const double moved = overlayDistanceCm(edited.pointsCm[20], capturedHand(60));
    INFO("the hand moved " << moved << " cm on frame 60");
    CHECK(moved > 5.0);
    CHECK(overlayDistanceCm(edited.pointsCm[25], capturedHand(65)) > 0.5);  // the spread, 5 frames on
    CHECK(overlayDistanceCm(edited.pointsCm[0], capturedHand(40)) < 1e-3);  // outside the falloff

    // Without the captured reference only the edited trail is drawn.
    s.showCapturedTrails = false;
    h->frame(1);
    CHECK(trailPaths(h->app->viewport().lastScene(), false).empty());
    CHECK(trailPaths(h->app->viewport().lastScene(), true).size() == 3);
}

TEST_CASE("gui overlays: a session keeps the onion skin and trail settings") {
    auto h = makeHarness(false, false);
    if (!h) return;
    ui::EditorState& s = h->app->state();
    s.showOnionSkin = true;
    s.onionSkin = {3, 1, 7};
    s.trails[static_cast<int>(render::TrailPart::kLFoot)] = true;
    s.trails[static_cast<int>(render::TrailPart::kRoot)] = true;
    s.trailHalfSpan = 45;
    s.showCapturedTrails = false;
    const SessionData saved = ui::editorSession(s);

    s.showOnionSkin = false;
    s.onionSkin = {};
    for (bool& on : s.trails) on = false;
    s.trailHalfSpan = 30;
    s.showCapturedTrails = true;
    ui::applyEditorSession(s, saved);
    CHECK(s.showOnionSkin);
    CHECK(s.onionSkin.before == 3);
    CHECK(s.onionSkin.after == 1);
    CHECK(s.onionSkin.spacing == 7);
    for (int i = 0; i < render::kTrailPartCount; ++i) {
        CAPTURE(i);
        CHECK(s.trails[i] ==
              (i == static_cast<int>(render::TrailPart::kLFoot) || i == static_cast<int>(render::TrailPart::kRoot)));
    }
    CHECK(s.trailHalfSpan == 45);
    CHECK_FALSE(s.showCapturedTrails);

    // A session from before these settings (or with values out of range): off, clamped.
    SessionData old = saved;
    old.ui.erase("onion_skin");
    old.ui["trails"] = {{"parts", {"rhand", "tail"}}, {"frames_each_side", 100000}};
    ui::applyEditorSession(s, old);
    CHECK_FALSE(s.showOnionSkin);
    CHECK(s.trails[static_cast<int>(render::TrailPart::kRHand)]);
    CHECK_FALSE(s.trails[static_cast<int>(render::TrailPart::kLFoot)]);
    CHECK(s.trailHalfSpan == 240);
    CHECK(s.showCapturedTrails);
}
