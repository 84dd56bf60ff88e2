// Editor part 2 through the UI (label `gl`, offscreen, no display): path keys set and moved with
// the mouse, regeneration, undo/redo by keyboard (exact poses and model versions), sessions
// saved → quit → opened again, a save killed half-way, and an autosave restored after a kill.
#include <doctest/doctest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "document_helpers.h"
#include "editor_harness.h"
#include "gl_test_paths.h"
#include "gp/model_file.h"
#include "io/clip_loader.h"
#include "io/fbx_export.h"
#include "render/png_capture.h"
#include "session/autosave.h"
#include "session/session_file.h"
#include "skeleton/forward_kinematics.h"

using namespace mgp;
namespace fs = std::filesystem;

namespace {

using test::kOutDir;

std::string outDir(const std::string& name) {
    const std::string dir = kOutDir + "/" + name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string readFile(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    std::ostringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

bool sameEdits(const std::map<int, EditRecord>& a, const std::map<int, EditRecord>& b) {
    if (a.size() != b.size()) return false;
    for (auto ia = a.begin(), ib = b.begin(); ia != a.end(); ++ia, ++ib)
        if (ia->first != ib->first || !posesIdentical(ia->second.pose, ib->second.pose) || ia->second.x != ib->second.x)
            return false;
    return true;
}

// The BVH's MOTION lines, one per frame.
std::vector<std::string> bvhFrames(const std::string& path) {
    std::istringstream in(readFile(path));
    std::vector<std::string> out;
    bool motion = false;
    for (std::string line; std::getline(in, line);) {
        if (motion)
            out.push_back(line);
        else if (line.rfind("Frame Time:", 0) == 0)
            motion = true;
    }
    return out;
}

// Starts `motiongp ARGS…` with extra environment variables; output goes to `log`.
pid_t spawnEditor(const std::vector<std::string>& args, const std::vector<std::pair<std::string, std::string>>& env,
                  const std::string& log) {
    const pid_t pid = fork();
    if (pid != 0) return pid;
    for (const auto& [k, v] : env) setenv(k.c_str(), v.c_str(), 1);
    setenv("DISPLAY", "", 1);
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(fd, 1);
    dup2(fd, 2);
    std::vector<char*> argv;
    static std::string exe = MOTIONGP_TEST_BINARY;
    argv.push_back(exe.data());
    std::vector<std::string> copy = args;
    for (std::string& a : copy) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(exe.c_str(), argv.data());
    _exit(127);
}

// Waits up to `seconds` for a file in `dir` whose name contains `part` (ends with it if
// `suffix`); "" if none appeared or the editor ended first.
std::string waitForFile(const std::string& dir, const std::string& part, double seconds, pid_t child,
                        bool suffix = false) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < end) {
        for (const auto& e : fs::directory_iterator(dir)) {
            const std::string name = e.path().filename().string();
            const auto at = name.rfind(part);
            if (at != std::string::npos && (!suffix || at + part.size() == name.size())) return e.path().string();
        }
        int status = 0;
        if (waitpid(child, &status, WNOHANG) == child) return "";  // the editor ended early
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return "";
}

void killAndReap(pid_t pid) {
    kill(pid, SIGKILL);
    int status = 0;
    waitpid(pid, &status, 0);
}

}  // namespace

TEST_CASE(
    "gui: set path keys, move one with the mouse, regenerate, keys met, other frames bit-identical, undo/redo exact") {
    auto h = test::makeHarness(false);
    if (!h) return;
    EditorDocument& doc = h->app->state().doc;
    const gp::ModelVersionPtr v0 = doc.model();
    const std::string dir = outDir("gui_path");

    ui::GuiScript s;
    s.add(0, "action", {"export-bvh", dir + "/before.bvh"});
    s.add(1, "action", {"frame", "110"});
    s.add(2, "action", {"path", "lfoot"});  // the left foot swings over 89–131 (the right one is planted)
    s.add(3, "action", {"path-keys", "89", "103", "117", "131"});
    s.add(4, "action", {"path-offset", "2", "0", "10", "4"});  // a numeric nudge of key 2
    s.add(6, "hover", {"key:3"});                              // key 3 dragged up with the mouse
    s.add(8, "down", {"left"});
    for (int k = 0; k < 5; ++k) s.add(10 + 2 * k, "moveby", {"0", "-8"});
    s.add(22, "up", {"left"});
    s.add(24, "action", {"regenerate", "300"});
    s.add(25, "action", {"wait"});
    s.add(27, "action", {"export-bvh", dir + "/after.bvh"});
    s.add(28, "action", {"export-gltf", dir + "/after.glb"});
    const bool blender = !findBlender().empty();
    if (blender) s.add(29, "action", {"export-fbx", dir + "/after.fbx"});  // in the background
    s.add(30, "action", {"wait"});
    CHECK(h->play(s).empty());
    CHECK(doc.undoLabel() == "regenerate lfoot, frames 90-130");  // the key drag was no effector drag

    REQUIRE(doc.paths().edit().has_value());
    const PathEdit& path = *doc.paths().edit();
    CHECK(path.keyFrames == std::vector<int>{88, 102, 116, 130});
    CHECK(path.keyOffsetsCm[1] == Eigen::Vector3d(0, 10, 4));
    INFO("key 3 offset after the mouse drag: " << path.keyOffsetsCm[2].transpose());
    CHECK(path.keyOffsetsCm[2].y() > 3.0);
    for (int k : {1, 2}) {
        const int t = path.keyFrames[k];
        REQUIRE(doc.isEdited(t));
        const Eigen::Vector3d foot = effectorCm(doc.clip().skeleton, doc.edits().at(t).pose, Effector::kLFoot);
        INFO("key " << k + 1 << " frame " << t + 1 << " residual " << (foot - doc.paths().keyPosition(k)).norm()
                    << " cm");
        CHECK((foot - doc.paths().keyPosition(k)).norm() <= 0.5);
    }
    for (int t = 0; t < doc.frameCount(); ++t) CHECK(doc.isEdited(t) == (t > 88 && t < 130));
    const std::vector<std::string> before = bvhFrames(dir + "/before.bvh"), after = bvhFrames(dir + "/after.bvh");
    REQUIRE(before.size() == std::size_t(doc.frameCount()));
    REQUIRE(after.size() == before.size());
    for (int t = 0; t < doc.frameCount(); ++t) CHECK((before[t] == after[t]) == !(t > 88 && t < 130));
    // The glTF export holds the same edited motion: every joint where the BVH export puts it.
    const Clip fromBvh = loadClip(dir + "/after.bvh"), fromGltf = loadClip(dir + "/after.glb");
    REQUIRE(fromGltf.frameCount() == doc.frameCount());
    double worstGltfCm = 0.0;
    FkState fkBvh, fkGltf;
    for (int t = 0; t < doc.frameCount(); ++t) {
        forwardKinematics(fromBvh.skeleton, fromBvh.frames[t], fkBvh);
        forwardKinematics(fromGltf.skeleton, fromGltf.frames[t], fkGltf);
        for (int j = 0; j < fromBvh.skeleton.jointCount(); ++j) {
            const int g = fromGltf.skeleton.findJoint(fromBvh.skeleton.joints[j].name);
            REQUIRE(g >= 0);
            worstGltfCm = std::max(worstGltfCm, (fkBvh.jointCm[j] - fkGltf.jointCm[g]).norm());
        }
    }
    INFO("worst joint gap between the BVH and glTF exports: " << worstGltfCm << " cm");
    CHECK(worstGltfCm < 1e-3);
    if (blender) {
        CHECK(std::filesystem::file_size(dir + "/after.fbx") > 0);
        const std::string said = "exported " + std::to_string(doc.frameCount()) + " frames to " + dir + "/after.fbx";
        const auto& history = h->app->state().messages.history();
        CHECK(std::any_of(history.begin(), history.end(), [&](const auto& m) { return m.text == said; }));
    } else {
        MESSAGE("no blender: the FBX export is not driven here");
    }

    doc.waitIdle();
    const gp::ModelVersionPtr v2 = doc.model();
    CHECK(v2->model->N() == v0->model->N() + 2);  // keys 2 and 3 joined the model
    const std::map<int, EditRecord> edited = doc.edits();

    ui::GuiScript undo;  // Ctrl+Z, then Ctrl+Shift+Z
    undo.add(0, "keydown", {"CTRL"});
    undo.add(1, "key", {"Z"});
    undo.add(3, "keyup", {"CTRL"});
    CHECK(h->play(undo).empty());
    CHECK(doc.edits().empty());
    CHECK(doc.model() == v0);
    CHECK(gp::modelToJsonText(*doc.model()->model) == gp::modelToJsonText(*v0->model));

    ui::GuiScript redo;
    redo.add(0, "keydown", {"CTRL"});
    redo.add(0, "keydown", {"SHIFT"});
    redo.add(1, "key", {"Z"});
    redo.add(3, "keyup", {"SHIFT"});
    redo.add(3, "keyup", {"CTRL"});
    CHECK(h->play(redo).empty());
    CHECK(sameEdits(doc.edits(), edited));
    CHECK(doc.model() == v2);
}

TEST_CASE("gui: save session → quit → open it again gives the same poses, model, path and camera") {
    auto h = test::makeHarness(false);
    if (!h) return;
    EditorDocument& doc = h->app->state().doc;
    const std::string dir = outDir("gui_session");
    const std::string file = dir + "/walk.mgsession";

    ui::GuiScript s;
    s.add(0, "action", {"frame", "100"});
    s.add(2, "hover", {"rfoot"});
    s.add(4, "down", {"left"});
    for (int k = 0; k < 4; ++k) s.add(6 + 2 * k, "moveby", {"0", "-8"});
    s.add(16, "up", {"left"});
    s.add(18, "action", {"path", "lhand"});
    s.add(19, "action", {"path-offset", "2", "5", "0", "10"});
    s.add(20, "action", {"regenerate", "200"});
    s.add(21, "action", {"wait"});
    s.add(22, "action", {"frame", "42"});
    s.add(23, "wheel", {"2"});
    CHECK(h->play(s).empty());
    REQUIRE(doc.edits().size() > 1);
    CHECK(h->app->dirty());

    ui::GuiScript save;
    save.add(0, "action", {"save-session", file});
    save.add(1, "action", {"quit"});
    CHECK(h->play(save).empty());
    CHECK_FALSE(h->app->dirty());
    CHECK(h->app->quitRequested());  // saved: no unsaved-changes prompt

    const std::map<int, EditRecord> edits = doc.edits();
    const std::string model = gp::modelToJsonText(*doc.model()->model);
    const int version = doc.model()->number;
    const PathEdit path = *doc.paths().edit();
    const render::OrbitCamera camera = h->app->state().camera;
    const int frame = doc.frame();

    h->restartApp();
    EditorDocument& doc2 = h->app->state().doc;
    REQUIRE(h->app->openSession(file) == "");
    h->frame(2);
    CHECK(sameEdits(doc2.edits(), edits));
    REQUIRE(doc2.hasModel());
    CHECK(gp::modelToJsonText(*doc2.model()->model) == model);
    CHECK(doc2.model()->number == version);
    REQUIRE(doc2.paths().edit().has_value());
    CHECK(doc2.paths().edit()->keyFrames == path.keyFrames);
    CHECK(doc2.paths().edit()->keyOffsetsCm == path.keyOffsetsCm);
    CHECK(doc2.frame() == frame);
    CHECK(h->app->state().camera.distanceCm == camera.distanceCm);
    CHECK(h->app->state().camera.yawDeg == camera.yawDeg);
    CHECK_FALSE(h->app->dirty());
    CHECK(h->app->sessionPath() == fs::absolute(file).lexically_normal().string());

    SUBCASE("an unsaved change asks before quitting") {
        doc2.clearEdit(doc2.edits().begin()->first);
        CHECK(h->app->dirty());
        h->app->requestQuit();
        h->frame(2);
        CHECK_FALSE(h->app->quitRequested());  // the prompt is up, waiting for the user
        CHECK(h->app->askingAboutUnsavedChanges());
    }
}

TEST_CASE("gui: killing the editor while it saves leaves the previous session file intact") {
    auto h = test::makeHarness(false, false);
    if (!h) return;
    const std::string dir = outDir("gui_kill_save");
    const std::string file = dir + "/kept.mgsession";
    h->app->state().doc.setFrame(60);
    REQUIRE(h->app->saveSession(file) == "");
    const std::string previous = readFile(file);

    {
        std::ofstream script(dir + "/script.txt");
        script << "1 action frame 20\n2 action path rfoot\n3 action save-session " << file << "\n4000 action pause\n";
    }
    // The fault makes the save stop half-way through writing for 30 s; we kill it there.
    const pid_t pid = spawnEditor({"gui", file, "--offscreen", "--size", "640x400", "--script", dir + "/script.txt"},
                                  {{"MOTIONGP_FAULT", "slow-write:30000"}}, dir + "/log.txt");
    const std::string temp = waitForFile(dir, ".tmp", 60.0, pid);
    INFO("editor log: " << readFile(dir + "/log.txt"));
    REQUIRE(!temp.empty());
    std::this_thread::sleep_for(std::chrono::milliseconds(200));  // well inside the 30 s pause
    killAndReap(pid);
    CHECK(readFile(file) == previous);
    CHECK(h->app->openSession(file) == "");
    CHECK(h->app->state().doc.frame() == 60);
}

TEST_CASE("gui: an editor killed after an autosave leaves it behind, and the next editor restores it") {
    auto h = test::makeHarness(false, false);
    if (!h) return;
    const std::string dir = outDir("gui_autosave");
    {
        std::ofstream script(dir + "/script.txt");
        script << "1 action frame 50\n2 hover rfoot\n4 down left\n6 moveby 0 -30\n8 up left\n10 action autosave\n"
                  "4000 action pause\n";
    }
    const pid_t pid = spawnEditor({"gui", test::mocapDir() + "/asf_amc/35_01.amc", "--offscreen", "--size", "1280x800",
                                   "--script", dir + "/script.txt"},
                                  {{"MOTIONGP_STATE_DIR", dir}}, dir + "/log.txt");
    const std::string autosave = waitForFile(dir, ".mgsession", 60.0, pid, true);
    INFO("editor log: " << readFile(dir + "/log.txt"));
    REQUIRE(!autosave.empty());
    killAndReap(pid);

    REQUIRE(findOrphanedAutosaves(dir).size() == 1);
    setenv("MOTIONGP_STATE_DIR", dir.c_str(), 1);
    // The next interactive editor offers it in a modal dialog (the picture is kept for a look).
    ui::EditorOptions offer;
    offer.offerAutosaveRestore = true;
    h->restartApp(offer);
    h->frame(3);
    CHECK(h->app->offeringAutosave());
    render::writePng(h->app->capture(test::kGuiWidth, test::kGuiHeight), dir + "/restore_offer.png");
    const std::string err = h->app->restoreAutosave();
    REQUIRE(err == "");
    h->frame(2);
    CHECK_FALSE(h->app->offeringAutosave());
    // The restored work is this editor's autosave now (a second crash would not lose it).
    CHECK(fs::exists(autosavePath()));
    unsetenv("MOTIONGP_STATE_DIR");
    EditorDocument& doc = h->app->state().doc;
    CHECK(doc.isEdited(49));
    CHECK(doc.frame() == 49);
    CHECK(h->app->dirty());  // restored work is not saved anywhere yet
    CHECK(findOrphanedAutosaves(dir).empty());
}
