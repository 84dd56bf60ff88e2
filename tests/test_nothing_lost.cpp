// Nothing lost: the atomic writes of MODELS (`motiongp train --out`) and
// SESSIONS (saveSession) under a kill mid-save, a full disk and a read-only folder, and what a
// killed save leaves behind. The writer's own tests are in test_atomic_file.cpp; the GUI's
// killed save and autosave restore in tests/gl/test_gui_sessions.cpp.
//
// Faults come from io/atomic_file.h's MOTIONGP_FAULT (slow-write:<ms> to kill mid-save, enospc).
// Root ignores directory permissions, so as root the read-only-folder writes run in a forked
// child after setgid/setuid(65534) (nobody), where the permission applies.
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <thread>

#include "gp/model_file.h"
#include "gp/train/trainer.h"
#include "io/parse_error.h"
#include "session/session_file.h"
#include "skeleton/synthetic_clip.h"
#include "skip.h"
#include "test_support.h"

using namespace mgp;
namespace fs = std::filesystem;

namespace {

// Files in `dir` other than those named in `keep`.
std::vector<std::string> strays(const std::string& dir, const std::vector<std::string>& keep) {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(dir)) {
        const std::string name = e.path().filename().string();
        if (std::find(keep.begin(), keep.end(), name) == keep.end()) out.push_back(name);
    }
    return out;
}

bool waitForFile(const std::string& path, double seconds) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    std::error_code ec;
    while (std::chrono::steady_clock::now() < end) {
        if (fs::exists(path, ec) && fs::file_size(path, ec) > 0) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return false;
}

// A short training run written to `out` (ASF/AMC: the train verb does not read BVH).
std::vector<std::string> trainArgs(const std::string& out) {
    return {"train",       test::mocap("asf_amc/35_01.amc"),
            "--frames",    "1:30",
            "--active",    "10",
            "--iters",     "1",
            "--scg-iters", "5",
            "--threads",   "1",
            "--out",       out};
}

test::CliLimits withFault(const std::string& fault) {
    test::CliLimits l;
    l.timeoutSeconds = 120;
    if (!fault.empty()) l.env = {{"MOTIONGP_FAULT", fault}};
    return l;
}

// The previous model: a first, successful `motiongp train`.
std::string trainPrevious(const std::string& path) {
    const test::CliResult r = test::runCliArgs(trainArgs(path), withFault(""));
    INFO(test::describe(r) << "\n" << r.err);
    REQUIRE(r.exitCode == 0);
    const std::string text = test::readText(path);
    REQUIRE(!text.empty());
    return text;
}

SessionData sessionWithFrame(int frame) {
    SessionData s;
    s.syntheticClip = true;
    s.syntheticFrames = 120;
    s.frame = frame;
    s.camera.yawDeg = frame;
    s.ui = {{"note", std::string(static_cast<std::size_t>(1000 + frame), 'u')}};
    return s;
}

void checkSessionLoads(const std::string& path, int frame) {
    const SessionData s = loadSession(path);
    CHECK(s.frame == frame);
    CHECK(loadSessionClip(s, path).has_value());
}

// Runs `fn` in a forked child (as nobody when root, so that file permissions apply) and returns
// the message it threw ("" if none). The message comes back through a pipe.
std::string inChild(bool asNobody, const std::function<void()>& fn) {
    int fds[2];
    REQUIRE(::pipe(fds) == 0);
    const pid_t pid = ::fork();
    REQUIRE(pid >= 0);
    if (pid == 0) {
        ::close(fds[0]);
        if (asNobody && ::geteuid() == 0 && !test::becomeNobody()) ::_exit(126);
        std::string msg;
        try {
            fn();
        } catch (const std::exception& e) {
            msg = e.what();
        }
        if (!msg.empty() && ::write(fds[1], msg.data(), msg.size()) < 0) ::_exit(125);
        ::_exit(0);
    }
    ::close(fds[1]);
    std::string msg;
    char buf[512];
    ssize_t n;
    while ((n = ::read(fds[0], buf, sizeof buf)) > 0) msg.append(buf, static_cast<std::size_t>(n));
    ::close(fds[0]);
    int status = 0;
    REQUIRE(::waitpid(pid, &status, 0) == pid);
    REQUIRE(WIFEXITED(status));
    REQUIRE(WEXITSTATUS(status) == 0);
    return msg;
}

}  // namespace

