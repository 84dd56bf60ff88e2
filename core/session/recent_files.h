#pragma once
// Recent files: the File ▸ Open Recent list, most recent first, at most 10 absolute paths, each
// tagged with what it is. Stored in configDir()/recent.json, written atomically:
//
//   {"format": "motiongp-recent", "version": 1,
//    "files": [{"path": absolute path, "kind": "session" | "clip" | "model"}, ...]}
//
// A damaged or foreign recent.json is ignored (the list starts empty and load() says why): it is
// a convenience, never a reason to refuse to start.
#include <cstddef>
#include <string>
#include <vector>

namespace mgp {

// A per-user folder: $<overrideVar> if set, else $<xdgVar>/motiongp, else $HOME/<homeRelative>
// (e.g. ".config/motiongp"). Created if missing (a failure shows up when a file is written).
std::string userDirectory(const char* overrideVar, const char* xdgVar, const char* homeRelative);
// $MOTIONGP_CONFIG_DIR, else $XDG_CONFIG_HOME/motiongp, else $HOME/.config/motiongp.
std::string configDir();

enum class RecentKind { kSession, kClip, kModel };
const char* recentKindName(RecentKind kind);
bool parseRecentKind(const std::string& name, RecentKind& out);

struct RecentFile {
    std::string path;  // absolute, symlinks resolved (one entry per real file)
    RecentKind kind = RecentKind::kSession;
};

class RecentFiles {
public:
    static constexpr std::size_t kMaxEntries = 10;

    // `file` = where the list lives; "" means configDir()/recent.json.
    explicit RecentFiles(std::string file = "");

    // Puts `path` (made absolute) first; an older entry for the same path is dropped and the
    // list is cut to kMaxEntries.
    void add(const std::string& path, RecentKind kind);
    void remove(const std::string& path);
    void clear() { entries_.clear(); }
    const std::vector<RecentFile>& entries() const { return entries_; }
    const std::string& file() const { return file_; }

    // Replaces the list with the file's. Returns "" (also when there is no file yet) or, for a
    // damaged file, "FILE: expected ..., found ... (ignored)" with the list left empty.
    std::string load();
    // Throws std::runtime_error ("PATH: expected a writable file, found …").
    void save() const;

private:
    std::string file_;
    std::vector<RecentFile> entries_;
};

}  // namespace mgp
