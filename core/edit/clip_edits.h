#pragma once
// ClipEdits: the clip being edited and what the user changed on it (docs/architecture.md §2).
//   clip       the loaded motion, angles unwrapped over time so it matches a model's rows
//   edits      accepted poses per frame; a frame without an edit shows the captured pose
//   contacts   the clip's foot contacts (motion/foot_contacts.h), some possibly switched off
// A change of edits arrives as a frame → (edit or none) map: the same map an undo step keeps,
// so applying a step's `before` or `after` is one call.
#include <cstddef>
#include <map>
#include <optional>
#include <string>

#include "edit/edit_record.h"
#include "motion/foot_contacts.h"
#include "skeleton/clip.h"

namespace mgp {

class ClipEdits {
public:
    // Replaces the clip (unwrapped here) and drops every edit; contacts are detected anew.
    void reset(Clip clip, bool synthetic);
    const Clip& clip() const { return clip_; }
    Clip& mutableClip() { return clip_; }  // renaming only; the frames are fixed once loaded
    bool synthetic() const { return synthetic_; }
    int frameCount() const { return clip_.frameCount(); }
    bool empty() const { return clip_.frameCount() == 0; }

    // The edit on `frame`, else the captured pose.
    const Pose& pose(int frame) const;
    bool isEdited(int frame) const { return edits_.count(frame) != 0; }
    std::optional<EditRecord> editAt(int frame) const;
    const std::map<int, EditRecord>& edits() const { return edits_; }
    // The frames' edits as they are now, for the `before` side of a step touching `frames`.
    FrameEdits current(const FrameEdits& frames) const;
    void apply(const FrameEdits& frames);
    void set(int frame, EditRecord record) { edits_[frame] = std::move(record); }
    void replaceAll(std::map<int, EditRecord> edits) { edits_ = std::move(edits); }

    const ContactSet& contacts() const { return contacts_; }
    // Switches contact `index` on or off; false if nothing changed (or no such contact).
    bool setContactEnabled(std::size_t index, bool on);

private:
    Clip clip_;
    bool synthetic_ = false;
    std::map<int, EditRecord> edits_;
    ContactSet contacts_;
};

}  // namespace mgp
