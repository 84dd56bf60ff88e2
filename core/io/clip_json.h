#pragma once
// Clip (de)serialisation as JSON, used inside the model file (core/gp/model_file.h).
//
// What is stored: name, format, convention, fps, cm per file unit, first frame label, rest-frame
// flag, the skeleton's joints (name, ASF bone role, parent, offset and tail in cm, axis frame C
// row-major, rotation order, animated axes), and per frame the pose vector (skeleton/pose_layout.h:
// the 47 ASF DOFs in the docs/maths.md §2.1 order, or every rotation channel of a BVH clip;
// degrees, unwrapped over time) plus the root translation in cm. Angles outside it (an ASF
// clip's hands, fingers, thumbs, toes) are not stored: a loaded clip holds them at 0, as
// docs/maths.md §2 decides for FK. The format "bvh" gives the channel layout back on reading.
// Doubles are written by nlohmann-json's shortest round-trip formatting, so they read back
// bit-exactly.
#include <nlohmann/json.hpp>
#include <string>

#include "skeleton/clip.h"

namespace mgp {

nlohmann::json clipToJson(const Clip& clip);
// `file` names the containing file for error messages; throws ParseError on any problem.
Clip clipFromJson(const nlohmann::json& j, const std::string& file);

}  // namespace mgp
