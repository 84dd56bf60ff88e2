// Recent files (order, dedup, cap, persistence, damaged list) and autosave (per-process path,
// orphans after a crash, the timer).
#include <doctest/doctest.h>

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <filesystem>

#include "session/autosave.h"
#include "session/recent_files.h"
#include "test_support.h"

using namespace mgp;
namespace fs = std::filesystem;

namespace {

// Sets an environment variable for one scope.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const char* value) : name_(name) {
        if (const char* old = std::getenv(name)) old_ = old;
        value ? ::setenv(name, value, 1) : ::unsetenv(name);
    }
    ~ScopedEnv() { old_.empty() ? ::unsetenv(name_) : ::setenv(name_, old_.c_str(), 1); }

private:
    const char* name_;
    std::string old_;
};

std::vector<std::string> paths(const RecentFiles& r) {
    std::vector<std::string> out;
    for (const RecentFile& f : r.entries()) out.push_back(f.path);
    return out;
}

// A pid no process has: kill(pid, 0) says ESRCH.
int deadPid() {
    for (int pid = 999999; pid > 1000; --pid)
        if (::kill(pid, 0) != 0 && errno == ESRCH) return pid;
    FAIL("no free pid found");
    return 0;
}

}  // namespace

TEST_CASE("the recent list is most recent first, without duplicates, at most 10, and persists") {
    const std::string dir = test::scratchDir("recent");
    RecentFiles r(dir + "/recent.json");
    r.add(dir + "/a.mgsession", RecentKind::kSession);
    r.add(dir + "/b.amc", RecentKind::kClip);
    r.add(dir + "/./a.mgsession", RecentKind::kSession);  // same file, moves to the front
    CHECK(paths(r) == std::vector<std::string>{dir + "/a.mgsession", dir + "/b.amc"});
    CHECK(r.entries()[1].kind == RecentKind::kClip);
    for (int i = 0; i < 12; ++i) r.add(dir + "/m" + std::to_string(i) + ".json", RecentKind::kModel);
    REQUIRE(r.entries().size() == RecentFiles::kMaxEntries);
    CHECK(r.entries().front().path == dir + "/m11.json");
    CHECK(r.entries().back().path == dir + "/m2.json");
    r.remove(dir + "/m5.json");
    CHECK(r.entries().size() == 9);

    r.save();
    RecentFiles again(dir + "/recent.json");
    CHECK(again.load() == "");
    CHECK(paths(again) == paths(r));
    CHECK(again.entries().front().kind == RecentKind::kModel);

    RecentFiles fresh(dir + "/none.json");
    CHECK(fresh.load() == "");  // no list yet is normal
    CHECK(fresh.entries().empty());
}

TEST_CASE("the recent list keeps one entry per real file, whatever link it was opened through") {
    const std::string dir = test::scratchDir("recent_links");
    test::writeText(dir + "/walk.amc", "x");
    std::error_code ec;
    fs::remove(dir + "/link.amc", ec);
    fs::create_symlink(dir + "/walk.amc", dir + "/link.amc");
    fs::remove(dir + "/linkdir", ec);
    fs::create_directory_symlink(dir, dir + "/linkdir");
    RecentFiles r(dir + "/recent.json");
    r.add(dir + "/walk.amc", RecentKind::kClip);
    r.add(dir + "/link.amc", RecentKind::kClip);
    r.add(dir + "/linkdir/walk.amc", RecentKind::kClip);
    REQUIRE(r.entries().size() == 1);
    CHECK(r.entries()[0].path == fs::canonical(dir + "/walk.amc").string());
    r.remove(dir + "/link.amc");
    CHECK(r.entries().empty());
}

TEST_CASE("a damaged recent list is ignored with a message") {
    const std::string dir = test::scratchDir("recent_damaged");
    const std::string file = dir + "/recent.json";
    RecentFiles r(file);
    r.add("/x/y.amc", RecentKind::kClip);
    const auto loadOf = [&](const std::string& text) {
        test::writeText(file, text);
        const std::string message = r.load();
        CHECK(r.entries().empty());
        return message;
    };
    CHECK(loadOf("{\"format\": \"motiongp-recent\", \"version\": 1, \"files\": [") ==
          file + ": expected a JSON recent-files list, found damaged JSON (ignored)");
    CHECK(loadOf("") == file + ": expected a JSON recent-files list, found an empty file (ignored)");
    CHECK(loadOf("{\"format\": \"motiongp-recent\", \"version\": 1, \"files\": [{\"path\": 3, \"kind\": \"clip\"}]}") ==
          file +
              ": expected entries {\"path\": string, \"kind\": session|clip|model}, found "
              "'{\"kind\":\"clip\",\"path\":3}' (ignored)");
    CHECK(loadOf("{\"format\": \"motiongp-recent\", \"version\": 9, \"files\": []}") ==
          file + ": expected version ≤ 1, found '9' (ignored)");
    CHECK(loadOf("[]") == file + ": expected \"format\": \"motiongp-recent\", found another document (ignored)");
}

