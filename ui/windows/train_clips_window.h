#pragma once
// Model ▸ Train on clips…: a modal that trains one model on the open clip and other clips of its
// skeleton. It lists the candidates (core/edit/training_candidates.h: the open clip first, always
// included, the model's primary clip; the AMC files of the same skeleton beside it; the refused
// files greyed out with the reason as tooltip), takes the frame range and step applied to each
// clip (as `train --frames A:B --step K`), shows the total N, and uses the Model panel's training
// options (drawTrainOptions). Train checks the clips with gp::prepareTrainingClips, as the CLI
// does, and starts the editor's TrainingJob; the model is installed when it finishes, as Train's
// is (the open clip and its edits stay). Cancel or Esc closes it without changes.
#include <map>
#include <string>
#include <vector>

#include "edit/training_candidates.h"
#include "gp/train/training_clips.h"

namespace mgp::ui {

class EditorCommands;
struct EditorState;

class TrainClipsWindow {
public:
    // Lists the candidates of the open clip and shows the modal (only the open clip checked).
    void show(EditorCommands& app);
    bool shown() const { return open_; }
    void close() { open_ = false; }

    const std::vector<TrainingCandidate>& candidates() const { return candidates_; }
    bool checked(std::size_t i) const { return i < checked_.size() && checked_[i]; }
    // Ticks or clears the candidate named `name` (file stem or file name); a path not listed is
    // added first (as "Add file…" does). Loads the clip to count its frames. "" or why not.
    std::string check(const std::string& name, bool on = true);
    // "Add file…": a clip file by path, checked when it can train with the open clip.
    std::string addFile(const std::string& path);
    gp::FrameSelection& selection() { return selection_; }
    // The training rows of the checked clips under the selection (N), or -1 with `error` set.
    int totalRows(std::string* error = nullptr) const;
    // Checks the chosen clips (gp::prepareTrainingClips) and starts training with the Model
    // panel's options; closes the modal when it started. "" or why not.
    std::string train(EditorCommands& app);

    // Between NewFrame and Render.
    void draw(EditorCommands& app);

private:
    const Clip* clipOf(std::size_t i, const EditorCommands& app) const;  // loaded (or the open clip), null if not
    std::string load(std::size_t i);                                     // "" or the reader's error
    // The parts of draw(), top to bottom.
    void drawCandidates(EditorCommands& app, float scale);  // the list, each row's checkbox
    void drawAddFile(float scale);                          // a path typed in, and its button
    void drawFrameSelection(float scale);                   // from, to and step of each clip
    // N, a frame range's error and the last refusal; returns N (-1 when the range is wrong).
    int drawSummary(const EditorState& s, float scale) const;

    bool open_ = false;
    bool popupUp_ = false;  // the modal was drawn last frame
    std::string openName_;  // the open clip the list was made for
    Clip openHeader_;       // its name, file, skeleton and rest-frame flag (no frames): "Add file…"
                            // is judged against it
    int openFrames_ = 0;    // its frame count
    std::vector<TrainingCandidate> candidates_;
    std::vector<bool> checked_;
    std::map<std::string, Clip> loaded_;  // by path: the checked clips read so far
    gp::FrameSelection selection_;
    std::string addPath_;
    std::string error_;  // the last refusal, shown in the modal
};

}  // namespace mgp::ui
