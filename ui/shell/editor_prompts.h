#pragma once
// The editor's modal questions: unsaved changes before quitting or replacing the document
// ("Save them before opening a model?"), opening a model trained on another clip than the open
// one, and restoring an autosave a crashed editor left behind.
// One modal at a time: a question waits while another popup or the file dialog is open.
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "session/autosave.h"

namespace mgp::ui {

class EditorPrompts {
public:
    // What the questions need from the editor.
    struct Hooks {
        std::string sessionPath;                                // "" until the session has a file
        std::function<bool(const std::string&)> save;           // saves the session there; true on success
        std::function<void()> askForSessionFile;                // opens the Save session dialog
        std::function<void(const std::string&)> restore;        // restores that autosave
        std::function<void(const std::string&)> recordControl;  // the last item's rectangle, by name (tests)
    };

    // Runs `action` now when nothing is unsaved, else after the user answered (Save, Don't
    // save; Cancel drops it).
    void guard(bool unsaved, std::function<void()> action, std::string what);
    // Between NewFrame and Render, after the file dialog.
    void draw(bool dialogOpen, const Hooks& hooks);
    bool askingUnsaved() const { return asking_; }  // the modal is up (as of the last draw)

    // A model whose clip is not the open clip: `lines` say which clips and how they differ;
    // "Open with its clip" (Enter) runs `openIt`, Cancel (Esc) drops it.
    void askModelClip(std::vector<std::string> lines, std::function<void()> openIt);
    bool askingModelClip() const { return askingModelClip_; }  // the modal is up (as of the last draw)

    // "Save" on a session without a file asks for one: the action waits for that save.
    std::function<void()> takeAfterSave() { return std::exchange(afterSave_, nullptr); }
    void dropAfterSave() { afterSave_ = nullptr; }

    void offerAutosaves(std::vector<AutosaveCandidate> found) { restoreOffer_ = std::move(found); }
    bool offeringAutosave() const { return !restoreOffer_.empty(); }
    void dropAutosaveOffer() { restoreOffer_.clear(); }

private:
    void unsavedChanges(bool dialogOpen, const Hooks& hooks);
    void restoreAutosave(bool dialogOpen, const Hooks& hooks);
    void modelClip(bool dialogOpen);

    std::function<void()> pending_, afterSave_;
    std::string pendingWhat_;
    bool asking_ = false;
    std::vector<std::string> modelClipLines_;
    std::function<void()> openModelClip_;
    bool askingModelClip_ = false;
    std::vector<AutosaveCandidate> restoreOffer_;
};

}  // namespace mgp::ui
