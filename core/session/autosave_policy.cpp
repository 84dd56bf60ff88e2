#include "session/autosave_policy.h"

namespace mgp {

AutosavePolicy::AutosavePolicy(double intervalSeconds, std::string file)
    : timer_(intervalSeconds), file_(std::move(file)) {}

bool AutosavePolicy::due(double nowSeconds, bool unsaved, long revision) const {
    // Only what changed since the last autosave (and is not saved in the session) is worth writing.
    return timer_.due(nowSeconds, unsaved && revision != autosavedRevision_);
}

void AutosavePolicy::write(const SessionData& session, double nowSeconds, long revision) {
    if (file_.empty()) file_ = autosavePath();
    saveSession(file_, session);
    timer_.markSaved(nowSeconds);
    autosavedRevision_ = revision;
}

void AutosavePolicy::forget(double nowSeconds, long revision) {
    if (!file_.empty()) discardAutosave(file_);
    timer_.markSaved(nowSeconds);
    autosavedRevision_ = revision;
}

void AutosavePolicy::discard() {
    if (!file_.empty()) discardAutosave(file_);
}

}  // namespace mgp