TEST_CASE("configDir and stateDir follow MOTIONGP_*, then XDG, then HOME, and are created") {
    const std::string dir = test::scratchDir("dirs");
    {
        ScopedEnv a("MOTIONGP_CONFIG_DIR", (dir + "/cfg").c_str()), b("MOTIONGP_STATE_DIR", (dir + "/state").c_str());
        CHECK(configDir() == dir + "/cfg");
        CHECK(stateDir() == dir + "/state");
        CHECK(fs::is_directory(dir + "/cfg"));
        CHECK(RecentFiles().file() == dir + "/cfg/recent.json");
    }
    {
        ScopedEnv a("MOTIONGP_CONFIG_DIR", nullptr), b("MOTIONGP_STATE_DIR", nullptr);
        ScopedEnv c("XDG_CONFIG_HOME", (dir + "/xdgc").c_str()), d("XDG_STATE_HOME", (dir + "/xdgs").c_str());
        CHECK(configDir() == dir + "/xdgc/motiongp");
        CHECK(stateDir() == dir + "/xdgs/motiongp");
        ScopedEnv e("XDG_CONFIG_HOME", nullptr), f("XDG_STATE_HOME", nullptr), g("HOME", (dir + "/home").c_str());
        CHECK(configDir() == dir + "/home/.config/motiongp");
        CHECK(stateDir() == dir + "/home/.local/state/motiongp");
        CHECK(fs::is_directory(dir + "/home/.local/state/motiongp"));
    }
}

TEST_CASE("autosaves are per process, only those of dead editors are offered, newest first") {
    const std::string dir = test::scratchDir("autosave");
    ScopedEnv env("MOTIONGP_STATE_DIR", dir.c_str());
    const std::string ours = autosavePath();
    CHECK(ours == dir + "/autosave-" + std::to_string(::getpid()) + ".mgsession");
    test::writeText(ours, "{}");  // our own, live: never an orphan

    const int dead = deadPid();
    const std::string older = dir + "/autosave-" + std::to_string(dead) + ".mgsession";
    test::writeText(older, "{}");
    fs::last_write_time(older, fs::last_write_time(older) - std::chrono::hours(1));
    int dead2 = dead - 1;
    while (::kill(dead2, 0) == 0 || errno != ESRCH) --dead2;
    const std::string newer = dir + "/autosave-" + std::to_string(dead2) + ".mgsession";
    test::writeText(newer, "{}");
    test::writeText(dir + "/autosave-1.mgsession", "{}");  // pid 1 always runs
    test::writeText(dir + "/autosave-x.mgsession", "{}");  // not ours at all
    test::writeText(dir + "/autosave-" + std::to_string(dead) + ".mgsession.tmp.5", "{}");

    const std::vector<AutosaveCandidate> found = findOrphanedAutosaves();
    REQUIRE(found.size() == 2);
    CHECK(found[0].path == newer);
    CHECK(found[0].pid == dead2);
    CHECK(found[1].path == older);
    CHECK(found[1].pid == dead);
    CHECK(found[0].mtimeSeconds > found[1].mtimeSeconds);

    // A file with our pid from before this process started: a crashed editor whose pid we got.
    fs::last_write_time(ours, fs::last_write_time(ours) - std::chrono::hours(2));
    CHECK(findOrphanedAutosaves().size() == 3);

    discardAutosave(newer);
    discardAutosave(newer);  // already gone: fine
    CHECK_FALSE(fs::exists(newer));
    CHECK(findOrphanedAutosaves().size() == 2);
}

TEST_CASE("the autosave timer fires once the document has been dirty for the interval") {
    AutosaveTimer t(120);
    CHECK_FALSE(t.due(0, false));
    CHECK_FALSE(t.due(500, false));  // clean for a long time: nothing to save
    CHECK_FALSE(t.due(510, true));   // first dirty at 510
    CHECK_FALSE(t.due(629.9, true));
    CHECK(t.due(630, true));
    t.markSaved(631);
    CHECK_FALSE(t.due(632, true));  // the clock restarts after a save
    CHECK_FALSE(t.due(751, true));
    CHECK(t.due(752, true));
    CHECK_FALSE(t.due(900, false));  // saved by the user: clean again
    CHECK_FALSE(t.due(901, true));
    CHECK(t.due(1021, true));
}
