#pragma once
// The editor's autosave policy: write this editor's autosave file (autosave.h) once unsaved
// changes have waited the whole interval and the last autosave does not already hold them;
// forget it after a save or an open (it is stale then), remove it on a normal quit.
#include <string>

#include "session/autosave.h"
#include "session/session_file.h"

namespace mgp {

class AutosavePolicy {
public:
    // `file` "" = autosavePath(), chosen at the first write.
    explicit AutosavePolicy(double intervalSeconds = 120, std::string file = "");

    // `unsaved`: the document differs from its session file; `revision`: the document's revision.
    bool due(double nowSeconds, bool unsaved, long revision) const;
    // Writes `session` (atomically; throws as saveSession) and restarts the clock.
    void write(const SessionData& session, double nowSeconds, long revision);
    // A save or an open holds everything: the autosave file goes and the clock restarts.
    void forget(double nowSeconds, long revision);
    void discard();                                    // a normal quit: no autosave is left to offer
    const std::string& file() const { return file_; }  // "" before the first write
    double interval() const { return timer_.interval(); }

private:
    AutosaveTimer timer_;
    std::string file_;
    long autosavedRevision_ = 0;
};

}  // namespace mgp
