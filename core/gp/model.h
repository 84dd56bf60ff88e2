#pragma once
// A trained GPLVM pose model (FASGPLVM or SGPLVM) plus everything `pose`, `edit` and `render`
// need: the whole source clips, the training rows and each row's clip and frame.
//
// Source clips: a model learns from one clip or from several clips of one skeleton (app `train`
// checks sameSkeleton, skeleton/clip_match.h). Clip 0, the PRIMARY clip, lives in `clip`,
// `sourceFile` and `sourceSha256` (every single-clip user reads these); clips 1..K−1 live in
// `moreClips`. The primary clip is the one `pose`, `edit`, `render` and the editor work on:
// withPrimaryClip(model, i) makes clip i primary (a relabelling; X, Y and θ are untouched).
// `trainingClips` holds each row's clip index; it is EMPTY for a single-clip model (every row is
// clip 0), so a single-clip model and its file are exactly as before multi-clip training.
//
// Units and conventions: poses in DEGREES in the docs/maths.md §2.1 order; Y and μ hold only the
// kept (non-constant) columns, in ascending order of their index into the pose vector (P entries:
// skeleton/pose_layout.h, 47 for ASF clips); constant columns
// are held at `constantValues`. Latent X is N×d (eq. 4: d = 2 for D < 60, else 3). Frame numbers are
// clip indices counted from 0 (the CLI prints them +1).
#include <Eigen/Core>
#include <string>
#include <vector>

#include "gp/kernel.h"
#include "gp/point_objective.h"
#include "gp/temporal_prior.h"
#include "skeleton/clip.h"

namespace mgp::gp {

// The settings a model was trained with (provenance; deterministic values only).
struct TrainingSettings {
    int activeSize = 200;                    // M
    int outerIterations = 100;               // T
    int scgIterations = 100;                 // SCG iterations per Step 6
    int pointIterations = 100;               // SCG iterations per point in Step 8
    double tolerance = 0.01;                 // C of Step 9
    int frameFirst = 1, frameLast = 0;       // --frames A:B as given (1-based; 0 = to the end)
    int frameStep = 1;                       // --step K
    LatentPrior prior = LatentPrior::kNone;  // temporal prior (docs/maths.md §19)
    double priorWeight = 0.0;                // its λ (0 with kNone)
    bool backConstraints = false;            // X a function of the poses (docs/maths.md §22)
};

// A source clip other than the primary one.
struct SourceClip {
    std::string file;    // file name (no directory), provenance only
    std::string sha256;  // SHA-256 of the source file
    Clip clip;           // the whole clip (unwrapped, like the primary one); clip.name is its file stem
};

struct GpModel {
    KernelKind kind = KernelKind::kFas;
    Eigen::VectorXd logParams;         // ψ = ln θ in the Kernel order (α, γ, β[, η])
    Eigen::VectorXd w;                 // D scale weights (Σ ln w = 0)
    Eigen::VectorXd mu;                // D training mean
    Eigen::MatrixXd X;                 // N×d latent points
    Eigen::MatrixXd Y;                 // N×D training rows (kept columns, uncentred, degrees)
    std::vector<int> active;           // active set (row indices into X/Y)
    std::vector<int> keptColumns;      // D indices into the pose vector
    std::vector<int> constantColumns;  // removed indices into the pose vector
    Eigen::VectorXd constantValues;    // their values (column means)
    std::vector<int> trainingFrames;   // frame index (0-based) of each training row within its clip
    std::vector<int> trainingClips;    // clip index of each training row; empty = all clip 0

    Clip clip;                          // the primary source clip (pose vectors, root translations, bones)
    std::string sourceFile;             // file name of the primary clip (no directory), provenance only
    std::string sourceSha256;           // SHA-256 of the source file ("" for a synthetic clip)
    std::vector<SourceClip> moreClips;  // clips 1..K−1 (empty for a single-clip model)

    TrainingSettings settings;
    int iterations = 0;      // outer iterations run
    bool converged = false;  // the Step-9 test triggered
    // Training convergence: entry 0 is L_init (L_GP at θ = 1 and the PCA latent points, on the
    // first active set), entry t (1..iterations) is L_GP after Step 6 of outer iteration t. Either
    // empty (a model file from before this field, or a non-finite objective) or iterations + 1
    // entries. Adaptive updates do not append to it.
    std::vector<double> objectiveHistory;

    int N() const { return static_cast<int>(X.rows()); }
    // Source clips: K = clipCount() ≥ 1; clip i's data, file and name (its file stem, clip.name).
    int clipCount() const { return 1 + static_cast<int>(moreClips.size()); }
    const Clip& clipAt(int i) const { return i == 0 ? clip : moreClips[static_cast<std::size_t>(i - 1)].clip; }
    const std::string& clipFile(int i) const {
        return i == 0 ? sourceFile : moreClips[static_cast<std::size_t>(i - 1)].file;
    }
    const std::string& clipSha256(int i) const {
        return i == 0 ? sourceSha256 : moreClips[static_cast<std::size_t>(i - 1)].sha256;
    }
    const std::string& clipName(int i) const { return clipAt(i).name; }
    // The index of the clip named `name` (file stem), or −1.
    int findClip(const std::string& name) const;
    // "10_02, 10_03": every clip name in order, for messages.
    std::string clipNames() const;
    // Clip index of training row r (0 for a single-clip model).
    int rowClip(int r) const { return trainingClips.empty() ? 0 : trainingClips[static_cast<std::size_t>(r)]; }
    // The training rows of clip c, in row order.
    std::vector<int> rowsOfClip(int c) const;
    // The training row of the primary clip's `frame`, or of its nearest trained frame (the first
    // such row; 0 when the primary clip has no rows, which training never produces).
    int primaryRowNearest(int frame) const;
    // poseMatrix of every source clip, in clip order (one pose vector per frame).
    std::vector<Eigen::MatrixXd> clipPoseMatrices() const;
    int D() const { return static_cast<int>(mu.size()); }
    int latentDim() const { return static_cast<int>(X.cols()); }
    Kernel kernel() const { return Kernel(kind, logParams); }
    // Centred active rows Ŷ (M×D) and active latent points X_I (M×d).
    Eigen::MatrixXd activeYhat() const;
    Eigen::MatrixXd activeX() const;
    // The precomputation for IK and prediction (docs/maths.md §9.1).
    ActiveSetPosterior posterior() const;
    // Expands kept columns to the full pose vector (constants filled in).
    Eigen::VectorXd fullPose(const Eigen::VectorXd& kept) const;
    Eigen::VectorXd keptPose(const Eigen::VectorXd& full) const;
};

// The first of the model's clips that holds the same capture as `open` (sameCapture,
// skeleton/clip_match.h), or −1; then `difference` says how `open` differs from the first clip.
int findCapture(const GpModel& model, const Clip& open, std::string* difference = nullptr);

// The same model with clip `index` as its primary clip (swapped with clip 0; rows keep their data
// and follow their clip). withPrimaryClip(m, 0) is m. Throws std::out_of_range for a bad index.
GpModel withPrimaryClip(GpModel model, int index);

}  // namespace mgp::gp
