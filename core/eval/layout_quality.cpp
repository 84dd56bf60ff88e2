#include "eval/layout_quality.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "gp/gp_objective.h"
#include "gp/scg.h"
#include "skeleton/pose_layout.h"

namespace mgp::eval {

std::vector<std::pair<int, int>> timeConsecutivePairs(const std::vector<int>& frames) {
    const int n = static_cast<int>(frames.size());
    std::vector<int> order(static_cast<std::size_t>(n));
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return frames[a] < frames[b]; });
    std::vector<int> gaps;
    for (int k = 1; k < n; ++k) {
        const int g = frames[order[k]] - frames[order[k - 1]];
        if (g > 0) gaps.push_back(g);
    }
    std::vector<std::pair<int, int>> out;
    if (gaps.empty()) return out;
    std::nth_element(gaps.begin(), gaps.begin() + static_cast<long>(gaps.size() / 2), gaps.end());
    const double hbar = gaps[gaps.size() / 2];
    for (int k = 1; k < n; ++k) {
        const int g = frames[order[k]] - frames[order[k - 1]];
        if (g > 0 && g <= 3.0 * hbar) out.emplace_back(order[k - 1], order[k]);
    }
    return out;
}

double percentile(std::vector<double> v, double q) {
    if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
    std::sort(v.begin(), v.end());
    const double pos = std::clamp(q, 0.0, 1.0) * static_cast<double>(v.size() - 1);
    const std::size_t lo = static_cast<std::size_t>(std::floor(pos));
    const std::size_t hi = std::min(lo + 1, v.size() - 1);
    return v[lo] + (pos - static_cast<double>(lo)) * (v[hi] - v[lo]);
}

ContinuityReport latentContinuity(const Eigen::MatrixXd& X, const std::vector<int>& frames) {
    if (static_cast<Eigen::Index>(frames.size()) != X.rows())
        throw std::invalid_argument("latentContinuity: expected one frame per latent row, found " +
                                    std::to_string(frames.size()) + " frames for " + std::to_string(X.rows()) +
                                    " rows");
    ContinuityReport r;
    const Eigen::Index n = X.rows();
    if (n < 2) return r;
    const Eigen::Index stride = std::max<Eigen::Index>(1, (n + 2999) / 3000);
    std::vector<double> pair;
    for (Eigen::Index i = 0; i < n; i += stride)
        for (Eigen::Index j = i + stride; j < n; j += stride) pair.push_back((X.row(i) - X.row(j)).norm());
    r.medianPairDistance = percentile(std::move(pair), 0.5);
    std::vector<double> steps;
    for (const auto& [a, b] : timeConsecutivePairs(frames)) steps.push_back((X.row(a) - X.row(b)).norm());
    r.steps = static_cast<int>(steps.size());
    if (steps.empty() || !(r.medianPairDistance > 0.0)) return r;
    for (double& s : steps) s /= r.medianPairDistance;
    r.p50 = percentile(steps, 0.5);
    r.p90 = percentile(steps, 0.9);
    r.p99 = percentile(steps, 0.99);
    r.max = *std::max_element(steps.begin(), steps.end());
    return r;
}

std::vector<ContinuityReport> latentContinuityPerClip(const gp::GpModel& model) {
    std::vector<ContinuityReport> out;
    for (int c = 0; c < model.clipCount(); ++c) {
        const std::vector<int> rows = model.rowsOfClip(c);
        Eigen::MatrixXd X(static_cast<Eigen::Index>(rows.size()), model.latentDim());
        std::vector<int> frames;
        for (std::size_t k = 0; k < rows.size(); ++k) {
            X.row(static_cast<Eigen::Index>(k)) = model.X.row(rows[k]);
            frames.push_back(model.trainingFrames[static_cast<std::size_t>(rows[k])]);
        }
        out.push_back(latentContinuity(X, frames));
    }
    return out;
}

