#include "editor_app.h"

#include <GL/gl.h>
#include <imgui.h>
#include <backends/imgui_impl_opengl3.h>

#include <algorithm>
#include <cfloat>
#include <cstdio>
#include <filesystem>

#include "gp/model_file.h"
#include "io/clip_loader.h"
#include "io/parse_error.h"
#include "model_panel.h"
#include "skeleton/synthetic_clip.h"

namespace mgp::ui {

namespace {
const char* kFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

void applyStyle() {
    ImGui::StyleColorsDark();
    ImGuiStyle& st = ImGui::GetStyle();
    st.WindowRounding = 0.0f;
    st.FrameRounding = 3.0f;
    st.GrabRounding = 3.0f;
    st.WindowBorderSize = 1.0f;
    st.FramePadding = ImVec2(6, 3);
    st.ItemSpacing = ImVec2(7, 5);
    ImVec4* c = st.Colors;
    c[ImGuiCol_WindowBg] = ImVec4(0.16f, 0.165f, 0.18f, 1.0f);
    c[ImGuiCol_TitleBg] = ImVec4(0.12f, 0.125f, 0.14f, 1.0f);
    c[ImGuiCol_TitleBgActive] = ImVec4(0.14f, 0.15f, 0.17f, 1.0f);
    c[ImGuiCol_MenuBarBg] = ImVec4(0.12f, 0.125f, 0.14f, 1.0f);
    c[ImGuiCol_FrameBg] = ImVec4(0.24f, 0.25f, 0.28f, 1.0f);
    c[ImGuiCol_Button] = ImVec4(0.27f, 0.29f, 0.33f, 1.0f);
    c[ImGuiCol_ButtonHovered] = ImVec4(0.35f, 0.40f, 0.48f, 1.0f);
    c[ImGuiCol_ButtonActive] = ImVec4(0.28f, 0.50f, 0.80f, 1.0f);
    c[ImGuiCol_Header] = ImVec4(0.28f, 0.32f, 0.38f, 1.0f);
    c[ImGuiCol_PlotHistogram] = ImVec4(0.28f, 0.58f, 0.92f, 1.0f);
    c[ImGuiCol_Border] = ImVec4(0.08f, 0.08f, 0.09f, 1.0f);
}

std::string baseName(const std::string& path) { return std::filesystem::path(path).filename().string(); }
}  // namespace

EditorApp::EditorApp(EditorOptions options) : options_(std::move(options)) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // a fixed layout; nothing written beside the working directory
    io.LogFilename = nullptr;
    io.BackendPlatformName = "motiongp";
    for (int k = 0; k < ImGuiKey_COUNT; ++k) io.KeyMap[k] = -1;
    io.KeyMap[ImGuiKey_Tab] = key::kTab;
    io.KeyMap[ImGuiKey_LeftArrow] = key::kLeft;
    io.KeyMap[ImGuiKey_RightArrow] = key::kRight;
    io.KeyMap[ImGuiKey_UpArrow] = key::kUp;
    io.KeyMap[ImGuiKey_DownArrow] = key::kDown;
    io.KeyMap[ImGuiKey_PageUp] = key::kPageUp;
    io.KeyMap[ImGuiKey_PageDown] = key::kPageDown;
    io.KeyMap[ImGuiKey_Home] = key::kHome;
    io.KeyMap[ImGuiKey_End] = key::kEnd;
    io.KeyMap[ImGuiKey_Delete] = key::kDelete;
    io.KeyMap[ImGuiKey_Backspace] = key::kBackspace;
    io.KeyMap[ImGuiKey_Space] = key::kSpace;
    io.KeyMap[ImGuiKey_Enter] = key::kEnter;
    io.KeyMap[ImGuiKey_Escape] = key::kEscape;
    io.KeyMap[ImGuiKey_A] = 'A';
    io.KeyMap[ImGuiKey_C] = 'C';
    io.KeyMap[ImGuiKey_V] = 'V';
    io.KeyMap[ImGuiKey_X] = 'X';
    io.KeyMap[ImGuiKey_Y] = 'Y';
    io.KeyMap[ImGuiKey_Z] = 'Z';
    std::error_code ec;
    if (!options_.builtinFont && std::filesystem::exists(kFontPath, ec))
        io.Fonts->AddFontFromFileTTF(kFontPath, 15.0f);
    applyStyle();
    ImGui_ImplOpenGL3_Init("#version 330 core");
    viewport_ = std::make_unique<ViewportPanel>();
}

