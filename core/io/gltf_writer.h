#pragma once
// glTF 2.0 export of a clip (docs/export.md): what game engines and DCC tools open.
//
//  - the skeleton as a node hierarchy, one node per joint under the source's joint names, rest
//    translation = the joint's offset in METRES, rest rotation identity (our rest pose), Y up;
//  - a skin over those joints (inverse bind matrices from the rest pose) attached to a simple
//    mesh, one pointed box per bone, each skinned to its bone, so that importers make an armature
//    rather than empties;
//  - one animation named after the clip: every joint's local rotation G_parentᵀ·G_j (from our
//    FK, so an importer places every joint where `motiongp fk` does) as quaternions made
//    continuous in sign, and the root's translation, one LINEAR key per frame at the clip's rate;
//  - extras: the source clip, its format and convention, the frame rate, whether frame 1 is a
//    converter's rest pose, and the tool; per joint
//    node its ASF bone role and its bone's tail (glTF joints have no length), which our reader
//    (io/gltf_reader.h) uses to give the clip back.
//
// `.glb` is binary glTF; `.gltf` is JSON with the buffer embedded as a data URI (one file).
#include <string>

#include "skeleton/clip.h"

namespace mgp {

// True for a path ending in .glb or .gltf (any case).
bool isGltfPath(const std::string& path);
// The file's bytes; binary = .glb.
std::string formatGltf(const Clip& clip, bool binary);
// Atomic (temp + rename); binary or JSON from the extension (.glb / .gltf).
void writeGltf(const Clip& clip, const std::string& path);

}  // namespace mgp
