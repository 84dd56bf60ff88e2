#pragma once
// Undo/redo of editor steps. One step = one drag, one latent drag, one regeneration or one
// cleared edit: the frames it touched (their edits before and after; none = captured pose) and
// the adaptive samples it posted. Undo also restores the model version the step changed, so the
// history also keeps a log of which version each adaptive sample left behind
// (ModelVersionLog): the version before a step is the one published after the last sample
// posted before it. Versions are immutable shared pointers, so "restores" means exactly.
#include <climits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "edit/edit_record.h"
#include "gp/model_version.h"

namespace mgp {

struct EditStep {
    // Given by EditHistory::push (or restore), unique within one history: how a later change to
    // the step (a drag's falloff merged into the drag's step) finds it; labels may repeat.
    long id = 0;
    std::string label;          // "drag rfoot on frame 101", shown as "Undo drag rfoot on frame 101"
    FrameEdits before, after;   // per touched frame (0-based)
    std::vector<long> samples;  // adaptive sample sequence numbers
    // Resolved on the first undo (the updates may still run when the step is recorded); both
    // null when the step leaves the model alone (no samples, or a model installed since).
    bool modelResolved = false;
    gp::ModelVersionPtr modelBefore, modelAfter;
};

class EditHistory {
public:
    // Each step keeps model versions alive (~1 MB each at N ≈ 350): the oldest steps go first.
    static constexpr std::size_t kMaxSteps = 100;
    // Drops the redo branch (and the oldest step beyond kMaxSteps); returns the step's id.
    long push(EditStep step);
    bool canUndo() const { return !undo_.empty(); }
    bool canRedo() const { return !redo_.empty(); }
    EditStep* topUndo() { return undo_.empty() ? nullptr : &undo_.back(); }
    EditStep* topRedo() { return redo_.empty() ? nullptr : &redo_.back(); }
    // The step on top of the undo stack when it is the one with `id`, else null (undone or superseded).
    EditStep* topUndoWithId(long id);
    const EditStep* topUndo() const { return undo_.empty() ? nullptr : &undo_.back(); }
    const EditStep* topRedo() const { return redo_.empty() ? nullptr : &redo_.back(); }
    void moveUndoToRedo();
    void moveRedoToUndo();
    void clear();
    // A new model replaced the one the steps refer to: keep their poses, stop touching the model.
    void forgetModels();
    int undoCount() const { return static_cast<int>(undo_.size()); }
    // Both stacks, oldest first (the top of each is its last step), for saving a session.
    const std::vector<EditStep>& undoSteps() const { return undo_; }
    const std::vector<EditStep>& redoSteps() const { return redo_; }
    // Replaces both stacks with steps read from a session. Model versions are not kept in a
    // session, so these steps restore frames only (as after forgetModels).
    void restore(std::vector<EditStep> undo, std::vector<EditStep> redo);
    // The first sample of the oldest step whose model versions are not resolved yet (what the
    // version log must still answer for); LONG_MAX when there is none.
    long oldestUnresolvedSample() const;

private:
    std::vector<EditStep> undo_, redo_;
    long lastId_ = 0;
};

// Which model version was current after each adaptive sample (by sequence number).
class ModelVersionLog {
public:
    // Starts over: `initial` is current before any sample after `lastSequence`.
    void reset(gp::ModelVersionPtr initial, long lastSequence = 0);
    void record(long sequence, gp::ModelVersionPtr published);
    // The version current once every sample before `sequence` was processed (null if unknown).
    gp::ModelVersionPtr before(long sequence) const;
    // Forgets what no before(s ≥ sequence) query can need (frees old versions).
    void pruneBefore(long sequence);

private:
    std::map<long, gp::ModelVersionPtr> after_;
};

}  // namespace mgp