TEST_CASE("models: `motiongp train --out` killed mid-save keeps the previous model, and the leftover is harmless") {
    const std::string dir = test::scratchDir("lost_model_kill");
    const std::string path = dir + "/model.json";
    const std::string previous = trainPrevious(path);

    // (a) A second run, killed while its save sleeps half-way through the temporary file.
    const test::CliLimits slow = withFault("slow-write:30000");
    const test::Child child = test::spawnCli(trainArgs(path), slow);
    const std::string tmp = path + ".tmp." + std::to_string(child.pid);
    const bool sawTmp = waitForFile(tmp, 60);
    ::kill(-child.pid, SIGKILL);
    const test::CliResult killed = test::waitBounded(child, slow);
    REQUIRE(sawTmp);
    CHECK(killed.signal == SIGKILL);
    CHECK(test::readText(path) == previous);  // byte-identical
    CHECK_NOTHROW(gp::loadModel(path));
    CHECK(fs::exists(tmp));  // the half-written temporary is all that is left of it
    CHECK(fs::file_size(tmp) < previous.size());

    // (d) The leftover confuses neither a load nor the next save, and that save removes it
    // (its process is gone).
    CHECK(gp::loadModel(path).N() == 30);
    const test::CliResult again = test::runCliArgs(trainArgs(path), withFault(""));
    INFO(test::describe(again) << "\n" << again.err);
    REQUIRE(again.exitCode == 0);
    CHECK(gp::loadModel(path).N() == 30);
    CHECK(test::readText(path) == previous);  // the same run again: the same bytes (no timestamps)
    CHECK_FALSE(fs::exists(tmp));
    CHECK(strays(dir, {"model.json"}).empty());
}

TEST_CASE("models: a full disk (MOTIONGP_FAULT=enospc) fails `motiongp train` clearly and keeps the previous model") {
    const std::string dir = test::scratchDir("lost_model_enospc");
    const std::string path = dir + "/model.json";
    const std::string previous = trainPrevious(path);
    const test::CliResult r = test::runCliArgs(trainArgs(path), withFault("enospc"));
    INFO(test::describe(r));
    CHECK(r.signal == 0);
    CHECK(r.exitCode != 0);
    CHECK(r.exitCode == 1);  // not bad input (2): the machine's problem
    CHECK(r.err.find("motiongp: error: " + path + ": expected a writable file, found No space left on device\n") !=
          std::string::npos);
    CHECK(test::readText(path) == previous);
    CHECK_NOTHROW(gp::loadModel(path));
    CHECK(strays(dir, {"model.json"}).empty());
}

TEST_CASE("models: a read-only folder fails `motiongp train` clearly and keeps the previous model") {
    const std::string dir = test::scratchDir("lost_model_readonly");
    const std::string sub = dir + "/ro";
    fs::create_directory(sub);
    const std::string path = sub + "/model.json";
    const std::string previous = trainPrevious(path);
    const std::string unreachable = test::unreachableAsNobody({sub, test::mocap("asf_amc/35_01.amc")});
    if (!unreachable.empty()) MGP_SKIP(unreachable);
    REQUIRE(::chmod(sub.c_str(), 0555) == 0);
    test::CliLimits l = withFault("");
    l.dropRoot = true;  // as root: run as nobody, for whom the folder is read-only
    const test::CliResult r = test::runCliArgs(trainArgs(path), l);
    ::chmod(sub.c_str(), 0755);
    INFO(test::describe(r));
    CHECK(r.signal == 0);
    CHECK(r.exitCode == 1);
    CHECK(r.err.find("motiongp: error: " + path + ": expected a writable file, found Permission denied\n") !=
          std::string::npos);
    CHECK(test::readText(path) == previous);
    CHECK_NOTHROW(gp::loadModel(path));
    CHECK(strays(sub, {"model.json"}).empty());
}

