#include "session/autosave.h"

#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <filesystem>

#include "session/recent_files.h"
#include "session/session_file.h"

namespace mgp {

namespace {

namespace fs = std::filesystem;

constexpr const char* kPrefix = "autosave-";

// Taken during static initialisation, i.e. when this process started: an autosave with our pid
// that is older than this was written by an earlier process that had the same pid.
const double kProcessStart = std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();

// "autosave-1234.mgsession" → 1234; 0 for any other name (temporaries included).
int pidFromName(const std::string& name) {
    const std::string ext = kSessionExtension;
    const std::size_t prefix = std::char_traits<char>::length(kPrefix);
    if (name.size() <= prefix + ext.size() || name.compare(0, prefix, kPrefix) != 0 ||
        name.compare(name.size() - ext.size(), ext.size(), ext) != 0)
        return 0;
    const std::string digits = name.substr(prefix, name.size() - prefix - ext.size());
    if (digits.size() > 9 || !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
        return 0;
    return std::stoi(digits);
}

bool processRunning(int pid) { return ::kill(pid, 0) == 0 || errno != ESRCH; }

}  // namespace

std::string stateDir() { return userDirectory("MOTIONGP_STATE_DIR", "XDG_STATE_HOME", ".local/state/motiongp"); }

std::string autosavePath() { return stateDir() + "/" + kPrefix + std::to_string(::getpid()) + kSessionExtension; }

std::vector<AutosaveCandidate> findOrphanedAutosaves(const std::string& dir) {
    std::vector<AutosaveCandidate> out;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
        const int pid = pidFromName(entry.path().filename().string());
        struct stat st {};
        if (pid <= 0 || ::stat(entry.path().c_str(), &st) != 0 || !S_ISREG(st.st_mode)) continue;
        const double mtime = static_cast<double>(st.st_mtim.tv_sec) + 1e-9 * static_cast<double>(st.st_mtim.tv_nsec);
        const bool orphan = pid == ::getpid() ? mtime < kProcessStart : !processRunning(pid);
        if (orphan) out.push_back({entry.path().string(), pid, mtime});
    }
    std::sort(out.begin(), out.end(), [](const AutosaveCandidate& a, const AutosaveCandidate& b) {
        return a.mtimeSeconds != b.mtimeSeconds ? a.mtimeSeconds > b.mtimeSeconds : a.path < b.path;
    });
    return out;
}

std::vector<AutosaveCandidate> findOrphanedAutosaves() { return findOrphanedAutosaves(stateDir()); }

void discardAutosave(const std::string& path) {
    std::error_code ec;
    fs::remove(path, ec);
}

AutosaveTimer::AutosaveTimer(double intervalSeconds) : interval_(intervalSeconds) {}

bool AutosaveTimer::due(double nowSeconds, bool dirty) const {
    if (!dirty) {
        dirtySince_.reset();
        return false;
    }
    if (!dirtySince_) dirtySince_ = nowSeconds;
    return nowSeconds - *dirtySince_ >= interval_;
}

void AutosaveTimer::markSaved(double /*nowSeconds*/) { dirtySince_.reset(); }

}  // namespace mgp
