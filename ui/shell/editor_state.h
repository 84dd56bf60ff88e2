#pragma once
// What the editor's panels share: the document (core), the background jobs, the camera and the
// small amount of UI-only state. Panels read and write it; EditorApp owns it.
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "edit/editor_document.h"
#include "edit/export_job.h"
#include "edit/training_job.h"
#include "gp/train/trainer.h"
#include "render/camera.h"
#include "render/motion_overlays.h"
#include "ui/shell/frame_profile.h"
#include "ui/shell/message_log.h"

namespace mgp::ui {

struct EditorState {
    EditorDocument doc;
    TrainingJob training;         // the main model
    TrainingJob compareTraining;  // the compare model (the other kernel)
    ExportJob exporting;          // FBX exports (Blender takes seconds)
    gp::TrainOptions trainOptions;
    render::OrbitCamera camera;
    bool cameraNeedsFraming = true;
    bool cameraRestored = false;  // set with a camera read from a session: following restarts there
    bool followCharacter = true;  // the camera follows the root over the ground

    std::string clipLabel;   // shown in the title bar
    std::string modelLabel;  // "trained fas", a file name, ...
    MessageLog messages;     // the status line and View > Messages
    double uiSeconds = 0.0;  // UI time (sum of frame dt): messages expire by it

    bool playing = false;
    double playAccumulator = 0.0;  // fractional frames

    int hoveredHandle = -1;  // Effector under the mouse in the viewport, -1 none
    std::optional<Effector> selected;
    int hoveredTrainingRow = -1;  // latent map hover
    // The latent map's clip legend as last drawn (a model of several clips): one line per clip,
    // "NAME #RRGGBB" and " (open)" on the open clip; "" for a single-clip model.
    std::string clipLegend;

    // A handle drag: where the handle started (cm), the axis it is held to (-1 free, 0 X, 1 Y,
    // 2 Z; X/Y/Z keys) and the offset readout the viewport shows ("" when not dragging).
    Eigen::Vector3d dragStartCm = Eigen::Vector3d::Zero();
    int dragAxis = -1;
    std::string dragReadout;
    // Rotate joint: the pose a slider gesture would give, drawn instead of the frame's pose until
    // the gesture ends (joint_rotation_window.h); none otherwise.
    std::optional<Pose> posePreview;
    FrameProfile profile;  // where the last frame's time went (bench --only ui)

    // Path editing (path panel, viewport, timeline); keys are indices into doc.paths().edit()->keyFrames.
    int hoveredKey = -1;   // path key under the mouse in the viewport, -1 none
    int selectedKey = -1;  // path key last dragged or picked, -1 none
    // The key picked in the Path tab's list: it comes first under the mouse in the viewport (keys
    // of a planted foot coincide) until a press elsewhere in the viewport; -1 none.
    int listPickedKey = -1;
    // Frames selected on the timeline by Shift+drag (0-based, first ≤ last): Fill between keys
    // fills every gap between keys inside it. A plain click on the timeline clears it.
    std::optional<std::pair<int, int>> timelineRange;
    bool showCapturedPath = true;         // the captured path beside the edited one
    bool showBeforeGhost = false;         // the current frame's pose before the last undoable step
    bool showNearestGhost = false;        // the captured frame nearest to the last learned solve
    bool showInterpolationGhost = false;  // between two keys: the keys' plain interpolation
    // View > Pose range: tint the figure by σ²(x) against the model's training range, with a legend
    // (render/range_tint.h). Only a solved pose is tinted (a drag, an edited frame) and only with a model.
    bool showRangeTint = true;
    std::string rangeLegend;  // the legend's text as last drawn, lines joined by '\n' ("" when hidden)
    // View > Balance: the current pose's centre of mass over the ground and the planted feet's
    // support polygon (motion/support_polygon.h), drawn over the viewport.
    bool showBalance = false;
    std::string balanceCaption;  // what the overlay last said ("" when hidden)
    // The rotate gizmo (render/rotate_gizmo.h): the joint it turns, the Rotate joint window's
    // (-1 while that window is hidden), and whether the rest of the pose follows the learned prior
    // (the window's option); EditorApp sets both each frame. The ring under the mouse or being
    // dragged (its DOF axis, -1 none).
    int gizmoJoint = -1;
    bool gizmoFollowPrior = false;
    int gizmoRing = -1;
    // View > Onion skins and View > Motion trails (render/motion_overlays.h), over the edited motion.
    bool showOnionSkin = false;
    render::OnionSkin onionSkin;
    bool trails[render::kTrailPartCount] = {};  // by TrailPart
    static constexpr int kDefaultTrailHalfSpan = 30, kMaxTrailHalfSpan = 240;
    int trailHalfSpan = kDefaultTrailHalfSpan;  // frames each side of the current one
    bool showCapturedTrails = true;             // the captured motion's trail beneath each

    // Where the viewport's image was last drawn (window pixels), so points can be projected to
    // the window outside the viewport's draw (scripts, tests).
    float viewportX = 0.0f, viewportY = 0.0f;
    int viewportWidth = 0, viewportHeight = 0;

    // Where each panel's main controls were last drawn (window pixels) and whether they were
    // visible (not clipped away): the layout tests read it.
    struct ControlRect {
        float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
        bool visible = false;
    };
    std::map<std::string, ControlRect> controls;
    // Call right after drawing the item named `name`.
    void recordControl(const std::string& name);

    // A modal, menu or text field has the keyboard this frame: panels ignore their keys.
    bool keysBlocked = false;

    // The one way a panel asks the app for something: an action of the action table by name
    // (editor_actions.h: "train", "open-model", ...), run by the app later in the same frame.
    // Each request is the action's name followed by its arguments.
    std::vector<std::vector<std::string>> requests;
    void request(std::string action, std::vector<std::string> args = {}) {
        args.insert(args.begin(), std::move(action));
        requests.push_back(std::move(args));
    }
    // Set by the frame-camera action: the viewport frames the character on its next draw.
    bool requestFrameCamera = false;

    void setStatus(std::string s, bool error = false) { messages.post(std::move(s), error, uiSeconds, doc.revision()); }
    // A message that stays while `holds` is true, then becomes `after` (or goes when it is "").
    void setStatusWhile(std::string s, std::function<bool()> holds, std::string after = "") {
        messages.post(std::move(s), false, uiSeconds, doc.revision(), std::move(holds), std::move(after));
    }
};

}  // namespace mgp::ui
