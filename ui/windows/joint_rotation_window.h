#pragma once
// Edit > Rotate joint: pick one joint (the combo, or click its bone in the viewport while the
// window is shown) and set its DOFs in degrees (core/edit/joint_rotation.h).
// A slider gesture previews the pose in the viewport (EditorState::posePreview) and becomes one
// undo step on release, through the `rotate-joint` action. "Follow with learned prior" re-solves
// the rest of the pose under the model, pins and feet in contact held.
#include <Eigen/Core>
#include <string>
#include <vector>

namespace mgp {
struct Joint;
}

namespace mgp::ui {

// The `rotate-joint` action that sets `joint`'s animated DOFs to anglesDeg (x, y, z; the axes it
// lacks left out): what the window's sliders and the viewport's gizmo run on release.
std::vector<std::string> rotateJointAction(const Joint& joint, const Eigen::Vector3d& anglesDeg);

class EditorCommands;
struct EditorState;

class JointRotationWindow {
public:
    void show() { open_ = true; }
    bool shown() const { return open_; }
    bool followPrior() const { return followPrior_; }
    void setFollowPrior(bool on) { followPrior_ = on; }
    // The joint the window edits (-1 none); selects it and shows the window.
    void selectJoint(int joint) {
        joint_ = joint;
        open_ = true;
    }
    int joint() const { return joint_; }
    const std::string& readout() const { return readout_; }  // the last solve, one line

    // Draws the window while shown.
    void draw(EditorCommands& app);
    // The `rotate-joint JOINT ANGLE...` action: one angle per DOF the joint has (degrees, strict
    // parsing), applied as one undo step, with the prior when the window's option is on.
    // "" or why not.
    std::string rotate(EditorState& state, const std::vector<std::string>& args);

private:
    bool open_ = false;
    bool followPrior_ = false;
    int joint_ = -1;
    bool gesture_ = false;  // a slider is being dragged (its preview is on screen)
    Eigen::Vector3d values_ = Eigen::Vector3d::Zero();
    std::string readout_;
};

}  // namespace mgp::ui
