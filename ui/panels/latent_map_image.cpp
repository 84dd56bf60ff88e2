#include "ui/panels/latent_map_image.h"

#include <algorithm>
#include <cmath>

namespace mgp::ui {

void colourMap(double t, std::uint8_t rgb[3]) {
    // Viridis-like stops.
    static const double stops[6][3] = {{68, 1, 84},    {65, 68, 135},  {42, 120, 142},
                                       {34, 168, 132}, {122, 209, 81}, {253, 231, 37}};
    if (!std::isfinite(t)) t = 1.0;
    t = std::clamp(t, 0.0, 1.0) * 5.0;
    const int i = std::min(4, int(t));
    const double f = t - i;
    for (int c = 0; c < 3; ++c) rgb[c] = std::uint8_t(std::lround(stops[i][c] * (1 - f) + stops[i + 1][c] * f));
}

Eigen::VectorXd latentMapBase(const gp::GpModel& model) {
    Eigen::VectorXd x = Eigen::VectorXd::Zero(model.latentDim());
    for (int k = 2; k < model.latentDim(); ++k) x[k] = model.X.col(k).mean();
    return x;
}

void latentBox(const gp::GpModel& model, double margin, double& x0, double& y0, double& x1, double& y1) {
    const Eigen::MatrixXd& X = model.X;
    x0 = X.col(0).minCoeff();
    x1 = X.col(0).maxCoeff();
    y0 = X.cols() > 1 ? X.col(1).minCoeff() : -1.0;
    y1 = X.cols() > 1 ? X.col(1).maxCoeff() : 1.0;
    const double cx = 0.5 * (x0 + x1), cy = 0.5 * (y0 + y1);
    const double half = 0.5 * std::max({x1 - x0, y1 - y0, 1e-6}) * (1.0 + 2.0 * margin);
    x0 = cx - half;
    x1 = cx + half;
    y0 = cy - half;
    y1 = cy + half;
}

LatentImage computeLatentImage(const gp::ModelVersion& version, int size) {
    LatentImage img;
    img.size = size;
    img.model = version.model.get();
    img.version = version.number;
    latentBox(*version.model, 0.15, img.x0, img.y0, img.x1, img.y1);
    // Row r·size + c of the grid is pixel (c, r), the image's top row at y1.
    const Eigen::VectorXd base = latentMapBase(*version.model);
    Eigen::MatrixXd grid = base.transpose().replicate(Eigen::Index(size) * size, 1);
    for (int r = 0; r < size; ++r) {
        for (int c = 0; c < size; ++c) {
            const Eigen::Index i = Eigen::Index(r) * size + c;
            grid(i, 0) = img.x0 + (c + 0.5) / size * (img.x1 - img.x0);
            if (grid.cols() > 1) grid(i, 1) = img.y1 - (r + 0.5) / size * (img.y1 - img.y0);
        }
    }
    const Eigen::VectorXd var = version.posterior->variances(grid);
    std::vector<double> logVar(std::size_t(size) * size);
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::size_t i = 0; i < logVar.size(); ++i) {
        const double lv = std::log(std::max(var[Eigen::Index(i)], 1e-300));
        logVar[i] = lv;
        if (std::isfinite(lv)) {
            lo = std::min(lo, lv);
            hi = std::max(hi, lv);
        }
    }
    if (!(hi > lo)) hi = lo + 1.0;
    img.minLogVar = lo;
    img.maxLogVar = hi;
    img.rgba.resize(std::size_t(size) * size * 4);
    for (std::size_t i = 0; i < logVar.size(); ++i) {
        colourMap(1.0 - (logVar[i] - lo) / (hi - lo), &img.rgba[i * 4]);
        img.rgba[i * 4 + 3] = 255;
    }
    return img;
}

LatentImageWorker::LatentImageWorker(int size)
    : size_(size),
      worker_(WorkerPolicy::kLatestRequest,
              [this](gp::ModelVersionPtr& v, const std::atomic<bool>& cancel) { return run(v, cancel); }) {}

bool LatentImageWorker::take(LatentImage& out) {
    std::optional<LatentImage> done = worker_.take();
    if (!done) return false;
    out = std::move(*done);
    return true;
}

// A failed computation (thrown or empty) leaves the last finished image in place.
JobOutcome<LatentImage> LatentImageWorker::run(gp::ModelVersionPtr& version, const std::atomic<bool>&) const {
    LatentImage img = computeLatentImage(*version, size_);
    if (img.size <= 0) return {};
    return {std::move(img), ""};
}

}  // namespace mgp::ui
