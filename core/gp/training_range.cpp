#include "gp/training_range.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace mgp::gp {

double percentileOf(std::vector<double> v, double p) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const double pos = std::clamp(p, 0.0, 100.0) / 100.0 * static_cast<double>(v.size() - 1);
    const auto lo = static_cast<std::size_t>(std::floor(pos));
    const std::size_t hi = std::min(lo + 1, v.size() - 1);
    return v[lo] + (pos - static_cast<double>(lo)) * (v[hi] - v[lo]);
}

void heldOutMomentScores(const GpModel& model, const ActiveSetPosterior& point, int windowFrames,
                         std::vector<double>& sigma2, std::vector<double>& lik) {
    sigma2.clear();
    lik.clear();
    Eigen::VectorXd x, y;
    std::vector<int> held;
    for (int i = 0; i < model.N(); ++i) {
        held.clear();
        for (std::size_t a = 0; a < model.active.size(); ++a)
            if (model.rowClip(model.active[a]) == model.rowClip(i) &&
                std::abs(model.trainingFrames[static_cast<std::size_t>(model.active[a])] -
                         model.trainingFrames[static_cast<std::size_t>(i)]) <= windowFrames)
                held.push_back(static_cast<int>(a));
        x = model.X.row(i).transpose();
        y = model.Y.row(i).transpose();
        double v = 0.0;
        const double l = point.evaluateHoldingOut(x, y, held, v);
        if (!std::isfinite(l) || !std::isfinite(v)) continue;
        sigma2.push_back(v);
        lik.push_back(l);
    }
}

TrainingRange computeTrainingRange(const GpModel& model, const ActiveSetPosterior& point, double percentile) {
    TrainingRange out;
    out.percentile = percentile;
    out.rows = model.N();
    std::vector<double> s2, lik;
    heldOutMomentScores(model, point, kHeldOutWindowFrames, s2, lik);
    out.sigma2Percentile = percentileOf(s2, percentile);
    out.sigma2Limit = kSigma2Margin * out.sigma2Percentile;
    out.likLimit = percentileOf(lik, percentile);
    out.sigma2Median = percentileOf(s2, 50.0);
    out.likMedian = percentileOf(lik, 50.0);
    return out;
}

}  // namespace mgp::gp
