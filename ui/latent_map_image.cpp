#include "latent_map_image.h"

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
    std::vector<double> logVar(std::size_t(size) * size);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(version.model->latentDim()), mean;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (int r = 0; r < size; ++r) {
        for (int c = 0; c < size; ++c) {
            x[0] = img.x0 + (c + 0.5) / size * (img.x1 - img.x0);
            if (x.size() > 1) x[1] = img.y1 - (r + 0.5) / size * (img.y1 - img.y0);
            double var = 0.0;
            version.posterior->predict(x, mean, var);
            const double lv = std::log(std::max(var, 1e-300));
            logVar[std::size_t(r) * size + c] = lv;
            if (std::isfinite(lv)) {
                lo = std::min(lo, lv);
                hi = std::max(hi, lv);
            }
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

LatentImageWorker::LatentImageWorker(int size) : size_(size), thread_(&LatentImageWorker::run, this) {}

LatentImageWorker::~LatentImageWorker() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    thread_.join();
}

void LatentImageWorker::request(gp::ModelVersionPtr version) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        pending_ = std::move(version);
    }
    wake_.notify_all();
}

bool LatentImageWorker::take(LatentImage& out) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!ready_) return false;
    out = std::move(done_);
    ready_ = false;
    return true;
}

bool LatentImageWorker::busy() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return working_ || pending_ != nullptr;
}

void LatentImageWorker::waitIdle() {
    std::unique_lock<std::mutex> lock(mutex_);
    idle_.wait(lock, [&] { return !working_ && !pending_; });
}

void LatentImageWorker::run() {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
        wake_.wait(lock, [&] { return stop_ || pending_; });
        if (stop_) return;
        gp::ModelVersionPtr v = std::move(pending_);
        pending_.reset();
        working_ = true;
        lock.unlock();
        LatentImage img;
        try {
            img = computeLatentImage(*v, size_);
        } catch (const std::exception&) {
            img = {};
        }
        lock.lock();
        working_ = false;
        if (img.size > 0) {
            done_ = std::move(img);
            ready_ = true;
        }
        idle_.notify_all();
    }
}

}  // namespace mgp::ui
