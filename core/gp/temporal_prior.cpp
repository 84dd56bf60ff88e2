#include "gp/temporal_prior.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace mgp::gp {

const char* latentPriorName(LatentPrior p) {
    switch (p) {
        case LatentPrior::kSmooth: return "smooth";
        case LatentPrior::kPaced: return "paced";
        case LatentPrior::kNone: break;
    }
    return "none";
}

bool parseLatentPrior(const std::string& s, LatentPrior& out) {
    if (s == "none")
        out = LatentPrior::kNone;
    else if (s == "smooth")
        out = LatentPrior::kSmooth;
    else if (s == "paced")
        out = LatentPrior::kPaced;
    else
        return false;
    return true;
}

namespace {

double medianOf(std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
    return v[v.size() / 2];
}

}  // namespace

template <class Gap>
TemporalPrior TemporalPrior::build(const std::vector<int>& frames, const std::vector<int>& clips, double weight,
                                   Gap gap) {
    if (!(weight >= 0.0) || !std::isfinite(weight))
        throw std::invalid_argument("TemporalPrior: expected a finite weight ≥ 0, found " + std::to_string(weight));
    if (!clips.empty() && clips.size() != frames.size())
        throw std::invalid_argument("TemporalPrior: expected one clip index per frame (" +
                                    std::to_string(frames.size()) + "), found " + std::to_string(clips.size()));
    TemporalPrior p;
    p.weight_ = weight;
    const int n = static_cast<int>(frames.size());
    auto clipOf = [&](int row) { return clips.empty() ? 0 : clips[static_cast<std::size_t>(row)]; };
    p.byRow_.assign(static_cast<std::size_t>(n), {});
    p.order_.resize(static_cast<std::size_t>(n));
    std::iota(p.order_.begin(), p.order_.end(), 0);
    std::stable_sort(p.order_.begin(), p.order_.end(), [&](int a, int b) {
        return clipOf(a) != clipOf(b) ? clipOf(a) < clipOf(b) : frames[a] < frames[b];
    });
    if (n < 3) return p;
    auto sameClip = [&](int k) { return clipOf(p.order_[k]) == clipOf(p.order_[k - 1]); };
    std::vector<int> gaps;
    for (int k = 1; k < n; ++k) {
        const int g = frames[p.order_[k]] - frames[p.order_[k - 1]];
        if (g > 0 && sameClip(k)) gaps.push_back(g);
    }
    if (gaps.empty()) return p;
    std::nth_element(gaps.begin(), gaps.begin() + static_cast<long>(gaps.size() / 2), gaps.end());
    const double hbar = gaps[gaps.size() / 2];
    auto joined = [&](int k) {  // rows order_[k−1] and order_[k] belong to one segment
        const int g = frames[p.order_[k]] - frames[p.order_[k - 1]];
        return sameClip(k) && g > 0 && g <= 3.0 * hbar;
    };
    std::vector<double> h(static_cast<std::size_t>(n), 0.0);  // h[k]: spacing of order_[k−1] → order_[k]
    std::vector<int> joinedAt;
    for (int k = 1; k < n; ++k)
        if (joined(k)) joinedAt.push_back(k);
    gap(p.order_, joinedAt, hbar, frames, h);
    for (int k = 1; k + 1 < n; ++k) {
        if (!joined(k) || !joined(k + 1)) continue;
        const double h1 = h[static_cast<std::size_t>(k)];
        const double h2 = h[static_cast<std::size_t>(k + 1)];
        Triple t;
        t.row[0] = p.order_[k - 1];
        t.row[1] = p.order_[k];
        t.row[2] = p.order_[k + 1];
        t.coef[0] = 2.0 / (h1 * (h1 + h2));
        t.coef[2] = 2.0 / (h2 * (h1 + h2));
        t.coef[1] = -(t.coef[0] + t.coef[2]);
        const int idx = static_cast<int>(p.triples_.size());
        p.triples_.push_back(t);
        for (int r : t.row) p.byRow_[static_cast<std::size_t>(r)].push_back(idx);
    }
    return p;
}

TemporalPrior TemporalPrior::secondDifference(const std::vector<int>& frames, double weight,
                                              const std::vector<int>& clips) {
    return build(frames, clips, weight,
                 [](const std::vector<int>& order, const std::vector<int>& joinedAt, double hbar,
                    const std::vector<int>& fr, std::vector<double>& h) {
                     for (int k : joinedAt) h[static_cast<std::size_t>(k)] = (fr[order[k]] - fr[order[k - 1]]) / hbar;
                 });
}

TemporalPrior TemporalPrior::posePaced(const std::vector<int>& frames, const Eigen::MatrixXd& Y, double weight,
                                       const std::vector<int>& clips) {
    if (Y.rows() != static_cast<Eigen::Index>(frames.size()))
        throw std::invalid_argument("TemporalPrior: expected one pose row per frame (" + std::to_string(frames.size()) +
                                    "), found " + std::to_string(Y.rows()));
    return build(frames, clips, weight,
                 [&Y](const std::vector<int>& order, const std::vector<int>& joinedAt, double, const std::vector<int>&,
                      std::vector<double>& h) {
                     if (joinedAt.empty()) return;
                     std::vector<double> dist;
                     dist.reserve(joinedAt.size());
                     for (int k : joinedAt) dist.push_back((Y.row(order[k]) - Y.row(order[k - 1])).norm());
                     const double med = medianOf(dist);
                     for (std::size_t i = 0; i < joinedAt.size(); ++i) {
                         // All poses equal along the joined pairs: no pace to follow, plain gaps of 1.
                         const double r = med > 0.0 ? dist[i] / med : 1.0;
                         h[static_cast<std::size_t>(joinedAt[i])] = std::clamp(r, kMinPaceGap, kMaxPaceGap);
                     }
                 });
}

double TemporalPrior::value(const Eigen::MatrixXd& X, Eigen::MatrixXd* grad) const {
    if (grad) grad->setZero(X.rows(), X.cols());
    double v = 0.0;
    if (weight_ == 0.0) return 0.0;
    Eigen::RowVectorXd r(X.cols());
    for (const Triple& t : triples_) {
        r = t.coef[0] * X.row(t.row[0]) + t.coef[1] * X.row(t.row[1]) + t.coef[2] * X.row(t.row[2]);
        v += r.squaredNorm();
        if (grad)
            for (int s = 0; s < 3; ++s) grad->row(t.row[s]) += weight_ * t.coef[s] * r;
    }
    return 0.5 * weight_ * v;
}

double TemporalPrior::pointValue(const Eigen::MatrixXd& X, int row, const Eigen::VectorXd& x,
                                 Eigen::VectorXd* grad) const {
    if (grad) grad->setZero(x.size());
    if (weight_ == 0.0 || row < 0 || row >= static_cast<int>(byRow_.size())) return 0.0;
    double v = 0.0;
    Eigen::VectorXd r(x.size());
    for (int idx : byRow_[static_cast<std::size_t>(row)]) {
        const Triple& t = triples_[static_cast<std::size_t>(idx)];
        r.setZero();
        double own = 0.0;
        for (int s = 0; s < 3; ++s) {
            if (t.row[s] == row) {
                r += t.coef[s] * x;
                own = t.coef[s];
            } else {
                r += t.coef[s] * X.row(t.row[s]).transpose();
            }
        }
        v += r.squaredNorm();
        if (grad) *grad += weight_ * own * r;
    }
    return 0.5 * weight_ * v;
}

}  // namespace mgp::gp
