// `motiongp gui [FILE] [--model MODEL] [--frames N] [--script FILE] [--screenshot OUT.png]
//               [--offscreen] [--size WxH] [--json]`: the interactive editor. With --frames or --script it
// runs that many frames (scripted input replaces the mouse and keyboard), optionally saves a
// screenshot of the whole window, and exits 0. --offscreen uses the EGL surfaceless context
// (no display); otherwise a GLFW window (a desktop or xvfb-run).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "cli_common.h"
#include "command_registry.h"
#include "gui_run.h"
#include "io/data_paths.h"
#include "io/parse_error.h"
#include "render/gl_context.h"
#include "render/png_capture.h"
#include "session/recent_files.h"
#include "ui/input/gui_script.h"
#include "ui/shell/editor_app.h"
#include "ui/shell/glfw_window.h"
#include "util/thread_priority.h"

namespace mgp::app {

namespace {

// What FILE is: a session, a model file, or (neither) a clip.
struct GuiFileKind {
    bool session = false, modelFile = false;
};

GuiFileKind checkGuiArgs(const GuiArgs& args) {
    if (args.width < 320 || args.height < 240 || args.width > 8192 || args.height > 8192)
        throw UsageError("expected --size between 320x240 and 8192x8192, found " + std::to_string(args.width) + "x" +
                         std::to_string(args.height));
    if (args.frames < 0) throw UsageError("expected --frames ≥ 0, found " + std::to_string(args.frames));
    const std::string ext = std::filesystem::path(args.clip).extension().string();
    GuiFileKind kind;
    kind.session = !args.clip.empty() && ext == ".mgsession";
    // Anything that is neither a session nor a clip is tried as a model file (.json, .model).
    kind.modelFile = !args.clip.empty() && !kind.session && ext != ".amc" && ext != ".bvh" && ext != ".asf";
    if (!args.clip.empty()) {
        // Said before a window opens (no display, or a file manager's stale entry).
        std::error_code ec;
        if (!std::filesystem::exists(args.clip, ec))  // a folder is the loaders' to report
            throw UsageError("expected a clip (ASF/AMC, BVH), session or model file, found no file at '" + args.clip +
                             "'");
        if (ext == ".asf")
            throw UsageError("expected a motion (.amc beside its .asf, or .bvh), found the skeleton '" + args.clip +
                             "': open one of its .amc files");
        if (!args.model.empty() && (kind.session || kind.modelFile))
            throw UsageError("expected --model with a clip, found it with '" + args.clip + "'");
    }
    return kind;
}

ui::EditorOptions guiEditorOptions(const GuiArgs& args, const ui::GlfwWindow* window,
                                   const std::optional<std::string>& mocap, bool scripted) {
    ui::EditorOptions eo;
    // HiDPI: --ui-scale, else the monitor's content scale (1 offscreen).
    eo.uiScale = args.uiScale > 0.0f ? args.uiScale : window ? window->contentScale() : 1.0f;
    if (mocap) eo.mocapDir = *mocap;
    // A scripted run neither asks about old autosaves nor changes the user's recent files.
    eo.offerAutosaveRestore = !scripted;
    eo.recentFiles = !scripted;
    if (!scripted) eo.layoutFile = configDir() + "/layout.json";  // the splitters, as last left
    return eo;
}

// FILE or --model; with neither, the default clip of the mocap folder, else the synthetic demo.
void openGuiDocument(ui::EditorApp& app, const GuiArgs& args, const GuiFileKind& kind,
                     const std::optional<std::string>& mocap) {
    if (kind.session) {
        const std::string err = app.openSession(args.clip);
        if (!err.empty()) throw ParseError(err);
    } else if (!args.model.empty() || kind.modelFile) {
        const std::string err = app.openModel(kind.modelFile ? args.clip : args.model);
        if (!err.empty()) throw ParseError(err);
    } else if (!args.clip.empty()) {
        const std::string err = app.openClip(args.clip);
        if (!err.empty()) throw ParseError(err);
    } else if (const auto def = mocap ? defaultClipIn(*mocap) : std::nullopt) {
        app.openClip(*def);
    } else {
        app.openSyntheticClip("no mocap folder found: showing the synthetic demo clip");
    }
}

// The frame loop's state: `window` is null offscreen, `player` null without --script, `total` 0
// runs until the app quits.
struct GuiLoop {
    GuiLoop(const GuiArgs& a, ui::EditorApp& editor, ui::GlfwWindow* w, ui::ScriptPlayer* p, int frames, bool s)
        : args(a), app(editor), window(w), player(p), total(frames), scripted(s) {}
    const GuiArgs& args;
    ui::EditorApp& app;
    ui::GlfwWindow* window;
    ui::ScriptPlayer* player;
    int total;
    bool scripted;
    ui::InputState scriptInput;
    int settle = 2;
    std::chrono::steady_clock::time_point t0;
    int framesRun = 0;
    std::vector<std::string> written;  // screenshots, in the order they were saved
};

// One frame's input, size and time step.
struct GuiFrameInput {
    ui::InputState* input;
    int w, h;
    double dt;
};

GuiFrameInput pollGuiWindow(GuiLoop& loop, int i) {
    GuiFrameInput in{&loop.scriptInput, loop.args.width, loop.args.height, 1.0 / 60.0};
    ui::GlfwWindow* window = loop.window;
    ui::EditorApp& app = loop.app;
    if (!window) return in;
    // Interactive and nothing moving: sleep until input (at most 0.25 s) instead of
    // redrawing at the display rate. Every input event gets two frames (ImGui settles
    // hover state and popups one frame late).
    if (!loop.scripted && !app.animating() && i > 2 && --loop.settle <= 0) {
        window->waitEvents(0.25);
        loop.settle = 2;
    } else if (!loop.scripted && !app.frameDrawn()) {
        // No swap paced the last frame: keep to the display rate (events arriving faster,
        // e.g. mouse moves over nothing that changes, wait for the next 1/60 s too).
        std::this_thread::sleep_until(loop.t0 + std::chrono::microseconds(16667));
        window->pollEvents();
    } else {
        window->pollEvents();
    }
    if (window->takeDamage()) app.requestRedraw();
    if (window->shouldClose()) {
        window->cancelClose();  // the app asks about unsaved changes first
        app.requestQuit();
    }
    if (!loop.scripted) in.input = &window->input();
    in.w = window->width();
    in.h = window->height();
    if (!loop.scripted) {
        const auto now = std::chrono::steady_clock::now();
        in.dt = std::chrono::duration<double>(now - loop.t0).count();
        loop.t0 = now;
    }
    return in;
}

// Script events, the frame itself, its screenshots, and the window's title and buffer swap.
void drawGuiFrame(GuiLoop& loop, int i, const GuiFrameInput& in) {
    ui::EditorApp& app = loop.app;
    std::vector<std::string> shots;
    if (loop.player) loop.player->apply(i, *in.input, app, shots);
    const bool lastFrame = loop.total > 0 && i == loop.total - 1;
    // A window's back buffer is undefined after a swap: a screenshot needs this frame drawn.
    if (loop.window && (!shots.empty() || (lastFrame && !loop.args.screenshot.empty()))) app.requestRedraw();
    app.frame(*in.input, in.dt, in.w, in.h);
    ++loop.framesRun;
    for (const std::string& s : shots) render::writePng(app.capture(in.w, in.h), s);
    loop.written.insert(loop.written.end(), shots.begin(), shots.end());
    if (!loop.args.screenshot.empty() && lastFrame) {
        render::writePng(app.capture(in.w, in.h), loop.args.screenshot);
        loop.written.push_back(loop.args.screenshot);
    }
    if (loop.window) {
        loop.window->setTitle(app.title());
        if (app.frameDrawn()) loop.window->present();  // else the front buffer already shows this frame
    }
}

}  // namespace

int runGui(const GuiArgs& args) {
    const GuiFileKind kind = checkGuiArgs(args);
    setBackgroundWorkersYield(true);  // the frame before background work (util/thread_priority.h)
    std::optional<ui::ScriptPlayer> player;
    if (!args.script.empty()) player.emplace(ui::GuiScript::load(args.script));

    std::unique_ptr<render::OffscreenContext> offscreen;
    std::unique_ptr<ui::GlfwWindow> window;
    if (args.offscreen)
        offscreen = std::make_unique<render::OffscreenContext>(args.width, args.height);
    else
        window = std::make_unique<ui::GlfwWindow>(args.width, args.height, "MotionGP");

    const auto mocap = findEditorMocapFolder(globalOptions().dataDir, globalOptions().exeDir);
    int total = args.frames;
    if (player) total = std::max(total, player->lastFrame() + 3);
    if (total == 0 && (args.offscreen || !args.screenshot.empty())) total = 3;
    const bool scripted = total > 0;

    ui::EditorApp app(guiEditorOptions(args, window.get(), mocap, scripted));
    openGuiDocument(app, args, kind, mocap);

    GuiLoop loop(args, app, window.get(), player ? &*player : nullptr, total, scripted);
    loop.t0 = std::chrono::steady_clock::now();
    for (int i = 0; total == 0 || i < total; ++i) {
        const GuiFrameInput in = pollGuiWindow(loop, i);
        drawGuiFrame(loop, i, in);
        if (app.quitRequested()) break;
    }
    const std::vector<std::string> scriptErrors = player ? player->errors() : std::vector<std::string>{};
    for (const std::string& e : scriptErrors) std::cerr << "gui: script " << args.script << ": " << e << "\n";
    if (args.json)
        printJson({{"frames", loop.framesRun},
                   {"screenshots", loop.written},
                   {"script_errors", scriptErrors},
                   {"quit_requested", app.quitRequested()},
                   {"title", app.title()}});
    return 0;
}

namespace {

const CommandRegistration guiCommand(
    "gui", "Open the interactive editor (or run it scripted and save a screenshot)",
    [](CLI::App& sub) -> CommandRunner {
        auto a = std::make_shared<GuiArgs>();
        auto size = std::make_shared<std::string>("1280x800");
        sub.add_option("file", a->clip,
                       "Session (.mgsession), ASF/AMC or BVH clip, or model file to open (default: the 10_02 kick, "
                       "else a synthetic walk)");
        sub.add_option("--model", a->model, "Saved model file to open (its clip comes with it)");
        sub.add_option("--frames", a->frames, "Run this many frames, then exit 0 (default: until the window closes)");
        sub.add_option("--script", a->script, "Timed input events (format: ui/input/gui_script.h)");
        sub.add_option("--screenshot", a->screenshot, "Save a PNG of the whole window after the last frame");
        sub.add_flag("--offscreen", a->offscreen, "Render on the EGL surfaceless context (no display needed)");
        sub.add_option("--size", *size, "Window size WxH (default 1280x800)");
        sub.add_option("--ui-scale", a->uiScale, "Scale of fonts and panels (default: the monitor's content scale)")
            ->check(CLI::Range(0.5f, 4.0f));
        sub.add_flag("--json", a->json,
                     "When the run ends, print one JSON object: frames run, screenshots written, script errors");
        return [=]() {
            GuiArgs g = *a;
            if (std::sscanf(size->c_str(), "%dx%d", &g.width, &g.height) != 2)
                throw UsageError("expected --size WxH (e.g. 1280x800), found '" + *size + "'");
            return runGui(g);
        };
    });

}  // namespace
}  // namespace mgp::app
