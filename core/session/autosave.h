#pragma once
// Autosave: the editor writes its session (session/session_file.h) every couple of minutes while
// there are unsaved changes, to stateDir()/autosave-<pid>.mgsession — one file per running
// editor, so two editors never overwrite each other. A clean exit discards the file; after a
// crash it is left behind, and the next editor offers to restore it (findOrphanedAutosaves).
#include <optional>
#include <string>
#include <vector>

namespace mgp {

// $MOTIONGP_STATE_DIR, else $XDG_STATE_HOME/motiongp, else $HOME/.local/state/motiongp
// (created on demand).
std::string stateDir();
// stateDir()/autosave-<our pid>.mgsession
std::string autosavePath();

struct AutosaveCandidate {
    std::string path;
    int pid = 0;              // of the editor that wrote it
    double mtimeSeconds = 0;  // last modification, seconds since the Unix epoch
};

// Autosave files in `dir` whose editor is gone: its pid is not running (kill(pid, 0) fails with
// ESRCH), or it is our own pid but the file predates this process (a crashed editor whose pid
// was reused). Our own live autosave is never listed. Newest first.
std::vector<AutosaveCandidate> findOrphanedAutosaves(const std::string& dir);
std::vector<AutosaveCandidate> findOrphanedAutosaves();  // in stateDir()
// Removes the file (a missing file is not an error).
void discardAutosave(const std::string& path);

// When to autosave. Times are seconds on any monotonic clock; `dirty` means "changed since the
// last autosave". Due once the document has been dirty for the whole interval: the clock starts
// at the first due() call that sees it dirty, and restarts at markSaved() or when it is clean.
class AutosaveTimer {
public:
    explicit AutosaveTimer(double intervalSeconds = 120);
    bool due(double nowSeconds, bool dirty) const;
    void markSaved(double nowSeconds);
    double interval() const { return interval_; }

private:
    double interval_;
    // When the document was first seen dirty since the last save. due() is a query for the UI
    // loop, but it has to remember this, hence mutable.
    mutable std::optional<double> dirtySince_;
};

}  // namespace mgp
