#pragma once
// Clip: one motion (skeleton + per-frame poses) as loaded from ASF/AMC, BVH or made by the
// synthetic generator. Frames are indexed from 0 here; the CLI counts them from 1.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "skeleton/pose_layout.h"
#include "skeleton/skeleton.h"

namespace mgp {

enum class ClipFormat { kAmc, kBvh, kSynthetic, kGltf };
const char* clipFormatName(ClipFormat f);

struct Clip {
    std::string name;          // e.g. "35_01"
    std::string sourcePath;    // the AMC/BVH file ("" for synthetic)
    std::string skeletonPath;  // the ASF file (AMC only)
    ClipFormat format = ClipFormat::kAmc;
    std::string convention;  // "cmu-asf", "cgspeed-daz", "cgspeed-motionbuilder", ...
    double fps = 120.0;
    double cmPerFileUnit = 1.0;  // how source lengths were scaled to cm
    Skeleton skeleton;
    std::vector<Pose> frames;
    long long firstFrameLabel = 1;            // the file's own number of frame 0 (AMC), else 1
    bool restFrame = false;                   // frame 0 is a converter-added rest/T-pose (BVH)
    std::vector<std::string> unmappedJoints;  // source joints with no ASF bone role

    int frameCount() const { return static_cast<int>(frames.size()); }
    // The first frame of motion: 1 past a rest frame (unless it is all there is), else 0. A rest
    // frame is no evidence of where the ground is.
    int firstMotionFrame() const { return restFrame && frames.size() > 1 ? 1 : 0; }
};

// Frames [first, first + count) of `from` appended to `into` (same skeleton: same joint count,
// else std::invalid_argument). An empty `into` takes `from`'s metadata and skeleton first, and
// keeps restFrame only if the slice starts at from's frame 0.
void appendFrames(Clip& into, const Clip& from, int first, int count);

// Unwraps each column over time (docs/maths.md §2.5): when a frame-to-frame change exceeds 180°
// in magnitude, add or subtract 360° to that frame and every later one.
void unwrapAngles(Eigen::MatrixXd& anglesByFrame);

// The N×P pose matrix Y (P = PoseLayout(clip.skeleton).size(): 47 for ASF), degrees, unwrapped
// over time (docs/maths.md §2.5).
Eigen::MatrixXd poseMatrix(const Clip& clip);
// Writes the unwrapped pose-vector angles back into the clip's frames, so its poses equal the rows of
// poseMatrix() (a model's clip must match its training data; FK is unchanged by 360° shifts).
void unwrapClip(Clip& clip);
// Root translations, N×3, cm.
Eigen::MatrixXd rootTranslations(const Clip& clip);

// Columns whose population standard deviation is ≤ tolDeg (docs/maths.md §5, step 2),
// ascending.
std::vector<int> constantColumns(const Eigen::MatrixXd& y, double tolDeg = 1e-6);

}  // namespace mgp
