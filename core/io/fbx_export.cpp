#include "io/fbx_export.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "io/gltf_writer.h"

extern char** environ;

namespace mgp {

namespace {

// Run by Blender: import the glTF, keep the clip's rate and frame range, bake every frame to FBX.
// Debian 12's Blender 3.4 glTF importer still uses numpy.bool, which numpy 1.24 removed.
constexpr const char* kBlenderScript = R"PY(
import sys
import numpy
if not hasattr(numpy, "bool"):
    numpy.bool = bool
import bpy
src, dst, fps = sys.argv[sys.argv.index("--") + 1:][:3]
fps = float(fps)
bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
scene.render.fps = round(fps)
scene.render.fps_base = round(fps) / fps
print("MOTIONGP_STAGE importing the glTF", flush=True)
bpy.ops.import_scene.gltf(filepath=src)
armatures = [o for o in scene.objects if o.type == "ARMATURE"]
if len(armatures) != 1 or len(bpy.data.actions) != 1:
    raise SystemExit(f"expected one armature and one action, found {len(armatures)} and {len(bpy.data.actions)}")
first, last = bpy.data.actions[0].frame_range
scene.frame_start, scene.frame_end = int(round(first)), int(round(last))
print("MOTIONGP_STAGE writing the FBX", flush=True)
bpy.ops.export_scene.fbx(filepath=dst, object_types={"ARMATURE", "MESH"}, add_leaf_bones=False,
                         bake_anim=True, bake_anim_use_all_actions=False, bake_anim_use_nla_strips=False,
                         bake_anim_force_startend_keying=True, bake_anim_simplify_factor=0.0)
)PY";

bool isExecutableFile(const std::string& path) {
    struct stat st {};
    return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::access(path.c_str(), X_OK) == 0;
}

// The last `lines` lines of a text file (Blender's log), for an error message.
std::string lastLinesOf(const std::string& path, int lines) {
    std::ifstream in(path);
    std::vector<std::string> all;
    for (std::string line; std::getline(in, line);) all.push_back(line);
    std::string out;
    for (std::size_t i = all.size() > static_cast<std::size_t>(lines) ? all.size() - lines : 0; i < all.size(); ++i)
        out += "\n  " + all[i];
    return out;
}

}  // namespace

std::string findBlender(std::string* why) {
    if (const char* env = std::getenv("MOTIONGP_BLENDER"); env && *env) {
        if (isExecutableFile(env)) return env;
        if (why) *why = std::string("found MOTIONGP_BLENDER=") + env + ", which is not an executable file";
        return "";
    }
    const char* path = std::getenv("PATH");
    std::stringstream dirs(path ? path : "/usr/bin:/bin");
    for (std::string dir; std::getline(dirs, dir, ':');)
        if (!dir.empty() && isExecutableFile(dir + "/blender")) return dir + "/blender";
    if (why) *why = "found no blender on PATH";
    return "";
}

std::string fbxExportUnavailable(const std::string& fbxPath) {
    std::string why;
    if (!findBlender(&why).empty()) return "";
    return fbxPath + ": FBX export needs Blender (apt-get install blender, or set MOTIONGP_BLENDER), " + why +
           "; glTF (.glb) needs nothing else";
}

void exportFbxThroughBlender(const Clip& clip, const std::string& fbxPath,
                             const std::function<void(const std::string&)>& progress) {
    auto say = [&](const std::string& what) {
        if (progress) progress(what);
    };
    if (const std::string problem = fbxExportUnavailable(fbxPath); !problem.empty()) throw std::runtime_error(problem);
    const std::string blender = findBlender();
    const std::string stem = fbxPath + ".tmp." + std::to_string(::getpid());
    const std::string glb = stem + ".glb", fbx = stem + ".fbx", log = stem + ".log";
    struct Cleanup {
        std::vector<std::string> paths;
        ~Cleanup() {
            for (const std::string& p : paths) ::unlink(p.c_str());
        }
    } cleanup{{glb, fbx, log}};
    say("writing a glTF for Blender");
    writeGltf(clip, glb);

    say("Blender: importing the glTF and writing the FBX (" + std::to_string(clip.frameCount()) + " frames)");
    char fpsText[32];
    std::snprintf(fpsText, sizeof fpsText, "%.9g", clip.fps);
    std::vector<std::string> args{
        blender, "-b",   "--factory-startup", "--python-exit-code", "1", "--python-expr", kBlenderScript, "--", glb,
        fbx,     fpsText};
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    pid_t pid = 0;
    const int spawned = posix_spawn(&pid, blender.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0)
        throw std::runtime_error(fbxPath + ": expected to start " + blender + ", found " + std::strerror(spawned));
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    struct stat st {};
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || ::stat(fbx.c_str(), &st) != 0 || st.st_size == 0)
        throw std::runtime_error(
            fbxPath + ": expected Blender to write the FBX, found " +
            (WIFEXITED(status) ? "exit status " + std::to_string(WEXITSTATUS(status)) : std::string("a crash")) +
            "; Blender's last lines:" + lastLinesOf(log, 6));
    if (::rename(fbx.c_str(), fbxPath.c_str()) != 0)
        throw std::runtime_error(fbxPath + ": expected a writable file, found " + std::strerror(errno));
    say("wrote " + fbxPath);
}

}  // namespace mgp
