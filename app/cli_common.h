#pragma once
// Small helpers shared by the command-line verbs.
#include <nlohmann/json.hpp>
#include <string>

#include "skeleton/clip.h"

namespace mgp::app {

// Thrown for bad command-line values; main prints it as "motiongp: error: <message>".
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Prints exactly one JSON object on stdout (the --json contract).
void printJson(const nlohmann::json& j);
// The claims of a repeated protocol (eval/claim_test.h claimJson), one verdict each, for a terminal.
void printClaims(const nlohmann::json& claims);
// Converts a 1-based --frame to a clip index, or throws UsageError naming the valid range.
int frameIndexFromCli(const Clip& clip, long long frame);
nlohmann::json vec3Json(const Eigen::Vector3d& v);
// `--out` of export and edit: throws UsageError unless exportClip writes its extension (checked
// before any work, so a long edit never ends in a refused file name).
void requireExportPath(const std::string& out);
// Writes the clip by its extension (io/clip_export.h), saying each stage of a slow export on stderr.
void exportFromCli(const Clip& clip, const std::string& out);
// Positions of root and the five effectors for one frame (null for an effector the clip lacks).
nlohmann::json effectorPositionsJson(const Clip& clip, int frameIndex);

}  // namespace mgp::app
