#pragma once
// Onion skins and motion trails: how an animator judges spacing while posing (docs/guide.md,
// "Onion skins", "Motion trails"). Plain scene data from poses, no GL.
//   onion skin  the frames around the current one as faded ghosts, those before in green and
//               those after in blue, fainter the further they are (Blender's onion skins, Maya's
//               ghosting); `spacing` frames apart.
//   trail       one body point (a hand, a foot, the head or the root) over a window of frames, a
//               tick on every frame, so that even spacing shows as even ticks; drawn for the
//               edited motion and, fainter and thinner beneath it, for the captured one.
#include <functional>
#include <string>
#include <vector>

#include "render/scene.h"
#include "skeleton/clip.h"
#include "skeleton/forward_kinematics.h"

namespace mgp::render {

struct OnionSkin {
    int before = 2;    // ghosts before the current frame
    int after = 2;     // ghosts after it
    int spacing = 10;  // frames from one ghost to the next (1/12 s at the CMU clips' 120 fps)
};
constexpr int kMaxOnionGhosts = 10;  // per side: more is clutter and costs the frame time
constexpr int kMaxOnionSpacing = 60;

struct OnionGhostFrame {
    int frame = 0;  // 0-based clip frame
    int step = 0;   // −before..−1 before the current frame, 1..after after it
};
// The ghosts' frames, farthest first on each side; frames outside 0..frameCount−1 are left out. Counts and spacing are
// clamped to 0..kMaxOnionGhosts and 1..kMaxOnionSpacing.
std::vector<OnionGhostFrame> onionFrames(const OnionSkin& onion, int current, int frameCount);
// The ghost of `step` (its tint by side, its opacity falling with |step|).
Figure onionGhost(const Skeleton& skeleton, const Pose& pose, int step, const OnionSkin& onion);

enum class TrailPart : int { kLHand = 0, kRHand, kLFoot, kRFoot, kHead, kRoot, kCount };
constexpr int kTrailPartCount = static_cast<int>(TrailPart::kCount);
const char* trailPartName(TrailPart part);  // lhand rhand lfoot rfoot head root
bool parseTrailPart(const std::string& name, TrailPart& out);
// Whether the skeleton has the point (the root always).
bool hasTrailPart(const Skeleton& skeleton, TrailPart part);

// `part` on frames first..last (clamped to the clip) of the motion `poseAt` gives, a tick on each
// frame and the current frame marked; `captured` draws it as the fainter, thinner reference.
// Empty if the skeleton lacks the part.
Path motionTrail(const Skeleton& skeleton, const std::function<const Pose&(int)>& poseAt, int frameCount,
                 TrailPart part, int first, int last, int current, bool captured);
// The same from each frame's forward kinematics (the editor keeps them between frames: FkMemo).
Path motionTrailFromFk(const Skeleton& skeleton, const std::function<const FkState&(int)>& fkAt, int frameCount,
                       TrailPart part, int first, int last, int current, bool captured);

// A trail cut for posing (Path::stillOverlay): the stretches before and after the current point,
// which stay put while the current frame is posed, as still overlays, and the live piece from the
// point before the current one to the point after it, with the current mark. A trail without a
// current point is one still piece.
std::vector<Path> splitForPosing(const Path& trail);
// Every path of `paths` cut so, in order (a path without a current point stays one still piece).
std::vector<Path> splitEachForPosing(const std::vector<Path>& paths);

// The stretches of `reference` that lie more than toleranceCm from `other` at the same index (each
// with its neighbouring points, so that it joins the rest), one path per stretch; none where the
// two agree everywhere. Both are trails of the same window.
std::vector<Path> differingParts(const Path& reference, const Path& other, float toleranceCm);

}  // namespace mgp::render
