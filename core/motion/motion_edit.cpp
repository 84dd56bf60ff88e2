#include "motion/motion_edit.h"

#include "motion/foot_contacts.h"
#include "motion/pose_layer.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "util/parallel_for.h"

namespace mgp {

std::string MotionEditJob::validate() const {
    if (!version) return "expected a model, found none";
    const int n = version->model->clip.frameCount();
    if (keyFrames.size() < 2) return "expected at least 2 key frames, found " + std::to_string(keyFrames.size());
    if (keyOffsetsCm.size() != keyFrames.size())
        return "expected one offset per key (" + std::to_string(keyFrames.size()) + "), found " +
               std::to_string(keyOffsetsCm.size());
    for (std::size_t i = 0; i < keyFrames.size(); ++i) {
        if (keyFrames[i] < 0 || keyFrames[i] >= n)
            return "expected key frames in 1.." + std::to_string(n) + ", found " + std::to_string(keyFrames[i] + 1);
        if (i > 0 && keyFrames[i] <= keyFrames[i - 1]) return "expected strictly increasing key frames";
        if (!keyOffsetsCm[i].allFinite()) return "expected finite key offsets, found NaN or Inf";
    }
    if (!version->model->clip.skeleton.hasEffector(effector))
        return std::string("expected an effector of this skeleton, found ") + effectorName(effector);
    for (Effector e : pins)
        if (!version->model->clip.skeleton.hasEffector(e))
            return std::string("expected pins on effectors of this skeleton, found ") + effectorName(e);
    for (const ContactInterval& c : heldPlaced) {
        if (!version->model->clip.skeleton.hasEffector(c.foot))
            return std::string("expected held effectors of this skeleton, found ") + effectorName(c.foot);
        if (c.first > c.last)
            return "expected held intervals first ≤ last, found " + std::to_string(c.first + 1) + ".." +
                   std::to_string(c.last + 1);
    }
    if (!(lambda > 0.0 && lambda < 1.0)) return "expected 0 < λ < 1, found " + std::to_string(lambda);
    if (base)
        if (const std::string problem = validateEditBase(*version->model, *base); !problem.empty()) return problem;
    if (!(spanWeights.locality >= 0.0) || !std::isfinite(spanWeights.locality))
        return "expected a locality ≥ 0, found " + std::to_string(spanWeights.locality);
    if (heldPose) {
        if (solver != EditSolver::kSpan) return "expected the span solver for a held pose, found the per-frame one";
        if (heldPose->frame < keyFrames.front() || heldPose->frame > keyFrames.back())
            return "expected the held frame in the span (" + std::to_string(keyFrames.front() + 1) + ".." +
                   std::to_string(keyFrames.back() + 1) + "), found " + std::to_string(heldPose->frame + 1);
        if (static_cast<int>(heldPose->pose.anglesDeg.size()) != version->model->clip.skeleton.jointCount())
            return "expected a held pose of the model's skeleton, found one with " +
                   std::to_string(heldPose->pose.anglesDeg.size()) + " joints";
        if (heldPose->x.size() != 0 && heldPose->x.size() != version->model->latentDim())
            return "expected a " + std::to_string(version->model->latentDim()) + "-D held latent point, found " +
                   std::to_string(heldPose->x.size());
        if (!heldPose->x.allFinite() || !allFinite(heldPose->pose))
            return "expected a finite held pose, found NaN or Inf";
    }
    return "";
}

const std::vector<Pose>& MotionEditJob::baseFrames() const { return base ? base->frames : version->model->clip.frames; }

std::vector<Eigen::Vector3d> MotionEditJob::capturedTrajectory() const {
    return effectorTrajectory(version->model->clip.skeleton, baseFrames(), effector);
}

std::vector<Eigen::Vector3d> editTargetPath(const std::vector<Eigen::Vector3d>& captured,
                                            const std::vector<int>& keyFrames,
                                            const std::vector<Eigen::Vector3d>& keyOffsetsCm, PathMode mode) {
    const int first = keyFrames.front(), last = keyFrames.back();
    const bool unmoved =
        std::all_of(keyOffsetsCm.begin(), keyOffsetsCm.end(), [](const Eigen::Vector3d& o) { return o.isZero(0.0); });
    if (unmoved) return {captured.begin() + first, captured.begin() + last + 1};  // no edit: the captured path
    std::vector<HermiteKey> keys;
    for (std::size_t i = 0; i < keyFrames.size(); ++i) {
        const Eigen::Vector3d p =
            mode == PathMode::kDirect ? Eigen::Vector3d(captured[keyFrames[i]] + keyOffsetsCm[i]) : keyOffsetsCm[i];
        keys.push_back({double(keyFrames[i]), p});
    }
    const HermitePath path =
        mode == PathMode::kDirect
            ? HermitePath(keys, capturedVelocity(captured, first), capturedVelocity(captured, last))
            : HermitePath(keys, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
    std::vector<Eigen::Vector3d> out;
    for (int t = first; t <= last; ++t) {
        const Eigen::Vector3d c = path.position(t);
        out.push_back(mode == PathMode::kDirect ? c : Eigen::Vector3d(captured[t] + c));
    }
    return out;
}

bool MotionEditJob::keysReached() const {
    return std::all_of(keys.begin(), keys.end(), [](const KeyResult& k) { return k.reached; });
}

const char* editSolverName(EditSolver s) { return s == EditSolver::kSpan ? "span" : "per-frame"; }

void liftPathAboveFloor(std::vector<Eigen::Vector3d>& path, double floorCm, int frames,
                        const std::vector<bool>& fixed) {
    const int n = static_cast<int>(path.size());
    auto isFixed = [&](int t) {
        return t >= 0 && t < static_cast<int>(fixed.size()) && fixed[static_cast<std::size_t>(t)];
    };
    std::vector<double> lift(path.size(), 0.0);
    for (int s = 0; s < n; ++s) {
        const double below = floorCm - path[static_cast<std::size_t>(s)].y();
        if (!(below > 0.0)) continue;
        int width = frames;  // each side's: the bump is 0 on a fixed frame
        for (int d = 1; d < width; ++d)
            if (isFixed(s - d) || isFixed(s + d)) width = d;
        for (int t = std::max(0, s - width); t <= std::min(n - 1, s + width); ++t)
            lift[static_cast<std::size_t>(t)] =
                std::max(lift[static_cast<std::size_t>(t)], below * poseLayerWeight(t, s, width));
    }
    for (int t = 0; t < n; ++t) path[static_cast<std::size_t>(t)].y() += lift[static_cast<std::size_t>(t)];
}

void MotionEditJob::run() {
    if (const std::string problem = validate(); !problem.empty()) throw std::invalid_argument(problem);
    const Clip& clip = version->model->clip;
    const std::vector<Eigen::Vector3d> target = editTargetPath(capturedTrajectory(), keyFrames, keyOffsetsCm, mode);
    const int first = keyFrames.front(), last = keyFrames.back();

    const std::vector<Pose>& start = baseFrames();
    frames = start;
    cancelled = false;
    // The floor (ContactSet::floorCm): a hand or foot is never asked below it. The keys still report
    // their distance from the path that was asked, so a key below the floor is reported missed.
    const ContactSet contactSet = contacts ? *contacts : detectFootContacts(clip);
    const bool floored = contactSet.floorCm && effector != Effector::kHead;
    solvedFrames.clear();
    pathCm.clear();
    for (int t = first + 1; t < last; ++t) {
        solvedFrames.push_back(t);
        pathCm.push_back(target[t - first]);
    }
    if (floored) {
        // The inner keys that ask for a place on or above the floor keep it (a bump would lift
        // them off it and report them missed).
        std::vector<bool> keyed(pathCm.size(), false);
        for (std::size_t k = 1; k + 1 < keyFrames.size(); ++k)
            if (const int i = keyFrames[k] - first - 1; i >= 0 && i < static_cast<int>(pathCm.size()) &&
                                                        pathCm[static_cast<std::size_t>(i)].y() >= *contactSet.floorCm)
                keyed[static_cast<std::size_t>(i)] = true;
        liftPathAboveFloor(pathCm, *contactSet.floorCm,
                           std::max(1, static_cast<int>(std::lround(kFloorLiftSeconds * clip.fps))), keyed);
    }
    results.assign(solvedFrames.size(), LearnedIkResult());
    const int count = static_cast<int>(solvedFrames.size());
    held.clear();
    // A whole-pose change's layer (EditBase::holdFrames) moves every effector, its path effector
    // too: that one's own stances in the span are held at their old place like the other feet's
    // (its path follows the layer only off them, below).
    const bool holdElsewhere = base && !base->holdFrames.empty();
    if (holdContacts) {
        for (const FootContact& c : contactSet.contacts)
            if (c.enabled && (c.foot != effector || holdElsewhere) && c.last > first && c.first < last)
                held.push_back({c.foot, c.first, c.last});
    }
    const std::size_t contactsHeld = held.size();
    for (const ContactInterval& c : heldPlaced)
        if ((c.foot != effector || holdElsewhere) && c.last > first && c.first < last) held.push_back(c);
    placedRunsHeld = static_cast<int>(held.size() - contactsHeld);
    // Held effectors per inner frame: user pins on every frame, contacts and earlier placements on
    // their frames; the edited effector is not held (except under a whole-pose layer, where its
    // holds become its path targets, below). Targets are the positions of that frame in
    // the base motion (EditBase::holdFrames when given; placements at EditBase::placedFrames when given).
    std::vector<std::vector<IkConstraint>> holds(count);
    {
        const std::vector<Effector> follow = holdElsewhere ? base->followLayer : std::vector<Effector>{};
        FkState fk;
        for (int i = 0; i < count; ++i) {
            const int t = solvedFrames[i];
            std::vector<Effector> hold;
            for (Effector e : pins)
                if (e != effector) hold.push_back(e);
            for (const ContactInterval& c : held)
                if (t >= c.first && t <= c.last) hold.push_back(c.foot);
            std::sort(hold.begin(), hold.end());
            hold.erase(std::unique(hold.begin(), hold.end()), hold.end());
            if (hold.empty()) continue;
            forwardKinematics(clip.skeleton, holdElsewhere ? base->holdFrames[static_cast<std::size_t>(t)] : start[t],
                              fk);
            for (Effector e : hold) holds[i].push_back({e, effectorCm(clip.skeleton, fk, e), true});
            if (base && !base->placedFrames.empty()) {
                forwardKinematics(clip.skeleton, base->placedFrames[static_cast<std::size_t>(t)], fk);
                for (IkConstraint& c : holds[i])
                    for (std::size_t k = contactsHeld; k < held.size(); ++k)
                        if (held[k].foot == c.effector && t >= held[k].first && t <= held[k].last)
                            c.targetCm = effectorCm(clip.skeleton, fk, c.effector);
            }
            if (!follow.empty()) {
                forwardKinematics(clip.skeleton, start[t], fk);
                for (IkConstraint& c : holds[i])
                    if (std::find(follow.begin(), follow.end(), c.effector) != follow.end())
                        c.targetCm = effectorCm(clip.skeleton, fk, c.effector);
            }
        }
        if (holdElsewhere) {
            guideHeldEnds(holds);
            // Where the path effector is held (its stances, and its guide between them) the hold
            // is its path target: one target per effector and frame.
            for (int i = 0; i < count; ++i) {
                const auto own = std::find_if(holds[i].begin(), holds[i].end(),
                                              [&](const IkConstraint& c) { return c.effector == effector; });
                if (own == holds[i].end()) continue;
                pathCm[static_cast<std::size_t>(i)] = own->targetCm;
                holds[i].erase(own);
            }
        }
    }
    if (solver == EditSolver::kSpan) {
        runSpan(holds);
    } else {
        runPerFrame(holds);
    }
    if (cancelled) {
        frames = start;
        return;
    }
    maxResidualCm = maxHeldResidualCm = 0.0;
    for (int i = 0; i < count; ++i) {
        frames[solvedFrames[i]] = results[i].pose;
        if (results[i].constraints.empty()) {
            maxResidualCm = std::numeric_limits<double>::infinity();
            continue;
        }
        maxResidualCm = std::max(maxResidualCm, results[i].constraints[0].residualCm);
        for (std::size_t k = 1; k < results[i].constraints.size(); ++k)
            maxHeldResidualCm = std::max(maxHeldResidualCm, results[i].constraints[k].residualCm);
    }
    if (heldPose) frames[heldPose->frame] = heldPose->pose;  // also when it is an end of the span
    keys.clear();
    for (std::size_t k = 1; k + 1 < keyFrames.size(); ++k) {
        const int t = keyFrames[k];
        const double error = (effectorCm(clip.skeleton, frames[t], effector) - target[t - first]).norm();
        keys.push_back({t, error, error <= kReachedToleranceCm});
    }
    std::vector<Eigen::Vector3d> path(target.begin(), target.end());
    // The report's contact travel is the planted feet's; a placement is where the animator put it.
    const std::vector<ContactInterval> contacts(held.begin(), held.begin() + static_cast<long>(contactsHeld));
    quality = measureSpan(clip, frames, first, last, effector, path, keyFrames, contacts);
}

void MotionEditJob::guideHeldEnds(std::vector<std::vector<IkConstraint>>& holds) const {
    const Clip& clip = version->model->clip;
    const std::vector<Pose>& layered = baseFrames();
    const int count = static_cast<int>(solvedFrames.size());
    // smoothstep(k / length): 0 at the anchor, 1 from `length` frames on, no kink at either end.
    auto ramp = [](int k, int length) {
        const double s = std::min(1.0, static_cast<double>(k) / static_cast<double>(length));
        return s * s * (3.0 - 2.0 * s);
    };
    // The effectors held at their old place somewhere in the span (one that follows the layer is
    // held where the layer has it: it has no old place to leave).
    const std::vector<Effector>& follow = base->followLayer;
    std::vector<Effector> effectors;
    for (const ContactInterval& c : held)
        if (std::find(effectors.begin(), effectors.end(), c.foot) == effectors.end() &&
            std::find(follow.begin(), follow.end(), c.foot) == follow.end())
            effectors.push_back(c.foot);
    FkState fk;
    for (const Effector e : effectors) {
        std::vector<char> heldHere(static_cast<std::size_t>(count)), key(static_cast<std::size_t>(count));
        for (int i = 0; i < count; ++i) {
            heldHere[i] =
                std::any_of(holds[i].begin(), holds[i].end(), [&](const IkConstraint& c) { return c.effector == e; });
            key[i] = std::find(keyFrames.begin(), keyFrames.end(), solvedFrames[i]) != keyFrames.end();
        }
        // Each run of frames between two anchors: a frame that holds `e` at its old place, or a key
        // (whose pose is given: the layered place) or the span's end.
        for (int lo = 0; lo < count;) {
            if (heldHere[lo] || key[lo]) {
                ++lo;
                continue;
            }
            int hi = lo;  // the run is lo..hi
            while (hi + 1 < count && !heldHere[hi + 1] && !key[hi + 1]) ++hi;
            const bool leftHeld = lo > 0 && heldHere[lo - 1], rightHeld = hi + 1 < count && heldHere[hi + 1];
            const int gap = hi - lo + 1;
            // Between a hold and a key the blend ends at the key at the latest; between two holds
            // each side blends over its own length and the product stays near the old path when
            // the gap is short (a short swing between the same two footprints as before). Between
            // two keys there is no old place to leave.
            if (!leftHeld && !rightHeld) {
                lo = hi + 1;
                continue;
            }
            // The old and the layered place over the run. The smoothstep adds at most 1.5·Δ/n per
            // frame, so n grows with the largest Δ until that is within the layer's speed limit.
            std::vector<Eigen::Vector3d> before(static_cast<std::size_t>(gap)), after(static_cast<std::size_t>(gap));
            double farthest = 0.0;
            for (int i = lo; i <= hi; ++i) {
                const auto t = static_cast<std::size_t>(solvedFrames[i]);
                forwardKinematics(clip.skeleton, base->holdFrames[t], fk);
                before[static_cast<std::size_t>(i - lo)] = effectorCm(clip.skeleton, fk, e);
                forwardKinematics(clip.skeleton, layered[t], fk);
                after[static_cast<std::size_t>(i - lo)] = effectorCm(clip.skeleton, fk, e);
                farthest = std::max(farthest, (after[i - lo] - before[i - lo]).norm());
            }
            const int blend = std::max(kHeldEndBlendFrames, layerBlendFrames(farthest, clip.fps));
            const int leftLength = rightHeld ? blend : std::min(blend, gap + 1);
            const int rightLength = leftHeld ? blend : std::min(blend, gap + 1);
            for (int i = lo; i <= hi; ++i) {
                const double w =
                    (leftHeld ? ramp(i - lo + 1, leftLength) : 1.0) * (rightHeld ? ramp(hi - i + 1, rightLength) : 1.0);
                const auto k = static_cast<std::size_t>(i - lo);
                holds[i].push_back({e, before[k] + w * (after[k] - before[k]), true});
            }
            lo = hi + 1;
        }
    }
}

void MotionEditJob::runSpan(const std::vector<std::vector<IkConstraint>>& holds) {
    const int first = keyFrames.front(), last = keyFrames.back();
    if (solvedFrames.empty()) return;  // adjacent end keys: nothing inside
    SpanWeights w = spanWeights;
    w.lambda = lambda;
    SpanSolver span(version, first, last, w, base.get());
    // A pose held on the span's first or last frame (a one-sided falloff on the clip's first or
    // last frame) is that end's fixed pose.
    const bool heldAtEnd = heldPose && (heldPose->frame == first || heldPose->frame == last);
    std::vector<SpanTarget> targets;
    for (std::size_t i = 0; i < solvedFrames.size(); ++i) {
        targets.push_back({solvedFrames[i], effector, pathCm[i], SpanTarget::Kind::kPath});
        for (const IkConstraint& c : holds[i])
            targets.push_back({solvedFrames[i], c.effector, c.targetCm, SpanTarget::Kind::kContact});
    }
    span.setTargets(targets);
    if (heldAtEnd) {
        if (const std::string problem = span.holdEnd(heldPose->frame, heldPose->pose); !problem.empty())
            throw std::invalid_argument(problem);  // validate() has checked what holdEnd() checks
    } else if (heldPose) {
        const Eigen::VectorXd x = heldPose->x.size() > 0 ? heldPose->x : latentStartForFrame(*version, heldPose->frame);
        if (const std::string problem = span.holdFrame(heldPose->frame, heldPose->pose, x); !problem.empty())
            throw std::invalid_argument(problem);  // validate() has checked what holdFrame() checks
    }
    const SpanResult r = span.solve(maxIterations, spanTolerance, cancel, spanMethod);
    spanStop = r.stop;
    spanIterations = r.iterations;
    if (r.stop == SpanStop::kCancelled) {
        cancelled = true;
        return;
    }
    std::size_t k = 0;
    for (std::size_t i = 0; i < solvedFrames.size(); ++i) {
        LearnedIkResult& out = results[i];
        out.pose = r.poses[i];
        out.x = r.x[i];
        out.y = r.y[i];
        out.lik = r.lik[i];
        out.iterations = r.iterations;
        out.diagnostic = spanStopName(r.stop);
        out.reached = true;
        out.constraints.clear();
        for (int j = 0; j < 1 + static_cast<int>(holds[i].size()); ++j, ++k) {
            IkConstraintResult c;
            c.effector = targets[k].effector;
            c.pin = j > 0;
            c.residualCm = r.targetResidualCm[k];
            c.reached = c.residualCm <= kReachedToleranceCm;
            out.reached = out.reached && c.reached;
            out.constraints.push_back(c);
        }
        out.converged = out.reached && r.stop == SpanStop::kConverged;
        if (framesDone) ++*framesDone;
    }
}

void MotionEditJob::runPerFrame(const std::vector<std::vector<IkConstraint>>& holds) {
    const std::vector<Pose>& start = baseFrames();
    const int count = static_cast<int>(solvedFrames.size());
    const int workers = std::max(1, std::min(resolveWorkers(threads), count));
    auto work = [&](int worker) {
        LearnedIkSolver solver(version);
        LearnedIkRequest req;
        req.lambda = lambda;
        req.maxIterations = maxIterations;
        for (int i = worker; i < count; i += workers) {  // fixed assignment: deterministic
            if (cancel && cancel->load()) return;
            const int t = solvedFrames[i];
            req.start = start[t];
            req.startX =
                base && !base->x.empty() && base->x[t].size() > 0 ? base->x[t] : latentStartForFrame(*version, t);
            req.constraints = {{effector, pathCm[i], false}};
            req.constraints.insert(req.constraints.end(), holds[i].begin(), holds[i].end());
            solver.solve(req, results[i]);
            if (framesDone) ++*framesDone;
        }
    };
    parallelFor(workers, work);
    if (cancel && cancel->load()) cancelled = true;
}

}  // namespace mgp
