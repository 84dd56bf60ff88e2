#include "ui/actions/editor_actions.h"

#include <imgui.h>

#include "ui/actions/action_args.h"
#include "ui/actions/editor_commands.h"
#include "ui/input/input_state.h"
#include "ui/shell/editor_state.h"
#include "ui/windows/joint_rotation_window.h"

namespace mgp::ui {

namespace {
using Run = std::function<std::string(EditorCommands&, const ActionArgs&)>;
using Enabled = std::function<bool(const EditorCommands&)>;

const EditorDocument& docOf(const EditorCommands& app) { return app.state().doc; }

// An action that takes no arguments and cannot fail.
Run plain(std::function<void(EditorCommands&)> f) {
    return [f = std::move(f)](EditorCommands& app, const ActionArgs&) {
        f(app);
        return std::string();
    };
}

// Moves the current frame by `delta` frames.
Run step(int delta) {
    return plain([delta](EditorCommands& app) { app.state().doc.setFrame(app.state().doc.frame() + delta); });
}

std::string effectorArg(const ActionArgs& a, Effector& e) {
    if (a.empty()) return "expected an effector (lhand rhand lfoot rfoot head)";
    if (!parseEffector(a[0], e)) return "unknown effector '" + a[0] + "'";
    return "";
}

// A release's step names what it let go of, on the status line; an error is returned as it is.
std::string reportRelease(EditorCommands& app, std::string err) {
    if (err.empty()) app.state().setStatus(app.state().doc.undoLabel());
    return err;
}

// A PATH argument runs `withPath`; none asks for the file with the dialog of `kind`.
Run pathOrDialog(std::function<std::string(EditorCommands&, const std::string&)> withPath,
                 std::function<void(EditorCommands&)> ask) {
    return [withPath = std::move(withPath), ask = std::move(ask)](EditorCommands& app, const ActionArgs& a) {
        if (!a.empty()) return withPath(app, a[0]);
        ask(app);
        return std::string();
    };
}

std::string train(EditorCommands& app, const ActionArgs& a) {
    EditorState& s = app.state();
    gp::TrainOptions o = s.trainOptions;
    if (a.size() > 0) {
        if (a[0] != "fas" && a[0] != "sgplvm") return "expected fas or sgplvm, found '" + a[0] + "'";
        o.kind = a[0] == "sgplvm" ? gp::KernelKind::kSgplvm : gp::KernelKind::kFas;
    }
    if (a.size() > 1)
        if (std::string err = parseIntArg(a[1], "the active set size M", o.activeSize); !err.empty()) return err;
    if (a.size() > 2)
        if (std::string err = parseIntArg(a[2], "the iteration count T", o.outerIterations); !err.empty()) return err;
    s.trainOptions = o;
    return app.startTraining();
}

std::string pathKeys(EditorCommands& app, const ActionArgs& a) {
    std::vector<int> keys;
    for (const std::string& t : a) {
        int f = 0;
        if (std::string err = parseIntArg(t, "a key frame", f); !err.empty()) return err;
        keys.push_back(f - 1);
    }
    return app.state().doc.paths().setKeyFrames(std::move(keys));
}

std::string pathOffset(EditorCommands& app, const ActionArgs& a) {
    if (a.size() != 4) return "expected path-offset KEY DX DY DZ";
    int key = 0;
    Eigen::Vector3d d;
    if (std::string err = parseIntArg(a[0], "the key number", key); !err.empty()) return err;
    for (int i = 0; i < 3; ++i)
        if (std::string err = parseFloatArg(a[1 + i], "an offset in cm", d[i]); !err.empty()) return err;
    return app.state().doc.paths().setKeyOffset(key - 1, d);
}

std::string regenerate(EditorCommands& app, const ActionArgs& a) {
    int iterations = 500;
    if (!a.empty())
        if (std::string err = parseIntArg(a[0], "the iteration count", iterations); !err.empty()) return err;
    return app.state().doc.startRegenerate(iterations);
}

// The table as it is made: the actions so far (in menu order) and the predicates several share.
struct ActionList {
    std::vector<EditorAction> actions;
    const Enabled always;  // null: enabled whatever the state
    const Enabled hasClip = [](const EditorCommands& app) { return docOf(app).hasClip(); };
    const Enabled hasModel = [](const EditorCommands& app) { return docOf(app).hasModel(); };
    const Enabled canPose = [](const EditorCommands& app) {
        return docOf(app).hasClip() && !docOf(app).regenerating();
    };
    const Enabled canTrain = [](const EditorCommands& app) {
        return docOf(app).trainable() && !app.state().training.running();
    };
    void add(EditorAction a) { actions.push_back(std::move(a)); }
};

// Opening and saving: clips, sessions and models.
void addOpenSaveActions(ActionList& list) {
    list.add({"open",
              "[PATH]",
              "Ctrl+O",
              {{'O', kCtrl}},
              "open an ASF/AMC or BVH clip; no PATH: the Open dialog (session, clip or model)",
              list.always,
              false,
              pathOrDialog(
                  [](EditorCommands& app, const std::string& p) {
                      // A PATH replaces the document as the dialog's choice does: after asking.
                      return app.runAfterAsking(
                          app.dirty(), [&app, p] { return app.openClip(p); }, "opening a clip");
                  },
                  [](EditorCommands& app) { app.askForFile(FileKind::kOpenAny, "opening another file"); })});
    list.add({"save-session",
              "[PATH]",
              "Ctrl+S",
              {{'S', kCtrl}},
              "save the session (no PATH: to its file, or ask for one)",
              list.hasClip,
              true,
              pathOrDialog([](EditorCommands& app, const std::string& p) { return app.saveSession(p); },
                           [](EditorCommands& app) { app.saveSessionOrAsk(); })});
    list.add({"save-session-as",
              "",
              "Ctrl+Shift+S",
              {{'S', kCtrl | kShift}},
              "save the session under a new name (the Save dialog)",
              list.hasClip,
              true,
              plain([](EditorCommands& app) { app.askForFile(FileKind::kSaveSession); })});
    list.add({"open-session",
              "PATH",
              "",
              {},
              "open a session",
              list.always,
              false,
              [](EditorCommands& app, const ActionArgs& a) {
                  if (a.empty()) return std::string("expected open-session PATH");
                  return app.runAfterAsking(
                      app.dirty(), [&app, p = a[0]] { return app.openSession(p); }, "opening a session");
              }});
    list.add({"open-model",
              "[PATH]",
              "Ctrl+M",
              {{'M', kCtrl}},
              "open a saved model with its clip (asks first if that is not the open clip); no PATH: the Open dialog",
              list.always,
              false,
              pathOrDialog([](EditorCommands& app, const std::string& p) { return app.openModel(p); },
                           [](EditorCommands& app) { app.askForFile(FileKind::kModel, "opening a model"); })});
    list.add({"model-clip",
              "NAME [N]",
              "",
              {},
              "make the model's training clip NAME the open clip at frame N (default 1), the model staying; asks about "
              "unsaved changes",
              list.hasModel,
              false,
              [](EditorCommands& app, const ActionArgs& a) {
                  if (a.empty()) return std::string("expected model-clip NAME [N]");
                  int n = 1;
                  if (a.size() > 1)
                      if (std::string err = parseIntArg(a[1], "a frame number N", n); !err.empty()) return err;
                  return app.openModelClip(a[0], n - 1);
              }});
    list.add({"save-model",
              "[PATH]",
              "",
              {},
              "save the current model; no PATH: the Save dialog",
              list.hasModel,
              false,
              pathOrDialog([](EditorCommands& app, const std::string& p) { return app.saveModel(p); },
                           [](EditorCommands& app) { app.askForFile(FileKind::kSaveModel); })});
}

// Exports, the demo clip, autosaves and quitting.
void addExportAndQuitActions(ActionList& list) {
    list.add({"export-bvh",
              "[PATH]",
              "Ctrl+E",
              {{'E', kCtrl}},
              "the edited motion as BVH; no PATH: the Save dialog",
              list.hasClip,
              true,
              pathOrDialog([](EditorCommands& app, const std::string& p) { return app.exportMotion(p, ".bvh"); },
                           [](EditorCommands& app) { app.askForFile(FileKind::kExportBvh); })});
    list.add({"export-gltf",
              "[PATH]",
              "",
              {},
              "the edited motion as glTF 2.0 (.glb; .gltf for text); no PATH: the Save dialog",
              list.hasClip,
              true,
              pathOrDialog([](EditorCommands& app, const std::string& p) { return app.exportMotion(p, ".glb"); },
                           [](EditorCommands& app) { app.askForFile(FileKind::kExportGltf); })});
    list.add({"export-fbx",
              "[PATH]",
              "",
              {},
              "the edited motion as FBX, converted by Blender in the background; no PATH: the Save dialog",
              list.hasClip,
              true,
              pathOrDialog([](EditorCommands& app, const std::string& p) { return app.exportMotion(p, ".fbx"); },
                           [](EditorCommands& app) { app.askForFile(FileKind::kExportFbx); })});
    list.add({"export-png",
              "[PATH]",
              "Ctrl+Shift+E",
              {{'E', kCtrl | kShift}},
              "the 3-D viewport as PNG; no PATH: the Save dialog",
              list.hasClip,
              true,
              pathOrDialog([](EditorCommands& app, const std::string& p) { return app.exportPng(p); },
                           [](EditorCommands& app) { app.askForFile(FileKind::kExportPng); })});
    list.add({"demo-clip",
              "",
              "",
              {},
              "open the synthetic demo clip (asks about unsaved changes)",
              list.always,
              false,
              plain([](EditorCommands& app) {
                  app.guardUnsaved([&app] { app.openSyntheticClip(""); }, "opening the demo clip");
              })});
    list.add({"autosave",
              "",
              "",
              {},
              "write this editor's autosave file now",
              list.always,
              false,
              [](EditorCommands& app, const ActionArgs&) { return app.autosaveNow(); }});
    list.add({"restore-autosave",
              "[PATH]",
              "",
              {},
              "restore an autosave (default: the newest a dead editor left)",
              list.always,
              false,
              [](EditorCommands& app, const ActionArgs& a) { return app.restoreAutosave(a.empty() ? "" : a[0]); }});
    list.add({"quit",
              "",
              "Ctrl+Q",
              {{'Q', kCtrl}},
              "quit (asks about unsaved changes)",
              list.always,
              false,
              plain([](EditorCommands& app) { app.requestQuit(); })});
    list.add({"discard-and-quit", "", "", {}, "quit without asking", list.always, false, plain([](EditorCommands& app) {
                  app.confirmQuit();
              })});
}

// Undo and redo, and the actions on the current frame's pose.
void addUndoAndPoseActions(ActionList& list) {
    list.add({"undo",
              "",
              "Ctrl+Z",
              {{'Z', kCtrl, true}},
              "undo one step (a drag or a regeneration is one step; so is the model version it changed)",
              [](const EditorCommands& app) { return docOf(app).canUndo() && !docOf(app).regenerating(); },
              true,
              [](EditorCommands& app, const ActionArgs&) {
                  // The status line says what went, so it no longer shows what the step had said.
                  const std::string label = app.state().doc.undoLabel();
                  std::string err = app.state().doc.undo();
                  if (err.empty()) app.state().setStatus("undid " + label);
                  return err;
              }});
    list.add({"redo",
              "",
              "Ctrl+Shift+Z",
              {{'Z', kCtrl | kShift, true}, {'Y', kCtrl, true}},
              "redo one step (also Ctrl+Y)",
              [](const EditorCommands& app) { return docOf(app).canRedo() && !docOf(app).regenerating(); },
              true,
              [](EditorCommands& app, const ActionArgs&) {
                  const std::string label = app.state().doc.redoLabel();
                  std::string err = app.state().doc.redo();
                  if (err.empty()) app.state().setStatus("redid " + label);
                  return err;
              }});
    list.add({"revert-frame",
              "",
              "",
              {},
              "revert the current frame to the capture",
              [](const EditorCommands& app) { return docOf(app).isEdited(docOf(app).frame()); },
              false,
              plain([](EditorCommands& app) { app.state().doc.clearEdit(app.state().doc.frame()); })});
    list.add({"copy-pose",
              "",
              "Ctrl+C",
              {{'C', kCtrl}},
              "copy the current frame's pose",
              list.hasClip,
              true,
              plain([](EditorCommands& app) { app.copyPose(); })});
    list.add({"paste-pose",
              "",
              "Ctrl+V",
              {{'V', kCtrl}},
              "paste the copied pose onto the current frame (root kept), one undo step",
              [](const EditorCommands& app) { return app.hasCopiedPose() && !docOf(app).regenerating(); },
              true,
              [](EditorCommands& app, const ActionArgs&) { return app.pastePose(); }});
    list.add({"mirror-pose",
              "",
              "Ctrl+Shift+M",
              {{'M', kCtrl | kShift}},
              "mirror the current frame's pose left/right (root position and heading kept), one undo step",
              list.canPose,
              true,
              [](EditorCommands& app, const ActionArgs&) { return app.mirrorPose(); }});
    list.add({"rotate-joint",
              "[JOINT ANGLE...]",
              "",
              {},
              "set a joint's DOFs in degrees (one per axis it animates, x y z order), one undo step; no arguments: the "
              "Rotate joint window",
              list.canPose,
              false,
              [](EditorCommands& app, const ActionArgs& a) { return app.rotateJoint(a); }});
    list.add({"follow-prior",
              "on|off",
              "",
              {},
              "rotate joint: the rest of the pose follows the learned prior (pins and feet in contact held)",
              list.always,
              false,
              [](EditorCommands& app, const ActionArgs& a) {
                  if (a.empty() || (a[0] != "on" && a[0] != "off"))
                      return "expected on or off, found '" + (a.empty() ? std::string() : a[0]) + "'";
                  app.jointWindow().setFollowPrior(a[0] == "on");
                  return std::string();
              }});
}

// Pins and held effectors.
void addPinAndHeldActions(ActionList& list) {
    list.add({"pin",
              "EFFECTOR",
              "P on handle",
              {},
              "pin or unpin an effector (lhand rhand lfoot rfoot head)",
              list.hasClip,
              false,
              [](EditorCommands& app, const ActionArgs& a) {
                  Effector e;
                  if (std::string err = effectorArg(a, e); !err.empty()) return err;
                  app.state().doc.togglePin(e);
                  return std::string();
              }});
    list.add({"release",
              "EFFECTOR",
              "Alt+click on handle",
              {},
              "release a held effector on the current frame and the neighbouring frames that hold it, one undo step",
              [](const EditorCommands& app) { return !docOf(app).heldEffectors().empty(); },
              false,
              [](EditorCommands& app, const ActionArgs& a) {
                  Effector e;
                  if (std::string err = effectorArg(a, e); !err.empty()) return err;
                  return reportRelease(app, app.state().doc.releaseHeld(e));
              }});
    list.add(
        {"release-all",
         "",
         "",
         {},
         "release every held effector on every frame, one undo step",
         [](const EditorCommands& app) { return docOf(app).anythingHeld(); },
         true,
         [](EditorCommands& app, const ActionArgs&) { return reportRelease(app, app.state().doc.releaseAllHeld()); }});
}

// Editing an effector's path and regenerating its span.
void addPathActions(ActionList& list) {
    list.add({"path",
              "EFFECTOR",
              "",
              {},
              "edit that effector's path (default keys around the current frame)",
              list.hasClip,
              false,
              [](EditorCommands& app, const ActionArgs& a) {
                  Effector e;
                  if (std::string err = effectorArg(a, e); !err.empty()) return err;
                  return app.state().doc.beginPathEdit(e);
              }});
    list.add({"path-keys",
              "F1 F2 ...",
              "",
              {},
              "the path's key frames (1-based, increasing)",
              list.always,
              false,
              pathKeys});
    list.add({"path-offset",
              "K DX DY DZ",
              "",
              {},
              "key K's (1-based) offset from the captured path, cm",
              list.always,
              false,
              pathOffset});
    list.add({"path-mode",
              "direct|displacement",
              "",
              {},
              "how the path's keys move the effector",
              list.always,
              false,
              [](EditorCommands& app, const ActionArgs& a) {
                  if (a.empty() || (a[0] != "direct" && a[0] != "displacement"))
                      return "expected direct or displacement, found '" + (a.empty() ? std::string() : a[0]) + "'";
                  app.state().doc.paths().setMode(a[0] == "displacement" ? PathMode::kDisplacement : PathMode::kDirect);
                  return std::string();
              }});
    list.add({"regenerate",
              "[ITERS]",
              "Ctrl+R",
              {{'R', kCtrl}},
              "solve the path span between the first and last key (background)",
              [](const EditorCommands& app) { return docOf(app).paths().edit() && !docOf(app).regenerating(); },
              false,
              regenerate});
    list.add({"cancel-regenerate",
              "",
              "",
              {},
              "cancel the running regeneration",
              [](const EditorCommands& app) { return docOf(app).regenerating(); },
              false,
              plain([](EditorCommands& app) { app.state().doc.cancelRegenerate(); })});
}

// Keys, the timeline range and Fill between keys; then the end of path editing.
void addKeyActions(ActionList& list) {
    list.add({"key",
              "",
              "K",
              {{'K', 0}},
              "mark or unmark the current frame as a key",
              list.hasClip,
              false,
              plain([](EditorCommands& app) { app.state().doc.toggleKey(app.state().doc.frame()); })});
    list.add({"timeline-range",
              "FIRST LAST|off",
              "Shift+drag on the timeline",
              {},
              "select frames FIRST..LAST (1-based) for Fill between keys, or drop the selection",
              list.hasClip,
              false,
              [](EditorCommands& app, const ActionArgs& a) {
                  if (a.size() == 1 && a[0] == "off") {
                      app.state().timelineRange.reset();
                      return std::string();
                  }
                  const int n = docOf(app).frameCount();
                  int first = 0, last = 0;
                  if (a.size() != 2) return std::string("expected FIRST LAST or off");
                  if (std::string err = parseIntArg(a[0], "a first frame FIRST", first); !err.empty()) return err;
                  if (std::string err = parseIntArg(a[1], "a last frame LAST", last); !err.empty()) return err;
                  if (first < 1 || last > n || first > last)
                      return "expected 1 ≤ FIRST ≤ LAST ≤ " + std::to_string(n) + ", found " + a[0] + " " + a[1];
                  app.state().timelineRange = std::make_pair(first - 1, last - 1);
                  return std::string();
              }});
    list.add(
        {"fill-between-keys",
         "[prior|interpolate]",
         "Ctrl+I",
         {{'I', kCtrl}},
         "regenerate the frames between keys from the keys and the training clips (background), one undo step: every "
         "gap inside "
         "the timeline's Shift+drag range, else the gap around the playhead",
         [](const EditorCommands& app) {
             const EditorDocument& d = docOf(app);
             const auto& range = app.state().timelineRange;
             const bool gaps =
                 range ? !d.keyGapsIn(range->first, range->second).empty() : d.keyGapAt(d.frame()).has_value();
             return d.hasModel() && gaps && !d.regenerating();
         },
         true,
         [](EditorCommands& app, const ActionArgs& a) {
             InbetweenMethod method = InbetweenMethod::kPrior;
             if (!a.empty()) {
                 if (a[0] == "interpolate")
                     method = InbetweenMethod::kInterpolate;
                 else if (a[0] != "prior")
                     return "expected prior or interpolate, found '" + a[0] + "'";
             }
             const std::string err = app.state().doc.startFill(method, app.state().timelineRange);
             if (err.empty()) app.state().setStatus("filling between keys...");
             return err;
         }});
    list.add({"end-path",
              "",
              "",
              {},
              "stop editing the path",
              [](const EditorCommands& app) { return docOf(app).paths().edit().has_value(); },
              false,
              plain([](EditorCommands& app) { app.state().doc.paths().end(); })});
}

// Training and the adaptive active set.
void addModelActions(ActionList& list) {
    list.add({"train",
              "[fas|sgplvm] [M] [T]",
              "Ctrl+T",
              {{'T', kCtrl}},
              "train on the open clip (defaults from the Model panel)",
              list.canTrain,
              false,
              train});
    list.add(
        {"train-clips",
         "[CLIPS [A:B|all] [K] [M] [T]]",
         "",
         {},
         "train on the open clip and others of its skeleton (CLIPS: comma-separated names or paths; frames A:B and "
         "step K "
         "of each clip; M, T as for train); no arguments: the Train on clips dialog",
         [](const EditorCommands& app) { return docOf(app).hasClip() && !app.state().training.running(); },
         false,
         [](EditorCommands& app, const ActionArgs& a) { return app.trainOnClips(a); }});
    list.add({"cancel-train",
              "",
              "",
              {},
              "cancel the training run",
              [](const EditorCommands& app) { return app.state().training.running(); },
              false,
              plain([](EditorCommands& app) { app.state().training.cancel(); })});
    list.add({"train-compare",
              "",
              "",
              {},
              "train the compare model (the other kernel) for `compare model`",
              list.always,
              false,
              [](EditorCommands& app, const ActionArgs&) { return app.startCompareTraining(); }});
    list.add({"adaptive",
              "on|off",
              "",
              {},
              "the adaptive active set (accepted poses join the model)",
              list.always,
              false,
              [](EditorCommands& app, const ActionArgs& a) {
                  if (a.empty() || (a[0] != "on" && a[0] != "off"))
                      return "expected on or off, found '" + (a.empty() ? std::string() : a[0]) + "'";
                  app.state().doc.setAdaptiveEnabled(a[0] == "on");
                  return std::string();
              }});
    list.add({"wait",
              "",
              "",
              {},
              "block until training, exports, adaptive updates and the latent map are done",
              list.always,
              false,
              plain([](EditorCommands& app) { app.waitIdle(); })});
}

// The camera, the compare ghost and the layout.
void addViewActions(ActionList& list) {
    list.add({"frame-camera",
              "",
              "F",
              {},
              "frame the character (F over the viewport)",
              list.always,
              false,
              plain([](EditorCommands& app) { app.state().requestFrameCamera = true; })});
    list.add({"compare",
              "none|plain|model",
              "",
              {},
              "the compare ghost: off, plain IK or the second model",
              list.always,
              false,
              [](EditorCommands& app, const ActionArgs& a) {
                  CompareMode m;
                  if (a.empty() || !parseCompareMode(a[0], m))
                      return "expected none, plain or model, found '" + (a.empty() ? std::string() : a[0]) + "'";
                  app.state().doc.setCompareMode(m);
                  return std::string();
              }});
    list.add({"reset-layout",
              "",
              "",
              {},
              "the panels' default sizes",
              [](const EditorCommands& app) { return app.layoutCustomized(); },
              false,
              plain([](EditorCommands& app) { app.resetLayout(); })});
}

// Playback, frame stepping, the help window and screenshots.
void addPlaybackAndHelpActions(ActionList& list) {
    list.add({"play-pause",
              "",
              "Space",
              {{key::kSpace}},
              "start or stop playback",
              list.always,
              false,
              plain([](EditorCommands& app) { app.state().playing = !app.state().playing; })});
    list.add({"play", "", "", {}, "start playback", list.always, false, plain([](EditorCommands& app) {
                  app.state().playing = true;
              })});
    list.add({"pause", "", "", {}, "stop playback", list.always, false, plain([](EditorCommands& app) {
                  app.state().playing = false;
              })});
    list.add(
        {"next-frame", "", "Right", {{key::kRight, kNoMods, true}}, "the next frame", list.always, false, step(1)});
    list.add({"previous-frame",
              "",
              "Left",
              {{key::kLeft, kNoMods, true}},
              "the previous frame",
              list.always,
              false,
              step(-1)});
    list.add({"forward-10",
              "",
              "Shift+Right",
              {{key::kRight, kShift, true}},
              "10 frames forward",
              list.always,
              false,
              step(10)});
    list.add(
        {"back-10", "", "Shift+Left", {{key::kLeft, kShift, true}}, "10 frames back", list.always, false, step(-10)});
    list.add({"first-frame",
              "",
              "Home",
              {{key::kHome}},
              "the first frame",
              list.always,
              false,
              plain([](EditorCommands& app) { app.state().doc.setFrame(0); })});
    list.add(
        {"last-frame", "", "End", {{key::kEnd}}, "the last frame", list.always, false, plain([](EditorCommands& app) {
             app.state().doc.setFrame(app.state().doc.frameCount() - 1);
         })});
    list.add({"frame",
              "N",
              "",
              {},
              "go to frame N (1-based, as the timeline shows it)",
              list.always,
              false,
              [](EditorCommands& app, const ActionArgs& a) {
                  int n = 0;
                  if (std::string err = parseIntArg(a.empty() ? "" : a[0], "a frame number N", n); !err.empty())
                      return err;
                  app.state().doc.setFrame(n - 1);
                  return std::string();
              }});
    // ---- Help
    list.add({"help",
              "",
              "F1",
              {{key::kF1}},
              "show or hide the controls window",
              list.always,
              false,
              plain([](EditorCommands& app) { app.toggleHelp(); })});
    list.add({"screenshot",
              "PATH",
              "",
              {},
              "save a PNG of the whole window after this frame (scripts only)",
              list.always,
              false,
              [](EditorCommands&, const ActionArgs&) {
                  return std::string("screenshot: only a script can take one (after its frame is drawn)");
              }});
}

std::vector<EditorAction> makeActions() {
    ActionList list;
    // ---- File
    addOpenSaveActions(list);
    addExportAndQuitActions(list);
    // ---- Edit
    addUndoAndPoseActions(list);
    addPinAndHeldActions(list);
    addPathActions(list);
    addKeyActions(list);
    // ---- Model
    addModelActions(list);
    // ---- View
    addViewActions(list);
    // ---- Playback, Help
    addPlaybackAndHelpActions(list);
    return std::move(list.actions);
}
}  // namespace

const ActionTable& ActionTable::editor() {
    static const ActionTable table = [] {
        ActionTable a;
        a.actions_ = makeActions();
        return a;
    }();
    return table;
}

const EditorAction* ActionTable::find(const std::string& name) const {
    for (const EditorAction& a : actions_)
        if (a.name == name) return &a;
    return nullptr;
}

bool ActionTable::enabled(const std::string& name, const EditorCommands& app) const {
    const EditorAction* a = find(name);
    return a && (!a->enabled || a->enabled(app));
}

std::string ActionTable::run(EditorCommands& app, const std::vector<std::string>& args) const {
    if (args.empty()) return "empty action";
    const EditorAction* a = find(args[0]);
    if (!a) return "unknown action '" + args[0] + "'";
    return a->run(app, ActionArgs(args.begin() + 1, args.end()));
}

namespace {
// Runs an action for a shortcut or a menu: its error goes to the status line, unless the action
// already said something there (training reports its own refusal).
void runReporting(EditorCommands& app, const EditorAction& a, const ActionArgs& args) {
    const long before = app.state().messages.postCount();
    const std::string err = a.run(app, args);
    if (!err.empty() && app.state().messages.postCount() == before) app.state().setStatus(err, true);
}
}  // namespace

void ActionTable::runShortcuts(EditorCommands& app) const {
    for (const EditorAction& a : actions_) {
        bool pressed = false;
        for (const KeyChord& c : a.chords) pressed |= chordPressed(c.key, c.mods, c.repeat);
        if (!pressed || !(a.keyWhenDisabled || !a.enabled || a.enabled(app))) continue;
        runReporting(app, a, {});
    }
}

void ActionTable::menuItem(EditorCommands& app, const std::string& name, const std::string& label,
                           const ActionArgs& args, bool selected, bool alsoEnabled) const {
    const EditorAction* a = find(name);
    if (!a) return;
    const bool on = alsoEnabled && (!a->enabled || a->enabled(app));
    if (!ImGui::MenuItem(label.c_str(), a->shortcut.empty() ? nullptr : a->shortcut.c_str(), selected, on)) return;
    runReporting(app, *a, args);
}

std::string ActionTable::markdownTable() const {
    auto cell = [](std::string s) {  // a table cell: '|' escaped
        std::string out;
        for (char c : s) out += c == '|' ? std::string("\\|") : std::string(1, c);
        return out;
    };
    std::string t = "| action | shortcut | what it does |\n|---|---|---|\n";
    for (const EditorAction& a : actions_) {
        const std::string call = a.args.empty() ? a.name : a.name + " " + a.args;
        t += "| `" + cell(call) + "` | " + cell(a.shortcut) + " | " + cell(a.summary) + " |\n";
    }
    return t;
}

}  // namespace mgp::ui
