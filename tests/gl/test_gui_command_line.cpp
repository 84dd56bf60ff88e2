// `motiongp FILE` (the editor on a clip, session or model, as `blender FILE`), `motiongp
// --version`, and the desktop entry `cmake --install` puts in place (label `gl`: the editor runs
// offscreen).
#include <doctest/doctest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "gl_test_paths.h"
#include "render/gl_context.h"
#include "skip.h"

namespace fs = std::filesystem;

namespace {

const std::string kBinary = MOTIONGP_TEST_BINARY;
using mgp::test::kMocap;
// One folder per process: ctest runs these test cases in parallel, and each run() captures into
// kOut's stdout.txt and stderr.txt.
const std::string kOut = std::string(MOTIONGP_GL_OUT_DIR) + "/command_line/" + std::to_string(::getpid());

struct Run {
    int code = -1;
    std::string out, err;
};

std::string slurp(const std::string& path) {
    std::ifstream f(path);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

// Runs `args` through the shell (arguments are quoted by the caller), without a display.
Run run(const std::string& args) {
    fs::create_directories(kOut);
    const std::string out = kOut + "/stdout.txt", err = kOut + "/stderr.txt";
    const std::string cmd = "env -u DISPLAY -u WAYLAND_DISPLAY " + args + " >'" + out + "' 2>'" + err + "' </dev/null";
    const int status = std::system(cmd.c_str());
    Run r;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
}

std::string q(const std::string& s) { return "'" + s + "'"; }

bool offscreenAvailable(std::string& why) {
    try {
        mgp::render::OffscreenContext ctx(64, 64);
        return true;
    } catch (const mgp::render::RenderError& e) {
        why = e.what();
        return false;
    }
}

int bvhFrames(const std::string& path) {
    const std::string text = slurp(path);
    const std::size_t at = text.find("Frames:");
    return at == std::string::npos ? -1 : std::atoi(text.c_str() + at + 7);
}

}  // namespace

TEST_CASE("cli: motiongp --version prints the version") {
    const Run r = run(q(kBinary) + " --version");
    INFO(r.err);
    CHECK(r.code == 0);
    CHECK(r.out.rfind("motiongp ", 0) == 0);
    CHECK(r.out.find('.') != std::string::npos);
}

TEST_CASE("cli: motiongp FILE opens a clip, a model or a session in the editor") {
    std::string why;
    if (!offscreenAvailable(why)) MGP_SKIP("no offscreen GL context: " << why);
    fs::create_directories(kOut);
    const std::string script = kOut + "/export.txt", bvh = kOut + "/opened.bvh", session = kOut + "/opened.mgsession";
    std::ofstream(script) << "1 action export-bvh " << bvh << "\n2 action save-session " << session << "\n";

    // A clip: the exported motion has the clip's frames (35_01: 358 frames).
    fs::remove(bvh);
    Run r = run(q(kBinary) + " " + q(kMocap + "/asf_amc/35_01.amc") + " --offscreen --script " + q(script));
    INFO(r.err);
    REQUIRE(r.code == 0);
    CHECK(bvhFrames(bvh) == 358);

    // A model file: the session saved from the editor holds the model.
    const std::string model = std::string(MOTIONGP_TEST_FIXTURES) + "/walk35_fas_m100_t3.model";
    fs::remove(session);
    r = run(q(kBinary) + " " + q(model) + " --offscreen --script " + q(script));
    INFO(r.err);
    REQUIRE(r.code == 0);
    const nlohmann::json saved = nlohmann::json::parse(slurp(session), nullptr, false);
    REQUIRE_FALSE(saved.is_discarded());
    CHECK(saved["model"].is_object());

    // That session, opened the same way, is the document again.
    const std::string again = kOut + "/again.txt", bvh2 = kOut + "/again.bvh";
    std::ofstream(again) << "1 action export-bvh " << bvh2 << "\n";
    r = run(q(kBinary) + " " + q(session) + " --offscreen --script " + q(again));
    INFO(r.err);
    REQUIRE(r.code == 0);
    CHECK(bvhFrames(bvh2) == 358);
}

TEST_CASE("cli: motiongp FILE with a missing file or a lone skeleton says so in one line, exit 2") {
    Run r = run(q(kBinary) + " " + q(kOut + "/no-such-clip.amc") + " --offscreen");
    CHECK(r.code == 2);
    CHECK(r.err.find("found no file at") != std::string::npos);
    CHECK(r.err.find('\n') == r.err.size() - 1);
    r = run(q(kBinary) + " " + q(kMocap + "/asf_amc/35.asf") + " --offscreen");
    CHECK(r.code == 2);
    CHECK(r.err.find("skeleton") != std::string::npos);
    // Verbs still win over file names.
    r = run(q(kBinary) + " info " + q(kMocap + "/asf_amc/35_01.amc") + " --json");
    CHECK(r.code == 0);
    CHECK(r.out.find("\"frames\"") != std::string::npos);
}

TEST_CASE("cli: cmake --install puts the desktop entry, icon and file types in place") {
    const fs::path buildDir = fs::path(kBinary).parent_path();
    if (std::system("cmake --version >/dev/null 2>&1") != 0) MGP_SKIP("no cmake on PATH to run the install");
    const std::string prefix = kOut + "/prefix";
    fs::remove_all(prefix);
    const Run r = run("cmake --install " + q(buildDir.string()) + " --prefix " + q(prefix));
    INFO(r.out << r.err);
    REQUIRE(r.code == 0);
    CHECK(fs::is_regular_file(prefix + "/bin/motiongp"));
    const std::string desktop = slurp(prefix + "/share/applications/motiongp.desktop");
    CHECK(desktop.find("Exec=motiongp %f") != std::string::npos);
    CHECK(desktop.find("Icon=motiongp") != std::string::npos);
    for (const char* type : {"application/x-motiongp-session", "application/x-acclaim-amc", "application/x-bvh"}) {
        CHECK(desktop.find(type) != std::string::npos);
        CHECK(slurp(prefix + "/share/mime/packages/motiongp.xml").find(type) != std::string::npos);
    }
    CHECK(fs::is_regular_file(prefix + "/share/icons/hicolor/scalable/apps/motiongp.svg"));
    // desktop-file-utils is one of .ci/install-deps' packages, so the validator is always there.
    const Run v = run("desktop-file-validate " + q(prefix + "/share/applications/motiongp.desktop"));
    INFO(v.out << v.err);
    CHECK(v.code == 0);
}

TEST_CASE("cli: render and gui take --json and print one JSON object") {
    std::string why;
    if (!offscreenAvailable(why)) MGP_SKIP("no offscreen GL context: " << why);
    fs::create_directories(kOut);
    const std::string png = kOut + "/json_render.png", shot = kOut + "/json_gui.png";
    fs::remove(png);
    Run r = run(q(kBinary) + " render " + q(kMocap + "/asf_amc/35_01.amc") + " --frame 7 --size 64x48 --out " + q(png) +
                " --json");
    INFO(r.err);
    REQUIRE(r.code == 0);
    nlohmann::json j = nlohmann::json::parse(r.out, nullptr, false);
    REQUIRE(j.is_object());
    CHECK(j["out"] == png);
    CHECK(j["width"] == 64);
    CHECK(j["height"] == 48);
    CHECK(j["clip"] == "35_01");
    CHECK(j["frame"] == 7);
    CHECK(j["model"] == false);
    CHECK(fs::is_regular_file(png));

    fs::remove(shot);
    r = run(q(kBinary) + " gui " + q(kMocap + "/asf_amc/35_01.amc") +
            " --offscreen --size 320x240 --frames 2 --screenshot " + q(shot) + " --json");
    INFO(r.err);
    REQUIRE(r.code == 0);
    j = nlohmann::json::parse(r.out, nullptr, false);
    REQUIRE(j.is_object());
    CHECK(j["frames"] == 2);
    CHECK(j["screenshots"] == nlohmann::json::array({shot}));
    CHECK(j["script_errors"] == nlohmann::json::array());
    CHECK(fs::is_regular_file(shot));
}

TEST_CASE("cli: without libGL.so.1 the editor and the UI bench stop with one line naming it") {
    std::string why;
    if (!offscreenAvailable(why)) MGP_SKIP("no offscreen GL context: " << why);
    // The shim makes dlopen("libGL.so.1") fail, as on a machine with EGL but no GLX library; the
    // offscreen context itself (EGL) still starts. GCC's dynamic ASan runtime would refuse a
    // preload ahead of it, hence verify_asan_link_order=0 (clang links its runtime statically).
    const std::string preload = std::string("LD_PRELOAD=") + q(MOTIONGP_TEST_NO_LIBGL_PRELOAD) +
                                " ASAN_OPTIONS=\"${ASAN_OPTIONS:-}:verify_asan_link_order=0\" ";
    // The editor says nothing else; the bench names its section on stderr first.
    const std::pair<std::string, std::string> runs[] = {{"gui --offscreen --frames 1", ""},
                                                        {"bench --only ui --quick --repeats 1", "bench: ui ...\n"}};
    for (const auto& verbAndBefore : runs) {
        // Copies, not a structured binding: clang 14 cannot capture one in doctest's INFO.
        const std::string verb = verbAndBefore.first, before = verbAndBefore.second;
        const Run r = run(preload + q(kBinary) + " " + verb);
        INFO(verb << "\nstdout: " << r.out << "\nstderr: " << r.err);
        CHECK(r.code == 1);
        REQUIRE(r.err.rfind(before, 0) == 0);
        const std::string line = r.err.substr(before.size());
        CHECK(line.rfind("motiongp: error: expected libGL.so.1", 0) == 0);
        CHECK(line.find("apt-get install libgl1") != std::string::npos);
        CHECK(line.find("/nonexistent/libGL.so.1: cannot open shared object file") != std::string::npos);
        CHECK(line.find('\n') == line.size() - 1);  // one line
    }
}
