#include "ui/windows/train_clips_window.h"

#include <imgui.h>

#include <algorithm>
#include <filesystem>

#include "io/clip_loader.h"
#include "ui/actions/editor_commands.h"
#include "ui/input/input_state.h"
#include "ui/panels/model_panel.h"
#include "ui/shell/editor_state.h"
#include "ui/widgets/widgets.h"
#include "ui/windows/file_dialog.h"

namespace mgp::ui {

namespace {
constexpr const char* kTitle = "Train on clips";

// "10_02" matches the candidate 10_02 and its file name 10_02.amc.
bool names(const TrainingCandidate& c, const std::string& name) {
    return c.name == name || (!c.path.empty() && std::filesystem::path(c.path).filename().string() == name);
}

// The refusal in a few words beside the name (the whole reason is the row's tooltip).
const char* shortReason(const std::string& reason) {
    if (reason.rfind("a BVH", 0) == 0 || reason.rfind("an ASF", 0) == 0) return "other format";
    if (reason.rfind("another skeleton", 0) == 0) return "other skeleton";
    return "cannot be used (hover: why)";
}
}  // namespace

void TrainClipsWindow::show(EditorCommands& app) {
    const EditorDocument& doc = app.state().doc;
    candidates_.clear();
    checked_.clear();
    loaded_.clear();
    error_.clear();
    if (!doc.hasClip()) return;
    candidates_ = trainingCandidates(doc.clip());
    checked_.assign(candidates_.size(), false);
    checked_[0] = candidates_[0].usable;  // the open clip is always part of the training
    openName_ = doc.clip().name;
    openHeader_ = doc.clip();
    openHeader_.frames.clear();
    openFrames_ = doc.clip().frameCount();
    open_ = true;
}

const Clip* TrainClipsWindow::clipOf(std::size_t i, const EditorCommands& app) const {
    if (i >= candidates_.size()) return nullptr;
    if (candidates_[i].open) return app.state().doc.hasClip() ? &app.state().doc.clip() : nullptr;
    const auto it = loaded_.find(candidates_[i].path);
    return it == loaded_.end() ? nullptr : &it->second;
}

std::string TrainClipsWindow::load(std::size_t i) {
    TrainingCandidate& c = candidates_[i];
    if (c.open || loaded_.count(c.path)) return "";
    try {
        loaded_.emplace(c.path, loadClip(c.path));
        return "";
    } catch (const std::exception& e) {
        c.usable = false;  // listed as refused from now on, with the reader's message
        c.reason = e.what();
        return e.what();
    }
}

std::string TrainClipsWindow::check(const std::string& name, bool on) {
    std::size_t i = 0;
    while (i < candidates_.size() && !names(candidates_[i], name)) ++i;
    if (i == candidates_.size()) {
        if (name.find('/') == std::string::npos) {
            std::string listed;
            for (const TrainingCandidate& c : candidates_)
                if (c.usable && !c.open) listed += (listed.empty() ? "" : ", ") + c.name;
            return "no clip '" + name + "' beside the open clip (offered: " + (listed.empty() ? "none" : listed) +
                   "; give a path to add another file)";
        }
        return addFile(name);
    }
    const TrainingCandidate& c = candidates_[i];
    if (c.open) return on ? "" : "the open clip is always part of the training (it becomes the model's primary clip)";
    if (!on) {
        checked_[i] = false;
        return "";
    }
    if (!c.usable) return c.name + " cannot train with " + openName_ + ": " + c.reason;
    if (std::string err = load(i); !err.empty()) return err;
    checked_[i] = true;
    return "";
}

std::string TrainClipsWindow::addFile(const std::string& path) {
    if (candidates_.empty()) return "no clip open";
    for (const TrainingCandidate& c : candidates_) {
        std::error_code ec;  // a path that does not exist is no error here: it is refused below
        if (!c.path.empty() && std::filesystem::equivalent(c.path, path, ec) && !ec) return check(c.name, true);
    }
    // Judged against the open clip, which the list was made for; a refused file stays listed with why.
    TrainingCandidate added = trainingCandidate(openHeader_, path);
    for (const TrainingCandidate& c : candidates_)
        if (c.name == added.name)  // a model names its clips by file stem
            return "expected clips with distinct names (file stems), found " + added.name + " twice";
    candidates_.push_back(std::move(added));
    checked_.push_back(false);
    const TrainingCandidate& c = candidates_.back();
    if (!c.usable) return c.name + " cannot train with " + openName_ + ": " + c.reason;
    if (std::string err = load(candidates_.size() - 1); !err.empty()) return err;
    checked_.back() = true;
    return "";
}

int TrainClipsWindow::totalRows(std::string* error) const {
    int rows = 0;
    try {
        for (std::size_t i = 0; i < candidates_.size(); ++i) {
            if (!checked_[i]) continue;
            int frames = openFrames_;
            bool restFrame = openHeader_.restFrame;
            if (!candidates_[i].open) {
                const auto it = loaded_.find(candidates_[i].path);
                if (it == loaded_.end()) continue;
                frames = it->second.frameCount();
                restFrame = it->second.restFrame;
            }
            rows += static_cast<int>(gp::trainingFrames(frames, restFrame, selection_, candidates_[i].name).size());
        }
    } catch (const std::exception& e) {
        if (error) *error = e.what();
        return -1;
    }
    return rows;
}

std::string TrainClipsWindow::train(EditorCommands& app) {
    EditorState& s = app.state();
    if (!open_ || candidates_.empty()) return "open Model > Train on clips... first";
    if (!s.doc.hasClip() || s.doc.clip().name != openName_ || s.doc.clip().frameCount() != openFrames_)
        return "the open clip changed since the list was made: open Train on clips again";
    if (!candidates_[0].usable) return candidates_[0].reason;
    if (s.training.running()) return "a training run is already in progress";
    std::vector<Clip> clips;
    std::vector<std::string> paths;
    for (std::size_t i = 0; i < candidates_.size(); ++i) {
        if (!checked_[i]) continue;
        const Clip* c = clipOf(i, app);
        if (!c) return "cannot read " + candidates_[i].name;
        clips.push_back(*c);
        paths.push_back(candidates_[i].path);
    }
    std::vector<gp::TrainingClip> prepared;
    try {
        prepared = gp::prepareTrainingClips(std::move(clips), paths, selection_);
    } catch (const std::exception& e) {
        return e.what();
    }
    const std::string err = app.startTraining(std::move(prepared), selection_);
    if (err.empty()) open_ = false;
    return err;
}

void TrainClipsWindow::drawCandidates(EditorCommands& app, float scale) {
    EditorState& s = app.state();
    // The list: open clip, offered clips, refused ones (greyed, the reason as tooltip).
    const float rowH = ImGui::GetFrameHeightWithSpacing();
    const float listH =
        std::min(rowH * float(candidates_.size()) + 2.0f * ImGui::GetStyle().WindowPadding.y, 260.0f * scale);
    ImGui::BeginChild("candidates", ImVec2(440.0f * scale, listH), true);
    for (std::size_t i = 0; i < candidates_.size(); ++i) {
        const TrainingCandidate& c = candidates_[i];
        ImGui::PushID(static_cast<int>(i));
        bool on = checked_[i];
        const bool locked = c.open || !c.usable;
        ImGui::BeginDisabled(locked);
        std::string label = c.name;
        if (c.open) label += "  (open clip, primary)";
        if (ImGui::Checkbox(label.c_str(), &on)) {
            if (std::string err = check(c.name, on); !err.empty())
                error_ = err;
            else
                error_.clear();
        }
        ImGui::EndDisabled();
        s.recordControl("train clips: " + c.name);
        if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
            if (!c.usable)
                tooltip("%s", c.reason.c_str());
            else if (!c.path.empty())
                tooltip("%s", c.path.c_str());
        }
        const Clip* clip = clipOf(i, app);
        ImGui::SameLine(260.0f * scale);
        if (!c.usable)
            ImGui::TextDisabled("%s", shortReason(c.reason));
        else if (clip)
            ImGui::TextDisabled("%d frames", clip->frameCount());
        else
            ImGui::TextDisabled("same skeleton");
        ImGui::PopID();
    }
    ImGui::EndChild();
}

