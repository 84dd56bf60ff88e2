#pragma once
// What the action table and the editor's windows may ask of the editor shell: open, save and
// export files, start trainings, the pose clipboard, quitting, the help window, the layout. The
// shell's EditorApp (ui/shell/) implements it; the action table, the menu bar, the windows and
// the script player see only this interface and EditorState, so no ui/ code but the shell
// depends on EditorApp. Each std::string result is "" or the error; nothing here throws.
#include <functional>
#include <string>
#include <vector>

#include "gp/train/training_clips.h"
#include "skeleton/skeleton.h"
#include "ui/shell/file_requests.h"

namespace mgp {
class RecentFiles;
}

namespace mgp::ui {

struct EditorState;
class FileDialog;
class JointRotationWindow;

class EditorCommands {
public:
    virtual ~EditorCommands() = default;

    virtual EditorState& state() = 0;
    virtual const EditorState& state() const = 0;
    virtual float uiScale() const = 0;  // HiDPI: the factor for fonts, spacing and window sizes
    // Runs a named action (ui/actions/editor_actions.h; args[0] is the name).
    virtual std::string runAction(const std::vector<std::string>& args) = 0;

    // Files (EditorApp's declarations say which of them ask about unsaved changes first).
    virtual std::string openClip(const std::string& path) = 0;
    virtual void openSyntheticClip(const std::string& why) = 0;
    virtual std::string openModel(const std::string& path, bool askedAboutUnsaved = false) = 0;
    virtual std::string saveModel(const std::string& path) = 0;
    virtual std::string openModelClip(const std::string& name, int frame) = 0;
    virtual std::string openSession(const std::string& path, bool addToRecent = true) = 0;
    virtual std::string saveSession(const std::string& path) = 0;
    virtual void saveSessionOrAsk() = 0;
    virtual std::string autosaveNow() = 0;
    virtual std::string restoreAutosave(const std::string& path = "") = 0;
    virtual std::string exportMotion(const std::string& path, const std::string& defaultExtension) = 0;
    virtual std::string exportPng(const std::string& path) = 0;
    virtual void askForFile(FileKind kind, const std::string& what = "") = 0;
    virtual const FileDialog& fileDialog() const = 0;
    virtual const RecentFiles* recentFiles() const = 0;  // null when turned off
    virtual void openRecent(const std::string& path) = 0;

    // Unsaved work and the questions about it.
    virtual bool dirty() const = 0;
    virtual void guardUnsaved(std::function<void()> action, std::string what) = 0;
    virtual std::string runAfterAsking(bool unsaved, std::function<std::string()> run, std::string what) = 0;
    virtual void requestQuit() = 0;
    virtual void confirmQuit() = 0;

    // Training.
    virtual std::string startTraining() = 0;
    virtual std::string startTraining(std::vector<gp::TrainingClip> clips, const gp::FrameSelection& selection) = 0;
    virtual std::string startCompareTraining() = 0;
    virtual std::string trainOnClips(const std::vector<std::string>& args) = 0;
    virtual void waitIdle() = 0;

    // Poses.
    virtual void copyPose() = 0;
    virtual std::string pastePose() = 0;
    virtual bool hasCopiedPose() const = 0;
    virtual std::string mirrorPose() = 0;
    virtual std::string rotateJoint(const std::vector<std::string>& args) = 0;
    virtual JointRotationWindow& jointWindow() = 0;

    // Windows and layout.
    virtual void toggleHelp() = 0;
    virtual bool layoutCustomized() const = 0;
    virtual void resetLayout() = 0;

    // Window pixels of what the last frame drew (the script player's hover targets).
    virtual bool handleScreenPosition(Effector e, float& x, float& y) const = 0;
    virtual bool keyScreenPosition(int key, float& x, float& y) const = 0;
    virtual bool latentDotScreenPosition(const std::string& clip, int frame, float& x, float& y) const = 0;
};

}  // namespace mgp::ui
