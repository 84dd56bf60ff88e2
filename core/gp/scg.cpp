#include "gp/scg.h"

#include <algorithm>
#include <cmath>
#include <limits>

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

ScgResult scgMinimize(const ValueAndGradient& fg, const Eigen::VectorXd& x0, const ScgOptions& opt) {
    constexpr double kSigma0 = 1e-4;
    constexpr double kBetaMin = 1e-15, kBetaMax = 1e100;
    const double eps = std::numeric_limits<double>::epsilon();
    const Eigen::Index n = x0.size();

    ScgResult res;
    Eigen::VectorXd x = x0, g(n), gOld(n), gNew(n), gPlus(n), xNew(n), xPlus(n);
    double fOld = fg(x, g);
    res.evaluations = 1;
    res.x = x;
    res.value = fOld;
    if (!std::isfinite(fOld) || !g.allFinite()) {
        res.stop = ScgStop::kBadStart;
        return res;
    }
    Eigen::VectorXd dir = -g;
    bool success = true;
    int nSuccess = 0;
    double beta = 1.0;
    double mu = 0.0, kappa = 0.0, theta = 0.0;

    for (int j = 1; j <= opt.maxIterations; ++j) {
        if (opt.shouldStop && opt.shouldStop()) {
            res.stop = ScgStop::kStopped;
            break;
        }
        res.iterations = j;
        if (success) {
            mu = dir.dot(g);
            if (mu >= 0.0) {
                dir = -g;
                mu = dir.dot(g);
            }
            kappa = dir.dot(dir);
            if (kappa < eps) {
                res.stop = ScgStop::kTinyDirection;
                break;
            }
            const double sigma = kSigma0 / std::sqrt(kappa);
            xPlus = x + sigma * dir;
            const double fPlus = fg(xPlus, gPlus);
            ++res.evaluations;
            theta = (std::isfinite(fPlus) && gPlus.allFinite()) ? dir.dot(gPlus - g) / sigma : 0.0;
        }
        double delta = theta + beta * kappa;
        if (delta <= 0.0) {
            delta = beta * kappa;
            beta = beta - theta / kappa;
        }
        const double alpha = -mu / delta;
        xNew = x + alpha * dir;
        const double fNew = fg(xNew, gNew);
        ++res.evaluations;
        double Delta = 2.0 * (fNew - fOld) / (alpha * mu);
        // docs/maths.md §7 step 4: a non-finite trial is a failure that must change the scale.
        if (!std::isfinite(fNew) || !gNew.allFinite() || std::isnan(Delta))
            Delta = -std::numeric_limits<double>::infinity();
        if (Delta >= 0.0) {
            success = true;
            ++nSuccess;
            const double stepMax = (alpha * dir).cwiseAbs().maxCoeff();
            const double fChange = std::abs(fNew - fOld);
            x = xNew;
            gOld = g;
            g = gNew;
            fOld = fNew;
            if (stepMax < opt.tolX && fChange < opt.tolF) {
                res.stop = ScgStop::kConverged;
                break;
            }
            if (g.dot(g) == 0.0) {
                res.stop = ScgStop::kZeroGradient;
                break;
            }
        } else {
            success = false;
        }
        if (Delta < 0.25) beta = std::min(4.0 * beta, kBetaMax);
        if (Delta > 0.75) beta = std::max(0.5 * beta, kBetaMin);
        if (nSuccess == n) {
            dir = -g;
            nSuccess = 0;
        } else if (success) {
            const double gamma = (gOld - g).dot(g) / mu;
            dir = gamma * dir - g;
        }
    }
    res.x = x;
    res.value = fOld;
    return res;
}

}  // namespace mgp::gp