TEST_CASE("sessions: saveSession killed mid-save keeps the previous session, and the leftover is harmless") {
    const std::string dir = test::scratchDir("lost_session_kill");
    const std::string path = dir + "/work.mgsession";
    saveSession(path, sessionWithFrame(3));
    const std::string previous = test::readText(path);

    ::setenv("MOTIONGP_FAULT", "slow-write:30000", 1);
    const pid_t pid = ::fork();
    REQUIRE(pid >= 0);
    if (pid == 0) {  // no doctest in the child
        try {
            saveSession(path, sessionWithFrame(7));
        } catch (...) {
            ::_exit(2);
        }
        ::_exit(0);
    }
    ::unsetenv("MOTIONGP_FAULT");
    const std::string tmp = path + ".tmp." + std::to_string(pid);
    const bool sawTmp = waitForFile(tmp, 20);
    ::kill(pid, SIGKILL);
    int status = 0;
    REQUIRE(::waitpid(pid, &status, 0) == pid);
    REQUIRE(sawTmp);
    CHECK(WIFSIGNALED(status));
    CHECK(test::readText(path) == previous);
    checkSessionLoads(path, 3);
    CHECK(fs::exists(tmp));

    // (d) The next save and load ignore the leftover; the save removes it (its process is gone).
    saveSession(path, sessionWithFrame(9));
    checkSessionLoads(path, 9);
    CHECK_FALSE(fs::exists(tmp));
    CHECK(strays(dir, {"work.mgsession"}).empty());
}

TEST_CASE("sessions: a stale temporary of a LIVE process or of another target is left alone") {
    const std::string dir = test::scratchDir("lost_session_live");
    const std::string path = dir + "/work.mgsession";
    // pid 1 always runs; "other.mgsession.tmp.<dead pid>" belongs to another target.
    test::writeText(path + ".tmp.1", "a save in progress elsewhere");
    pid_t dead = ::fork();
    REQUIRE(dead >= 0);
    if (dead == 0) ::_exit(0);
    REQUIRE(::waitpid(dead, nullptr, 0) == dead);
    test::writeText(dir + "/other.mgsession.tmp." + std::to_string(dead), "not ours");
    test::writeText(path + ".tmp.notapid", "not a temporary of ours");
    saveSession(path, sessionWithFrame(4));
    checkSessionLoads(path, 4);
    CHECK(fs::exists(path + ".tmp.1"));
    CHECK(fs::exists(dir + "/other.mgsession.tmp." + std::to_string(dead)));
    CHECK(fs::exists(path + ".tmp.notapid"));
}

TEST_CASE(
    "sessions: a full disk (MOTIONGP_FAULT=enospc) fails saveSession clearly, keeps the previous one, no temporary") {
    const std::string dir = test::scratchDir("lost_session_enospc");
    const std::string path = dir + "/work.mgsession";
    saveSession(path, sessionWithFrame(3));
    const std::string previous = test::readText(path);
    ::setenv("MOTIONGP_FAULT", "enospc", 1);
    CHECK_THROWS_WITH_AS(saveSession(path, sessionWithFrame(8)),
                         (path + ": expected a writable file, found No space left on device").c_str(),
                         std::runtime_error);
    ::unsetenv("MOTIONGP_FAULT");
    CHECK(test::readText(path) == previous);
    checkSessionLoads(path, 3);
    CHECK(strays(dir, {"work.mgsession"}).empty());
}

TEST_CASE("sessions: a read-only folder fails saveSession clearly and keeps the previous one") {
    const std::string dir = test::scratchDir("lost_session_readonly");
    const std::string sub = dir + "/ro";
    fs::create_directory(sub);
    const std::string path = sub + "/work.mgsession";
    saveSession(path, sessionWithFrame(3));
    const std::string previous = test::readText(path);
    const std::string unreachable = test::unreachableAsNobody({sub});
    if (!unreachable.empty()) MGP_SKIP(unreachable);
    REQUIRE(::chmod(sub.c_str(), 0555) == 0);
    // As root, in a child running as nobody (root would write anyway).
    const std::string msg = inChild(true, [&] { saveSession(path, sessionWithFrame(8)); });
    ::chmod(sub.c_str(), 0755);
    CHECK(msg == path + ": expected a writable file, found Permission denied");
    CHECK(test::readText(path) == previous);
    checkSessionLoads(path, 3);
    CHECK(strays(sub, {"work.mgsession"}).empty());
}