double fullGpNegLogLikelihood(const Eigen::MatrixXd& X, const Eigen::MatrixXd& Ys, const Eigen::Vector4d& psiIn,
                              Eigen::Vector4d* grad) {
    const double inf = std::numeric_limits<double>::infinity();
    if (grad) grad->setZero();
    const Eigen::Index n = X.rows();
    const double D = static_cast<double>(Ys.cols());
    if (n == 0 || Ys.rows() != n || !psiIn.allFinite()) return inf;
    const Eigen::Vector4d psi = psiIn.cwiseMax(-gp::kLogParamBound).cwiseMin(gp::kLogParamBound);
    const double alpha = std::exp(psi[0]), gamma = std::exp(psi[1]), bias = std::exp(psi[2]), beta = std::exp(psi[3]);
    Eigen::MatrixXd r2(n, n), R(n, n);
    for (Eigen::Index j = 0; j < n; ++j)
        for (Eigen::Index i = j; i < n; ++i) {
            const double v = (X.row(i) - X.row(j)).squaredNorm();
            r2(i, j) = r2(j, i) = v;
            R(i, j) = R(j, i) = std::exp(-0.5 * gamma * v);
        }
    Eigen::MatrixXd K = alpha * R;
    K.array() += bias;
    K.diagonal().array() += 1.0 / beta;
    Eigen::LLT<Eigen::MatrixXd> llt;
    double jitter = 0.0;
    if (!gp::jitterCholesky(K, llt, jitter)) return inf;
    const double logDet = 2.0 * llt.matrixLLT().diagonal().array().log().sum();
    const Eigen::MatrixXd A = llt.solve(Ys);  // K⁻¹ Ys
    const double quad = (Ys.array() * A.array()).sum();
    const double value = 0.5 * D * logDet + 0.5 * quad + 0.5 * static_cast<double>(n) * D * std::log(2.0 * M_PI);
    if (!std::isfinite(value)) return inf;
    if (grad) {
        const Eigen::MatrixXd Kinv = llt.solve(Eigen::MatrixXd::Identity(n, n));
        const Eigen::MatrixXd G = 0.5 * (D * Kinv - A * A.transpose());  // ∂(−ln p)/∂K
        (*grad)[0] = alpha * (G.array() * R.array()).sum();
        (*grad)[1] = -0.5 * alpha * gamma * (G.array() * r2.array() * R.array()).sum();
        (*grad)[2] = bias * G.sum();
        (*grad)[3] = -G.trace() / beta;
        // The clamp makes the function flat outside the box.
        for (int p = 0; p < 4; ++p)
            if (psiIn[p] != psi[p]) (*grad)[p] = 0.0;
    }
    return value;
}

FullGpScore fitFullGp(const Eigen::MatrixXd& X, const Eigen::MatrixXd& Y, int maxIterations) {
    FullGpScore best;
    const Eigen::Index n = Y.rows();
    if (n < 2 || X.rows() != n) return best;
    std::vector<Eigen::Index> keep;
    const Eigen::RowVectorXd mean = Y.colwise().mean();
    for (Eigen::Index k = 0; k < Y.cols(); ++k)
        if (std::sqrt((Y.col(k).array() - mean[k]).square().mean()) > 1e-6) keep.push_back(k);
    if (keep.empty()) return best;
    Eigen::MatrixXd Ys(n, static_cast<Eigen::Index>(keep.size()));
    for (std::size_t c = 0; c < keep.size(); ++c) {
        const Eigen::VectorXd col = Y.col(keep[c]).array() - mean[keep[c]];
        Ys.col(static_cast<Eigen::Index>(c)) = col / std::sqrt(col.squaredNorm() / static_cast<double>(n));
    }
    std::vector<double> d2;
    for (Eigen::Index i = 0; i < n; ++i)
        for (Eigen::Index j = i + 1; j < n; ++j) d2.push_back((X.row(i) - X.row(j)).squaredNorm());
    const double med = std::max(percentile(std::move(d2), 0.5), 1e-12);
    const gp::ValueAndGradient fg = [&](const Eigen::VectorXd& z, Eigen::VectorXd& g) {
        Eigen::Vector4d gg;
        const double v = fullGpNegLogLikelihood(X, Ys, Eigen::Vector4d(z), &gg);
        g = gg;
        return v;
    };
    gp::ScgOptions so;
    so.maxIterations = maxIterations;
    so.tolX = 1e-6;
    so.tolF = 1e-6;
    double bestValue = std::numeric_limits<double>::infinity();
    for (double g0 : {1.0, 20.0}) {
        const Eigen::Vector4d z0(std::log(0.9), std::log(g0 / med), std::log(0.1), std::log(10.0));
        const gp::ScgResult r = gp::scgMinimize(fg, z0, so);
        const Eigen::Vector4d z = Eigen::Vector4d(r.x).cwiseMax(-gp::kLogParamBound).cwiseMin(gp::kLogParamBound);
        const double v = fullGpNegLogLikelihood(X, Ys, z, nullptr);
        if (std::isfinite(v) && v < bestValue) {
            bestValue = v;
            best.ok = true;
            best.logLikelihood = -v;
            best.perValue = -v / (static_cast<double>(n) * static_cast<double>(Ys.cols()));
            best.alpha = std::exp(z[0]);
            best.gamma = std::exp(z[1]);
            best.bias = std::exp(z[2]);
            best.noiseVariance = std::exp(-z[3]);
            best.iterations = r.iterations;
        }
    }
    return best;
}

