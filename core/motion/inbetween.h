#pragma once
// Motion from key poses: the frames strictly between two keys generated from the keys, the frames
// around them and the model's training clips (docs/maths-inbetween.md).
//
// A gap (a, b) of a clip keeps frames a and b (the keys) and everything outside a+1..b−1 bit for
// bit. The frames between are made by one of four methods:
//   kHold        the zero-velocity baseline: key a held until b;
//   kInterpolate the interpolation baseline: root translation linear, every joint's rotation
//                slerped (quaternions) from key a to key b;
//   kRetrieve    the training clips' stretch that best joins the keys (pose at both keys, velocity
//                at both joins, the distance and turn travelled between them; time scaled by up to
//                ±25 %), turned and moved onto key a, then warped onto both keys: the joints'
//                offsets fade along a smoothstep (the joins keep the stretch's velocity), the
//                root's linearly;
//   kPrior       (the default) kRetrieve, then every gap solved as one span under the learned
//                prior (motion/span_solver.h) with every foot the retrieved stretch has planted
//                held: where the key has it when the contact runs on from a key, else where the
//                stretch has it mid-contact.
// Every training stretch that overlaps the gap of the same capture is left out: the frames being
// generated are never read.
#include <atomic>
#include <optional>
#include <string>
#include <vector>

#include "gp/model_version.h"
#include "motion/motion_quality.h"
#include "motion/span_solver.h"
#include "skeleton/clip.h"

namespace mgp {

struct InbetweenGap {
    int a = 0, b = 0;  // the keys (0-based clip frames); a + 1 < b
};

// "" or what is wrong with the gaps for a clip of `frameCount` frames (each a + 1 < b inside the
// clip, in increasing order, none overlapping another's inner frames).
std::string validateGaps(const std::vector<InbetweenGap>& gaps, int frameCount);

enum class InbetweenMethod { kHold, kInterpolate, kRetrieve, kPrior };
const char* inbetweenMethodName(InbetweenMethod m);  // "hold", "interpolate", "retrieve", "prior"

// The interpolation baseline's pose at s ∈ [0, 1] between `a` and `b` (root lerp, joint slerp;
// each joint's Euler angles the triple nearest the linear blend of the two keys' angles).
Pose interpolatedPose(const Skeleton& skeleton, const Pose& a, const Pose& b, double s);

// The span weights of kPrior: the defaults with every held foot ten times stiffer (targets
// 1000 per cm²): a generated gap has no captured frame of its own to stay near, and at 100 a foot
// held through 1.5 s drifted 1.3 cm against the smoothness of the warped stretch.
SpanWeights heldFeetWeights();

struct InbetweenJob {
    // Inputs.
    gp::ModelVersionPtr version;
    Clip clip;  // the clip whose gaps are filled (the model's skeleton)
    std::vector<InbetweenGap> gaps;
    InbetweenMethod method = InbetweenMethod::kPrior;
    // The model's clip that `clip` is a take of (its frames overlapping a gap are never read), −1
    // for none; unset: gp::findCapture of `clip` (which an edited copy no longer matches).
    std::optional<int> sameCapture;
    SpanWeights spanWeights = heldFeetWeights();  // kPrior
    int maxIterations = 100;                      // kPrior: LM iterations per gap
    double spanTolerance = 1e-6;
    const std::atomic<bool>* cancel = nullptr;  // optional; run() then sets `cancelled`

    // Outputs.
    std::vector<Pose> frames;  // the whole clip, gaps filled
    // Per clip frame: the latent point of each generated frame (kRetrieve, kPrior), else empty.
    std::vector<Eigen::VectorXd> x;
    struct GapReport {
        InbetweenGap gap;
        double seconds = 0.0;
        // The retrieved stretch (kRetrieve, kPrior): source clip, its first and last frame, the
        // time scale (source frames per generated frame) and the match cost.
        std::string sourceClip;
        int sourceFirst = -1, sourceLast = -1;
        double timeScale = 1.0, matchCost = 0.0;
        SecondDifferenceStats smoothness;              // of the result, centres a..b (both joins count)
        SecondDifferenceStats reference;               // the same of the clip's own frames (where it has them)
        double keyErrorCm = 0.0;                       // largest joint distance at the two keys from the clip's
        double maxHeldResidualCm = 0.0;                // kPrior: worst held-foot target residual
        int heldFootFrames = 0;                        // kPrior: foot-frames held
        double meanVariance = 0.0, maxVariance = 0.0;  // σ²(x) along the path (kRetrieve, kPrior)
        SpanStop stop = SpanStop::kConverged;
        int iterations = 0;
    };
    std::vector<GapReport> reports;
    bool cancelled = false;

    std::string validate() const;  // "" or "expected …, found …"
    void run();                    // throws std::invalid_argument if validate() fails
};

}  // namespace mgp
