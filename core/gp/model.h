#pragma once
// A trained GPLVM pose model (FASGPLVM or SGPLVM) plus everything `pose`, `edit` and `render`
// need: the whole source clip, the training rows and their clip frame numbers.
//
// Units and conventions: poses in DEGREES in the §2.3 order; Y and μ hold only the kept
// (non-constant) columns, in ascending order of their index into the 47-vector; constant columns
// are held at `constantValues`. Latent X is N×d (d = 2 for the 47-DOF pose). Frame numbers are
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
    int activeSize = 200;        // M
    int outerIterations = 100;   // T
    int scgIterations = 100;     // SCG iterations per Step 6
    int pointIterations = 100;   // SCG iterations per point in Step 8
    double tolerance = 0.01;     // C of Step 9
    int frameFirst = 1, frameLast = 0;  // --frames A:B as given (1-based; 0 = to the end)
    int frameStep = 1;                  // --step K
    LatentPrior prior = LatentPrior::kNone;  // temporal prior (docs/maths.md §19)
    double priorWeight = 0.0;                // its λ (0 with kNone)
};

struct GpModel {
    KernelKind kind = KernelKind::kFas;
    Eigen::VectorXd logParams;  // ψ = ln θ in the Kernel order (α, γ, β[, η])
    Eigen::VectorXd w;          // D scale weights (Σ ln w = 0)
    Eigen::VectorXd mu;         // D training mean
    Eigen::MatrixXd X;          // N×d latent points
    Eigen::MatrixXd Y;          // N×D training rows (kept columns, uncentred, degrees)
    std::vector<int> active;    // active set (row indices into X/Y)
    std::vector<int> keptColumns;      // D indices into the 47-vector
    std::vector<int> constantColumns;  // removed indices into the 47-vector
    Eigen::VectorXd constantValues;    // their values (column means)
    std::vector<int> trainingFrames;   // clip frame index (0-based) of each training row

    Clip clip;                  // the whole source clip (47-DOF poses, root translations, bones)
    std::string sourceFile;     // file name of the source clip (no directory), provenance only
    std::string sourceSha256;   // SHA-256 of the source file ("" for a synthetic clip)

    TrainingSettings settings;
    int iterations = 0;         // outer iterations run
    bool converged = false;     // the Step-9 test triggered
    // Training convergence: entry 0 is L_init (L_GP at θ = 1 and the PCA latent points, on the
    // first active set), entry t (1..iterations) is L_GP after Step 6 of outer iteration t. Either
    // empty (a model file from before this field, or a non-finite objective) or iterations + 1
    // entries. Adaptive updates do not append to it.
    std::vector<double> objectiveHistory;

    int N() const { return static_cast<int>(X.rows()); }
    int D() const { return static_cast<int>(mu.size()); }
    int latentDim() const { return static_cast<int>(X.cols()); }
    Kernel kernel() const { return Kernel(kind, logParams); }
    // Centred active rows Ŷ (M×D) and active latent points X_I (M×d).
    Eigen::MatrixXd activeYhat() const;
    Eigen::MatrixXd activeX() const;
    // The §6.2 precomputation for IK and prediction.
    ActiveSetPosterior posterior() const;
    // Expands kept columns to the full 47-vector (constants filled in).
    Eigen::VectorXd fullPose(const Eigen::VectorXd& kept) const;
    Eigen::VectorXd keptPose(const Eigen::VectorXd& full47) const;
};

}  // namespace mgp::gp