EditorApp::~EditorApp() {
    viewport_.reset();
    ImGui_ImplOpenGL3_Shutdown();
    ImGui::DestroyContext();
}

std::string EditorApp::openClip(const std::string& path) {
    try {
        Clip clip = loadClip(path);
        state_.training.cancel();
        state_.doc.setClip(std::move(clip), false);
        state_.clipLabel = baseName(path);
        state_.modelLabel.clear();
        state_.cameraNeedsFraming = true;
        state_.playing = false;
        std::error_code ec;
        const std::string shown = std::filesystem::weakly_canonical(path, ec).string();
        state_.setStatus("opened " + (ec ? path : shown) +
                         (state_.doc.trainable() ? "" : "  (BVH: view-only, training needs ASF/AMC)"));
        return "";
    } catch (const std::exception& e) {
        state_.setStatus(e.what(), true);
        return e.what();
    }
}

void EditorApp::openSyntheticClip(const std::string& why) {
    state_.doc.setClip(makeSyntheticWalk(), true);
    state_.clipLabel = "synthetic demo clip";
    state_.modelLabel.clear();
    state_.cameraNeedsFraming = true;
    state_.setStatus(why.empty() ? "synthetic demo clip" : why);
}

std::string EditorApp::openModel(const std::string& path) {
    try {
        gp::ModelVersionPtr v = gp::ModelVersion::make(gp::loadModel(path));
        state_.doc.setModel(v, true);
        state_.clipLabel = v->model->sourceFile.empty() ? v->model->clip.name : v->model->sourceFile;
        state_.modelLabel = baseName(path);
        state_.cameraNeedsFraming = true;
        state_.setStatus("opened model " + path);
        return "";
    } catch (const std::exception& e) {
        state_.setStatus(e.what(), true);
        return e.what();
    }
}

std::string EditorApp::saveModel(const std::string& path) {
    const gp::ModelVersionPtr v = state_.doc.model();
    if (!v) {
        state_.setStatus("no model to save", true);
        return "no model to save";
    }
    try {
        gp::saveModel(path, *v->model);
        state_.modelLabel = baseName(path);
        state_.setStatus("saved model " + path);
        return "";
    } catch (const std::exception& e) {
        state_.setStatus(e.what(), true);
        return e.what();
    }
}

std::string EditorApp::startTraining() {
    if (!state_.doc.hasClip()) return "no clip";
    const std::string err =
        state_.training.start(state_.doc.clip(), state_.trainOptions, baseName(state_.doc.clip().sourcePath));
    if (err.empty()) state_.setStatus("training started (the editor stays usable; Cancel in the Model panel)");
    else state_.setStatus(err, true);
    return err;
}

void EditorApp::pollJobs() {
    if (gp::ModelVersionPtr v = state_.training.take()) {
        const Clip& c = v->model->clip;
        const bool same = state_.doc.hasClip() && c.name == state_.doc.clip().name &&
                          c.frameCount() == state_.doc.frameCount();
        state_.doc.setModel(v, !same);
        state_.modelLabel = std::string("trained ") + gp::kernelKindName(v->model->kind) + " (unsaved)";
        state_.setStatus(state_.training.message());
    }
    if (gp::ModelVersionPtr v = state_.compareTraining.take()) {
        state_.doc.setCompareModel(v);
        state_.setStatus("compare model: " + state_.compareTraining.message());
    }
    if (state_.requestTrain) {
        state_.requestTrain = false;
        startTraining();
    }
    if (state_.requestTrainCompare) {
        state_.requestTrainCompare = false;
        gp::TrainOptions o = state_.trainOptions;
        o.kind = o.kind == gp::KernelKind::kFas ? gp::KernelKind::kSgplvm : gp::KernelKind::kFas;
        const std::string err = state_.compareTraining.start(state_.doc.clip(), o);
        if (!err.empty()) state_.setStatus(err, true);
    }
}

void EditorApp::waitIdle() {
    state_.training.join();
    state_.compareTraining.join();
    pollJobs();
    state_.doc.waitIdle();
    latent_.prefetch(state_);  // the next frame uploads it
    latent_.waitIdle();
}

