#pragma once
// The session file (*.mgsession): everything needed to reopen the editor where the user left
// it — the clip reference (or the model that carries its clip), the latest model version, the
// accepted edits, pins, camera, path edit and free-form UI state. One JSON document (UTF-8),
// written atomically (io/atomic_file.h).
//
//   {
//     "format": "motiongp-session", "version": 1,
//     "clip": {"synthetic": bool, "synthetic_frames": int,      the built-in walk and its length
//              "path": absolute AMC/BVH path or "",  "relative_path": the same relative to the
//              session's folder or "",  "skeleton_path", "skeleton_relative_path": the ASF ("" =
//              the clip loader's default),  "sha256": hex of the clip file or ""},
//     "model": { a whole motiongp-model document, gp/model_file.h } | null,
//     "model_version": int ≥ 0,                              ModelVersion::number of "model"
//     "compare_model": { motiongp-model document } | null,
//     "edits": [ {"frame": 0-based int, "root_cm": [3], "angles_deg": [[3] × every joint of the
//                 clip's skeleton], "x": [latent_dim] or [] (solved without a model)} ],
//     "frame": 0-based int,
//     "pins": [effector names],                              lhand rhand lfoot rfoot head
//     "keys": [0-based ints],                                 marked key frames (optional: none)
//     "selected_effector": effector name | null,
//     "compare_mode": "none" | "plain" | "model",
//     "adaptive_enabled": bool,
//     "camera": {"yaw_deg", "pitch_deg", "distance_cm", "fov_y_deg", "target_cm": [3],
//                "follow_character": bool},
//     "path": null | {"effector": name, "key_frames": [0-based ints], "key_offsets_cm": [[3] per
//                     key], "mode": "direct" | "displacement"},
//     "ui": { free-form object, stored as given },
//     "history": {"undo": [step], "redo": [step]},              oldest first (version 2)
//         step: {"label": string, "before": [change], "after": [change]}
//         change: {"frame": 0-based int, "edit": an edit as above without "frame", or null for
//                  the captured pose}
//     "adaptive_history": [ {"when_unix_ms": int, "frame": int, "accepted": bool,      (version 2)
//         "diagnostic": string, "seconds", "version_before": int, "version_after": int,
//         "rows_after": int, "active_size": int, "active_changed": int,
//         "new_point_active": bool, "objective_before", "objective_after"} ]
//   }
// The undo steps keep their frames, not the model versions they changed (one model is about the
// size of the whole session, docs/architecture.md §9): reopened, they restore frames only.
//
// Units as everywhere (docs/maths.md, conventions): cm, degrees, Y up. Every number must be finite; frames
// are 0-based, distinct and inside the clip. Doubles use nlohmann-json's shortest round-trip
// form, so everything reads back bit-exactly. With a model, the clip is the model's own and the
// clip reference is informational; without one, the clip file is found relative to the session
// first (so a folder of session + clips can be moved), then by its absolute path, and a changed
// SHA-256 is reported as a warning, not an error.
// Version policy (as gp/model_file.h): a reader accepts versions ≤ its own; anything else, or a
// damaged file, is a ParseError "file: expected ..., found ...".
#include <Eigen/Core>
#include <array>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "edit/editor_document.h"
#include "gp/model.h"
#include "motion/motion_edit.h"
#include "skeleton/clip.h"

namespace mgp {

constexpr int kSessionFileVersion = 2;  // 2: undo history and adaptive history
constexpr const char* kSessionFileFormat = "motiongp-session";
constexpr const char* kSessionExtension = ".mgsession";

struct SessionCamera {
    double yawDeg = 0, pitchDeg = 10, distanceCm = 400, fovYDeg = 35;
    Eigen::Vector3d targetCm{0, 90, 0};
    bool followCharacter = true;
};

struct SessionPathEdit {
    bool present = false;
    Effector effector = Effector::kRFoot;
    std::vector<int> keyFrames;  // 0-based clip frames
    std::vector<Eigen::Vector3d> keyOffsetsCm;
    PathMode mode = PathMode::kDisplacement;
};

struct SessionData {
    // Clip reference (used when there is no model; a model carries its own clip).
    std::string clipPath, skeletonPath;  // absolute when saved; "" for synthetic
    std::string clipSha256;              // of the clip file (AMC or BVH); "" if synthetic
    bool syntheticClip = false;
    int syntheticFrames = 240;         // makeSyntheticWalk's length
    std::optional<gp::GpModel> model;  // the latest model version (active set + parameters)
    int modelVersion = 0;              // its ModelVersion::number
    std::optional<gp::GpModel> compareModel;
    std::map<int, EditRecord> edits;  // accepted poses per 0-based frame
    int frame = 0;
    std::array<bool, kEffectorCount> pins{};
    std::set<int> keys;                // marked key frames (0-based)
    int selectedEffector = -1;         // an Effector value, -1 none
    std::string compareMode = "none";  // none | plain | model
    bool adaptiveEnabled = true;
    SessionCamera camera;
    SessionPathEdit path;
    nlohmann::json ui = nlohmann::json::object();       // free-form UI state, stored as given
    std::vector<EditStep> undoSteps, redoSteps;         // oldest first; frames only (no model versions)
    std::vector<AdaptiveHistoryEntry> adaptiveHistory;  // the Model panel's update table, oldest first

    // Filled on reading, never saved as such: the clip paths as stored relative to the session
    // ("" if none; saving recomputes them) and problems that did not stop the load (a changed
    // clip file).
    std::string clipRelativePath, skeletonRelativePath;
    std::vector<std::string> warnings;
};

// `sessionPath` is where the text will be written; clip paths are stored both absolute and
// relative to its folder.
std::string sessionToJsonText(const SessionData& session, const std::string& sessionPath);
// Parses and checks everything that needs no other file (with a model: edits against its clip).
// Throws ParseError "file: expected ..., found ...".
SessionData sessionFromJsonText(const std::string& text, const std::string& file);

// Checks the edits, frame and path keys against the clip they apply to: "" or
// "expected ..., found ...".
std::string validateAgainstClip(const SessionData& session, const Clip& clip);

// Atomic write; throws std::runtime_error ("PATH: expected a writable file, found …").
void saveSession(const std::string& path, const SessionData& session);
// Reads and parses, then (without a model, for a file clip) resolves the clip and skeleton
// paths — relative to the session first, then absolute — into clipPath/skeletonPath, and adds a
// warning when the clip's SHA-256 differs. Throws ParseError if the file is bad or the clip
// file is missing.
SessionData loadSession(const std::string& path);

// The clip the session's edits apply to: the referenced file (io/clip_loader.h) or the
// synthetic walk, checked with validateAgainstClip; std::nullopt when the model carries the
// clip. `file` names the session in error messages. Throws ParseError.
std::optional<Clip> loadSessionClip(const SessionData& session, const std::string& file);

}  // namespace mgp
