#include "io/clip_export.h"

#include <stdexcept>

#include "io/bvh_writer.h"
#include "io/fbx_export.h"
#include "io/gltf_writer.h"
#include "io/text_reader.h"

namespace mgp {

const char* exportExtensions() { return ".bvh, .glb, .gltf or .fbx"; }

bool isExportPath(const std::string& path) {
    const std::string ext = fileExtension(path);
    return ext == "bvh" || ext == "fbx" || isGltfPath(path);
}

void exportClip(const Clip& clip, const std::string& path, const std::function<void(const std::string&)>& progress) {
    const std::string ext = fileExtension(path);
    if (ext == "bvh") return writeBvh(clip, path);
    if (ext == "fbx") return exportFbxThroughBlender(clip, path, progress);
    if (isGltfPath(path)) return writeGltf(clip, path);
    throw std::invalid_argument(path + ": expected an output file ending in " + std::string(exportExtensions()) +
                                ", found '." + ext + "'");
}

}  // namespace mgp
