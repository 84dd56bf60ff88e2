#pragma once
// The 3-D viewport: draws the scene into an offscreen texture, copied into the window under the
// ImGui overlays (presentTo), and maps the mouse to the camera (orbit: left drag on empty space; pan: middle drag or
// Shift+left; zoom: wheel; F frames the character) and to effector drags (hover highlights a handle; left drag moves it
// on a camera-facing plane, Shift on a horizontal plane; right-click or P pins). While an effector path is edited it
// also shows the edited path, its keys (dragged like handles; handles win where they overlap), the captured path and
// the before ghost (EditorState flags).
#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "render/png_capture.h"
#include "render/scene_builder.h"
#include "render/skeleton_renderer.h"
#include "skeleton/fk_memo.h"
#include "ui/shell/editor_state.h"

namespace mgp::ui {

class ViewportPanel {
public:
    ViewportPanel();
    ~ViewportPanel();
    ViewportPanel(const ViewportPanel&) = delete;
    ViewportPanel& operator=(const ViewportPanel&) = delete;
    // Draws the panel content (call between ImGui::Begin/End of the viewport window).
    void draw(EditorState& state);
    // Screen (window) pixel of an effector's handle; false if not visible or not drawn yet.
    bool handleScreenPosition(const EditorState& state, Effector e, float& x, float& y) const;
    // Screen (window) pixel of path key `key` (0-based); false without a path edit or off screen.
    bool keyScreenPosition(const EditorState& state, int key, float& x, float& y) const;
    void frameCharacter(EditorState& state) const;
    // The 3-D view at the viewport's size with 4× MSAA and no overlay text (File > Export PNG;
    // ui/panels/viewport_export.cpp). Throws render::RenderError before the first draw.
    render::Image renderImage(const EditorState& state);
    // While on (the Rotate joint window is shown), a left click on a bone that does not orbit the
    // camera picks that bone's joint; takePickedJoint returns it once (-1 none).
    void setJointPicking(bool on) { jointPicking_ = on; }
    int takePickedJoint() { return std::exchange(pickedJoint_, -1); }
    // Copies the scene into the window's framebuffer where the panel is, scaled up from the part
    // drawn while moving. Call after the window is cleared and before ImGui renders its draw
    // lists, which then lay the overlays on top: on llvmpipe a blit costs a fraction of a
    // blended, textured ImGui quad the size of the viewport (docs/architecture.md §3).
    void presentTo(int windowHeight) const;
    long sceneDraws() const { return sceneDraws_; }                            // how often the 3-D scene was redrawn
    long overlayLayerDraws() const { return renderer_->overlayLayerDraws(); }  // ... and its still overlays
    const render::Scene& lastScene() const { return lastScene_; }              // as last built by draw()

private:
    void ensureTarget(int w, int h);
    void interact(EditorState& state, float mx, float my, bool hovered);
    // The phases of interact(): the mouse in viewport pixels, its motion since the last frame, Shift.
    struct Pointer {
        float mx, my, dx, dy;
        bool shift;
    };
    struct Pickables;
    Pickables collectPickables(const EditorState& state) const;
    void updateHover(EditorState& state, const Pointer& p, const Pickables& picks, bool hovered) const;
    void pressMouse(EditorState& state, const Pointer& p, const render::RotateGizmo& gizmo);
    void pressLeft(EditorState& state, const Pointer& p, const render::RotateGizmo& gizmo);
    void continueGesture(EditorState& state, const Pointer& p);
    void continueHandleDrag(EditorState& state, const Pointer& p);
    void continueKeyDrag(EditorState& state, const Pointer& p);
    // The phases of draw().
    void keepCharacterInView(EditorState& state);
    void handleViewportKeys(EditorState& state);
    void redrawSceneIfChanged(EditorState& state, int w, int h);
    void drawMouseHints(EditorState& state, float x0, float y0) const;  // top-left corner at (x0, y0)
    void showHoverTooltips(const EditorState& state) const;
    render::Scene buildScene(const EditorState& state) const;
    // The animated joint whose bone is under viewport pixel (mx, my) (within its drawn radius
    // + 1 cm), -1 none.
    int pickJoint(const EditorState& state, float mx, float my) const;

