#include "io/data_paths.h"

#include <sys/stat.h>

#include <cstdlib>
#include <filesystem>
#include <initializer_list>

namespace mgp {

namespace {
bool isDir(const std::string& p) {
    struct stat st {};
    return ::stat(p.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}
bool isFile(const std::string& p) {
    struct stat st {};
    return ::stat(p.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}
}  // namespace

bool isMocapFolder(const std::string& dir) { return !dir.empty() && (isDir(dir + "/asf_amc") || isDir(dir + "/bvh")); }

namespace {
// The first of exeDir + relative that is a mocap folder ("" exeDir: none).
std::optional<std::string> firstMocapFolderBeside(const std::string& exeDir,
                                                  std::initializer_list<const char*> relatives) {
    if (!exeDir.empty())
        for (const char* rel : relatives)
            if (isMocapFolder(exeDir + rel)) return exeDir + rel;
    return std::nullopt;
}
}  // namespace

std::optional<std::string> findMocapFolder(const std::string& cliDir, const std::string& exeDir) {
    if (!cliDir.empty()) {
        if (isMocapFolder(cliDir)) return cliDir;
        return std::nullopt;  // an explicit choice that does not exist is not silently replaced
    }
    if (const char* env = std::getenv("MOTIONGP_DATA"); env && isMocapFolder(env)) return std::string(env);
#ifdef MOTIONGP_SHARED_MOCAP
    if (isMocapFolder(MOTIONGP_SHARED_MOCAP)) return std::string(MOTIONGP_SHARED_MOCAP);
#endif
    return firstMocapFolderBeside(exeDir, {"/../shared/mocap", "/../../shared/mocap", "/shared/mocap"});
}

std::optional<std::string> findShippedMocapFolder(const std::string& exeDir) {
#ifdef MOTIONGP_SHIPPED_MOCAP
    if (isMocapFolder(MOTIONGP_SHIPPED_MOCAP)) return std::string(MOTIONGP_SHIPPED_MOCAP);
#endif
    return firstMocapFolderBeside(exeDir, {"/../assets/mocap", "/assets/mocap", "/../share/motiongp/mocap"});
}

std::optional<std::string> findEditorMocapFolder(const std::string& cliDir, const std::string& exeDir) {
    if (auto full = findMocapFolder(cliDir, exeDir)) return full;
    if (!cliDir.empty()) return std::nullopt;
    return findShippedMocapFolder(exeDir);
}

std::optional<std::string> defaultClipIn(const std::string& mocapDir) {
    const std::string amc = mocapDir + "/asf_amc/10_02.amc";
    if (isFile(amc) && isFile(mocapDir + "/asf_amc/10.asf")) return amc;
    return std::nullopt;
}

std::string absolutePath(const std::string& path) {
    if (path.empty()) return path;
    std::error_code ec;
    const std::filesystem::path p = std::filesystem::absolute(path, ec);
    return ec ? path : p.lexically_normal().string();
}

}  // namespace mgp
