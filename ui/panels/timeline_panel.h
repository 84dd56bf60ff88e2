#pragma once
// The timeline: scrub (click or drag on the track), play/pause (Space), step (Left/Right),
// first/last (Home/End), the current frame number and time; edited frames are marked, and so
// are an edited path's span (tinted) and keys (diamonds).
#include "ui/shell/editor_state.h"

namespace mgp::ui {

// The labelled ticks' spacing in frames: the smallest of 1, 2, 5, 10, 15, 30, 60, 120, 300 and 600
// seconds at `fps` (rounded to whole frames) whose labels are at least minGapPx apart at
// pixelsPerFrame; 600 s when none is.
int timelineMajorStep(double fps, float pixelsPerFrame, float minGapPx);
// The small ticks' spacing in frames: the finest of major/12, /10, /6, /5, /4, /3, /2 that divides
// `major` and is at least 4 px apart, else `major` (so every labelled tick is one of them).
int timelineMinorStep(int major, float pixelsPerFrame);

class TimelinePanel {
public:
    void draw(EditorState& state);
    // Advances playback by dt seconds (called once per frame by the app).
    static void advance(EditorState& state, double dt);

private:
    // While the track is held: moves the playhead, or the Shift+drag range, to mouseFrame.
    void scrub(EditorState& state, bool active, int mouseFrame);
    bool scrubbing_ = false;
    bool selecting_ = false;  // a Shift+drag selecting a range (EditorState::timelineRange)
    int rangeAnchor_ = 0;     // the frame the range drag started on
};

}  // namespace mgp::ui
