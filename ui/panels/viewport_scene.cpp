// ViewportPanel::buildScene: what the 3-D view shows on this frame, as a plain render::Scene (the
// figure with its range tint, handles, ghosts, paths, the drag target, pins and planted feet).
#include "ui/panels/viewport_panel.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include "motion/inbetween.h"
#include "render/range_tint.h"
#include "render/scene_builder.h"
#include "skeleton/fk_memo.h"
#include "skeleton/forward_kinematics.h"

namespace mgp::ui {

namespace {

// The captured frame nearest to the last learned solve (SolveReadout::nearest), with the current
// pose's root position and rotation, so that only the body's shape is compared.
std::optional<Pose> nearestGhostPose(const EditorState& s) {
    const SolveReadout& r = s.doc.readout();
    if (!r.valid || r.nearest.row < 0 || r.nearest.row >= s.doc.frameCount()) return std::nullopt;
    Pose pose = s.doc.clip().frames[r.nearest.row];
    const Pose& current = s.doc.currentPose();
    pose.rootCm = current.rootCm;
    if (!pose.anglesDeg.empty() && !current.anglesDeg.empty()) pose.anglesDeg[0] = current.anglesDeg[0];
    return pose;
}

// Onion skins and motion trails over the edited motion (a trail of the captured motion beneath).
// Everything but the trails' pieces at the current frame is a still overlay (Path::stillOverlay):
// a drag there redraws none of it. `memo` keeps each frame's FK between UI frames.
void addMotionOverlays(const EditorState& s, render::Scene& scene, FkMemo& memo) {
    const EditorDocument& doc = s.doc;
    const Skeleton& skeleton = doc.clip().skeleton;
    if (s.showOnionSkin)
        for (const render::OnionGhostFrame& g : render::onionFrames(s.onionSkin, doc.frame(), doc.frameCount()))
            scene.figures.push_back(render::onionGhost(skeleton, doc.poseAt(g.frame), g.step, s.onionSkin));
    // Slots: 2f for the edited frame f, 2f + 1 for the captured one.
    const auto edited = [&](int f) -> const FkState& {
        return memo.of(skeleton, f == doc.frame() ? doc.currentPose() : doc.poseAt(f), 2L * f);
    };
    const auto captured = [&](int f) -> const FkState& { return memo.of(skeleton, doc.clip().frames[f], 2L * f + 1); };
    const int half = std::clamp(s.trailHalfSpan, 1, doc.frameCount());  // no overflow for any typed value
    const int first = doc.frame() - half, last = doc.frame() + half;
    for (int i = 0; i < render::kTrailPartCount; ++i) {
        if (!s.trails[i]) continue;
        const auto part = static_cast<render::TrailPart>(i);
        const render::Path editedTrail =
            render::motionTrailFromFk(skeleton, edited, doc.frameCount(), part, first, last, doc.frame(), false);
        // The captured trail only where the edit moved the point: elsewhere the edited trail
        // covers it exactly, and llvmpipe pays for every segment drawn.
        if (s.showCapturedTrails) {
            const render::Path capturedTrail =
                render::motionTrailFromFk(skeleton, captured, doc.frameCount(), part, first, last, doc.frame(), true);
            for (render::Path& moved : render::differingParts(capturedTrail, editedTrail, 0.05f)) {
                moved.stillOverlay = true;  // captured points: they only come and go with an edit
                scene.paths.push_back(std::move(moved));
            }
        }
        for (render::Path& piece : render::splitForPosing(editedTrail)) scene.paths.push_back(std::move(piece));
    }
}

}  // namespace

std::optional<Pose> beforeGhostPose(const EditorState& s) {
    if (std::optional<Pose> before = s.doc.beforeGhost()) return before;
    // No undo step for this frame (e.g. a reopened session, whose history is not saved): an
    // edited frame's "before" is its captured pose.
    if (s.doc.hasClip() && s.doc.isEdited(s.doc.frame())) return s.doc.capturedPose();
    return std::nullopt;
}

std::optional<render::Path> editedPath(const EditorState& s) {
    const auto& path = s.doc.paths().edit();
    if (!path) return std::nullopt;
    render::Path p;
    for (const Eigen::Vector3d& v : s.doc.paths().targets()) p.pointsCm.push_back(toGlm(v));
    const int keys = static_cast<int>(path->keyFrames.size());
    for (int k = 0; k < keys; ++k) p.keysCm.push_back(toGlm(s.doc.paths().keyPosition(k)));
    p.colour = {0.20f, 0.55f, 0.95f};
    p.radiusCm = 0.7f;
    const int first = path->keyFrames.front(), last = path->keyFrames.back();
    if (s.doc.frame() >= first && s.doc.frame() <= last) p.currentPoint = s.doc.frame() - first;
    // Keys at least kMinKeyRadiusPx in radius on screen (12 px across), measured at the farthest
    // key from the camera, so that each can be grabbed at any zoom.
    if (s.viewportHeight > 0 && !p.keysCm.empty()) {
        constexpr float kMinKeyRadiusPx = 6.0f;
        float cmPerPixel = 0.0f;
        for (const glm::vec3& k : p.keysCm) cmPerPixel = std::max(cmPerPixel, s.camera.cmPerPixel(k, s.viewportHeight));
        p.minKeyRadiusCm = kMinKeyRadiusPx * cmPerPixel;
    }
    p.hoveredKey = s.hoveredKey < keys ? s.hoveredKey : -1;
    p.selectedKey = s.selectedKey < keys ? s.selectedKey : -1;
    return p;
}

render::RotateGizmo viewportGizmo(const EditorState& s) {
    const EditorDocument& doc = s.doc;
    if (s.gizmoJoint < 0 || !doc.hasClip() || s.gizmoJoint >= doc.clip().skeleton.jointCount() || s.viewportHeight <= 0)
        return {};
    const Pose& pose = s.posePreview ? *s.posePreview : doc.currentPose();
    FkState fk;
    forwardKinematics(doc.clip().skeleton, pose, fk);
    // Rings of the same size on screen at any zoom: kGizmoRadiusPx at the joint's distance.
    const float cmPerPixel = s.camera.cmPerPixel(toGlm(fk.jointCm[s.gizmoJoint]), s.viewportHeight);
    const glm::vec3 eye = s.camera.eye();
    return render::rotateGizmo(doc.clip().skeleton, pose, fk, s.gizmoJoint, kGizmoRadiusPx * cmPerPixel, &eye);
}

render::Scene ViewportPanel::buildScene(const EditorState& s) const {
    const EditorDocument& doc = s.doc;
    // Built here rather than with render::buildClipScene, which recomputes the clip's floor
    // height (FK over every frame) on each call; the floor is cached per clip.
    if (groundClip_ != doc.clip().name + "#" + std::to_string(doc.frameCount())) {
        groundClip_ = doc.clip().name + "#" + std::to_string(doc.frameCount());
        groundHeight_ = render::clipGroundHeight(doc.clip());
        overlayFk_.forget();
    }
    render::Scene scene;
    FkState fk;
    // A rotate-joint gesture shows its preview (EditorState::posePreview), untinted.
    forwardKinematics(doc.clip().skeleton, s.posePreview ? *s.posePreview : doc.currentPose(), fk);
    scene.figures.push_back(render::makeFigure(doc.clip().skeleton, fk));
    if (s.showRangeTint && !s.posePreview)
        if (const std::optional<ShownVerdict> v = doc.shownPoseVerdict())
            render::applyRangeTint(scene.figures.back(), render::rangeTint(v->shown()));
    scene.groundHeightCm = groundHeight_;
    scene.groundCentreCm = toGlm(fk.jointCm[0]);
    scene.handles = render::effectorHandles(doc.clip().skeleton, fk);
    for (render::Handle& h : scene.handles) {
        if (h.id == s.hoveredHandle) h.state = render::HandleState::kHover;
        if (doc.dragging() && h.id == static_cast<int>(doc.dragEffector())) h.state = render::HandleState::kSelected;
    }
    auto addGhost = [&](const Pose& pose, std::optional<glm::vec3> tint) {
        FkState ghostFk;
        forwardKinematics(doc.clip().skeleton, pose, ghostFk);
        render::Figure ghost = render::makeFigure(doc.clip().skeleton, ghostFk);
        ghost.ghost = true;
        if (tint) ghost.ghostTint = *tint;
        ghost.castsShadow = false;
        scene.figures.push_back(std::move(ghost));
    };
    if (doc.comparePose()) addGhost(*doc.comparePose(), std::nullopt);
    // Violet: distinct from the blue compare ghost and from the warm right-side bones.
    if (s.showBeforeGhost)
        if (const std::optional<Pose> before = beforeGhostPose(s)) addGhost(*before, glm::vec3(0.78f, 0.38f, 1.0f));
    // Green: the captured frame nearest to the last solve, laid over the current pose's root.
    if (s.showNearestGhost)
        if (const std::optional<Pose> nearest = nearestGhostPose(s)) addGhost(*nearest, glm::vec3(0.3f, 0.9f, 0.5f));
    // Yellow, as the keys on the timeline: what plain interpolation of the keys around the playhead
    // (root linear, joints slerped) would show here, to compare with Fill between keys.
    if (s.showInterpolationGhost)
        if (const std::optional<InbetweenGap> gap = doc.keyGapAt(doc.frame()); gap && doc.frame() > gap->a)
            addGhost(interpolatedPose(doc.clip().skeleton, doc.poseAt(gap->a), doc.poseAt(gap->b),
                                      double(doc.frame() - gap->a) / double(gap->b - gap->a)),
                     glm::vec3(0.95f, 0.8f, 0.25f));
    addMotionOverlays(s, scene, overlayFk_);
    if (doc.paths().edit() && s.showCapturedPath) {
        // Fainter and thinner than the edited path, which covers it where the two agree.
        render::Path captured;
        for (const Eigen::Vector3d& v : doc.paths().captured()) captured.pointsCm.push_back(toGlm(v));
        captured.colour = {0.62f, 0.64f, 0.70f};
        captured.radiusCm = 0.35f;
        scene.paths.push_back(std::move(captured));
    }
    if (auto p = editedPath(s)) scene.paths.push_back(std::move(*p));
    if (doc.dragging()) {
        render::Target t;
        t.positionCm = toGlm(doc.dragTarget());
        t.hasFrom = true;
        t.fromCm = toGlm(doc.effectorPosition(doc.dragEffector()));
        t.reached = doc.readout().valid && doc.readout().reached;
        scene.targets.push_back(t);
    }
    if (s.gizmoJoint >= 0) render::addRotateGizmo(scene, viewportGizmo(s), s.gizmoRing);
    for (Effector e : doc.pinnedEffectors()) scene.pins.push_back({toGlm(doc.effectorPosition(e))});
    // Held where an earlier edit placed it (not while that effector is being dragged again).
    const std::vector<Effector> held = doc.heldEffectors();
    for (Effector e : held)
        if (doc.hasEffector(e) && !(doc.dragging() && doc.dragEffector() == e))
            scene.heldMarks.push_back({toGlm(doc.effectorPosition(e))});
    // Feet planted on this frame that a drag or Regenerate holds (not switched off, not released).
    // A foot an edit placed (lifted off its footprint, say) shows its held mark instead.
    for (Effector foot : {Effector::kLFoot, Effector::kRFoot})
        if (doc.hasEffector(foot) && doc.inContact(foot) && !doc.contactReleased(foot) &&
            std::find(held.begin(), held.end(), foot) == held.end())
            scene.footprints.push_back({toGlm(doc.effectorPosition(foot))});
    return scene;
}

}  // namespace mgp::ui
