#include "io/clip_loader.h"

#include "io/amc_reader.h"
#include "io/asf_reader.h"
#include "io/bvh_reader.h"
#include "io/gltf_reader.h"
#include "io/parse_error.h"
#include "io/text_reader.h"

namespace mgp {

std::string defaultAsfFor(const std::string& amcPath) {
    const std::size_t slash = amcPath.find_last_of('/');
    const std::string dir = slash == std::string::npos ? "" : amcPath.substr(0, slash + 1);
    const std::string base = slash == std::string::npos ? amcPath : amcPath.substr(slash + 1);
    const std::size_t cut = base.find('_');
    const std::size_t dot = base.find_last_of('.');
    const std::string subject = base.substr(0, cut != std::string::npos ? cut : dot);
    return dir + subject + ".asf";
}

bool isClipPath(const std::string& path) {
    const std::string ext = fileExtension(path);
    return ext == "amc" || ext == "bvh" || ext == "glb" || ext == "gltf";
}

Clip loadClip(const std::string& path, const std::string& skeletonPath) {
    const std::string ext = fileExtension(path);
    if (ext == "bvh") return readBvh(path);
    if (ext == "glb" || ext == "gltf") return readGltfClip(path);
    if (ext == "amc") {
        const std::string asfPath = skeletonPath.empty() ? defaultAsfFor(path) : skeletonPath;
        const AsfSkeleton asf = readAsf(asfPath);
        return readAmc(path, asf);
    }
    if (ext == "asf")
        throwParseError(path, 0, "a motion clip (.amc or .bvh; pass the .asf with --skel)", "a skeleton file");
    throwParseError(path, 0, "a clip ending in .amc, .bvh, .glb or .gltf", "'." + ext + "'");
}

}  // namespace mgp
