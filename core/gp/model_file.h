#pragma once
// The model file: one self-contained JSON document (UTF-8), written atomically.
//
//   {
//     "format": "motiongp-model",  "version": 1 (one source clip) or 2 (several),
//     "kernel": "fas" | "sgplvm",
//     "log_params": [ln α, ln γ, ln β(, ln η)],      authoritative θ (Kernel order)
//     "params": {"alpha", "beta", "gamma", "eta"},  exp(log_params), for readers (eta null for SGPLVM)
//     "N", "D", "latent_dim",
//     "w": [D], "mu": [D],                          scale weights (Σ ln w = 0) and training mean
//     "X": [[d] × N],                               latent points, one per training row
//     "active": [M],                                active-set row indices (0-based)
//     "kept_columns": [D], "constant_columns": [..], "constant_values": [..]   (indices into the 47-vector)
//     "training_frames": [N],                       frame index (0-based) of each training row in its clip
//     "training_clips": [N],                        version 2 only: clip index of each row (0 = "clip")
//     "training": {"active_size", "outer_iterations", "scg_iterations", "point_iterations",
//                  "tolerance", "frame_first", "frame_last", "frame_step", "iterations", "converged",
//                  "objective_history": [L_init, L_1, …, L_T]},   optional (older files: absent,
//                                                  read as empty); finite numbers; see GpModel
//     "source": {"file": name without directory, "sha256": hex},   provenance only (clip 0)
//     "clip": { see io/clip_json.h: skeleton bones, 47-DOF poses of every frame, root translations }
//     "more_clips": [{"file", "sha256", "clip"}],  version 2 only: clips 1..K−1, one skeleton
//                                                  (sameSkeleton), distinct names (clip.name = stem)
//   }
//
// The training rows Y are not stored twice: they are each row's clip's poses at its
// training_frames entry, kept columns. Doubles use nlohmann-json's shortest round-trip form (bit-exact on reading).
// No wall-clock data is written, so identical runs give byte-identical files.
// Version policy: a model of one clip is written as version 1, byte for byte as before version 2
// existed (older builds still read it); a model of several clips as version 2. A reader accepts
// versions ≤ its own; anything else, or a damaged file, is a
// ParseError "file: expected ..., found ...".
#include <string>

#include "gp/model.h"

namespace mgp::gp {

constexpr int kModelFileVersion = 2;
// Single-clip models are still written as version 1 (unchanged bytes; older builds read them).
constexpr int kSingleClipModelFileVersion = 1;
constexpr const char* kModelFileFormat = "motiongp-model";

std::string modelToJsonText(const GpModel& model);
GpModel modelFromJsonText(const std::string& text, const std::string& file);

// Writes `path` atomically (io/atomic_file.h: temp file, fsync, rename); throws
// std::runtime_error ("PATH: expected a writable file, found …") if it cannot.
void saveModel(const std::string& path, const GpModel& model);
GpModel loadModel(const std::string& path);

}  // namespace mgp::gp
