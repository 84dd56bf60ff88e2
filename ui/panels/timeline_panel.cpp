#include "ui/panels/timeline_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include "ui/widgets/widgets.h"

namespace mgp::ui {

int timelineMajorStep(double fps, float pixelsPerFrame, float minGapPx) {
    const int second = std::max(1, int(std::lround(fps)));
    int step = second;
    for (int seconds : {1, 2, 5, 10, 15, 30, 60, 120, 300, 600}) {
        step = seconds * second;
        if (step * pixelsPerFrame >= minGapPx) break;
    }
    return step;
}

int timelineMinorStep(int major, float pixelsPerFrame) {
    for (int parts : {12, 10, 6, 5, 4, 3, 2})
        if (major % parts == 0 && float(major / parts) * pixelsPerFrame >= 4.0f) return major / parts;
    return std::max(1, major);
}

void TimelinePanel::advance(EditorState& s, double dt) {
    if (!s.playing || !s.doc.hasClip() || s.doc.dragging() || s.doc.latentDragging()) return;
    s.playAccumulator += dt * s.doc.clip().fps;
    const int steps = int(std::floor(s.playAccumulator));
    if (steps <= 0) return;
    s.playAccumulator -= steps;
    const int n = s.doc.frameCount();
    s.doc.setFrame((s.doc.frame() + steps) % std::max(1, n));
}

namespace {

// The transport row: first/previous/play/next/last, the frame and time, a running fill's cancel
// button and the edit count.
void drawTimelineTransport(EditorState& s) {
    EditorDocument& doc = s.doc;
    const int n = doc.frameCount();
    const double fps = doc.clip().fps;
    if (ImGui::Button("|<")) doc.setFrame(0);
    if (ImGui::IsItemHovered()) tooltip("First frame (Home)");
    ImGui::SameLine();
    if (ImGui::Button("<")) doc.setFrame(doc.frame() - 1);
    if (ImGui::IsItemHovered()) tooltip("Previous frame (Left)");
    ImGui::SameLine();
    // Wide enough for "Pause" in any font size (HiDPI), so the row does not jump when it toggles.
    const float playW = std::max(56.0f, ImGui::CalcTextSize("Pause").x + 2.0f * ImGui::GetStyle().FramePadding.x);
    if (ImGui::Button(s.playing ? "Pause" : "Play", ImVec2(playW, 0))) s.playing = !s.playing;
    if (ImGui::IsItemHovered()) tooltip("Play / pause (Space)");
    ImGui::SameLine();
    if (ImGui::Button(">")) doc.setFrame(doc.frame() + 1);
    if (ImGui::IsItemHovered()) tooltip("Next frame (Right)");
    ImGui::SameLine();
    if (ImGui::Button(">|")) doc.setFrame(n - 1);
    if (ImGui::IsItemHovered()) tooltip("Last frame (End)");
    ImGui::SameLine();
    ImGui::Text("Frame %d / %d   %.2f s / %.2f s   %.0f fps%s", doc.frame() + 1, n, doc.frame() / fps, (n - 1) / fps,
                fps, doc.isEdited(doc.frame()) ? "   [edited]" : "");
    if (doc.filling()) {  // a fill between keys runs in the background (Edit > Fill between keys)
        ImGui::SameLine();
        const bool cancel = ImGui::Button("Cancel fill");
        s.recordControl("Cancel fill");
        if (cancel) doc.cancelRegenerate();
    }
    // The edit count on the right of the row, or left out when the row is too narrow for it
    // (a small window): never drawn over the frame text.
    char edited[48];
    std::snprintf(edited, sizeof edited, "%zu edited frame%s", doc.edits().size(), doc.edits().size() == 1 ? "" : "s");
    const float editedX =
        ImGui::GetWindowContentRegionMax().x - std::max(170.0f, ImGui::CalcTextSize(edited).x + 65.0f);
    if (editedX - ImGui::GetStyle().ItemSpacing.x >= ImGui::GetItemRectMax().x - ImGui::GetWindowPos().x) {
        ImGui::SameLine(editedX);
        ImGui::TextDisabled("%s", edited);
    }
}

// The track's rectangle and the frame <-> pixel mapping along it.
struct TimelineTrack {
    ImVec2 t0, t1;  // top-left and bottom-right corners
    float width = 0.0f, h = 0.0f;
    float pad = 8.0f;
    int n = 1;  // frames

