#include "gp/scg.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace mgp::gp {

const char* scgStopName(ScgStop s) {
    switch (s) {
        case ScgStop::kMaxIterations: return "max_iterations";
        case ScgStop::kConverged: return "converged";
        case ScgStop::kZeroGradient: return "zero_gradient";
        case ScgStop::kTinyDirection: return "tiny_direction";
        case ScgStop::kStopped: return "stopped";
        default: return "bad_start";
    }
}

namespace {
constexpr double kSigma0 = 1e-4;
constexpr double kBetaMin = 1e-15, kBetaMax = 1e100;
}  // namespace

ScgMachine::ScgMachine(const Eigen::VectorXd& x0, const ScgOptions& options) : opt_(options), x_(x0) {
    const Eigen::Index n = x0.size();
    g_.resize(n);
    gOld_.resize(n);
    gNew_.resize(n);
    gPlus_.resize(n);
    xNew_.resize(n);
    xPlus_.resize(n);
}

const Eigen::VectorXd& ScgMachine::request() const {
    return phase_ == Phase::kCurvature ? xPlus_ : phase_ == Phase::kTrial ? xNew_ : x_;
}

Eigen::VectorXd& ScgMachine::gradientSlot() {
    return phase_ == Phase::kCurvature ? gPlus_ : phase_ == Phase::kTrial ? gNew_ : g_;
}

void ScgMachine::finish(ScgStop stop) {
    res_.stop = stop;
    res_.x = x_;
    res_.value = fOld_;
    phase_ = Phase::kDone;
}

void ScgMachine::supply(double value) {
    ++res_.evaluations;
    switch (phase_) {
        case Phase::kStart:
            fOld_ = value;
            if (!std::isfinite(fOld_) || !g_.allFinite()) return finish(ScgStop::kBadStart);
            dir_ = -g_;
            return beginIteration();
        case Phase::kCurvature:
            theta_ = (std::isfinite(value) && gPlus_.allFinite()) ? dir_.dot(gPlus_ - g_) / sigma_ : 0.0;
            return requestTrial();
        case Phase::kTrial: break;
        case Phase::kDone: throw std::logic_error("ScgMachine::supply: the minimisation has ended");
    }
    const double fNew = value;
    double Delta = 2.0 * (fNew - fOld_) / (alpha_ * mu_);
    // docs/maths.md §7 step 4: a non-finite trial is a failure that must change the scale.
    if (!std::isfinite(fNew) || !gNew_.allFinite() || std::isnan(Delta))
        Delta = -std::numeric_limits<double>::infinity();
    if (Delta >= 0.0) {
        success_ = true;
        ++nSuccess_;
        const double stepMax = (alpha_ * dir_).cwiseAbs().maxCoeff();
        const double fChange = std::abs(fNew - fOld_);
        x_ = xNew_;
        gOld_ = g_;
        g_ = gNew_;
        fOld_ = fNew;
        if (stepMax < opt_.tolX && fChange < opt_.tolF) return finish(ScgStop::kConverged);
        if (g_.dot(g_) == 0.0) return finish(ScgStop::kZeroGradient);
    } else {
        success_ = false;
    }
    if (Delta < 0.25) beta_ = std::min(4.0 * beta_, kBetaMax);
    if (Delta > 0.75) beta_ = std::max(0.5 * beta_, kBetaMin);
    if (nSuccess_ == x_.size()) {
        dir_ = -g_;
        nSuccess_ = 0;
    } else if (success_) {
        const double gamma = (gOld_ - g_).dot(g_) / mu_;
        dir_ = gamma * dir_ - g_;
    }
    beginIteration();
}

void ScgMachine::beginIteration() {
    if (++iteration_ > opt_.maxIterations) return finish(ScgStop::kMaxIterations);
    if (opt_.shouldStop && opt_.shouldStop()) return finish(ScgStop::kStopped);
    res_.iterations = iteration_;
    if (!success_) return requestTrial();
    mu_ = dir_.dot(g_);
    if (mu_ >= 0.0) {
        dir_ = -g_;
        mu_ = dir_.dot(g_);
    }
    kappa_ = dir_.dot(dir_);
    if (kappa_ < std::numeric_limits<double>::epsilon()) return finish(ScgStop::kTinyDirection);
    sigma_ = kSigma0 / std::sqrt(kappa_);
    xPlus_ = x_ + sigma_ * dir_;
    phase_ = Phase::kCurvature;
}

void ScgMachine::requestTrial() {
    double delta = theta_ + beta_ * kappa_;
    if (delta <= 0.0) {
        delta = beta_ * kappa_;
        beta_ = beta_ - theta_ / kappa_;
    }
    alpha_ = -mu_ / delta;
    xNew_ = x_ + alpha_ * dir_;
    phase_ = Phase::kTrial;
}

ScgResult scgMinimize(const ValueAndGradient& fg, const Eigen::VectorXd& x0, const ScgOptions& opt) {
    ScgMachine m(x0, opt);
    while (!m.done()) {
        const double f = fg(m.request(), m.gradientSlot());
        m.supply(f);
    }
    return m.result();
}

}  // namespace mgp::gp