bool EditorApp::animating() const {
    const EditorDocument& d = state_.doc;
    return state_.playing || d.dragging() || d.latentDragging() || state_.training.running() ||
           state_.compareTraining.running() || d.adaptivePending() > 0 || latent_.busy() ||
           (d.hasModel() && !latent_.upToDate(state_));
}

std::string EditorApp::title() const {
    std::string t = "MotionGP - ";
    if (!state_.doc.hasClip()) t += "no clip";
    else if (state_.doc.synthetic()) t += "synthetic demo clip (no mocap data found)";
    else t += state_.clipLabel + (state_.doc.clip().format == ClipFormat::kBvh ? " (BVH, view-only)" : "");
    if (!state_.modelLabel.empty()) t += " - model: " + state_.modelLabel;
    return t;
}

bool EditorApp::handleScreenPosition(Effector e, float& x, float& y) const {
    return viewport_->handleScreenPosition(state_, e, x, y);
}

std::string EditorApp::runAction(const std::vector<std::string>& a) {
    if (a.empty()) return "empty action";
    const std::string& n = a[0];
    const std::string arg = a.size() > 1 ? a[1] : "";
    if (n == "open") return openClip(arg);
    if (n == "open-model") return openModel(arg);
    if (n == "save-model") return saveModel(arg);
    if (n == "train") {
        if (a.size() > 1) state_.trainOptions.kind = arg == "sgplvm" ? gp::KernelKind::kSgplvm : gp::KernelKind::kFas;
        if (a.size() > 2) state_.trainOptions.activeSize = std::atoi(a[2].c_str());
        if (a.size() > 3) state_.trainOptions.outerIterations = std::atoi(a[3].c_str());
        return startTraining();
    }
    if (n == "train-compare") {
        state_.requestTrainCompare = true;
        pollJobs();
        return "";
    }
    if (n == "cancel-train") {
        state_.training.cancel();
        return "";
    }
    if (n == "wait") {
        waitIdle();
        return "";
    }
    if (n == "play" || n == "pause") {
        state_.playing = n == "play";
        return "";
    }
    if (n == "frame") {
        state_.doc.setFrame(std::atoi(arg.c_str()) - 1);
        return "";
    }
    if (n == "pin") {
        Effector e;
        if (!parseEffector(arg, e)) return "unknown effector '" + arg + "'";
        state_.doc.togglePin(e);
        return "";
    }
    if (n == "compare") {
        state_.doc.setCompareMode(arg == "plain" ? CompareMode::kPlainIk
                                  : arg == "model" ? CompareMode::kSecondModel
                                                   : CompareMode::kNone);
        return "";
    }
    if (n == "frame-camera") {
        state_.requestFrameCamera = true;
        return "";
    }
    return "unknown action '" + n + "'";
}

void EditorApp::shortcuts() {
    ImGuiIO& io = ImGui::GetIO();
    if (io.WantTextInput || dialog_.isOpen()) return;
    EditorDocument& doc = state_.doc;
    if (io.KeyCtrl) {
        if (ImGui::IsKeyPressed('O', false)) state_.requestOpenClip = true;
        if (ImGui::IsKeyPressed('M', false)) state_.requestOpenModel = true;
        if (ImGui::IsKeyPressed('S', false) && doc.hasModel()) state_.requestSaveModel = true;
        if (ImGui::IsKeyPressed('T', false) && doc.trainable() && !state_.training.running()) state_.requestTrain = true;
        if (ImGui::IsKeyPressed('Q', false)) state_.requestQuit = true;
        return;
    }
    if (ImGui::IsKeyPressed(key::kSpace, false)) state_.playing = !state_.playing;
    if (ImGui::IsKeyPressed(key::kRight, true)) doc.setFrame(doc.frame() + (io.KeyShift ? 10 : 1));
    if (ImGui::IsKeyPressed(key::kLeft, true)) doc.setFrame(doc.frame() - (io.KeyShift ? 10 : 1));
    if (ImGui::IsKeyPressed(key::kHome, false)) doc.setFrame(0);
    if (ImGui::IsKeyPressed(key::kEnd, false)) doc.setFrame(doc.frameCount() - 1);
    if (ImGui::IsKeyPressed(key::kF1, false)) showHelp_ = !showHelp_;
}

