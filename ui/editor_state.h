#pragma once
// What the editor's panels share: the document (core), the background jobs, the camera and the
// small amount of UI-only state. Panels read and write it; EditorApp owns it.
#include <optional>
#include <string>

#include "camera.h"
#include "edit/editor_document.h"
#include "edit/training_job.h"
#include "gp/trainer.h"

namespace mgp::ui {

struct EditorState {
    EditorDocument doc;
    TrainingJob training;         // the main model
    TrainingJob compareTraining;  // the compare model (the other kernel)
    gp::TrainOptions trainOptions;
    render::OrbitCamera camera;
    bool cameraNeedsFraming = true;
    bool followCharacter = true;  // the camera follows the root over the ground

    std::string clipLabel;   // shown in the title bar
    std::string modelLabel;  // "trained fas", a file name, ...
    std::string status;      // the status bar's latest message
    bool statusIsError = false;

    bool playing = false;
    double playAccumulator = 0.0;  // fractional frames

    int hoveredHandle = -1;  // Effector under the mouse in the viewport, -1 none
    std::optional<Effector> selected;
    int hoveredTrainingRow = -1;  // latent map hover

    // Path editing (path panel, viewport, timeline); keys are indices into doc.pathEdit()->keyFrames.
    int hoveredKey = -1;            // path key under the mouse in the viewport, -1 none
    int selectedKey = -1;           // path key last dragged or picked, -1 none
    bool showCapturedPath = true;   // the captured path beside the edited one
    bool showBeforeGhost = false;   // the current frame's pose before the last undoable step

    // Where the viewport's image was last drawn (window pixels), so points can be projected to
    // the window outside the viewport's draw (scripts, tests).
    float viewportX = 0.0f, viewportY = 0.0f;
    int viewportWidth = 0, viewportHeight = 0;

    // Requests the panels raise for EditorApp (file dialogs, training).
    bool requestOpenClip = false, requestOpenModel = false, requestSaveModel = false;
    bool requestTrain = false, requestTrainCompare = false, requestFrameCamera = false;
    bool requestQuit = false;

    void setStatus(std::string s, bool error = false) {
        status = std::move(s);
        statusIsError = error;
    }
};

}  // namespace mgp::ui
