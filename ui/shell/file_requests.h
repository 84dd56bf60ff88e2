#pragma once
// The files the editor asks for, and how each file dialog opens: title, mode, extensions, start
// folder and a default name made from the session or the clip ("35_01_edited.bvh",
// "35_01_f41.png"), ready to confirm.
#include <string>
#include <vector>

#include "edit/editor_document.h"
#include "ui/windows/file_dialog.h"

namespace mgp::ui {

enum class FileKind {
    kNone,
    kOpenAny,
    kModel,
    kSaveModel,
    kSaveSession,
    kExportBvh,
    kExportGltf,
    kExportFbx,
    kExportPng
};

struct FileRequest {
    std::string title;
    FileDialog::Mode mode = FileDialog::Mode::kOpen;
    std::vector<std::string> extensions;
    std::string startDir;     // "" = the current directory
    std::string defaultName;  // "" for the open dialogs
};

// `sessionPath` "" = not saved yet; `mocapDir` "" = no data folder (File > Open starts in its
// asf_amc/ otherwise).
// The file name of `path` without its folders, as the title bar and labels show it.
std::string fileNameOf(const std::string& path);

FileRequest fileRequest(FileKind kind, const EditorDocument& doc, const std::string& sessionPath,
                        const std::string& mocapDir);

}  // namespace mgp::ui
