#pragma once
// FBX export through Blender (docs/export.md): Unity and Unreal take FBX, and the only well-kept
// FBX writer on Debian is Blender's. The clip goes to a temporary .glb beside the target (our
// glTF writer), a background Blender (`blender -b`) imports it and writes the FBX with every frame
// baked (no key reduction), and the result is renamed over the target: atomic, like every file we
// write. Blender's numpy shim for Debian 12 and the scene's frame rate are set in its script.
#include <functional>
#include <string>

#include "skeleton/clip.h"

namespace mgp {

// The Blender executable FBX export would run ($MOTIONGP_BLENDER, else `blender` on PATH), or ""
// when there is none; then `why` (if given) says what was looked for, as the end of a sentence.
std::string findBlender(std::string* why = nullptr);
// "" when FBX export can run here, else the one line saying why not (no Blender), for `fbxPath`.
std::string fbxExportUnavailable(const std::string& fbxPath);
// Throws std::runtime_error with one clear line: no Blender ("FBX export needs Blender ..."), or
// Blender's failure with the last lines it printed. `progress` hears each stage, in words.
void exportFbxThroughBlender(const Clip& clip, const std::string& fbxPath,
                             const std::function<void(const std::string&)>& progress = {});

}  // namespace mgp