HeldOutSplit everyNthHeldOut(std::vector<int> frames, int every, int offset) {
    if (every < 2) throw std::invalid_argument("everyNthHeldOut: expected every ≥ 2, found " + std::to_string(every));
    if (offset < 0 || offset >= every)
        throw std::invalid_argument("everyNthHeldOut: expected 0 ≤ offset < " + std::to_string(every) + ", found " +
                                    std::to_string(offset));
    std::sort(frames.begin(), frames.end());
    frames.erase(std::unique(frames.begin(), frames.end()), frames.end());
    HeldOutSplit s;
    const auto e = static_cast<std::size_t>(every), o = static_cast<std::size_t>(offset);
    for (std::size_t k = 0; k < frames.size(); ++k)
        ((k + 1) % e == o ? s.heldFrames : s.trainFrames).push_back(frames[k]);
    return s;
}

Spread spreadOf(const std::vector<double>& values) {
    Spread s;
    s.count = static_cast<int>(values.size());
    if (values.empty()) return s;
    double sum = 0.0;
    for (double v : values) sum += v;
    s.mean = sum / s.count;
    double ss = 0.0;
    for (double v : values) ss += (v - s.mean) * (v - s.mean);
    s.sd = s.count > 1 ? std::sqrt(ss / (s.count - 1)) : 0.0;
    s.min = *std::min_element(values.begin(), values.end());
    s.max = *std::max_element(values.begin(), values.end());
    return s;
}

void summarizeHeldOut(HeldOutOffsetsReport& report) {
    std::vector<double> rms, nearest, time;
    for (const HeldOutReport& h : report.perOffset) {
        rms.push_back(h.rmsDeg);
        nearest.push_back(h.nearestRmsDeg);
        if (h.timeCount > 0) time.push_back(h.timeRmsDeg);
    }
    report.rmsDeg = spreadOf(rms);
    report.nearestRmsDeg = spreadOf(nearest);
    report.timeRmsDeg = spreadOf(time);
}

HeldOutOffsetsReport heldOutOverOffsets(const gp::GpModel& model, const gp::TrainOptions& options, int every,
                                        const std::vector<int>& offsets) {
    HeldOutOffsetsReport rep;
    rep.offsets = offsets;
    for (int offset : offsets) {
        const HeldOutSplit split = everyNthHeldOut(model.trainingFrames, every, offset);
        if (split.trainFrames.size() < 3 || split.heldFrames.empty())
            throw std::invalid_argument(
                "heldOutOverOffsets: expected at least 3 training and 1 held-out frame at offset " +
                std::to_string(offset) + ", found " + std::to_string(split.trainFrames.size()) + " and " +
                std::to_string(split.heldFrames.size()));
        const auto t0 = std::chrono::steady_clock::now();
        gp::TrainResult r = gp::train(gp::trainingDataFromClip(model.clip, split.trainFrames), options);
        rep.trainSeconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        r.model.clip = model.clip;
        rep.perOffset.push_back(heldOutReconstruction(r.model, split.heldFrames));
    }
    summarizeHeldOut(rep);
    return rep;
}