    float xOf(int f) const { return t0.x + pad + (width - 2 * pad) * (n > 1 ? float(f) / (n - 1) : 0.0f); }
    int frameAt(float mouseX) const {
        const float u = (mouseX - t0.x - pad) / std::max(1.0f, width - 2 * pad);
        return std::clamp(int(std::lround(u * (n - 1))), 0, n - 1);
    }
};

void drawTimelineTicks(ImDrawList& dl, const TimelineTrack& t, double fps) {
    // Labelled ticks as far apart as the widest label needs (a long clip labels every few seconds
    // instead of overlapping its numbers); small ticks between them, at least 4 px apart.
    char widest[16];
    std::snprintf(widest, sizeof widest, "%d", t.n);
    const float pixelsPerFrame = (t.width - 2 * t.pad) / float(std::max(1, t.n - 1));
    const int major = timelineMajorStep(fps, pixelsPerFrame, ImGui::CalcTextSize(widest).x + 12.0f);
    const int minor = timelineMinorStep(major, pixelsPerFrame);
    for (int f = 0; f < t.n; f += minor) {
        const bool isMajor = f % major == 0;
        const float x = t.xOf(f);
        dl.AddLine(ImVec2(x, t.t1.y - (isMajor ? 12.0f : 5.0f)), ImVec2(x, t.t1.y), IM_COL32(120, 124, 132, 255));
        if (isMajor) {
            char buf[16];
            std::snprintf(buf, sizeof buf, "%d", f + 1);
            dl.AddText(ImVec2(x + 2, t.t0.y + 2), IM_COL32(150, 154, 162, 255), buf);
        }
    }
}

void drawEditedFrameMarks(ImDrawList& dl, const TimelineTrack& t, const EditorDocument& doc) {
    const auto& path = doc.paths().edit();
    if (path)  // the edited span, tinted under the edited-frame marks
        dl.AddRectFilled(ImVec2(t.xOf(path->keyFrames.front()), t.t0.y + t.h * 0.4f),
                         ImVec2(t.xOf(path->keyFrames.back()), t.t1.y - 2.0f), IM_COL32(51, 140, 242, 60));
    for (const auto& [f, rec] : doc.edits()) {
        (void)rec;
        const float x = t.xOf(f);
        dl.AddRectFilled(ImVec2(x - 1.5f, t.t0.y + t.h * 0.45f), ImVec2(x + 1.5f, t.t1.y - 2.0f),
                         IM_COL32(255, 140, 40, 255));
    }
}

void drawAnimatorKeys(ImDrawList& dl, const TimelineTrack& t, const EditorState& s) {
    // The animator's keys: a yellow diamond each at the top of the track; what a fill would
    // regenerate, tinted: the gaps inside the Shift+drag range, else the gap at the playhead.
    const EditorDocument& doc = s.doc;
    const int n = t.n;
    auto tintGap = [&](const InbetweenGap& g) {
        dl.AddRectFilled(ImVec2(t.xOf(g.a), t.t0.y + t.h * 0.2f), ImVec2(t.xOf(g.b), t.t0.y + t.h * 0.32f),
                         IM_COL32(240, 200, 60, 70));
    };
    if (s.timelineRange) {
        const int r0 = std::clamp(s.timelineRange->first, 0, n - 1), r1 = std::clamp(s.timelineRange->second, 0, n - 1);
        dl.AddRectFilled(ImVec2(t.xOf(r0) - 1.0f, t.t0.y + 1.0f), ImVec2(t.xOf(r1) + 1.0f, t.t1.y - 1.0f),
                         IM_COL32(120, 170, 255, 45));
        for (const InbetweenGap& g : doc.keyGapsIn(r0, r1)) tintGap(g);
    } else if (const std::optional<InbetweenGap> gap = doc.keyGapAt(doc.frame())) {
        tintGap(*gap);
    }
    const float yc = t.t0.y + t.h * 0.26f, r = 5.0f;
    for (int k : doc.keys()) {
        const float x = t.xOf(k);
        dl.AddQuadFilled(ImVec2(x, yc - r), ImVec2(x + r, yc), ImVec2(x, yc + r), ImVec2(x - r, yc),
                         IM_COL32(240, 200, 60, 255));
    }
}

void drawPathKeyDiamonds(ImDrawList& dl, const TimelineTrack& t, const EditorState& s) {
    const auto& path = s.doc.paths().edit();
    if (!path) return;
    // A diamond per key above the edited-frame marks (the selected key in the handle colour).
    const float yc = t.t0.y + t.h * 0.4f, r = 5.0f;
    for (std::size_t k = 0; k < path->keyFrames.size(); ++k) {
        const float x = t.xOf(path->keyFrames[k]);
        const ImU32 c = int(k) == s.selectedKey ? IM_COL32(255, 77, 56, 255) : IM_COL32(150, 200, 255, 255);
        dl.AddQuadFilled(ImVec2(x, yc - r), ImVec2(x + r, yc), ImVec2(x, yc + r), ImVec2(x - r, yc), c);
    }
}

// Draws the foot contact lanes; returns the contact under the mouse, -1 none. Each foot has two
// lanes, heel above toe: its stance (heel strike to toe-off) is a dim bar across both, and each
// point's phase a bright one on its lane, so the roll from heel to toe shows as a step.
int drawContactLanes(ImDrawList& dl, const TimelineTrack& t, const ContactSet& contacts, ImVec2 mouse) {
    // 2 px lanes: the four fit under the frame numbers of the shortest track (24 px).
    const float laneH = 2.0f, footH = 2.0f * laneH + 1.0f;
    auto footY = [&](Effector foot) {
        return t.t1.y - 2.0f - (foot == Effector::kLFoot ? 2.0f * footH + 1.0f : footH);
    };
    int hoveredContact = -1;
    for (std::size_t i = 0; i < contacts.contacts.size(); ++i) {
        const FootContact& c = contacts.contacts[i];
        const float y = footY(c.foot), x0 = t.xOf(c.first), x1 = std::max(t.xOf(c.last), x0 + 2.0f);
        dl.AddRectFilled(ImVec2(x0, y), ImVec2(x1, y + footH),
                         c.enabled ? IM_COL32(50, 110, 66, 230) : IM_COL32(80, 80, 86, 200));
        const ImU32 bright = c.enabled ? IM_COL32(90, 210, 120, 255) : IM_COL32(130, 130, 136, 220);
        auto phase = [&](const FrameRange& r, float top) {
            if (r.empty()) return;
            const float a = t.xOf(r.first), b = std::max(t.xOf(r.last), a + 2.0f);
            dl.AddRectFilled(ImVec2(a, top), ImVec2(b, top + laneH), bright);
        };
        phase(c.heel, y);
        phase(c.toe, y + laneH + 1.0f);
        if (mouse.x >= x0 && mouse.x <= x1 && mouse.y >= y - 2.0f && mouse.y <= y + footH + 2.0f)
            hoveredContact = static_cast<int>(i);
    }
    return hoveredContact;
}

// "heel 86-101, toe 90-107" (1-based frames), the phases a stance has.
std::string contactPhases(const FootContact& c) {
    std::string out;
    for (const auto& [name, r] : {std::pair<const char*, FrameRange>{"heel", c.heel}, {"toe", c.toe}}) {
        if (r.empty()) continue;
        if (!out.empty()) out += ", ";
        out += std::string(name) + " " + std::to_string(r.first + 1) + "-" + std::to_string(r.last + 1);
    }
    return out;
}

}  // namespace

void TimelinePanel::scrub(EditorState& s, bool active, int mouseFrame) {
    EditorDocument& doc = s.doc;
    if (active) {
        const int f = mouseFrame;
        if (ImGui::IsItemActivated()) {  // the press: Shift starts a range, a plain click drops it
            selecting_ = ImGui::GetIO().KeyShift;
            rangeAnchor_ = f;
            s.timelineRange.reset();
        }
        if (selecting_)
            s.timelineRange = std::make_pair(std::min(rangeAnchor_, f), std::max(rangeAnchor_, f));
        else if (f != doc.frame())
            doc.setFrame(f);
        scrubbing_ = !selecting_;
    } else {
        scrubbing_ = false;
        selecting_ = false;
    }
}

void TimelinePanel::draw(EditorState& s) {
    EditorDocument& doc = s.doc;
    if (!doc.hasClip()) {
        ImGui::TextDisabled("No clip");
        return;
    }
    const int n = doc.frameCount();
    const double fps = doc.clip().fps;
    // Transport.
    drawTimelineTransport(s);

    // Track.
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    TimelineTrack track;
    track.t0 = ImGui::GetCursorScreenPos();
    track.h = std::max(24.0f, avail.y - 2.0f);
    ImGui::InvisibleButton("##track", ImVec2(avail.x, track.h));
    s.recordControl("timeline track");
    const bool active = ImGui::IsItemActive();
    ImDrawList* dl = ImGui::GetWindowDrawList();
    track.t1 = ImVec2(track.t0.x + avail.x, track.t0.y + track.h);
    track.width = avail.x;
    track.n = n;
    const ImVec2 t0 = track.t0, t1 = track.t1;
    dl->AddRectFilled(t0, t1, IM_COL32(34, 36, 42, 255), 4.0f);
    drawTimelineTicks(*dl, track, fps);
    drawEditedFrameMarks(*dl, track, doc);
    drawAnimatorKeys(*dl, track, s);
    drawPathKeyDiamonds(*dl, track, s);
    // Foot contacts: thin heel and toe lanes per foot (left above right) at the bottom of the track,
    // green when held by regeneration, grey when switched off; right-click one to switch it. Shown
    // while they matter: a path is edited or drags spread over a span.
    static const ContactSet kNone;
    const ContactSet& contacts = doc.paths().edit() || doc.dragFalloff() > 0 ? doc.contacts() : kNone;
    const int hoveredContact = drawContactLanes(*dl, track, contacts, ImGui::GetIO().MousePos);
    if (hoveredContact >= 0 && ImGui::IsItemClicked(ImGuiMouseButton_Right)) {
        const FootContact& c = contacts.contacts[hoveredContact];
        doc.setContactEnabled(static_cast<std::size_t>(hoveredContact), !c.enabled);
    }
    const float xc = track.xOf(doc.frame());
    dl->AddLine(ImVec2(xc, t0.y), ImVec2(xc, t1.y), IM_COL32(90, 170, 255, 255), 2.0f);
    dl->AddTriangleFilled(ImVec2(xc - 6, t0.y), ImVec2(xc + 6, t0.y), ImVec2(xc, t0.y + 8),
                          IM_COL32(90, 170, 255, 255));
    // The frame under the mouse, for the tooltip and the scrub.
    const int mouseFrame = track.frameAt(ImGui::GetIO().MousePos.x);
    if (ImGui::IsItemHovered() && !active) {
        const int f = mouseFrame;
        if (hoveredContact >= 0) {
            const FootContact& c = contacts.contacts[hoveredContact];
            tooltip("%s contact, frames %d-%d (%s): %s (right-click to switch)", effectorName(c.foot), c.first + 1,
                    c.last + 1, contactPhases(c).c_str(), c.enabled ? "held when regenerating" : "off");
        } else {
            tooltip("Frame %d  (%.2f s)", f + 1, f / fps);
        }
    }
    scrub(s, active, mouseFrame);
}

}  // namespace mgp::ui
