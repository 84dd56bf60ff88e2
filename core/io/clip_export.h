#pragma once
// Writes a clip in the format its path names: .bvh (io/bvh_writer.h), .glb or .gltf
// (io/gltf_writer.h), .fbx (through Blender, io/fbx_export.h). Atomic, like every file we write.
#include <functional>
#include <string>

#include "skeleton/clip.h"

namespace mgp {

// The extensions exportClip writes, for messages: ".bvh, .glb, .gltf or .fbx".
const char* exportExtensions();
bool isExportPath(const std::string& path);
// Throws std::invalid_argument ("expected ... found '.ext'") for any other extension, and
// std::runtime_error when the write (or Blender, for FBX) fails. `progress` hears the stages of
// an FBX export (it takes seconds); the other formats are written at once.
void exportClip(const Clip& clip, const std::string& path,
                const std::function<void(const std::string&)>& progress = {});

}  // namespace mgp
