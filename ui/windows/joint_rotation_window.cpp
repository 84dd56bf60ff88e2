#include "ui/windows/joint_rotation_window.h"

#include <imgui.h>

#include <cmath>
#include <cstdio>

#include "edit/joint_rotation.h"
#include "ui/actions/action_args.h"
#include "ui/actions/editor_commands.h"
#include "ui/shell/editor_state.h"
#include "ui/widgets/widgets.h"

namespace mgp::ui {

namespace {
constexpr const char* kAxisNames[3] = {"rx", "ry", "rz"};

bool animates(const Joint& j) { return j.dof[0] || j.dof[1] || j.dof[2]; }

}  // namespace

std::vector<std::string> rotateJointAction(const Joint& joint, const Eigen::Vector3d& anglesDeg) {
    std::vector<std::string> args{"rotate-joint", joint.name};
    for (int a = 0; a < 3; ++a) {
        if (!joint.dof[a]) continue;
        char buf[40];
        std::snprintf(buf, sizeof buf, "%.17g", anglesDeg[a]);  // round-trips the double exactly
        args.push_back(buf);
    }
    return args;
}

void JointRotationWindow::draw(EditorCommands& app) {
    EditorState& s = app.state();
    EditorDocument& doc = s.doc;
    if (!open_ || !doc.hasClip()) {
        if (gesture_) s.posePreview.reset();
        gesture_ = false;
        return;
    }
    const Skeleton& sk = doc.clip().skeleton;
    if (joint_ < 0 || joint_ >= sk.jointCount() || !animates(sk.joints[joint_])) {
        joint_ = sk.findBone("lhumerus");
        for (int j = 0; joint_ < 0 && j < sk.jointCount(); ++j)
            if (animates(sk.joints[j])) joint_ = j;
    }
    ImGui::SetNextWindowSize(ImVec2(330 * app.uiScale(), 0), ImGuiCond_Appearing);
    ImGui::SetNextWindowPos(ImVec2(s.viewportX + 12 * app.uiScale(), s.viewportY + 40 * app.uiScale()),
                            ImGuiCond_Appearing);
    if (!ImGui::Begin("Rotate joint", &open_, ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_AlwaysAutoResize) ||
        joint_ < 0) {
        ImGui::End();
        return;
    }
    if (ImGui::BeginCombo("Joint", sk.joints[joint_].name.c_str())) {
        for (int j = 0; j < sk.jointCount(); ++j) {
            if (!animates(sk.joints[j])) continue;
            if (ImGui::Selectable(sk.joints[j].name.c_str(), j == joint_)) joint_ = j;
        }
        ImGui::EndCombo();
    }
    s.recordControl("rotate joint: joint");
    // Between gestures the sliders show the frame's pose (frame changes, undo, other edits), or
    // the rotation the viewport's gizmo is previewing.
    if (!gesture_) values_ = (s.posePreview ? *s.posePreview : doc.currentPose()).anglesDeg[joint_];
    bool changed = false, active = false, released = false;
    const Joint& jt = sk.joints[joint_];
    for (int a = 0; a < 3; ++a) {
        if (!jt.dof[a]) continue;
        // The ASF reader does not keep `limits`, so the range is a turn around zero (wider for an
        // unwrapped angle beyond it); Ctrl+click types a value.
        const double lo = std::min(-180.0, std::floor(values_[a])), hi = std::max(180.0, std::ceil(values_[a]));
        if (ImGui::SliderScalar(kAxisNames[a], ImGuiDataType_Double, &values_[a], &lo, &hi, "%.2f deg")) changed = true;
        s.recordControl(std::string("rotate joint: ") + kAxisNames[a]);
        active = active || ImGui::IsItemActive();
        released = released || ImGui::IsItemDeactivatedAfterEdit();
    }
    const bool hasModel = doc.hasModel();
    if (!hasModel) ImGui::BeginDisabled();
    bool follow = followPrior_ && hasModel;
    if (ImGui::Checkbox("Follow with learned prior", &follow)) followPrior_ = follow;
    s.recordControl("rotate joint: follow prior");
    if (!hasModel) {
        ImGui::EndDisabled();
        ImGui::TextDisabled("(the prior needs a model)");
    }
    if (changed && !released) {
        // Live preview: a short solve per change, the full one on release.
        JointRotation rot;
        rot.joint = joint_;
        rot.anglesDeg = values_;
        rot.followPrior = followPrior_ && hasModel;
        const JointRotationResult r = solveJointRotation(doc, rot, 30);
        if (r.error.empty()) s.posePreview = r.pose;
        gesture_ = true;
    }
    if (released) {
        const std::string err = app.runAction(rotateJointAction(jt, values_));
        if (!err.empty()) s.setStatus(err, true);
        s.posePreview.reset();
        gesture_ = false;
    } else if (!active && gesture_) {
        s.posePreview.reset();  // the gesture ended without an edit
        gesture_ = false;
    }
    if (!readout_.empty()) textWrappedAtSpaces(readout_);
    ImGui::End();
    if (!open_ && gesture_) {
        s.posePreview.reset();
        gesture_ = false;
    }
}

std::string JointRotationWindow::rotate(EditorState& state, const std::vector<std::string>& a) {
    EditorDocument& doc = state.doc;
    if (!doc.hasClip()) return "no clip: open one first";
    const Skeleton& sk = doc.clip().skeleton;
    const int joint = sk.findJoint(a[0]) >= 0 ? sk.findJoint(a[0]) : sk.findBone(a[0]);
    if (joint < 0) return "rotate-joint: unknown joint '" + a[0] + "'";
    const Joint& jt = sk.joints[joint];
    std::string axes;
    for (int k = 0; k < 3; ++k)
        if (jt.dof[k]) axes += std::string(axes.empty() ? "" : " ") + "xyz"[k];
    const std::size_t want = (jt.dof[0] ? 1 : 0) + (jt.dof[1] ? 1 : 0) + (jt.dof[2] ? 1 : 0);
    if (want == 0) return "rotate-joint: " + jt.name + " has no rotation DOFs";
    if (a.size() - 1 != want)
        return "rotate-joint: expected " + std::to_string(want) + " angle" + (want > 1 ? "s" : "") + " for " + jt.name +
               " (" + axes + "), found " + std::to_string(a.size() - 1);
    JointRotation rot;
    rot.joint = joint;
    rot.anglesDeg = doc.currentPose().anglesDeg[joint];
    rot.followPrior = followPrior_;
    std::size_t next = 1;
    for (int k = 0; k < 3; ++k)
        if (jt.dof[k])
            if (std::string err = parseFloatArg(a[next++], "an angle in degrees", rot.anglesDeg[k]); !err.empty())
                return err;
    JointRotationResult result;
    const std::string err = applyJointRotation(doc, rot, &result);
    if (!err.empty()) return err;
    selectJoint(joint);
    std::string text = "rotated " + jt.name + " on frame " + std::to_string(doc.frame() + 1);
    char buf[200];
    if (result.learned) {
        std::snprintf(buf, sizeof buf,
                      "; the prior re-solved the rest%s: L_IK %.1f, %d held effector%s within %.3f cm (%s)",
                      result.settled ? ", the hips settled" : "", result.ik.lik, result.holdCount,
                      result.holdCount == 1 ? "" : "s", result.holdMissCm, ikStopName(result.ik.stop));
        text += buf;
    } else if (result.settled) {
        std::snprintf(buf, sizeof buf, "; the legs and hips kept %d held effector%s within %.3f cm", result.holdCount,
                      result.holdCount == 1 ? "" : "s", result.holdMissCm);
        text += buf;
    }
    if (result.holdMissCm > kReachedToleranceCm) {
        std::snprintf(buf, sizeof buf, "; a held effector is %.1f cm off its place (out of reach)", result.holdMissCm);
        text += buf;
    }
    readout_ = text;
    state.setStatus(text);
    return "";
}

}  // namespace mgp::ui
