#include "motion/inbetween.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "gp/capture_range.h"
#include "motion/foot_contacts.h"
#include "skeleton/clip_match.h"
#include "skeleton/forward_kinematics.h"
#include "skeleton/pose_mirror.h"
#include "skeleton/rotation.h"

namespace mgp {

std::string validateGaps(const std::vector<InbetweenGap>& gaps, int frameCount) {
    if (gaps.empty()) return "expected at least one gap A:B, found none";
    for (std::size_t i = 0; i < gaps.size(); ++i) {
        const InbetweenGap& g = gaps[i];
        const std::string name = std::to_string(g.a + 1) + ":" + std::to_string(g.b + 1);
        if (g.a < 0 || g.b >= frameCount)
            return "expected gaps inside the clip's frames 1.." + std::to_string(frameCount) + ", found " + name;
        if (g.a + 1 >= g.b)
            return "expected at least one frame between the keys of a gap A:B (A + 1 < B), found " + name;
        if (i > 0 && g.a < gaps[i - 1].b)
            return "expected gaps in increasing order that do not overlap, found " + name + " after " +
                   std::to_string(gaps[i - 1].a + 1) + ":" + std::to_string(gaps[i - 1].b + 1);
    }
    return "";
}

const char* inbetweenMethodName(InbetweenMethod m) {
    switch (m) {
        case InbetweenMethod::kHold: return "hold";
        case InbetweenMethod::kInterpolate: return "interpolate";
        case InbetweenMethod::kRetrieve: return "retrieve";
        case InbetweenMethod::kPrior: return "prior";
    }
    return "?";
}

namespace {

// Linear blend of two neighbouring frames (angles through the shorter way round).
Pose blendPoses(const Pose& a, const Pose& b, double s) {
    Pose p = a;
    p.rootCm = (1.0 - s) * a.rootCm + s * b.rootCm;
    for (std::size_t j = 0; j < a.anglesDeg.size(); ++j)
        for (int k = 0; k < 3; ++k)
            p.anglesDeg[j][k] = a.anglesDeg[j][k] + s * wrap180(b.anglesDeg[j][k] - a.anglesDeg[j][k]);
    return p;
}

double smoothstep(double s) { return s * s * (3.0 - 2.0 * s); }

double yawDeg(const FkState& fk) { return headingRadians(fk) * kRadToDeg; }

// Every rotation axis free: fitJointAngles then picks the Euler triple of a rotation nearest a
// reference, exactly (a joint with fewer DOFs keeps the slerped rotation's other angles).
constexpr std::array<bool, 3> kAllAxes{true, true, true};

// What the match compares of every frame of a motion: joint positions relative to the root in the
// frame's heading frame (the body's shape), the velocity into the frame and out of it in the same
// frame, the root's ground position and the heading.
struct MotionFeatures {
    std::vector<Eigen::VectorXd> shape, velocityIn, velocityOut;  // 3J each (velocity in cm/frame)
    std::vector<Eigen::Vector3d> root;
    std::vector<Eigen::Matrix3d> heading;  // headingRemoval of the frame
    std::vector<double> yaw;               // degrees
};

MotionFeatures motionFeatures(const Skeleton& sk, const std::vector<Pose>& frames) {
    const int n = static_cast<int>(frames.size());
    const int J = sk.jointCount();
    MotionFeatures f;
    std::vector<std::vector<Eigen::Vector3d>> joints(n);
    FkState fk;
    for (int t = 0; t < n; ++t) {
        forwardKinematics(sk, frames[static_cast<std::size_t>(t)], fk);
        joints[t] = fk.jointCm;
        f.heading.push_back(headingRemoval(fk));
        f.yaw.push_back(yawDeg(fk));
        f.root.push_back(fk.jointCm[0]);
        f.shape.push_back(gp::captureShape(sk, fk));
    }
    for (int t = 0; t < n; ++t) {
        Eigen::VectorXd in = Eigen::VectorXd::Zero(3 * J), out = Eigen::VectorXd::Zero(3 * J);
        for (int j = 0; j < J; ++j) {
            if (t > 0) in.segment<3>(3 * j) = f.heading[t] * (joints[t][j] - joints[t - 1][j]);
            if (t + 1 < n) out.segment<3>(3 * j) = f.heading[t] * (joints[t + 1][j] - joints[t][j]);
        }
        f.velocityIn.push_back(in);
        f.velocityOut.push_back(out);
    }
    return f;
}

// The match cost's weights (docs/maths-inbetween.md §2): per joint cm² of shape, (cm/frame)² of
// velocity weighed like 10 cm of shape per cm/frame, cm² of travel at a quarter (the warp spreads
// a travel error over the whole gap), degrees² of turn.
constexpr double kVelocityWeight = 100.0;
constexpr double kTravelWeight = 0.25;
constexpr double kTurnWeight = 1.0;
// Time scales tried: source frames per generated frame.
constexpr double kTimeScales[] = {0.8, 0.87, 0.93, 1.0, 1.07, 1.15, 1.25};

struct Stretch {
    int clip = -1, first = 0, last = 0;
    double cost = std::numeric_limits<double>::infinity();
    // The source frame nearest to frame i of an L-frame gap (0 and L: the stretch's ends).
    int sourceFrame(int i, int L) const {
        return static_cast<int>(std::lround(first + static_cast<double>(i) * (last - first) / L));
    }
};

// The stretch of the model's clips that best joins keys a and b of `target` (clip −1 if none fits).
Stretch bestStretch(const std::vector<MotionFeatures>& sources, int excludeClip, const MotionFeatures& target, int a,
                    int b, int targetFrames) {
    const int L = b - a;
    const double J = static_cast<double>(target.shape.front().size() / 3);
    const Eigen::Vector3d travelKey = target.heading[a] * (target.root[b] - target.root[a]);
    const double turnKey = wrap180(target.yaw[b] - target.yaw[a]);
    const bool velocityAtA = a > 0, velocityAtB = b + 1 < targetFrames;
    Stretch best;
    for (int c = 0; c < static_cast<int>(sources.size()); ++c) {
        const MotionFeatures& src = sources[c];
        const int n = static_cast<int>(src.shape.size());
        for (double scale : kTimeScales) {
            const int Ls = static_cast<int>(std::lround(L * scale));
            if (Ls < 1) continue;
            const double rate = static_cast<double>(Ls) / L;  // generated velocity = rate · source velocity
            for (int s = 1; s + Ls + 1 < n; ++s) {
                const int e = s + Ls;
                if (c == excludeClip && s <= b && e >= a) continue;  // never read the gap itself
                double cost =
                    ((src.shape[s] - target.shape[a]).squaredNorm() + (src.shape[e] - target.shape[b]).squaredNorm()) /
                    J;
                if (velocityAtA)
                    cost += kVelocityWeight * (rate * src.velocityIn[s] - target.velocityIn[a]).squaredNorm() / J;
                if (velocityAtB)
                    cost += kVelocityWeight * (rate * src.velocityOut[e] - target.velocityOut[b]).squaredNorm() / J;
                const Eigen::Vector3d travel = src.heading[s] * (src.root[e] - src.root[s]);
                cost += kTravelWeight * (travel - travelKey).squaredNorm();
                const double turn = wrap180(wrap180(src.yaw[e] - src.yaw[s]) - turnKey);
                cost += kTurnWeight * turn * turn;
                if (cost < best.cost) best = {c, s, e, cost};
            }
        }
    }
    return best;
}

// Frames s..e of `source` resampled to L + 1 frames, turned and moved so that its first frame
// stands where key `ka` stands and faces its way, then warped onto both keys.
std::vector<Pose> warpedStretch(const Skeleton& sk, const std::vector<Pose>& source, int s, int e, const Pose& ka,
                                const Pose& kb, int L) {
    std::vector<Pose> out;
    out.reserve(static_cast<std::size_t>(L + 1));
    for (int i = 0; i <= L; ++i) {
        const double u = s + static_cast<double>(i) * (e - s) / L;
        const int f0 = std::min(static_cast<int>(std::floor(u)), e);
        const int f1 = std::min(f0 + 1, e);
        out.push_back(blendPoses(source[static_cast<std::size_t>(f0)], source[static_cast<std::size_t>(f1)], u - f0));
    }
    // Turn about the vertical through the first frame's root and move onto key a.
    FkState fk;
    forwardKinematics(sk, out.front(), fk);
    const double turn = [&] {
        FkState fa;
        forwardKinematics(sk, ka, fa);
        return yawDeg(fa) - yawDeg(fk);
    }();
    const Eigen::Matrix3d ry = axisRotation(kAxisY, turn * kDegToRad);
    const Joint& root = sk.joints[0];
    const Eigen::Matrix3d rootTurn = root.axis.transpose() * ry * root.axis;
    const Eigen::Vector3d pivot(out.front().rootCm.x(), 0.0, out.front().rootCm.z());
    const Eigen::Vector3d onto(ka.rootCm.x(), 0.0, ka.rootCm.z());
    Eigen::Vector3d previous = ka.anglesDeg[0];
    for (Pose& p : out) {
        p.rootCm = ry * (p.rootCm - pivot) + onto;
        previous = fitJointAngles(rootTurn * eulerMatrix(p.anglesDeg[0], root.order), root.order, kAllAxes, previous);
        p.anglesDeg[0] = previous;
    }
    // Warp: the joints' offsets to the keys fade along a smoothstep (zero slope at both joins, so
    // the joins keep the stretch's velocity); the root's fade linearly, so a stretch that travels
    // further or less than the keys do keeps its speed profile (a smoothstep would add a surge in
    // the middle).
    Pose da = ka, db = kb;
    da.rootCm = ka.rootCm - out.front().rootCm;
    db.rootCm = kb.rootCm - out.back().rootCm;
    for (std::size_t j = 0; j < ka.anglesDeg.size(); ++j)
        for (int k = 0; k < 3; ++k) {
            da.anglesDeg[j][k] = wrap180(ka.anglesDeg[j][k] - out.front().anglesDeg[j][k]);
            db.anglesDeg[j][k] = wrap180(kb.anglesDeg[j][k] - out.back().anglesDeg[j][k]);
        }
    for (int i = 0; i <= L; ++i) {
        const double w = smoothstep(static_cast<double>(i) / L);
        const double wr = static_cast<double>(i) / L;
        Pose& p = out[static_cast<std::size_t>(i)];
        p.rootCm += (1.0 - wr) * da.rootCm + wr * db.rootCm;
        for (std::size_t j = 0; j < p.anglesDeg.size(); ++j)
            p.anglesDeg[j] += (1.0 - w) * da.anglesDeg[j] + w * db.anglesDeg[j];
    }
    out.front() = ka;
    out.back() = kb;
    return out;
}

// For each frame of clip c, the model's training row of that clip nearest in time.
std::vector<int> nearestRows(const gp::GpModel& m, int c) {
    const int n = m.clipAt(c).frameCount();
    std::vector<int> rows = m.rowsOfClip(c), nearest(static_cast<std::size_t>(n), -1);
    for (int f = 0; f < n; ++f) {
        int best = -1;
        for (int r : rows)
            if (best < 0 || std::abs(m.trainingFrames[static_cast<std::size_t>(r)] - f) <
                                std::abs(m.trainingFrames[static_cast<std::size_t>(best)] - f))
                best = r;
        nearest[static_cast<std::size_t>(f)] = best;
    }
    return nearest;
}

// The planted feet held on the inner frames of gap (a, b) filled with `stretch` (frames of
// `source`, mapped linearly onto the gap): a foot is held where the stretch's own capture has it
// planted (its contacts, not the warped copy's, which the warp makes slide). A run inside the gap
// keeps the foot where the filled motion has it on the run's middle frame. A run that starts on
// the gap's first inner frame continues the contact of key a: it starts where key a has the foot
// and eases (smoothstep) to that middle place by its end, so a foot the stretch plants elsewhere
// than the key does neither jumps at the key nor strands the leg; one ending on the last inner
// frame eases into key b's place likewise; one doing both moves linearly from key a's to key b's.
std::vector<SpanTarget> heldFeet(const Skeleton& sk, const std::vector<Pose>& filled, int a, int b,
                                 const ContactSet& source, const Stretch& stretch) {
    std::vector<SpanTarget> targets;
    const int L = b - a;
    for (Effector foot : {Effector::kLFoot, Effector::kRFoot}) {
        if (!sk.hasEffector(foot)) continue;
        // Held in one place only while the stretch's foot is flat (FootContact::flatAt): its ball
        // moves while the foot rolls onto its sole and pivots at toe-off.
        auto planted = [&](int i) {
            const int f = stretch.sourceFrame(i, L);
            const FootContact* c = source.at(foot, f);
            return c != nullptr && c->flatAt(f);
        };
        const auto footAt = [&](int t) { return effectorCm(sk, filled[static_cast<std::size_t>(t)], foot); };
        for (int i = 1; i < L; ++i) {
            if (!planted(i)) continue;
            int j = i;
            while (j + 1 < L && planted(j + 1)) ++j;
            const bool fromA = i == 1, toB = j == L - 1;
            const Eigen::Vector3d pa = footAt(a), pb = footAt(b), mid = footAt(a + (i + j) / 2);
            for (int k = i; k <= j; ++k) {
                // Along the run, 0 on the frame after its first and 1 on the frame after its last.
                const double along = smoothstep(static_cast<double>(k - i + 1) / (j - i + 2));
                Eigen::Vector3d p = mid;
                if (fromA && toB)
                    p = pa + (pb - pa) * (static_cast<double>(k) / L);
                else if (fromA)
                    p = pa + (mid - pa) * along;
                else if (toB)
                    p = mid + (pb - mid) * along;
                targets.push_back({a + k, foot, p, SpanTarget::Kind::kContact});
            }
            i = j;
        }
    }
    return targets;
}

double keyErrorCm(const Skeleton& sk, const Pose& a, const Pose& b) {
    FkState fa, fb;
    forwardKinematics(sk, a, fa);
    forwardKinematics(sk, b, fb);
    double worst = 0.0;
    for (std::size_t j = 0; j < fa.jointCm.size(); ++j) worst = std::max(worst, (fa.jointCm[j] - fb.jointCm[j]).norm());
    return worst;
}

}  // namespace

Pose interpolatedPose(const Skeleton& skeleton, const Pose& a, const Pose& b, double s) {
    Pose p = blendPoses(a, b, s);  // the root, and the Euler blend each joint's triple is chosen near
    for (int j = 0; j < skeleton.jointCount(); ++j) {
        const RotationOrder& order = skeleton.joints[static_cast<std::size_t>(j)].order;
        const Eigen::Quaterniond qa(eulerMatrix(a.anglesDeg[j], order)), qb(eulerMatrix(b.anglesDeg[j], order));
        p.anglesDeg[j] = fitJointAngles(qa.slerp(s, qb).toRotationMatrix(), order, kAllAxes, p.anglesDeg[j]);
    }
    return p;
}

SpanWeights heldFeetWeights() {
    SpanWeights w;
    w.target = 1000.0;
    return w;
}

std::string InbetweenJob::validate() const {
    if (!version || !version->model) return "expected a model, found none";
    const gp::GpModel& m = *version->model;
    std::string difference;
    if (!sameSkeleton(m.clip.skeleton, clip.skeleton, &difference))
        return "expected a clip of the model's skeleton, found another one (" + difference + ")";
    for (const Pose& p : clip.frames)
        if (static_cast<int>(p.anglesDeg.size()) != clip.skeleton.jointCount() || !allFinite(p))
            return "expected a clip of finite poses, found NaN, Inf or a wrong joint count";
    if (maxIterations < 1) return "expected at least one iteration, found " + std::to_string(maxIterations);
    if (const std::string problem = validateGaps(gaps, clip.frameCount()); !problem.empty()) return problem;
    if (method == InbetweenMethod::kRetrieve || method == InbetweenMethod::kPrior) {
        // The shortest stretch (time scale 0.8) with a frame before and after it must fit a clip.
        int longest = 0;
        for (int c = 0; c < m.clipCount(); ++c) longest = std::max(longest, m.clipAt(c).frameCount());
        auto fits = [&](int L) { return std::lround(L * kTimeScales[0]) + 3 <= longest; };
        int most = 0;
        while (fits(most + 1)) ++most;
        for (const InbetweenGap& g : gaps)
            if (!fits(g.b - g.a))
                return "expected gaps the model's clips can fill (keys at most " + std::to_string(most) +
                       " frames apart), found " + std::to_string(g.a + 1) + ":" + std::to_string(g.b + 1);
    }
    return "";
}

void InbetweenJob::run() {
    if (const std::string problem = validate(); !problem.empty()) throw std::invalid_argument(problem);
    const gp::GpModel& m = *version->model;
    const Skeleton& sk = m.clip.skeleton;
    frames = clip.frames;
    reports.assign(gaps.size(), {});
    x.clear();
    cancelled = false;
    using Clock = std::chrono::steady_clock;
    const bool retrieves = method == InbetweenMethod::kRetrieve || method == InbetweenMethod::kPrior;
    std::vector<MotionFeatures> sources;
    std::vector<std::vector<int>> rowOf;
    const int capture = !retrieves ? -1 : sameCapture ? *sameCapture : gp::findCapture(m, clip);
    const MotionFeatures target = retrieves ? motionFeatures(sk, clip.frames) : MotionFeatures{};
    if (retrieves)
        for (int c = 0; c < m.clipCount(); ++c) {
            rowOf.push_back(nearestRows(m, c));
            // A clip without training rows has no latent points to start from: not a source.
            const bool rows = !rowOf.back().empty() && rowOf.back().front() >= 0;
            sources.push_back(rows ? motionFeatures(sk, m.clipAt(c).frames) : MotionFeatures{});
        }
    // Cancelled: the clip as it was, nothing filled.
    const auto giveUp = [&] {
        cancelled = true;
        frames = clip.frames;
        x.clear();
    };
    // Stage 1: every gap filled by its method (the start of stage 2 for kPrior).
    x.assign(frames.size(), Eigen::VectorXd());
    std::vector<Stretch> stretches(gaps.size());
    for (std::size_t g = 0; g < gaps.size(); ++g) {
        if (cancel && cancel->load()) return giveUp();
        const auto t0 = Clock::now();
        const int a = gaps[g].a, b = gaps[g].b, L = b - a;
        GapReport& r = reports[g];
        r.gap = gaps[g];
        if (method == InbetweenMethod::kHold) {
            for (int t = a + 1; t < b; ++t)
                frames[static_cast<std::size_t>(t)] = clip.frames[static_cast<std::size_t>(a)];
        } else if (method == InbetweenMethod::kInterpolate) {
            for (int t = a + 1; t < b; ++t)
                frames[static_cast<std::size_t>(t)] =
                    interpolatedPose(sk, clip.frames[static_cast<std::size_t>(a)],
                                     clip.frames[static_cast<std::size_t>(b)], static_cast<double>(t - a) / L);
        } else {
            const Stretch& st = stretches[g] = bestStretch(sources, capture, target, a, b, clip.frameCount());
            if (st.clip < 0)
                throw std::invalid_argument("expected training clips long enough for a " + std::to_string(L) +
                                            "-frame gap, found none");
            const std::vector<Pose> warped =
                warpedStretch(sk, m.clipAt(st.clip).frames, st.first, st.last, clip.frames[static_cast<std::size_t>(a)],
                              clip.frames[static_cast<std::size_t>(b)], L);
            for (int i = 1; i < L; ++i) {
                frames[static_cast<std::size_t>(a + i)] = warped[static_cast<std::size_t>(i)];
                x[static_cast<std::size_t>(a + i)] =
                    m.X.row(rowOf[st.clip][static_cast<std::size_t>(st.sourceFrame(i, L))]).transpose();
            }
            r.sourceClip = m.clipName(st.clip);
            r.sourceFirst = st.first;
            r.sourceLast = st.last;
            r.timeScale = static_cast<double>(st.last - st.first) / L;
            r.matchCost = st.cost;
        }
        r.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    }
    // Stage 2 (kPrior): each gap as one span under the prior, planted feet held.
    if (method == InbetweenMethod::kPrior) {
        EditBase base;
        base.frames = frames;
        base.x = x;
        std::vector<ContactSet> sourceContacts;
        for (int c = 0; c < m.clipCount(); ++c) sourceContacts.push_back(detectFootContacts(m.clipAt(c)));
        for (std::size_t g = 0; g < gaps.size(); ++g) {
            if (cancel && cancel->load()) return giveUp();
            const auto t0 = Clock::now();
            const int a = gaps[g].a, b = gaps[g].b;
            GapReport& r = reports[g];
            SpanSolver solver(version, a, b, spanWeights, &base);
            std::vector<SpanTarget> held =
                heldFeet(sk, frames, a, b, sourceContacts[static_cast<std::size_t>(stretches[g].clip)], stretches[g]);
            r.heldFootFrames = static_cast<int>(held.size());
            solver.setTargets(std::move(held));
            const SpanResult res = solver.solve(maxIterations, spanTolerance, cancel);
            if (res.stop == SpanStop::kCancelled) return giveUp();
            for (int i = 0; i + 1 < b - a; ++i) {
                const std::size_t t = static_cast<std::size_t>(a + 1 + i);
                frames[t] = base.frames[t] =
                    res.poses[static_cast<std::size_t>(i)];  // a next gap joins the solved frames
                x[t] = base.x[t] = res.x[static_cast<std::size_t>(i)];
            }
            for (double e : res.targetResidualCm) r.maxHeldResidualCm = std::max(r.maxHeldResidualCm, e);
            r.stop = res.stop;
            r.iterations = res.iterations;
            r.seconds += std::chrono::duration<double>(Clock::now() - t0).count();
        }
    }
    for (std::size_t g = 0; g < gaps.size(); ++g) {
        GapReport& r = reports[g];
        const int a = gaps[g].a, b = gaps[g].b;
        r.smoothness = secondDifferences(frames, sk, a, b);
        r.reference = secondDifferences(clip.frames, sk, a, b);
        r.keyErrorCm =
            std::max(keyErrorCm(sk, frames[static_cast<std::size_t>(a)], clip.frames[static_cast<std::size_t>(a)]),
                     keyErrorCm(sk, frames[static_cast<std::size_t>(b)], clip.frames[static_cast<std::size_t>(b)]));
        if (!retrieves) continue;
        double sum = 0.0;
        Eigen::VectorXd mean;
        for (int t = a + 1; t < b; ++t) {
            double var = 0.0;
            version->posterior->predict(x[static_cast<std::size_t>(t)], mean, var);
            sum += var;
            r.maxVariance = std::max(r.maxVariance, var);
        }
        r.meanVariance = sum / (b - a - 1);
    }
}

}  // namespace mgp