void TrainClipsWindow::drawAddFile(float scale) {
    // Add file…: a path typed in (there is no native file dialog).
    char buf[512];
    const std::size_t n = std::min(addPath_.size(), sizeof buf - 1);
    addPath_.copy(buf, n);
    buf[n] = '\0';
    ImGui::SetNextItemWidth(340.0f * scale);
    if (ImGui::InputTextWithHint("##addfile", "another .amc or .bvh file (path)", buf, sizeof buf)) addPath_ = buf;
    ImGui::SameLine();
    ImGui::BeginDisabled(addPath_.empty());
    if (ImGui::Button("Add file")) {
        error_ = addFile(addPath_);
        if (error_.empty()) addPath_.clear();
    }
    ImGui::EndDisabled();
}

void TrainClipsWindow::drawFrameSelection(float scale) {
    // Frames of each clip, as `train --frames A:B --step K`.
    ImGui::PushItemWidth(70.0f * scale);
    ImGui::InputInt("from", &selection_.first, 0);
    ImGui::SameLine();
    ImGui::InputInt("to (0: end)", &selection_.last, 0);
    ImGui::SameLine();
    ImGui::InputInt("step", &selection_.step, 0);
    ImGui::PopItemWidth();
    selection_.first = std::max(selection_.first, 1);
    selection_.last = std::max(selection_.last, 0);
    selection_.step = std::max(selection_.step, 1);
    if (ImGui::IsItemHovered()) tooltip("Frames from..to of each clip (counted from 1 within it), then every step-th");
}

