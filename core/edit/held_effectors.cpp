#include "edit/held_effectors.h"

#include <algorithm>

namespace mgp {

namespace {
const EditRecord* recordAt(const ClipEdits& edits, int frame) {
    const auto it = edits.edits().find(frame);
    return it == edits.edits().end() ? nullptr : &it->second;
}

bool contains(const std::vector<Effector>& v, Effector e) { return std::find(v.begin(), v.end(), e) != v.end(); }

EditRecord without(EditRecord record, Effector e) {
    record.moved.erase(std::remove(record.moved.begin(), record.moved.end(), e), record.moved.end());
    return record;
}
}  // namespace

bool isHeld(const ClipEdits& edits, int frame, Effector e) {
    const EditRecord* r = recordAt(edits, frame);
    return r && contains(r->moved, e);
}

bool anyHeld(const ClipEdits& edits) {
    return std::any_of(edits.edits().begin(), edits.edits().end(),
                       [](const auto& entry) { return !entry.second.moved.empty(); });
}

std::vector<Effector> heldOn(const ClipEdits& edits, int frame) {
    const EditRecord* r = recordAt(edits, frame);
    return r ? withHeld({}, r->moved) : std::vector<Effector>{};
}

std::vector<ContactInterval> heldRuns(const ClipEdits& edits, int first, int last, Effector except) {
    std::vector<ContactInterval> out;
    for (int i = 0; i < kEffectorCount; ++i) {
        const auto e = static_cast<Effector>(i);
        if (e == except) continue;
        int runStart = -1;
        for (int t = first; t <= last + 1; ++t) {
            const bool held = t <= last && isHeld(edits, t, e);
            if (held && runStart < 0) runStart = t;
            if (!held && runStart >= 0) {
                out.push_back({e, runStart, t - 1});
                runStart = -1;
            }
        }
    }
    return out;
}

std::vector<Effector> withHeld(std::vector<Effector> a, const std::vector<Effector>& b) {
    for (Effector e : b)
        if (!contains(a, e)) a.push_back(e);
    std::sort(a.begin(), a.end());
    return a;
}

FrameEdits releaseRun(const ClipEdits& edits, int frame, Effector e) {
    FrameEdits out;
    if (!isHeld(edits, frame, e)) return out;
    for (int t = frame; t >= 0 && isHeld(edits, t, e); --t) out[t] = without(*recordAt(edits, t), e);
    for (int t = frame + 1; t < edits.frameCount() && isHeld(edits, t, e); ++t)
        out[t] = without(*recordAt(edits, t), e);
    return out;
}

FrameEdits releaseEverywhere(const ClipEdits& edits) {
    FrameEdits out;
    for (const auto& [t, record] : edits.edits()) {
        if (record.moved.empty()) continue;
        EditRecord released = record;
        released.moved.clear();
        out[t] = std::move(released);
    }
    return out;
}

}  // namespace mgp
