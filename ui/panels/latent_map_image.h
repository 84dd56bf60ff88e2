#pragma once
// The latent map's background: the model's predictive variance σ²(x) on a regular grid over the
// latent bounding box (plus a margin), coloured, computed on a worker thread (never on the UI
// thread) and picked up by the UI when ready. No GL here: the panel uploads the pixels.
#include <atomic>
#include <cstdint>
#include <vector>

#include "gp/model_version.h"
#include "util/background_worker.h"

namespace mgp::ui {

// Colour map (perceptually ordered, viridis-like: dark purple at 0, yellow at 1), RGB 0..255.
// The image uses t = 1 - normalised log σ², so confident regions are bright (as in the paper's
// figures) and the colour bar runs from low σ² (left, bright) to high σ² (right, dark).
void colourMap(double t, std::uint8_t rgb[3]);

struct LatentImage {
    int size = 0;                           // size×size texels
    double x0 = 0, y0 = 0, x1 = 1, y1 = 1;  // latent box: texel (0,0) is at (x0, y1) (top-left)
    double minLogVar = 0, maxLogVar = 0;    // the colour bar's range (natural log of σ²)
    std::vector<std::uint8_t> rgba;
    const void* model = nullptr;  // which model version this shows
    int version = -1;
};

// The map shows latent axes 1 and 2. With d = 3 (a BVH pose vector of 60 or more DOFs, eq. 4) it
// is the slice through the training points' mean on axis 3: this point, whose first two entries
// the map sets (0) and whose later entries are the mean of X's columns.
Eigen::VectorXd latentMapBase(const gp::GpModel& model);

// Latent box of a model: bounding box of X plus `margin` of its size on each side, made square.
void latentBox(const gp::GpModel& model, double margin, double& x0, double& y0, double& x1, double& y1);

// Computes the image synchronously (the worker calls this; tests may too).
LatentImage computeLatentImage(const gp::ModelVersion& version, int size);

// Computes images on a BackgroundWorker (core/util/background_worker.h) that keeps only the
// latest request: a newer request replaces one not yet started.
class LatentImageWorker {
public:
    explicit LatentImageWorker(int size = 160);
    ~LatentImageWorker() = default;  // the worker finishes the image in progress and joins
    LatentImageWorker(const LatentImageWorker&) = delete;
    LatentImageWorker& operator=(const LatentImageWorker&) = delete;
    // Asks for the image of `version` (replaces any request not yet started).
    void request(gp::ModelVersionPtr version) { worker_.post(std::move(version)); }
    // Moves a finished image out (true once per finished image).
    bool take(LatentImage& out);
    bool busy() const { return worker_.busy(); }
    void waitIdle() { worker_.waitIdle(); }

private:
    JobOutcome<LatentImage> run(gp::ModelVersionPtr& version, const std::atomic<bool>& cancel) const;
    int size_;
    BackgroundWorker<gp::ModelVersionPtr, LatentImage> worker_;  // last: joined before size_ goes
};

}  // namespace mgp::ui