void EditorApp::menus() {
    EditorDocument& doc = state_.doc;
    if (!ImGui::BeginMainMenuBar()) return;
    if (ImGui::BeginMenu("File")) {
        if (ImGui::MenuItem("Open clip...", "Ctrl+O")) state_.requestOpenClip = true;
        if (ImGui::MenuItem("Open model...", "Ctrl+M")) state_.requestOpenModel = true;
        if (ImGui::MenuItem("Save model...", "Ctrl+S", false, doc.hasModel())) state_.requestSaveModel = true;
        ImGui::Separator();
        if (ImGui::MenuItem("Synthetic demo clip")) openSyntheticClip("");
        ImGui::Separator();
        if (ImGui::MenuItem("Quit", "Ctrl+Q")) state_.requestQuit = true;
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Edit")) {
        ImGui::MenuItem("Undo", "Ctrl+Z", false, false);
        ImGui::MenuItem("Redo", "Ctrl+Y", false, false);
        ImGui::Separator();
        if (ImGui::MenuItem("Revert frame to capture", nullptr, false, doc.isEdited(doc.frame()))) doc.clearEdit(doc.frame());
        if (ImGui::BeginMenu("Pins")) {
            for (int i = 0; i < kEffectorCount; ++i) {
                const auto e = static_cast<Effector>(i);
                if (ImGui::MenuItem(effectorName(e), i == 0 ? "P on handle" : nullptr, doc.pinned(e), doc.hasEffector(e)))
                    doc.togglePin(e);
            }
            ImGui::EndMenu();
        }
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Model")) {
        if (ImGui::MenuItem("Train", "Ctrl+T", false, doc.trainable() && !state_.training.running()))
            state_.requestTrain = true;
        if (ImGui::MenuItem("Cancel training", nullptr, false, state_.training.running())) state_.training.cancel();
        bool adaptive = doc.adaptiveEnabled();
        if (ImGui::MenuItem("Adaptive active set", nullptr, &adaptive)) doc.setAdaptiveEnabled(adaptive);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("View")) {
        if (ImGui::MenuItem("Frame character", "F")) state_.requestFrameCamera = true;
        ImGui::MenuItem("Follow character", nullptr, &state_.followCharacter);
        if (ImGui::BeginMenu("Compare ghost")) {
            if (ImGui::MenuItem("Off", nullptr, doc.compareMode() == CompareMode::kNone)) doc.setCompareMode(CompareMode::kNone);
            if (ImGui::MenuItem("Plain IK", nullptr, doc.compareMode() == CompareMode::kPlainIk))
                doc.setCompareMode(CompareMode::kPlainIk);
            if (ImGui::MenuItem("Second model", nullptr, doc.compareMode() == CompareMode::kSecondModel))
                doc.setCompareMode(CompareMode::kSecondModel);
            ImGui::EndMenu();
        }
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Playback")) {
        if (ImGui::MenuItem(state_.playing ? "Pause" : "Play", "Space")) state_.playing = !state_.playing;
        if (ImGui::MenuItem("Next frame", "Right")) doc.setFrame(doc.frame() + 1);
        if (ImGui::MenuItem("Previous frame", "Left")) doc.setFrame(doc.frame() - 1);
        if (ImGui::MenuItem("Forward 10 frames", "Shift+Right")) doc.setFrame(doc.frame() + 10);
        if (ImGui::MenuItem("First frame", "Home")) doc.setFrame(0);
        if (ImGui::MenuItem("Last frame", "End")) doc.setFrame(doc.frameCount() - 1);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Help")) {
        if (ImGui::MenuItem("Controls", "F1")) showHelp_ = true;
        ImGui::EndMenu();
    }
    // Right side of the menu bar: background work.
    std::string bg;
    if (state_.training.running()) {
        const TrainingProgress p = state_.training.progress();
        bg = "training " + std::to_string(p.iteration) + "/" + std::to_string(p.total);
    } else if (doc.adaptivePending() > 0) {
        bg = "adaptive update...";
    } else if (latent_.busy()) {
        bg = "latent map...";
    }
    if (!bg.empty()) {
        ImGui::SameLine(ImGui::GetWindowWidth() - ImGui::CalcTextSize(bg.c_str()).x - 16);
        ImGui::TextColored(ImVec4(0.45f, 0.8f, 1.0f, 1), "%s", bg.c_str());
    }
    ImGui::EndMainMenuBar();
}

