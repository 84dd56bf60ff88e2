#pragma once
// The verdict the range tint and its legend show for an edited frame: the frame's own admission
// verdict, steadied over its edited neighbours so that a class held for one or two frames of a
// regenerated span does not blink (docs/maths-ik.md §5, "Steady feedback").
//
// A frame's class is natural, unusual or refused (eval/admission.h). Over the frames t−2 … t+2 that
// are edited and joined to t by edited frames, a class held by more than half of them is shown;
// with no such majority, t's own. So a class must hold for three frames of five to show, a lone
// frame or a two-frame gap takes its neighbours' class, and a ramp (natural, unusual, refused) keeps
// each frame's own class where none holds the majority.
#include <optional>
#include <vector>

#include "eval/admission.h"

namespace mgp {

enum class VerdictClass { kNatural, kUnusual, kRefused };
VerdictClass verdictClass(const AdmissionVerdict& v);
// Whether a frame judged so may show its neighbours' class: natural, unusual or unlike the captured
// data (the capture-range judgements that flicker through a span), not out of reach, through the
// floor or off balance (what a gesture did to this frame).
bool steadiable(PoseJudgement judgement);

// The class shown for `classes[self]`, given its window (at most 5 joined edited frames, in order).
VerdictClass steadyClass(const std::vector<VerdictClass>& classes, std::size_t self);

struct ShownVerdict {
    AdmissionVerdict own;  // the frame's own verdict (what the adaptive update and the readout judge)
    // Set when the window's majority differs from `own`: the verdict of the nearest frame in the
    // window with that class, judged without the model's σ² and L_IK (they are not judged).
    std::optional<AdmissionVerdict> steadied;
    int steadiedFrame = -1;   // that frame (0-based)
    int first = 0, last = 0;  // the window (0-based, inclusive)
    // What the tint and the legend's first line show.
    const AdmissionVerdict& shown() const { return steadied ? *steadied : own; }
};

}  // namespace mgp
