#include "edit/clip_edits.h"

#include <exception>
#include <utility>

namespace mgp {

void ClipEdits::reset(Clip clip, bool synthetic) {
    unwrapClip(clip);
    clip_ = std::move(clip);
    synthetic_ = synthetic;
    edits_.clear();
    try {
        contacts_ = detectFootContacts(clip_);
    } catch (const std::exception&) {
        contacts_ = {};  // no feet to hold: regeneration holds pins only
    }
}

const Pose& ClipEdits::pose(int frame) const {
    const auto it = edits_.find(frame);
    return it != edits_.end() ? it->second.pose : clip_.frames[frame];
}

std::optional<EditRecord> ClipEdits::editAt(int frame) const {
    const auto it = edits_.find(frame);
    return it == edits_.end() ? std::nullopt : std::optional<EditRecord>(it->second);
}

FrameEdits ClipEdits::current(const FrameEdits& frames) const {
    FrameEdits out;
    for (const auto& entry : frames) out[entry.first] = editAt(entry.first);
    return out;
}

void ClipEdits::apply(const FrameEdits& frames) {
    for (const auto& [frame, record] : frames) {
        if (record)
            edits_[frame] = *record;
        else
            edits_.erase(frame);
    }
}

bool ClipEdits::setContactEnabled(std::size_t index, bool on) {
    if (index >= contacts_.contacts.size() || contacts_.contacts[index].enabled == on) return false;
    contacts_.contacts[index].enabled = on;
    return true;
}

}  // namespace mgp