void EditorApp::layout(int w, int h) {
    const float menuH = ImGui::GetFrameHeight();
    const float rightW = 380.0f, timelineH = 104.0f;
    const float modelH = 262.0f, latentH = 356.0f;
    const float leftW = float(w) - rightW;
    const ImGuiWindowFlags fixed = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus;
    auto place = [](float x, float y, float ww, float hh) {
        ImGui::SetNextWindowPos(ImVec2(x, y));
        ImGui::SetNextWindowSize(ImVec2(std::max(ww, 50.0f), std::max(hh, 40.0f)));
    };

    place(0, menuH, leftW, float(h) - menuH - timelineH);
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
    ImGui::Begin("Viewport", nullptr, fixed | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoBackground |
                                          ImGuiWindowFlags_NoScrollWithMouse);
    ImGui::PopStyleVar();
    viewport_->draw(state_);
    ImGui::End();

    place(0, float(h) - timelineH, leftW, timelineH);
    ImGui::Begin("Timeline", nullptr, fixed | ImGuiWindowFlags_NoScrollbar);
    {
        // Track above, status line below.
        const float statusH = ImGui::GetTextLineHeightWithSpacing();
        ImGui::BeginChild("tl", ImVec2(0, -statusH), false, ImGuiWindowFlags_NoScrollbar);
        timeline_.draw(state_);
        ImGui::EndChild();
        if (state_.statusIsError) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.45f, 1), "%s", state_.status.c_str());
        else ImGui::TextDisabled("%s", state_.status.c_str());
    }
    ImGui::End();

    place(leftW, menuH, rightW, modelH);
    ImGui::Begin("Model", nullptr, fixed);
    drawModelPanel(state_);
    ImGui::End();

    place(leftW, menuH + modelH, rightW, latentH);
    ImGui::Begin("Latent map", nullptr, fixed | ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
    latent_.draw(state_);
    ImGui::End();

    place(leftW, menuH + modelH + latentH, rightW, float(h) - menuH - modelH - latentH);
    ImGui::Begin("IK readout", nullptr, fixed);
    drawIkReadout(state_);
    ImGui::End();

    if (showHelp_) {
        ImGui::SetNextWindowPos(ImVec2(leftW * 0.5f, float(h) * 0.4f), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
        ImGui::Begin("Controls", &showHelp_, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings);
        ImGui::Text("Viewport");
        ImGui::BulletText("Hover a hand/foot/head handle, left-drag: pose with learned IK (camera-facing plane)");
        ImGui::BulletText("Shift while dragging a handle: move on the horizontal plane");
        ImGui::BulletText("Right-click or P on a handle: pin / unpin (keeps a foot planted)");
        ImGui::BulletText("Left-drag empty space: orbit   Middle-drag or Shift+left: pan   Wheel: zoom   F: frame");
        ImGui::BulletText("Esc during a drag: cancel");
        ImGui::Text("Timeline");
        ImGui::BulletText("Space: play/pause   Left/Right: step (Shift: 10)   Home/End: first/last");
        ImGui::Text("Latent map");
        ImGui::BulletText("Hover: nearest training frame   Click a point: go to its frame");
        ImGui::BulletText("Drag the red point: pose from the model mean f(x)");
        ImGui::End();
    }
}

void EditorApp::dialogs() {
    if (state_.requestOpenClip) {
        state_.requestOpenClip = false;
        dialog_.open("Open clip (ASF/AMC or BVH)", FileDialog::Mode::kOpen, {".amc", ".bvh"},
                     options_.mocapDir.empty() ? "" : options_.mocapDir + "/asf_amc");
        purpose_ = DialogPurpose::kClip;
    }
    if (state_.requestOpenModel) {
        state_.requestOpenModel = false;
        dialog_.open("Open model", FileDialog::Mode::kOpen, {".json"}, "");
        purpose_ = DialogPurpose::kModel;
    }
    if (state_.requestSaveModel) {
        state_.requestSaveModel = false;
        dialog_.open("Save model", FileDialog::Mode::kSave, {".json"}, "");
        purpose_ = DialogPurpose::kSaveModel;
    }
    if (auto path = dialog_.draw()) {
        switch (purpose_) {
            case DialogPurpose::kClip: openClip(*path); break;
            case DialogPurpose::kModel: openModel(*path); break;
            case DialogPurpose::kSaveModel: saveModel(*path); break;
            case DialogPurpose::kNone: break;
        }
        purpose_ = DialogPurpose::kNone;
    }
}

void EditorApp::frame(InputState& in, double dt, int width, int height) {
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(float(width), float(height));
    io.DisplayFramebufferScale = ImVec2(1, 1);
    io.DeltaTime = dt > 0.0 ? float(dt) : 1.0f / 60.0f;
    io.MousePos = in.mouseX >= 0 && in.mouseY >= 0 ? ImVec2(in.mouseX, in.mouseY) : ImVec2(-FLT_MAX, -FLT_MAX);
    for (int b = 0; b < 3; ++b) io.MouseDown[b] = in.mouseDown[b];
    io.MouseWheel = in.wheel;
    in.wheel = 0.0f;
    for (int k = 0; k < key::kCount && k < int(IM_ARRAYSIZE(io.KeysDown)); ++k) io.KeysDown[k] = in.keys[k];
    io.KeyShift = in.shift();
    io.KeyCtrl = in.ctrl();
    io.KeyAlt = in.alt();
    for (char32_t c : in.chars) io.AddInputCharacter(static_cast<unsigned>(c));
    in.chars.clear();

    pollJobs();
    TimelinePanel::advance(state_, io.DeltaTime);

    ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();
    shortcuts();
    menus();
    layout(width, height);
    dialogs();
    ImGui::Render();

    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
    glDisable(GL_SCISSOR_TEST);
    glClearColor(0.1f, 0.1f, 0.11f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

render::Image EditorApp::capture(int width, int height) const {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return render::readFramebuffer(width, height);
}

// ---- script player ---------------------------------------------------------------------------

ScriptPlayer::ScriptPlayer(GuiScript script) : script_(std::move(script)) {}

void ScriptPlayer::apply(int frame, InputState& in, EditorApp& app, std::vector<std::string>& screenshots) {
    for (int k : releaseNext_) in.keys[k] = false;
    releaseNext_.clear();
    const auto& ev = script_.events();
    auto button = [](const std::string& b) { return b == "left" ? 0 : b == "right" ? 1 : 2; };
    while (next_ < ev.size() && ev[next_].frame <= frame) {
        const ScriptEvent& e = ev[next_++];
        const auto& a = e.args;
        if (e.verb == "move") {
            in.mouseX = float(std::atof(a[0].c_str()));
            in.mouseY = float(std::atof(a[1].c_str()));
        } else if (e.verb == "moveby") {
            in.mouseX += float(std::atof(a[0].c_str()));
            in.mouseY += float(std::atof(a[1].c_str()));
        } else if (e.verb == "hover") {
            Effector eff;
            float x, y;
            if (parseEffector(a[0], eff) && app.handleScreenPosition(eff, x, y)) {
                in.mouseX = x;
                in.mouseY = y;
            } else {
                errors_.push_back("line " + std::to_string(e.line) + ": handle '" + a[0] + "' is not on screen");
            }
        } else if (e.verb == "down" || e.verb == "up") {
            in.mouseDown[button(a[0])] = e.verb == "down";
        } else if (e.verb == "wheel") {
            in.wheel += float(std::atof(a[0].c_str()));
        } else if (e.verb == "key" || e.verb == "keydown" || e.verb == "keyup") {
            const int k = keyFromName(a[0]);
            if (k < 0) continue;
            in.keys[k] = e.verb != "keyup";
            if (e.verb == "key") releaseNext_.push_back(k);
        } else if (e.verb == "action") {
            if (a[0] == "screenshot") {
                screenshots.push_back(a.size() > 1 ? a[1] : "screenshot.png");
            } else {
                const std::string err = app.runAction(a);
                if (!err.empty()) errors_.push_back("line " + std::to_string(e.line) + ": " + err);
            }
        }
    }
}

}  // namespace mgp::ui
