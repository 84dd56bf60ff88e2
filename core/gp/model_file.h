#pragma once
// The model file: one self-contained JSON document (UTF-8), written atomically.
//
//   {
//     "format": "motiongp-model",  "version": 1,
//     "kernel": "fas" | "sgplvm",
//     "log_params": [ln α, ln γ, ln β(, ln η)],      authoritative θ (Kernel order)
//     "params": {"alpha", "beta", "gamma", "eta"},  exp(log_params), for readers (eta null for SGPLVM)
//     "N", "D", "latent_dim",
//     "w": [D], "mu": [D],                          scale weights (Σ ln w = 0) and training mean
//     "X": [[d] × N],                               latent points, one per training row
//     "active": [M],                                active-set row indices (0-based)
//     "kept_columns": [D], "constant_columns": [..], "constant_values": [..]   (indices into the 47-vector)
//     "training_frames": [N],                       clip frame index (0-based) of each training row
//     "training": {"active_size", "outer_iterations", "scg_iterations", "point_iterations",
//                  "tolerance", "frame_first", "frame_last", "frame_step", "iterations", "converged",
//                  "objective_history": [L_init, L_1, …, L_T]},   optional (older files: absent,
//                                                  read as empty); finite numbers; see GpModel
//     "source": {"file": name without directory, "sha256": hex},   provenance only
//     "clip": { see io/clip_json.h: skeleton bones, 47-DOF poses of every frame, root translations }
//   }
//
// The training rows Y are not stored twice: they are the clip's poses at training_frames,
// kept columns. Doubles use nlohmann-json's shortest round-trip form (bit-exact on reading).
// No wall-clock data is written, so identical runs give byte-identical files.
// Version policy: a reader accepts versions ≤ its own; anything else, or a damaged file, is a
// ParseError "file: expected ..., found ...".
#include <string>

#include "gp/model.h"

namespace mgp::gp {

constexpr int kModelFileVersion = 1;
constexpr const char* kModelFileFormat = "motiongp-model";

std::string modelToJsonText(const GpModel& model);
GpModel modelFromJsonText(const std::string& text, const std::string& file);

// Writes `path` atomically (io/atomic_file.h: temp file, fsync, rename); throws
// std::runtime_error ("PATH: expected a writable file, found …") if it cannot.
void saveModel(const std::string& path, const GpModel& model);
GpModel loadModel(const std::string& path);

}  // namespace mgp::gp
