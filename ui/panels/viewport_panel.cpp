#include "ui/panels/viewport_panel.h"

#include <GL/gl.h>
#include <GL/glext.h>
#include <imgui.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <utility>

#include "edit/joint_rotation.h"
#include "motion/support_polygon.h"
#include "render/picking.h"
#include "render/range_tint.h"
#include "render/scene_builder.h"
#include "skeleton/centre_of_mass.h"
#include "skeleton/forward_kinematics.h"
#include "skeleton/rotation.h"
#include "ui/actions/shortcuts.h"
#include "ui/widgets/widgets.h"
#include "ui/windows/joint_rotation_window.h"

namespace mgp::ui {

namespace {
Eigen::Vector3d toEigen(const glm::vec3& v) { return {v.x, v.y, v.z}; }

// Ray-plane intersection; false if parallel or behind the eye.
bool intersectPlane(const render::Ray& ray, const glm::vec3& point, const glm::vec3& normal, glm::vec3& hit) {
    const float denom = glm::dot(ray.direction, normal);
    if (std::abs(denom) < 1e-6f) return false;
    const float t = glm::dot(point - ray.origin, normal) / denom;
    if (!(t > 0.0f) || !std::isfinite(t)) return false;
    hit = ray.origin + ray.direction * t;
    return true;
}

// The point under pixel (mx, my) on the drag plane through `anchor`: camera-facing, or
// horizontal (Shift). Shared by effector handle and path key drags.
bool dragPlanePoint(const render::OrbitCamera& camera, float mx, float my, int width, int height,
                    const Eigen::Vector3d& anchor, bool horizontal, Eigen::Vector3d& out) {
    const render::Ray ray = camera.rayFromPixel(mx, my, width, height);
    const glm::vec3 normal = horizontal ? glm::vec3(0, 1, 0) : glm::normalize(camera.eye() - camera.targetCm);
    glm::vec3 hit;
    if (!intersectPlane(ray, toGlm(anchor), normal, hit)) return false;
    out = toEigen(hit);
    return true;
}

// The point of the world axis line through `anchor` nearest the mouse ray (axis 0 X, 1 Y, 2 Z);
// false when the ray runs along the axis (no usable point).
bool dragAxisPoint(const render::OrbitCamera& camera, float mx, float my, int width, int height,
                   const Eigen::Vector3d& anchor, int axis, Eigen::Vector3d& out) {
    const render::Ray ray = camera.rayFromPixel(mx, my, width, height);
    const Eigen::Vector3d o = toEigen(ray.origin), d = toEigen(ray.direction).normalized();
    const Eigen::Vector3d a = Eigen::Vector3d::Unit(axis);
    const Eigen::Vector3d w = anchor - o;
    const double ad = a.dot(d), denom = 1.0 - ad * ad;
    if (denom < 1e-6) return false;
    const double t = (ad * d.dot(w) - a.dot(w)) / denom;  // along the axis from the anchor
    out = anchor + t * a;
    return out.allFinite();
}

const char* dragAxisLabel(int axis) {
    return axis == 0 ? "along X" : axis == 1 ? "along Y" : axis == 2 ? "along Z" : "free";
}

// Path keys as pickable spheres (id = key index), the size they are drawn, nearest in time to
// the current frame first: keys of a planted foot coincide, and picking takes the first of
// equally near hits, so scrubbing to a key's frame makes that key the one grabbed.
std::vector<render::Handle> keyHandles(const EditorState& s) {
    std::vector<render::Handle> out;
    if (const auto p = editedPath(s)) {
        for (std::size_t k = 0; k < p->keysCm.size(); ++k)
            out.push_back({static_cast<int>(k), p->keysCm[k], p->keyRadiusCm(), render::HandleState::kIdle});
        const std::vector<int>& frames = s.doc.paths().edit()->keyFrames;
        std::stable_sort(out.begin(), out.end(), [&](const render::Handle& a, const render::Handle& b) {
            return std::abs(frames[a.id] - s.doc.frame()) < std::abs(frames[b.id] - s.doc.frame());
        });
    }
    return out;
}
}  // namespace

bool viewportWindowPosition(const EditorState& s, const Eigen::Vector3d& pointCm, float& x, float& y) {
    const int w = s.viewportWidth, h = s.viewportHeight;
    if (w <= 0 || h <= 0) return false;
    glm::vec3 p;
    if (!s.camera.project(toGlm(pointCm), w, h, p)) return false;
    if (p.x < 0 || p.y < 0 || p.x >= w || p.y >= h) return false;
    x = s.viewportX + p.x;
    y = s.viewportY + p.y;
    return true;
}

bool pathKeyWindowPosition(const EditorState& s, int key, float& x, float& y) {
    const auto& path = s.doc.paths().edit();
    if (!path || key < 0 || key >= static_cast<int>(path->keyFrames.size())) return false;
    return viewportWindowPosition(s, s.doc.paths().keyPosition(key), x, y);
}

// The scene goes into fbo_ (RGBA8, DEPTH24_STENCIL8: the formats the backdrop layer copies into).
ViewportPanel::ViewportPanel() : renderer_(std::make_unique<render::SceneRenderer>(1)) {
    renderer_->useBackdropLayer(true);
}

ViewportPanel::~ViewportPanel() {
    if (fbo_) glDeleteFramebuffers(1, &fbo_);
    if (colour_) glDeleteTextures(1, &colour_);
    if (depth_) glDeleteRenderbuffers(1, &depth_);
}

void ViewportPanel::presentTo(int windowHeight) const {
    if (!fbo_ || presentW_ <= 0) return;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    const int y0 = windowHeight - presentY_ - presentH_;  // GL counts rows from the bottom
    glBlitFramebuffer(0, 0, rw_, rh_, presentX_, y0, presentX_ + presentW_, y0 + presentH_, GL_COLOR_BUFFER_BIT,
                      rw_ == presentW_ && rh_ == presentH_ ? GL_NEAREST : GL_LINEAR);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void ViewportPanel::ensureTarget(int w, int h) {
    if (w == width_ && h == height_ && fbo_) return;
    if (!fbo_) {
        glGenFramebuffers(1, &fbo_);
        glGenTextures(1, &colour_);
        glGenRenderbuffers(1, &depth_);
    }
    glBindTexture(GL_TEXTURE_2D, colour_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glBindRenderbuffer(GL_RENDERBUFFER, depth_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, w, h);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour_, 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depth_);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    width_ = w;
    height_ = h;
}

void ViewportPanel::frameCharacter(EditorState& s) const {
    if (!s.doc.hasClip()) return;
    FkState fk;
    forwardKinematics(s.doc.clip().skeleton, s.doc.currentPose(), fk);
    render::Scene scene;
    scene.figures.push_back(render::makeFigure(s.doc.clip().skeleton, fk));
    const render::Bounds b = render::sceneBounds(scene);
    const float aspect = height_ > 0 ? float(width_) / float(height_) : 1.5f;
    if (s.cameraNeedsFraming) {
        s.camera = render::presetCamera(render::CameraPreset::kThreeQuarter,
                                        render::characterForward(s.doc.clip().skeleton, fk), b.centreCm,
                                        b.radiusCm * 1.25f, aspect);
    } else {
        s.camera.frame(b.centreCm, b.radiusCm * 1.25f, aspect);
    }
    s.cameraNeedsFraming = false;
}

bool ViewportPanel::handleScreenPosition(const EditorState& s, Effector e, float& x, float& y) const {
    return s.doc.hasEffector(e) && viewportWindowPosition(s, s.doc.effectorPosition(e), x, y);
}

bool ViewportPanel::keyScreenPosition(const EditorState& s, int key, float& x, float& y) const {
    return pathKeyWindowPosition(s, key, x, y);
}

// What the mouse can pick this frame: effector handles, path keys and (with no gesture under way)
// the rotate gizmo.
struct ViewportPanel::Pickables {
    std::vector<render::Handle> handles, keys;
    render::RotateGizmo gizmo;
};

ViewportPanel::Pickables ViewportPanel::collectPickables(const EditorState& s) const {
    const EditorDocument& doc = s.doc;
    Pickables picks;
    if (doc.hasClip()) {
        FkState fk;
        forwardKinematics(doc.clip().skeleton, doc.currentPose(), fk);
        picks.handles = render::effectorHandles(doc.clip().skeleton, fk);
    }
    picks.keys = keyHandles(s);
    picks.gizmo = mode_ == Mode::kNone ? viewportGizmo(s) : render::RotateGizmo{};
    return picks;
}

void ViewportPanel::updateHover(EditorState& s, const Pointer& p, const Pickables& picks, bool hovered) const {
    const std::vector<render::Handle>& handles = picks.handles;
    const std::vector<render::Handle>& keys = picks.keys;
    s.hoveredHandle = -1;
    s.hoveredKey = -1;
    s.gizmoRing = -1;
    // The gizmo's rings are drawn over everything, so they win over handles and keys.
    if (hovered && picks.gizmo.joint >= 0)
        s.gizmoRing = render::pickGizmoRing(picks.gizmo, s.camera, p.mx, p.my, width_, height_);
    if (hovered && s.gizmoRing < 0 && s.listPickedKey >= 0) {
        // The key picked in the Path tab's list comes first where it lies under the mouse: keys of a
        // planted foot coincide with each other and with the foot's handle, and the list is how
        // the animator says which one to drag.
        for (const render::Handle& key : keys)
            if (key.id == s.listPickedKey &&
                render::pickHandleAtPixel({key}, s.camera, p.mx, p.my, width_, height_, 2.5f) == 0)
                s.hoveredKey = key.id;
        if (s.hoveredKey >= 0) return;
    }
    if (hovered && s.gizmoRing < 0) {
        // Effector handles first: a key lying on a handle must not hide it.
        const int i = render::pickHandleAtPixel(handles, s.camera, p.mx, p.my, width_, height_, 2.5f);
        if (i >= 0) s.hoveredHandle = handles[i].id;
        const int k = i >= 0 ? -1 : render::pickHandleAtPixel(keys, s.camera, p.mx, p.my, width_, height_, 2.5f);
        if (k >= 0) s.hoveredKey = keys[k].id;
        // Inside the view ring, where no handle or key is, a drag is the free (trackball) rotation.
        if (i < 0 && k < 0 && picks.gizmo.joint >= 0 &&
            render::insideTrackball(picks.gizmo, s.camera, p.mx, p.my, width_, height_))
            s.gizmoRing = render::kTrackball;
    }
}

void ViewportPanel::pressMouse(EditorState& s, const Pointer& p, const render::RotateGizmo& gizmo) {
    const ImGuiIO& io = ImGui::GetIO();
    EditorDocument& doc = s.doc;
    if (io.MouseClicked[0]) {
        pressLeft(s, p, gizmo);
    } else if (io.MouseClicked[2]) {
        mode_ = Mode::kPan;
    } else if (io.MouseClicked[1] && s.hoveredHandle >= 0) {
        const auto e = static_cast<Effector>(s.hoveredHandle);
        doc.togglePin(e);
        s.setStatus(std::string(doc.pinned(e) ? "pinned " : "unpinned ") + effectorName(e));
    }
    if (io.MouseWheel != 0.0f) s.camera.zoom(std::pow(0.88f, io.MouseWheel));
}

void ViewportPanel::pressLeft(EditorState& s, const Pointer& p, const render::RotateGizmo& gizmo) {
    EditorDocument& doc = s.doc;
    // A press anywhere but on the key picked in the list ends that pick: the handle under it is
    // the foot's again.
    if (s.hoveredKey < 0 || s.hoveredKey != s.listPickedKey) s.listPickedKey = -1;
    if (s.gizmoRing >= 0) {
        mode_ = Mode::kRotateRing;
        ringGizmo_ = gizmo;
        ringAxis_ = s.gizmoRing;
        ringStartAngles_ = doc.currentPose().anglesDeg[gizmo.joint];
        ringSweepDeg_ = 0.0;
        ringTurn_ = Eigen::Matrix3d::Identity();
        ringTravelPx_ = 0.0f;
        ringFrame_ = doc.frame();
        ringUndoCount_ = doc.history().undoCount();
        lastX_ = p.mx;  // the sweep starts at the press, not where the mouse was a frame ago
        lastY_ = p.my;
        s.playing = false;
    } else if (s.hoveredHandle >= 0 && ImGui::GetIO().KeyAlt) {
        // Alt+click lets go of what an earlier gesture placed (edit/held_effectors.h).
        s.request("release", {effectorName(static_cast<Effector>(s.hoveredHandle))});
    } else if (s.hoveredHandle >= 0) {
        const auto e = static_cast<Effector>(s.hoveredHandle);
        const Eigen::Vector3d start = doc.effectorPosition(e);
        const std::string err = doc.beginDrag(e);
        if (err.empty()) {
            mode_ = Mode::kDragHandle;
            s.dragStartCm = start;
            s.dragAxis = -1;
            s.selected = e;
            s.playing = false;
        } else {
            s.setStatus(err, true);
        }
    } else if (s.hoveredKey >= 0) {
        mode_ = Mode::kDragKey;
        dragKey_ = s.hoveredKey;
        dragKeyStartOffset_ = doc.paths().edit()->keyOffsetsCm[dragKey_];
        s.selectedKey = dragKey_;
        s.playing = false;
    } else {
        mode_ = p.shift ? Mode::kPan : Mode::kOrbit;
        pressX_ = p.mx;
        pressY_ = p.my;
    }
}

void ViewportPanel::continueGesture(EditorState& s, const Pointer& p) {
    const ImGuiIO& io = ImGui::GetIO();
    EditorDocument& doc = s.doc;
    switch (mode_) {
        case Mode::kOrbit:
            if (!io.MouseDown[0]) {
                mode_ = Mode::kNone;
                if (jointPicking_ && std::abs(p.mx - pressX_) + std::abs(p.my - pressY_) < 4.0f)
                    pickedJoint_ = pickJoint(s, p.mx, p.my);
            } else if (movedThisFrame_)
                s.camera.orbit(-p.dx * 0.4f, p.dy * 0.4f);
            break;
        case Mode::kPan:
            if (!io.MouseDown[0] && !io.MouseDown[2])
                mode_ = Mode::kNone;
            else if (movedThisFrame_)
                s.camera.pan(p.dx, p.dy, height_);
            break;
        case Mode::kDragHandle: continueHandleDrag(s, p); break;
        case Mode::kDragKey: continueKeyDrag(s, p); break;
        case Mode::kRotateRing:
            if (movedThisFrame_ || !io.MouseDown[0] || doc.frame() != ringFrame_ ||
                doc.history().undoCount() != ringUndoCount_)
                rotateRing(s, p.mx, p.my, io.KeyCtrl, !io.MouseDown[0]);
            break;
        case Mode::kNone: break;
    }
}

void ViewportPanel::continueHandleDrag(EditorState& s, const Pointer& p) {
    EditorDocument& doc = s.doc;
    if (!doc.dragging()) {
        mode_ = Mode::kNone;
    } else if (!ImGui::GetIO().MouseDown[0]) {
        doc.endDrag();
        mode_ = Mode::kNone;
        const std::string accepted = "accepted pose for frame " + std::to_string(doc.frame() + 1);
        if (doc.models().pending() > 0)
            s.setStatusWhile(
                accepted + " (adaptive update running)", [d = &doc] { return d->models().pending() > 0; },
                accepted + " (adaptive update done)");
        else
            s.setStatus(accepted);
    } else if (movedThisFrame_) {
        Eigen::Vector3d hit;
        const bool ok = s.dragAxis >= 0
                            ? dragAxisPoint(s.camera, p.mx, p.my, width_, height_, s.dragStartCm, s.dragAxis, hit)
                            : dragPlanePoint(s.camera, p.mx, p.my, width_, height_, doc.dragTarget(), p.shift, hit);
        const PhaseTimer timer(s.profile, s.profile.solveSeconds);
        if (ok) doc.dragTo(hit, 50);
    } else {
        const PhaseTimer timer(s.profile, s.profile.solveSeconds);
        doc.refine(50);  // the user holds still: keep converging
    }
}

void ViewportPanel::continueKeyDrag(EditorState& s, const Pointer& p) {
    EditorDocument& doc = s.doc;
    // The key applies live (the path is only targets; Regenerate solves poses later).
    if (!doc.paths().edit() || dragKey_ >= static_cast<int>(doc.paths().edit()->keyFrames.size())) {
        mode_ = Mode::kNone;
    } else if (!ImGui::GetIO().MouseDown[0]) {
        mode_ = Mode::kNone;
        const Eigen::Vector3d o = doc.paths().edit()->keyOffsetsCm[dragKey_];
        char buf[96];
        std::snprintf(buf, sizeof buf, "key %d moved to offset (%.1f, %.1f, %.1f) cm", dragKey_ + 1, o.x(), o.y(),
                      o.z());
        s.setStatus(buf);
    } else if (movedThisFrame_) {
        Eigen::Vector3d hit;
        if (dragPlanePoint(s.camera, p.mx, p.my, width_, height_, doc.paths().keyPosition(dragKey_), p.shift, hit)) {
            const std::string err = doc.paths().setKeyPosition(dragKey_, hit);
            if (!err.empty()) s.setStatus(err, true);
        }
    }
}

void ViewportPanel::interact(EditorState& s, float mx, float my, bool hovered) {
    Pointer p{mx, my, mx - lastX_, my - lastY_, ImGui::GetIO().KeyShift};
    if (!std::isfinite(p.dx) || !std::isfinite(p.dy)) p.dx = p.dy = 0.0f;
    movedThisFrame_ = p.dx != 0.0f || p.dy != 0.0f;

    // Hover (only when not in another mode), then a press starts a gesture and the gesture under
    // way follows the mouse.
    const Pickables picks = collectPickables(s);
    if (mode_ == Mode::kNone) updateHover(s, p, picks, hovered);
    if (mode_ == Mode::kNone && hovered) pressMouse(s, p, picks.gizmo);
    continueGesture(s, p);
    lastX_ = mx;
    lastY_ = my;
}

void ViewportPanel::rotateRing(EditorState& s, float mx, float my, bool snap, bool released) {
    EditorDocument& doc = s.doc;
    const int joint = ringGizmo_.joint;
    // The drag belongs to the frame and the pose it started on: playback, a frame change or an
    // undo during it cancels it rather than writing the old angles onto another pose.
    if (!doc.hasClip() || joint < 0 || joint >= doc.clip().skeleton.jointCount() || s.gizmoJoint != joint ||
        doc.frame() != ringFrame_ || doc.history().undoCount() != ringUndoCount_) {
        s.posePreview.reset();
        s.dragReadout.clear();
        mode_ = Mode::kNone;
        return;
    }
    const bool viewRing = ringAxis_ == render::kViewRing, trackball = ringAxis_ == render::kTrackball;
    if (trackball) {
        // The trackball's turns compose; its angle is the composed turn's.
        const render::TrackballTurn step = render::trackballTurn(s.camera, mx - lastX_, my - lastY_);
        ringTurn_ = Eigen::AngleAxisd(step.degrees * kDegToRad, toEigen(step.axisWorld)).toRotationMatrix() * ringTurn_;
        ringTravelPx_ += std::hypot(mx - lastX_, my - lastY_);
        ringSweepDeg_ = Eigen::AngleAxisd(ringTurn_).angle() * kRadToDeg;
    } else {
        // Summed frame by frame, so that a drag once round the joint is a whole turn.
        ringSweepDeg_ +=
            render::gizmoSweepDeg(ringGizmo_, ringAxis_, s.camera, lastX_, lastY_, mx, my, width_, height_);
    }
    // Ctrl snaps the change (not the angle) to 5° steps, as Blender's and Maya's rotate tools do.
    const double delta = snap ? 5.0 * std::round(ringSweepDeg_ / 5.0) : ringSweepDeg_;
    JointRotation rot;
    rot.joint = joint;
    rot.anglesDeg = ringStartAngles_;
    if (viewRing || trackball) {
        // About the line of sight at the press (the view ring's axis then), or about the
        // trackball's composed axis; the document's pose is still the one the drag started from
        // (the preview is separate).
        const Eigen::Vector3d axis =
            trackball ? Eigen::AngleAxisd(ringTurn_).axis() : toEigen(ringGizmo_.rings.back().axisWorld);
        const std::optional<Eigen::Vector3d> turned =
            anglesTurnedAboutWorldAxis(doc.clip().skeleton, doc.currentPose(), joint, axis, delta);
        if (turned) rot.anglesDeg = *turned;
    } else {
        rot.anglesDeg[ringAxis_] += delta;
    }
    rot.followPrior = s.gizmoFollowPrior && doc.hasModel();
    const Joint& jt = doc.clip().skeleton.joints[joint];
    char text[96];
    std::snprintf(text, sizeof text, "%s %s %+.1f deg%s", jt.name.c_str(), render::gizmoRingName(ringAxis_), delta,
                  snap ? " (5 deg steps)" : "");
    s.dragReadout = text;
    if (!released) {
        // Live preview: a short solve per move (the action solves fully on release).
        const JointRotationResult r = solveJointRotation(doc, rot, 30);
        if (r.error.empty())
            s.posePreview = r.pose;
        else
            s.setStatus(r.error, true);
        return;
    }
    s.posePreview.reset();
    s.dragReadout.clear();
    mode_ = Mode::kNone;
    // A press inside the rings that did not move is a click: it picks the bone there, as elsewhere.
    if (trackball && ringTravelPx_ < 4.0f) {
        if (jointPicking_) pickedJoint_ = pickJoint(s, mx, my);
        return;
    }
    if (delta == 0.0) return;
    std::vector<std::string> args = rotateJointAction(jt, rot.anglesDeg);
    const std::string action = args.front();
    args.erase(args.begin());
    s.request(action, std::move(args));  // one undo step, spread like the other pose edits
}

int ViewportPanel::pickJoint(const EditorState& s, float mx, float my) const {
    if (!s.doc.hasClip()) return -1;
    const Skeleton& sk = s.doc.clip().skeleton;
    FkState fk;
    forwardKinematics(sk, s.doc.currentPose(), fk);
    std::vector<render::Segment> bones;
    std::vector<int> joints;
    for (int j = 1; j < sk.jointCount(); ++j) {
        const Joint& jt = sk.joints[j];
        if (!(jt.dof[0] || jt.dof[1] || jt.dof[2]) || jt.tailCm.norm() < 0.1) continue;
        // Each bone as thick as it is drawn, and 1 cm more: a click on a thigh's surface picks
        // the thigh, and a finger does not reach beyond its own size.
        bones.push_back({toGlm(fk.jointCm[j]), toGlm(boneEndCm(sk, fk, j)), render::boneRadiusCm(jt.bone) + 1.0f});
        joints.push_back(j);
    }
    // The nearest bone along the ray wins where several qualify.
    const int i = render::pickSegment(bones, s.camera.rayFromPixel(mx, my, width_, height_), 3.0f);
    return i < 0 ? -1 : joints[i];
}

namespace {
// What the viewport shows, as numbers: the scene is redrawn only when they change.
std::vector<float> viewportSceneSignature(const render::Scene& scene, const render::OrbitCamera& camera, int rw,
                                          int rh) {
    std::vector<float> sig = {float(rw),     float(rh),       camera.targetCm.x, camera.targetCm.y, camera.targetCm.z,
                              camera.yawDeg, camera.pitchDeg, camera.distanceCm, camera.fovYDeg};
    auto addVec = [&](const glm::vec3& v) { sig.insert(sig.end(), {v.x, v.y, v.z}); };
    for (const render::Figure& f : scene.figures) {
        sig.insert(sig.end(), {f.ghost ? 1.0f : 0.0f, f.ghostAlpha});
        addVec(f.ghostTint);
        addVec(f.tint);
        sig.push_back(f.tintWeight);
        for (const render::BoneSegment& b : f.bones) addVec(b.startCm), addVec(b.endCm);
    }
    for (const render::Handle& hd : scene.handles) addVec(hd.positionCm), sig.push_back(float(hd.state));
    for (const render::Target& t : scene.targets) addVec(t.positionCm), sig.push_back(t.reached ? 1.0f : 0.0f);
    // Counts first: a pin, a held ring and a footprint at the same point are different pictures.
    sig.insert(sig.end(), {float(scene.pins.size()), float(scene.heldMarks.size()), float(scene.footprints.size())});
    for (const render::Pin& p : scene.pins) addVec(p.positionCm);
    for (const render::HeldMark& m : scene.heldMarks) addVec(m.positionCm);
    for (const render::Footprint& f : scene.footprints) addVec(f.positionCm);
    for (const render::Path& p : scene.paths) {
        sig.insert(sig.end(),
                   {float(p.pointsCm.size()), float(p.currentPoint), float(p.hoveredKey), float(p.selectedKey),
                    p.radiusCm, p.tickRadiusCm, p.minKeyRadiusCm, p.onTop ? 1.0f : 0.0f});
        addVec(p.colour);
        for (const glm::vec3& v : p.pointsCm) addVec(v);
        for (const glm::vec3& v : p.keysCm) addVec(v);
    }
    sig.push_back(scene.groundHeightCm);
    return sig;
}
}  // namespace

void ViewportPanel::keepCharacterInView(EditorState& s) {
    // Follow: the camera keeps the character's root (projected on the ground) where it was, so a
    // walk stays in view during playback and scrubbing.
    if (std::exchange(s.cameraRestored, false)) followValid_ = false;  // the camera is as saved
    if (s.doc.hasClip()) {
        const Eigen::Vector3d root = s.doc.currentPose().rootCm;
        if (s.followCharacter && followValid_ && s.doc.clip().name == followClip_) {
            s.camera.targetCm.x += float(root.x() - followRoot_.x());
            s.camera.targetCm.z += float(root.z() - followRoot_.z());
        }
        followRoot_ = root;
        followClip_ = s.doc.clip().name;
        followValid_ = root.allFinite();
    }
}

void ViewportPanel::handleViewportKeys(EditorState& s) {
    if (chordPressed('F')) frameCharacter(s);
    // X, Y or Z during a handle drag: move along that world axis only (again: free).
    for (int a = 0; a < 3; ++a)
        if (mode_ == Mode::kDragHandle && chordPressed("XYZ"[a])) s.dragAxis = s.dragAxis == a ? -1 : a;
    // P acts on the handle under the mouse only: over the floor it would pin what the user
    // does not see they picked (Model > Pin and the `pin` action name the effector).
    if (chordPressed('P')) {
        if (s.hoveredHandle >= 0) {
            const auto e = static_cast<Effector>(s.hoveredHandle);
            s.doc.togglePin(e);
            s.setStatus(std::string(s.doc.pinned(e) ? "pinned " : "unpinned ") + effectorName(e));
        } else {
            s.setStatus("P pins the handle under the mouse: point at a hand, a foot or the head");
        }
    }
    if (chordPressed(256 /*Escape*/) && s.doc.dragging()) {
        s.doc.cancelDrag();
        mode_ = Mode::kNone;
        s.setStatus("drag cancelled");
    }
    if (chordPressed(256 /*Escape*/) && mode_ == Mode::kDragKey) {
        s.doc.paths().setKeyOffset(dragKey_, dragKeyStartOffset_);
        mode_ = Mode::kNone;
        s.setStatus("key drag cancelled");
    }
    if (chordPressed(256 /*Escape*/) && mode_ == Mode::kRotateRing) {
        s.posePreview.reset();
        s.dragReadout.clear();
        mode_ = Mode::kNone;
        s.setStatus("rotation cancelled");
    }
}

void ViewportPanel::redrawSceneIfChanged(EditorState& s, int w, int h) {
    const render::Scene scene = buildScene(s);
    // Redraw only when what the viewport shows changed (llvmpipe spends most of a frame
    // rasterising the scene; an idle editor should not).
    // While the user drags, orbits or plays, the scene is drawn at a lower resolution into the
    // corner of the target and scaled up (as Blender does during navigation); at rest it is
    // drawn at full resolution again.
    const bool moving = mode_ != Mode::kNone || s.playing || s.doc.latentDragging();
    const float scale = moving ? kMovingScale : 1.0f;
    rw_ = std::max(16, int(w * scale));
    rh_ = std::max(16, int(h * scale));
    std::vector<float> sig = viewportSceneSignature(scene, s.camera, rw_, rh_);
    lastScene_ = scene;
    if (sig != lastSignature_) {
        const PhaseTimer timer(s.profile, s.profile.sceneSeconds);
        renderer_->draw(scene, s.camera, rw_, rh_, fbo_);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        lastSignature_ = std::move(sig);
        ++sceneDraws_;
    }
}

void ViewportPanel::drawMouseHints(EditorState& s, float x0, float y0) const {
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const ImVec2 origin(x0, y0);
    // Overlay: what the mouse does.
    const char* hint =
        mode_ == Mode::kDragHandle
            ? "Dragging: release to accept  |  X/Y/Z: along an axis  |  Shift: ground plane  |  Esc: cancel"
        : mode_ == Mode::kDragKey    ? "Dragging path key: the path follows  |  Shift: ground plane  |  Esc: cancel"
        : mode_ == Mode::kRotateRing ? "Rotating the joint: release to apply  |  Ctrl: 5 deg steps  |  Esc: cancel"
        : s.doc.paths().edit()
            ? "LMB handle/key: drag  |  RMB/P: pin  |  LMB: orbit  |  MMB/Shift+LMB: pan  |  Wheel: zoom  |  F: frame"
            : "LMB handle: drag  |  RMB/P: pin  |  LMB: orbit  |  MMB/Shift+LMB: pan  |  Wheel: zoom  |  F: frame";
    dl->AddText(ImVec2(origin.x + 8, origin.y + 6), IM_COL32(230, 232, 236, 200), hint);
    if (mode_ == Mode::kDragHandle && s.doc.dragging()) {
        // The offset from where the handle was picked up, in cm, and the axis it is held to.
        const Eigen::Vector3d d = s.doc.dragTarget() - s.dragStartCm;
        char buf[160];
        std::snprintf(buf, sizeof buf, "%s  dX %+.1f  dY %+.1f  dZ %+.1f cm  |d| %.1f cm", dragAxisLabel(s.dragAxis),
                      d.x(), d.y(), d.z(), d.norm());
        s.dragReadout = buf;
        const float lh = ImGui::GetTextLineHeightWithSpacing();
        dl->AddText(ImVec2(origin.x + 8, origin.y + 6 + lh), IM_COL32(255, 214, 120, 255), buf);
    } else if (mode_ == Mode::kRotateRing) {
        const float lh = ImGui::GetTextLineHeightWithSpacing();
        dl->AddText(ImVec2(origin.x + 8, origin.y + 6 + lh), IM_COL32(255, 214, 120, 255), s.dragReadout.c_str());
    } else {
        s.dragReadout.clear();
    }
}

void ViewportPanel::showHoverTooltips(const EditorState& s) const {
    if (s.gizmoRing >= 0 && mode_ == Mode::kNone && s.gizmoJoint >= 0 &&
        s.gizmoJoint < s.doc.clip().skeleton.jointCount())
        tooltip("%s: %s%s\nLMB drag to rotate, Ctrl for 5 deg steps",
                s.doc.clip().skeleton.joints[s.gizmoJoint].name.c_str(), render::gizmoRingName(s.gizmoRing),
                s.gizmoRing == render::kTrackball  ? " (drag inside the rings)"
                : s.gizmoRing == render::kViewRing ? " (turns about the line of sight)"
                                                   : "");
    if (s.hoveredHandle >= 0 && mode_ == Mode::kNone) {
        const auto e = static_cast<Effector>(s.hoveredHandle);
        const bool held = s.doc.held(e);
        tooltip("%s%s%s\nLMB drag to pose, RMB or P to %s%s", effectorName(e), s.doc.pinned(e) ? " (pinned)" : "",
                held ? " (held: placed by an edit)" : "", s.doc.pinned(e) ? "unpin" : "pin",
                held ? "\nAlt+click to release it (here and on the neighbouring frames that hold it)" : "");
    }
    const int key = mode_ == Mode::kDragKey ? dragKey_ : mode_ == Mode::kNone ? s.hoveredKey : -1;
    if (key >= 0 && s.doc.paths().edit() && key < static_cast<int>(s.doc.paths().edit()->keyFrames.size())) {
        const Eigen::Vector3d& o = s.doc.paths().edit()->keyOffsetsCm[key];
        tooltip("key %d, frame %d, offset (%.1f, %.1f, %.1f) cm", key + 1, s.doc.paths().edit()->keyFrames[key] + 1,
                o.x(), o.y(), o.z());
    }
}

void ViewportPanel::draw(EditorState& s) {
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    ImVec2 avail = ImGui::GetContentRegionAvail();
    const int w = std::max(16, int(avail.x)), h = std::max(16, int(avail.y));
    ensureTarget(w, h);
    s.viewportX = origin.x;
    s.viewportY = origin.y;
    s.viewportWidth = w;
    s.viewportHeight = h;
    if (s.cameraNeedsFraming || s.requestFrameCamera) {
        frameCharacter(s);
        s.requestFrameCamera = false;
    }
    ImGui::InvisibleButton(
        "##viewport", ImVec2(float(w), float(h)),
        ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight | ImGuiButtonFlags_MouseButtonMiddle);
    const bool hovered = ImGui::IsItemHovered();
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    keepCharacterInView(s);
    // The mouse can leave the window (ImGui reports -FLT_MAX): no camera or drag update then.
    if (s.doc.hasClip() && ImGui::IsMousePosValid(&mouse)) interact(s, mouse.x - origin.x, mouse.y - origin.y, hovered);

    // Keys that act on the viewport.
    if (!s.keysBlocked) handleViewportKeys(s);

    if (s.doc.hasClip()) redrawSceneIfChanged(s, w, h);
    presentX_ = int(origin.x), presentY_ = int(origin.y), presentW_ = w,
    presentH_ = h;  // presentTo() copies the scene there
    drawMouseHints(s, origin.x, origin.y);
    drawBalance(s, origin.x, origin.y + h);
    drawRangeLegend(s, origin.y, origin.x + w, origin.y + h);
    showHoverTooltips(s);
}

// The balance overlay: the planted feet's support polygon on the ground (yellow), the centre of mass with a line down
// to its ground point (green over the support, red when more than the tolerance outside, grey with no foot planted),
// and a caption above the bottom-left corner (x0, y1).
void ViewportPanel::drawBalance(EditorState& s, float x0, float y1) {
    s.balanceCaption.clear();
    if (!s.showBalance || !s.doc.hasClip()) return;
    const Skeleton& skeleton = s.doc.clip().skeleton;
    FkState fk;
    forwardKinematics(skeleton, s.doc.currentPose(), fk);
    const std::optional<Eigen::Vector3d> com = centreOfMass(skeleton, fk);
    if (!com) {
        s.balanceCaption = "balance: this skeleton has no thighs or trunk to weigh";
    } else {
        const double groundY = lastScene_.groundHeightCm;
        const std::optional<SupportPolygon> support = supportPolygon(skeleton, fk, s.doc.contacts(), s.doc.frame());
        const double outside = support ? support->outsideCm({com->x(), com->z()}) : 0.0;
        const ImU32 green = IM_COL32(90, 220, 120, 255), red = IM_COL32(255, 90, 80, 255),
                    grey = IM_COL32(190, 190, 190, 255);
        const ImU32 comCol = !support ? grey : outside > kBalanceToleranceCm ? red : green;
        ImDrawList* dl = ImGui::GetWindowDrawList();
        if (support) {
            std::vector<ImVec2> ring;
            const std::vector<Eigen::Vector2d> outline = support->grownOutline();
            for (const Eigen::Vector2d& p : outline) {
                float x = 0.0f, y = 0.0f;
                if (viewportWindowPosition(s, Eigen::Vector3d(p.x(), groundY, p.y()), x, y)) ring.emplace_back(x, y);
            }
            if (ring.size() == outline.size() && !ring.empty())
                dl->AddPolyline(ring.data(), int(ring.size()), IM_COL32(240, 220, 90, 255), ImDrawFlags_Closed, 2.0f);
        }
        float cx = 0.0f, cy = 0.0f, gx = 0.0f, gy = 0.0f;
        const bool comShown = viewportWindowPosition(s, *com, cx, cy);
        const bool groundShown = viewportWindowPosition(s, Eigen::Vector3d(com->x(), groundY, com->z()), gx, gy);
        if (comShown && groundShown) dl->AddLine(ImVec2(cx, cy), ImVec2(gx, gy), comCol, 1.5f);
        if (comShown) dl->AddCircleFilled(ImVec2(cx, cy), 5.0f, comCol);
        if (groundShown) dl->AddCircle(ImVec2(gx, gy), 7.0f, comCol, 0, 2.0f);
        char buf[160];
        if (!support)
            std::snprintf(buf, sizeof buf, "balance: no foot planted on this frame");
        else
            std::snprintf(buf, sizeof buf, "balance: centre of mass %s (%.1f cm outside the support)",
                          outside > kBalanceToleranceCm ? "off the planted feet" : "over the planted feet", outside);
        s.balanceCaption = buf;
    }
    const float lh = ImGui::GetTextLineHeightWithSpacing();
    const ImVec2 at(x0 + 8, y1 - 8 - 2 * lh), size = ImGui::CalcTextSize(s.balanceCaption.c_str());
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->AddRectFilled(ImVec2(at.x - 4, at.y - 2), ImVec2(at.x + size.x + 4, at.y + size.y + 2),
                      IM_COL32(20, 22, 26, 190), 3.0f);
    dl->AddText(at, IM_COL32(230, 232, 236, 255), s.balanceCaption.c_str());
}

// Bottom-right corner (the hints are top-left, the caption bottom-left): the colour bar of render::rangeTint (natural →
// amber as the body nears the capture's limit → red when refused), the verdict in words and whether the model learns
// from the pose; the numbers behind it in a tooltip over the box.
namespace {

// The window rectangle the character covers on screen (its joints and bone ends, padded by a
// few pixels); empty (x0 > x1) when none of it is in view.
EditorState::ControlRect characterScreenRect(const EditorState& s) {
    EditorState::ControlRect r{1e9f, 1e9f, -1e9f, -1e9f, false};
    const Skeleton& sk = s.doc.clip().skeleton;
    FkState fk;
    forwardKinematics(sk, s.posePreview ? *s.posePreview : s.doc.currentPose(), fk);
    auto add = [&](const Eigen::Vector3d& p) {
        float x, y;
        if (!viewportWindowPosition(s, p, x, y)) return;
        r.x0 = std::min(r.x0, x - 8.0f), r.y0 = std::min(r.y0, y - 8.0f);
        r.x1 = std::max(r.x1, x + 8.0f), r.y1 = std::max(r.y1, y + 8.0f);
        r.visible = true;
    };
    for (int j = 0; j < sk.jointCount(); ++j) {
        add(fk.jointCm[j]);
        add(boneEndCm(sk, fk, j));
    }
    return r;
}

bool rectsOverlap(const EditorState::ControlRect& a, const EditorState::ControlRect& b) {
    return a.visible && b.visible && a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

}  // namespace

void ViewportPanel::drawRangeLegend(EditorState& s, float y0, float x1, float y1) {
    s.rangeLegend.clear();
    s.controls.erase("range legend");
    if (!s.showRangeTint || !s.doc.hasModel()) return;
    const std::optional<ShownVerdict> shown = s.doc.shownPoseVerdict();
    // The tint and the first line: the steadied class; the second line and the tooltip: this frame's own verdict.
    const AdmissionVerdict* v = shown ? &shown->own : nullptr;
    const render::RangeTint tint = shown ? render::rangeTint(shown->shown()) : render::RangeTint{};
    std::string l1, l2;
    if (v) {
        l1 = std::string("this pose is ") + judgementWords(shown->shown().judgement);
        if (shown->steadied)
            l1 += std::string(" like frame ") + std::to_string(shown->steadiedFrame + 1) +
                  " (alone: " + judgementWords(v->judgement) + ")";
        l2 = v->admitted ? "the model learns from it" : "kept as an edit, the model does not learn from it";
    } else {
        l1 = "no solved pose on this frame: not tinted";
    }
    s.rangeLegend = l1 + (v ? "\n" + l2 : "");

    ImDrawList* dl = ImGui::GetWindowDrawList();
    const float lh = ImGui::GetTextLineHeightWithSpacing();
    const float pad = 6.0f * ImGui::GetFontSize() / 15.0f;
    const char* labels[3] = {"natural", "unusual", "unlike the capture"};
    // A fixed width, so the box does not change size from frame to frame; a longer line wraps inside it.
    const float barW = std::max(ImGui::CalcTextSize("kept as an edit, the model does not learn from it").x,
                                3.0f * (ImGui::CalcTextSize(labels[2]).x + pad));
    const float gap = lh - ImGui::GetTextLineHeight();
    const auto heightOf = [&](const std::string& t) {
        return t.empty() ? 0.0f : ImGui::CalcTextSize(t.c_str(), nullptr, false, barW).y + gap;
    };
    const float h1 = heightOf(l1), h2 = heightOf(l2);
    const float boxW = barW + 2 * pad, boxH = pad + lh * 0.6f + 6.0f + lh + h1 + h2 + pad;
    const ImVec2 a(x1 - boxW - 8.0f, y1 - boxH - 8.0f);
    const ImU32 stateCol = !v                                            ? IM_COL32(200, 200, 200, 255)
                           : tint.band == render::RangeBand::kOutOfRange ? IM_COL32(255, 110, 100, 255)
                           : tint.band == render::RangeBand::kNearLimit  ? IM_COL32(255, 190, 90, 255)
                                                                         : IM_COL32(150, 230, 150, 255);
    const auto detailsOnHover = [&](const ImVec2& p0, const ImVec2& p1) {
        if (v && mode_ == Mode::kNone && ImGui::IsMouseHoveringRect(p0, p1))
            tooltip("%s\n%s", l2.c_str(), admissionDetails(*v, *s.doc.model()->model).c_str());
    };
    // In a small viewport the box would cover the character: one line at the top-right instead,
    // the rest in its tooltip (as in Blender, overlays give way to the model).
    if (rectsOverlap({a.x, a.y, a.x + boxW, a.y + boxH, true}, characterScreenRect(s))) {
        const ImVec2 size = ImGui::CalcTextSize(l1.c_str());
        const ImVec2 c(x1 - size.x - 2 * pad - 8.0f, y0 + 2.0f * lh + 8.0f);
        const ImVec2 c1(c.x + size.x + 2 * pad, c.y + size.y + 2 * pad);
        dl->AddRectFilled(c, c1, IM_COL32(20, 22, 26, 210), 4.0f);
        dl->AddText(ImVec2(c.x + pad, c.y + pad), v ? stateCol : IM_COL32(230, 232, 236, 255), l1.c_str());
        s.controls["range legend"] = {c.x, c.y, c1.x, c1.y, true};
        detailsOnHover(c, c1);
        return;
    }
    s.controls["range legend"] = {a.x, a.y, a.x + boxW, a.y + boxH, true};
    dl->AddRectFilled(a, ImVec2(a.x + boxW, a.y + boxH), IM_COL32(20, 22, 26, 210), 4.0f);
    // The bar: one third per band; the middle third ramps from the neutral bone colour to amber.
    const auto col = [](const glm::vec3& c) { return ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, 1.0f)); };
    const float bx = a.x + pad, by = a.y + pad, third = barW / 3.0f, bh = lh * 0.6f;
    const glm::vec3 neutral{0.90f, 0.87f, 0.80f};
    dl->AddRectFilled(ImVec2(bx, by), ImVec2(bx + third, by + bh), col(neutral));
    dl->AddRectFilledMultiColor(ImVec2(bx + third, by), ImVec2(bx + 2 * third, by + bh), col(neutral),
                                col(render::kRangeAmber), col(render::kRangeAmber), col(neutral));
    dl->AddRectFilled(ImVec2(bx + 2 * third, by), ImVec2(bx + barW, by + bh), col(render::kRangeRed));
    if (v) {
        // Where the shown pose sits on the bar: its nearest-frame distance against the capture's median, then the ramp.
        const AdmissionVerdict& at0 = shown->shown();
        const float at =
            tint.band == render::RangeBand::kOutOfRange ? 2.5f
            : tint.band == render::RangeBand::kNearLimit
                ? 1.0f + tint.weight
                : std::clamp(float(at0.capture.nearestCm / std::max(at0.nearestMedianCm, 1e-9)), 0.0f, 1.0f);
        const float px = bx + at * third;
        dl->AddTriangleFilled(ImVec2(px, by + bh + 1), ImVec2(px - 5, by + bh + 7), ImVec2(px + 5, by + bh + 7),
                              IM_COL32(255, 255, 255, 255));
    }
    for (int i = 0; i < 3; ++i) {
        const float tw = ImGui::CalcTextSize(labels[i]).x;
        dl->AddText(ImVec2(bx + third * (i + 0.5f) - tw * 0.5f, by + bh + 6), IM_COL32(220, 222, 226, 255), labels[i]);
    }
    const float ty = by + bh + 6 + lh;
    const auto text = [&](float y, ImU32 c, const std::string& t) {
        dl->AddText(ImGui::GetFont(), ImGui::GetFontSize(), ImVec2(bx, y), c, t.c_str(), nullptr, barW);
    };
    text(ty, v ? stateCol : IM_COL32(230, 232, 236, 255), l1);
    if (v) text(ty + h1, IM_COL32(230, 232, 236, 255), l2);
    if (v && mode_ == Mode::kNone && ImGui::IsMouseHoveringRect(a, ImVec2(a.x + boxW, a.y + boxH)))
        tooltip("%s", admissionDetails(*v, *s.doc.model()->model).c_str());
}

}  // namespace mgp::ui
