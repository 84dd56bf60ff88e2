#include "gp/training_range.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace mgp::gp {

namespace {
// Linear interpolation between order statistics (the "R-7" definition).
double percentileOf(std::vector<double> v, double p) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const double pos = std::clamp(p, 0.0, 100.0) / 100.0 * static_cast<double>(v.size() - 1);
    const auto lo = static_cast<std::size_t>(std::floor(pos));
    const std::size_t hi = std::min(lo + 1, v.size() - 1);
    return v[lo] + (pos - static_cast<double>(lo)) * (v[hi] - v[lo]);
}
}  // namespace

TrainingRange computeTrainingRange(const GpModel& model, const PointModel& point, double percentile) {
    TrainingRange out;
    out.percentile = percentile;
    out.rows = model.N();
    std::vector<double> s2, lik;
    s2.reserve(model.N());
    lik.reserve(model.N());
    PointWorkspace ws;
    Eigen::VectorXd x, y;
    for (int i = 0; i < model.N(); ++i) {
        x = model.X.row(i).transpose();
        y = model.Y.row(i).transpose();
        const double l = point.evaluate(x, y, ws, nullptr, nullptr);
        if (!std::isfinite(l) || !std::isfinite(ws.variance)) continue;
        lik.push_back(l);
        s2.push_back(ws.variance);
    }
    // σ² is near 1/β at a training row itself, so the rows alone would refuse nearly every new
    // pose: the reference also holds σ² halfway between consecutive training frames (in clip
    // order), i.e. along the captured motion's own latent path.
    std::vector<int> order(static_cast<std::size_t>(model.N()));
    for (int i = 0; i < model.N(); ++i) order[static_cast<std::size_t>(i)] = i;
    std::sort(order.begin(), order.end(), [&](int a, int b) { return model.trainingFrames[a] < model.trainingFrames[b]; });
    Eigen::VectorXd mean;
    for (std::size_t k = 1; k < order.size(); ++k) {
        x = 0.5 * (model.X.row(order[k - 1]) + model.X.row(order[k])).transpose();
        double v = 0.0;
        point.predict(x, mean, v);
        if (std::isfinite(v)) s2.push_back(v);
    }
    out.sigma2Percentile = percentileOf(s2, percentile);
    out.sigma2Limit = kSigma2Margin * out.sigma2Percentile;
    out.likLimit = percentileOf(lik, percentile);
    out.sigma2Median = percentileOf(s2, 50.0);
    out.likMedian = percentileOf(lik, 50.0);
    return out;
}

AdmissionVerdict admitPose(const TrainingRange& range, bool reached, double sigma2, double lik) {
    AdmissionVerdict v;
    v.range = range;
    v.reached = reached;
    v.sigma2 = sigma2;
    v.lik = lik;
    v.sigma2InRange = std::isfinite(sigma2) && sigma2 <= range.sigma2Limit;
    v.likInRange = std::isfinite(lik) && lik <= range.likLimit;
    v.admitted = v.reached && v.sigma2InRange && v.likInRange;
    char buf[200];
    if (!v.reached) {
        v.reason = "a target or pin was not reached";
    } else if (!v.likInRange) {
        std::snprintf(buf, sizeof buf, "L_IK %.4g is above the training frames' %gth percentile %.4g", lik, range.percentile,
                      range.likLimit);
        v.reason = buf;
    } else if (!v.sigma2InRange) {
        std::snprintf(buf, sizeof buf, "σ² %.4g is above %g × the training frames' %gth percentile %.4g", sigma2,
                      kSigma2Margin, range.percentile, range.sigma2Percentile);
        v.reason = buf;
    }
    return v;
}

}  // namespace mgp::gp