int TrainClipsWindow::drawSummary(const EditorState& s, float scale) const {
    std::string rangeError;
    const int rows = totalRows(&rangeError);
    int clipsChecked = 0;
    for (bool b : checked_) clipsChecked += b ? 1 : 0;
    if (rows >= 0) {
        ImGui::Text("N = %d training frames from %d clip%s", rows, clipsChecked, clipsChecked == 1 ? "" : "s");
        if (rows > 0 && s.trainOptions.activeSize >= rows) {
            ImGui::SameLine();
            ImGui::TextDisabled("(M >= N: every frame active)");
        }
    } else {
        ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1), "%s", rangeError.c_str());
    }
    if (!error_.empty()) {
        ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + 440.0f * scale);
        ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.45f, 1), "%s", error_.c_str());
        ImGui::PopTextWrapPos();
    }
    return rows;
}

void TrainClipsWindow::draw(EditorCommands& app) {
    EditorState& s = app.state();
    if (open_ && !popupUp_ && !ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId) && !app.fileDialog().isOpen())
        ImGui::OpenPopup(kTitle);
    ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    popupUp_ =
        ImGui::BeginPopupModal(kTitle, nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings);
    if (!popupUp_) return;
    if (!open_) {  // closed by train() or an action
        ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
        popupUp_ = false;
        return;
    }
    const float scale = app.uiScale();
    ImGui::Text("One model from the open clip and other clips of its skeleton");
    ImGui::TextDisabled("The open clip is always included and becomes the model's primary clip.");
    drawCandidates(app, scale);
    drawAddFile(scale);
    drawFrameSelection(scale);
    drawTrainOptions(s.trainOptions);
    const int rows = drawSummary(s, scale);
    const bool busy = s.training.running();
    const bool canTrain = !busy && rows >= 3;
    ImGui::BeginDisabled(!canTrain);
    const bool trainClicked = ImGui::Button("Train", ImVec2(110.0f * scale, 0));
    ImGui::EndDisabled();
    s.recordControl("train clips: Train");
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled) && !canTrain)
        tooltip("%s", busy ? "a training run is already in progress" : "expected at least 3 training frames");
    ImGui::SameLine();
    const bool cancel = ImGui::Button("Cancel", ImVec2(110.0f * scale, 0));
    s.recordControl("train clips: Cancel");
    // Esc closes, but not on the frame the modal appears (the key that opened it may still be down).
    const bool escape = !ImGui::IsWindowAppearing() && ImGui::IsKeyPressed(key::kEscape, false);
    if (trainClicked) {
        error_ = train(app);
        if (!error_.empty()) s.setStatus(error_, true);
    }
    if (cancel || escape) open_ = false;
    if (!open_) {
        ImGui::CloseCurrentPopup();
        popupUp_ = false;
    }
    ImGui::EndPopup();
}

}  // namespace mgp::ui
