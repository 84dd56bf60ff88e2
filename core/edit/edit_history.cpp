#include "edit/edit_history.h"

namespace mgp {

void EditHistory::push(EditStep step) {
    undo_.push_back(std::move(step));
    redo_.clear();
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

gp::ModelVersionPtr ModelVersionLog::before(long sequence) const {
    auto it = after_.lower_bound(sequence);  // first entry ≥ sequence: the one before it is ours
    if (it == after_.begin()) return nullptr;
    return std::prev(it)->second;
}

}  // namespace mgp
