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

namespace mgp::app {

int runGui(const GuiArgs& args) {
    if (args.width < 320 || args.height < 240 || args.width > 8192 || args.height > 8192)
        throw UsageError("expected --size between 320x240 and 8192x8192, found " + std::to_string(args.width) + "x" +
                         std::to_string(args.height));
    if (args.frames < 0) throw UsageError("expected --frames ≥ 0, found " + std::to_string(args.frames));
    const std::string ext = std::filesystem::path(args.clip).extension().string();
    const bool session = !args.clip.empty() && ext == ".mgsession";
    // Anything that is neither a session nor a clip is tried as a model file (.json, .model).
    const bool modelFile = !args.clip.empty() && !session && ext != ".amc" && ext != ".bvh" && ext != ".asf";
    if (!args.clip.empty()) {
        // Said before a window opens (no display, or a file manager's stale entry).
        std::error_code ec;
        if (!std::filesystem::exists(args.clip, ec))  // a folder is the loaders' to report
            throw UsageError("expected a clip (ASF/AMC, BVH), session or model file, found no file at '" + args.clip +
                             "'");
        if (ext == ".asf")
            throw UsageError("expected a motion (.amc beside its .asf, or .bvh), found the skeleton '" + args.clip +
                             "': open one of its .amc files");
        if (!args.model.empty() && (session || modelFile))
            throw UsageError("expected --model with a clip, found it with '" + args.clip + "'");
    }
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

    ui::EditorOptions eo;
    // HiDPI: --ui-scale, else the monitor's content scale (1 offscreen).
    eo.uiScale = args.uiScale > 0.0f ? args.uiScale : window ? window->contentScale() : 1.0f;
    if (mocap) eo.mocapDir = *mocap;
    // A scripted run neither asks about old autosaves nor changes the user's recent files.
    eo.offerAutosaveRestore = !scripted;
    eo.recentFiles = !scripted;
    if (!scripted) eo.layoutFile = configDir() + "/layout.json";  // the splitters, as last left
    ui::EditorApp app(eo);
    if (session) {
        const std::string err = app.openSession(args.clip);
        if (!err.empty()) throw ParseError(err);
    } else if (!args.model.empty() || modelFile) {
        const std::string err = app.openModel(modelFile ? args.clip : args.model);
        if (!err.empty()) throw ParseError(err);
    } else if (!args.clip.empty()) {
        const std::string err = app.openClip(args.clip);
        if (!err.empty()) throw ParseError(err);
    } else if (const auto def = mocap ? defaultClipIn(*mocap) : std::nullopt) {
        app.openClip(*def);
    } else {
        app.openSyntheticClip("no mocap folder found: showing the synthetic demo clip");
    }

    ui::InputState scriptInput;
    int settle = 2;
    int framesRun = 0;
    std::vector<std::string> written;  // screenshots, in the order they were saved
    auto t0 = std::chrono::steady_clock::now();
    for (int i = 0; total == 0 || i < total; ++i) {
        ui::InputState* input = &scriptInput;
        int w = args.width, h = args.height;
        double dt = 1.0 / 60.0;
        if (window) {
            // Interactive and nothing moving: sleep until input (at most 0.25 s) instead of
            // redrawing at the display rate. Every input event gets two frames (ImGui settles
            // hover state and popups one frame late).
            if (!scripted && !app.animating() && i > 2 && --settle <= 0) {
                window->waitEvents(0.25);
                settle = 2;
            } else if (!scripted && !app.frameDrawn()) {
                // No swap paced the last frame: keep to the display rate (events arriving faster,
                // e.g. mouse moves over nothing that changes, wait for the next 1/60 s too).
                std::this_thread::sleep_until(t0 + std::chrono::microseconds(16667));
                window->pollEvents();
            } else {
                window->pollEvents();
            }
            if (window->takeDamage()) app.requestRedraw();
            if (window->shouldClose()) {
                window->cancelClose();  // the app asks about unsaved changes first
                app.requestQuit();
            }
            if (!scripted) input = &window->input();
            w = window->width();
            h = window->height();
            if (!scripted) {
                const auto now = std::chrono::steady_clock::now();
                dt = std::chrono::duration<double>(now - t0).count();
                t0 = now;
            }
        }
        std::vector<std::string> shots;
        if (player) player->apply(i, *input, app, shots);
        const bool lastFrame = total > 0 && i == total - 1;
        // A window's back buffer is undefined after a swap: a screenshot needs this frame drawn.
        if (window && (!shots.empty() || (lastFrame && !args.screenshot.empty()))) app.requestRedraw();
        app.frame(*input, dt, w, h);
        ++framesRun;
        for (const std::string& s : shots) render::writePng(app.capture(w, h), s);
        written.insert(written.end(), shots.begin(), shots.end());
        if (!args.screenshot.empty() && lastFrame) {
            render::writePng(app.capture(w, h), args.screenshot);
            written.push_back(args.screenshot);
        }
        if (window) {
            window->setTitle(app.title());
            if (app.frameDrawn()) window->present();  // else the front buffer already shows this frame
        }
        if (app.quitRequested()) break;
    }
    const std::vector<std::string> scriptErrors = player ? player->errors() : std::vector<std::string>{};
    for (const std::string& e : scriptErrors) std::cerr << "gui: script " << args.script << ": " << e << "\n";
    if (args.json)
        printJson({{"frames", framesRun},
                   {"screenshots", written},
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