    std::unique_ptr<render::SceneRenderer> renderer_;
    std::unique_ptr<render::SceneRenderer> exportRenderer_;  // created on the first export
    unsigned fbo_ = 0, colour_ = 0, depth_ = 0;
    int width_ = 0, height_ = 0;
    int rw_ = 16, rh_ = 16;  // the part of the target the last scene was drawn into
    int presentX_ = 0, presentY_ = 0, presentW_ = 0, presentH_ = 0;  // where draw() put the panel (0 wide: nowhere)
    static constexpr float kMovingScale = 0.7f;
    enum class Mode { kNone, kOrbit, kPan, kDragHandle, kDragKey, kRotateRing } mode_ = Mode::kNone;
    // A kRotateRing drag: the gizmo as it was when the drag began, the ring's DOF axis (or the
    // view ring, or the trackball inside it), the joint's angles then, and the turn so far (degrees).
    render::RotateGizmo ringGizmo_;
    int ringAxis_ = -1;
    Eigen::Vector3d ringStartAngles_ = Eigen::Vector3d::Zero();
    double ringSweepDeg_ = 0.0;
    Eigen::Matrix3d ringTurn_ = Eigen::Matrix3d::Identity();  // a trackball drag's turn so far (world)
    float ringTravelPx_ = 0.0f;                               // ... and the mouse's path length
    int ringFrame_ = -1, ringUndoCount_ = 0;                  // the frame and history the drag started on
    void rotateRing(EditorState& state, float mx, float my, bool snap, bool released);
    int dragKey_ = -1;                                              // the key of a kDragKey drag
    Eigen::Vector3d dragKeyStartOffset_ = Eigen::Vector3d::Zero();  // restored by Esc
    float lastX_ = 0, lastY_ = 0;
    float pressX_ = 0, pressY_ = 0;  // where the left button went down (a click picks a bone)
    bool jointPicking_ = false;
    int pickedJoint_ = -1;
    bool movedThisFrame_ = false;
    bool followValid_ = false;
    Eigen::Vector3d followRoot_ = Eigen::Vector3d::Zero();
    std::string followClip_;
    std::vector<float> lastSignature_;
    long sceneDraws_ = 0;
    render::Scene lastScene_;
    // Bottom-right corner at (x1, y1), or one line at the top-right (the viewport's top at y0)
    // where the box would cover the character.
    void drawRangeLegend(EditorState& state, float y0, float x1, float y1);
    void drawBalance(EditorState& state, float x0, float y1);  // bottom-left corner at (x0, y1)
    mutable std::string groundClip_;
    mutable FkMemo overlayFk_;  // the trails' frames (forgotten with groundClip_)
    mutable float groundHeight_ = 0.0f;
};

using render::toGlm;
// Window pixel of a world point (cm) in the viewport as last drawn (EditorState::viewport*);
// false when behind the camera or outside the viewport. Usable without the panel (scripts, tests).
bool viewportWindowPosition(const EditorState& state, const Eigen::Vector3d& pointCm, float& x, float& y);
// The pose the "Before ghost" shows on the current frame: the pose before the last undoable step
// that touched it, else (no such step) the captured pose of an edited frame; none otherwise.
std::optional<Pose> beforeGhostPose(const EditorState& state);
// The edited path with its keys (what the viewport draws and where keys are picked), or nullopt
// when no path is being edited.
std::optional<render::Path> editedPath(const EditorState& state);
// Window pixel of path key `key` (0-based); false without a path edit, a bad key or off screen.
bool pathKeyWindowPosition(const EditorState& state, int key, float& x, float& y);
// The rotate gizmo of EditorState::gizmoJoint on the shown pose (a rotation's preview while one
// is dragged), its axis rings kGizmoRadiusPx in radius on screen (the view ring 1.25 times that);
// an empty gizmo (joint −1) when none.
constexpr float kGizmoRadiusPx = 70.0f;
render::RotateGizmo viewportGizmo(const EditorState& state);

}  // namespace mgp::ui
