#include "ui/shell/file_requests.h"

#include <filesystem>

namespace mgp::ui {

std::string fileNameOf(const std::string& path) { return std::filesystem::path(path).filename().string(); }

FileRequest fileRequest(FileKind kind, const EditorDocument& doc, const std::string& sessionPath,
                        const std::string& mocapDir) {
    using Mode = FileDialog::Mode;
    const std::string clipStem = doc.hasClip() && !doc.clip().sourcePath.empty()
                                     ? std::filesystem::path(doc.clip().sourcePath).stem().string()
                                 : doc.hasClip() && !doc.clip().name.empty() ? doc.clip().name
                                                                             : "motion";
    switch (kind) {
        case FileKind::kOpenAny:
            return {"Open session, clip (ASF/AMC, BVH) or model",
                    Mode::kOpen,
                    {".mgsession", ".amc", ".bvh", ".json", ".model"},
                    mocapDir.empty() ? "" : mocapDir + "/asf_amc",
                    ""};
        case FileKind::kModel: return {"Open model", Mode::kOpen, {".json", ".model"}, "", ""};
        case FileKind::kSaveModel: return {"Save model", Mode::kSave, {".json", ".model"}, "", clipStem + ".model"};
        case FileKind::kSaveSession:
            return {
                "Save session",
                Mode::kSave,
                {".mgsession"},
                "",
                sessionPath.empty() ? clipStem + ".mgsession" : std::filesystem::path(sessionPath).filename().string()};
        case FileKind::kExportBvh: return {"Export motion as BVH", Mode::kSave, {".bvh"}, "", clipStem + "_edited.bvh"};
        case FileKind::kExportGltf:
            return {"Export motion as glTF (.glb binary, .gltf text)",
                    Mode::kSave,
                    {".glb", ".gltf"},
                    "",
                    clipStem + "_edited.glb"};
        case FileKind::kExportFbx:
            return {"Export motion as FBX (through Blender)", Mode::kSave, {".fbx"}, "", clipStem + "_edited.fbx"};
        case FileKind::kExportPng:
            return {"Export viewport as PNG",
                    Mode::kSave,
                    {".png"},
                    "",
                    clipStem + "_f" + std::to_string(doc.frame() + 1) + ".png"};
        case FileKind::kNone: break;
    }
    return {};
}

}  // namespace mgp::ui