HeldOutReport heldOutReconstruction(const gp::GpModel& model, const std::vector<int>& heldFrames, int iterations) {
    HeldOutReport rep;
    rep.trained = model.N();
    if (heldFrames.empty() || model.N() == 0) return rep;
    const Eigen::MatrixXd poses = poseMatrix(model.clip);
    const gp::ActiveSetPosterior pm = model.posterior();
    // Non-root DOFs: 3..P−1 of the pose vector.
    const int nonRoot = static_cast<int>(poses.cols()) - 3;
    Eigen::MatrixXd trainFull(model.N(), poses.cols());
    for (int i = 0; i < model.N(); ++i) trainFull.row(i) = model.fullPose(model.Y.row(i).transpose()).transpose();
    double sse = 0.0, sseNearest = 0.0, sseTime = 0.0;
    // Training rows by frame, and the median frame gap (the segmentation of the temporal prior).
    std::vector<std::pair<int, int>> byFrame;
    for (int i = 0; i < model.N() && i < static_cast<int>(model.trainingFrames.size()); ++i)
        byFrame.emplace_back(model.trainingFrames[static_cast<std::size_t>(i)], i);
    std::sort(byFrame.begin(), byFrame.end());
    std::vector<double> gaps;
    for (std::size_t k = 1; k < byFrame.size(); ++k)
        if (byFrame[k].first > byFrame[k - 1].first) gaps.push_back(byFrame[k].first - byFrame[k - 1].first);
    const double hbar = gaps.empty() ? 1.0 : percentile(gaps, 0.5);
    gp::ScgOptions so;
    so.maxIterations = iterations;
    std::vector<double> frameRms;
    for (int f : heldFrames) {
        if (f < 0 || f >= model.clip.frameCount())
            throw std::invalid_argument("heldOutReconstruction: frame " + std::to_string(f) + " outside the clip");
        const Eigen::VectorXd truth = poses.row(f).transpose();
        // The three nearest training poses (non-root RMS).
        std::vector<std::pair<double, int>> dist;
        for (int i = 0; i < model.N(); ++i)
            dist.emplace_back((trainFull.row(i).tail(nonRoot) - truth.tail(nonRoot).transpose()).squaredNorm(), i);
        const std::size_t take = std::min<std::size_t>(3, dist.size());
        std::partial_sort(dist.begin(), dist.begin() + static_cast<long>(take), dist.end());
        sseNearest += dist[0].first;
        const Eigen::VectorXd y = model.keptPose(truth);
        const gp::ValueAndGradient fg = [&](const Eigen::VectorXd& x, Eigen::VectorXd& g) {
            return pm.evaluate(x, y, &g, nullptr);
        };
        double bestL = std::numeric_limits<double>::infinity();
        Eigen::VectorXd bestX = model.X.row(dist[0].second).transpose();
        for (std::size_t s = 0; s < take; ++s) {
            const gp::ScgResult r = gp::scgMinimize(fg, model.X.row(dist[s].second).transpose(), so);
            if (r.x.allFinite()) {
                Eigen::VectorXd g(r.x.size());
                const double L = fg(r.x, g);
                if (L < bestL) {
                    bestL = L;
                    bestX = r.x;
                }
            }
        }
        Eigen::VectorXd mean;
        double var = 0.0;
        pm.predict(bestX, mean, var);
        const Eigen::VectorXd pred = model.fullPose(mean);
        const double frameSse = (pred.tail(nonRoot) - truth.tail(nonRoot)).squaredNorm();
        sse += frameSse;
        frameRms.push_back(std::sqrt(frameSse / nonRoot));
        if (frameRms.back() > rep.worstFrameRmsDeg) {
            rep.worstFrameRmsDeg = frameRms.back();
            rep.worstFrame = f;
        }
        // In-betweening from the time neighbours (within 3 median gaps on each side).
        const auto after = std::upper_bound(byFrame.begin(), byFrame.end(), std::make_pair(f, model.N()));
        if (after != byFrame.end() && after != byFrame.begin()) {
            const auto before = std::prev(after);
            const int f0 = before->first, f1 = after->first;
            if (f0 < f && f < f1 && f - f0 <= 3.0 * hbar && f1 - f <= 3.0 * hbar) {
                const double u = static_cast<double>(f - f0) / (f1 - f0);
                const Eigen::VectorXd xt =
                    (1.0 - u) * model.X.row(before->second).transpose() + u * model.X.row(after->second).transpose();
                pm.predict(xt, mean, var);
                sseTime += (model.fullPose(mean).tail(nonRoot) - truth.tail(nonRoot)).squaredNorm();
                ++rep.timeCount;
            }
        }
    }
    const double count = static_cast<double>(heldFrames.size()) * nonRoot;
    rep.heldOut = static_cast<int>(heldFrames.size());
    rep.rmsDeg = std::sqrt(sse / count);
    rep.medianFrameRmsDeg = percentile(frameRms, 0.5);
    rep.nearestRmsDeg = std::sqrt(sseNearest / count);
    rep.timeRmsDeg = rep.timeCount > 0 ? std::sqrt(sseTime / (static_cast<double>(rep.timeCount) * nonRoot)) : 0.0;
    return rep;
}

gp::TrainOptions trainOptionsOf(const gp::GpModel& model) {
    gp::TrainOptions o;
    o.kind = model.kind;
    o.activeSize = model.settings.activeSize;
    o.outerIterations = model.settings.outerIterations;
    o.scgIterations = model.settings.scgIterations;
    o.pointIterations = model.settings.pointIterations;
    o.tolerance = model.settings.tolerance;
    o.prior = model.settings.prior;
    if (o.prior != gp::LatentPrior::kNone) o.priorWeight = model.settings.priorWeight;
    o.backConstraints = model.settings.backConstraints;
    return o;
}

}  // namespace mgp::eval
