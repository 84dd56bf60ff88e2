#include "edit/edit_history.h"

#include <algorithm>

namespace mgp {

long EditHistory::push(EditStep step) {
    step.id = ++lastId_;
    undo_.push_back(std::move(step));
    redo_.clear();
    if (undo_.size() > kMaxSteps) undo_.erase(undo_.begin());
    return lastId_;
}

EditStep* EditHistory::topUndoWithId(long id) {
    EditStep* top = topUndo();
    return top && top->id == id ? top : nullptr;
}

long EditHistory::oldestUnresolvedSample() const {
    long oldest = LONG_MAX;
    for (const auto* stack : {&undo_, &redo_})
        for (const EditStep& s : *stack)
            if (!s.modelResolved && !s.samples.empty()) oldest = std::min(oldest, s.samples.front());
    return oldest;
}

void EditHistory::moveUndoToRedo() {
    redo_.push_back(std::move(undo_.back()));
    undo_.pop_back();
}

void EditHistory::moveRedoToUndo() {
    undo_.push_back(std::move(redo_.back()));
    redo_.pop_back();
}

void EditHistory::clear() {
    undo_.clear();
    redo_.clear();
}

void EditHistory::restore(std::vector<EditStep> undo, std::vector<EditStep> redo) {
    undo_ = std::move(undo);
    redo_ = std::move(redo);
    for (auto* stack : {&undo_, &redo_})
        for (EditStep& s : *stack) s.id = ++lastId_;
    forgetModels();
}

void EditHistory::forgetModels() {
    for (auto* stack : {&undo_, &redo_})
        for (EditStep& s : *stack) {
            s.samples.clear();
            s.modelResolved = true;
            s.modelBefore = s.modelAfter = nullptr;
        }
}

void ModelVersionLog::reset(gp::ModelVersionPtr initial, long lastSequence) {
    after_.clear();
    after_[lastSequence] = std::move(initial);
}

void ModelVersionLog::record(long sequence, gp::ModelVersionPtr published) { after_[sequence] = std::move(published); }

void ModelVersionLog::pruneBefore(long sequence) {
    auto keep = after_.lower_bound(sequence);
    if (keep == after_.begin()) return;
    after_.erase(after_.begin(), std::prev(keep));  // the entry just below answers before(sequence)
}

gp::ModelVersionPtr ModelVersionLog::before(long sequence) const {
    auto it = after_.lower_bound(sequence);  // first entry ≥ sequence: the one before it is ours
    if (it == after_.begin()) return nullptr;
    return std::prev(it)->second;
}

}  // namespace mgp
