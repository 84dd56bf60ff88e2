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
