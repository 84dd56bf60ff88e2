#include "ui/panels/latent_map_panel.h"

#include <GL/gl.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "eval/layout_quality.h"
#include "ui/widgets/widgets.h"

namespace mgp::ui {

namespace {
constexpr float kBarWidth = 10.0f;  // the upright colour bar beside the map

ImU32 mapColour(double t, int alpha = 255) {
    std::uint8_t rgb[3];
    colourMap(t, rgb);
    return IM_COL32(rgb[0], rgb[1], rgb[2], alpha);
}
// Training points: coloured by frame along a hue ramp (blue at the first frame -> green -> yellow
// at the last), light so they stand out on the dark (uncertain) background.
ImU32 frameColour(double t) {
    float r, g, b;
    ImGui::ColorConvertHSVtoRGB(float(0.60 - 0.50 * std::clamp(t, 0.0, 1.0)), 0.65f, 1.0f, r, g, b);
    return ImGui::ColorConvertFloat4ToU32(ImVec4(r, g, b, 1.0f));
}
// The time path's pairs: each clip's rows joined in its own frame order, never across clips.
std::vector<std::pair<int, int>> clipPairs(const gp::GpModel& model) {
    if (model.clipCount() == 1) return eval::timeConsecutivePairs(model.trainingFrames);
    std::vector<std::pair<int, int>> all;
    for (int c = 0; c < model.clipCount(); ++c) {
        const std::vector<int> rows = model.rowsOfClip(c);
        std::vector<int> frames;
        for (int i : rows) frames.push_back(model.trainingFrames[static_cast<std::size_t>(i)]);
        for (auto [a, b] : eval::timeConsecutivePairs(frames))
            all.emplace_back(rows[static_cast<std::size_t>(a)], rows[static_cast<std::size_t>(b)]);
    }
    return all;
}
// A model of several clips: each clip's colour index is its name's rank among the clips' names,
// so a clip keeps its colour when another one becomes the open (primary) clip.
std::vector<int> clipColourIndices(const gp::GpModel& model) {
    std::vector<int> order(static_cast<std::size_t>(model.clipCount()));
    for (int c = 0; c < model.clipCount(); ++c) order[static_cast<std::size_t>(c)] = c;
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return model.clipName(a) < model.clipName(b); });
    std::vector<int> index(order.size());
    for (std::size_t r = 0; r < order.size(); ++r) index[static_cast<std::size_t>(order[r])] = int(r);
    return index;
}
// Clip colours: well separated hues (blue, orange, green, magenta, yellow, cyan, red, violet,
// then the same shifted); the frame within the clip brightens the dot from its first frame to its
// last. The open clip's dots are saturated and opaque, the other clips' paler and translucent.
ImU32 clipColour(int colourIndex, double t, bool open) {
    static const float kHues[] = {0.58f, 0.07f, 0.33f, 0.85f, 0.15f, 0.48f, 0.0f, 0.72f};
    const float hue = std::fmod(kHues[colourIndex % 8] + 0.04f * float(colourIndex / 8), 1.0f);
    const float u = float(std::clamp(t, 0.0, 1.0));
    float r, g, b;
    ImGui::ColorConvertHSVtoRGB(hue, open ? 0.8f : 0.55f, open ? 0.65f + 0.35f * u : 0.5f + 0.3f * u, r, g, b);
    return ImGui::ColorConvertFloat4ToU32(ImVec4(r, g, b, open ? 1.0f : 0.85f));
}
std::string hexColour(ImU32 c) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "#%02X%02X%02X", unsigned(c & 0xFF), unsigned((c >> 8) & 0xFF),
                  unsigned((c >> 16) & 0xFF));
    return buf;
}
}  // namespace

LatentMapPanel::LatentMapPanel() = default;

LatentMapPanel::~LatentMapPanel() {
    if (texture_) glDeleteTextures(1, &texture_);
}

bool LatentMapPanel::dotPosition(const EditorState& s, int row, float& x, float& y) const {
    const gp::ModelVersionPtr v = s.doc.model();
    if (!v || v->model.get() != drawn_.model || row < 0 || row >= v->model->N()) return false;
    const gp::GpModel& m = *v->model;
    x = float(drawn_.x0 + (m.X(row, 0) - drawn_.bx0) / (drawn_.bx1 - drawn_.bx0) * drawn_.side);
    y = float(drawn_.y0 +
              (drawn_.by1 - (m.latentDim() > 1 ? m.X(row, 1) : 0.0)) / (drawn_.by1 - drawn_.by0) * drawn_.side);
    return true;
}

bool LatentMapPanel::upToDate(const EditorState& s) const {
    const gp::ModelVersionPtr v = s.doc.model();
    return v && shown_.model == v->model.get() && shown_.version == v->number;
}

void LatentMapPanel::prefetch(const EditorState& s) {
    const gp::ModelVersionPtr v = s.doc.model();
    if (!v) return;
    if (requestedModel_ != v->model.get() || requestedVersion_ != v->number) {
        worker_.request(v);
        requestedModel_ = v->model.get();
        requestedVersion_ = v->number;
    }
}

// ---- The phases of LatentMapPanel::draw ----------------------------------------------------------

// The map's place on screen: a square map, the colour bar below it (and, for a model of several
// clips, the clip legend under that), and the latent box the square shows.
struct LatentMapPanel::MapLayout {
    struct LegendEntry {
        std::string name, label;
        ImU32 colour;
        float width;
    };
    std::vector<LegendEntry> legend;  // a swatch and the clip's name per clip, flowed into legendRows rows
    int legendRows = 0;
    ImVec2 avail;
    float lineH = 0.0f;
    ImVec2 cur, p0, p1;  // the content's top-left corner; the map square's corners
    float side = 0.0f;
    double bx0 = 0, by0 = 0, bx1 = 1, by1 = 1;

    ImVec2 toScreen(double lx, double ly) const {
        return ImVec2(float(p0.x + (lx - bx0) / (bx1 - bx0) * side), float(p0.y + (by1 - ly) / (by1 - by0) * side));
    }
    ImVec2 rowToScreen(const gp::GpModel& model, int i) const {
        return toScreen(model.X(i, 0), model.latentDim() > 1 ? model.X(i, 1) : 0.0);
    }
    Eigen::VectorXd toLatent(const gp::GpModel& model, ImVec2 p) const {
        Eigen::VectorXd x = latentMapBase(model);
        x[0] = bx0 + (p.x - p0.x) / side * (bx1 - bx0);
        if (x.size() > 1) x[1] = by1 - (p.y - p0.y) / side * (by1 - by0);
        return x;
    }
    // The training row whose dot is nearest the mouse within 7 pixels, -1 none.
    int nearestRow(const gp::GpModel& model, ImVec2 mouse) const {
        int nearest = -1;
        float nearestD2 = 7.0f * 7.0f;
        for (int i = 0; i < model.N(); ++i) {
            const ImVec2 p = rowToScreen(model, i);
            const float d2 = (p.x - mouse.x) * (p.x - mouse.x) + (p.y - mouse.y) * (p.y - mouse.y);
            if (d2 < nearestD2) {
                nearestD2 = d2;
                nearest = i;
            }
        }
        return nearest;
    }
};

// The mouse over the map this frame.
struct LatentMapPanel::MapPointer {
    bool hovered = false;
    ImVec2 mouse;
    int nearest = -1;              // the training row under the mouse
    ImVec2 current{-1e6f, -1e6f};  // the current latent point on screen
    float currentD2 = 0.0f;        // squared pixel distance from the mouse to it
};

namespace {
// The training dots' colours. A multi-clip model: rows of the open clip (the model's primary
// clip, clip 0) are frames of the open clip; every clip's dots take that clip's colour, its frame
// within the clip brightening it (clipColour).
struct LatentDotColours {
    const gp::GpModel& model;
    const std::vector<int>& colourIndex;
    int clips;
    int frames;
    bool rowsKnown;

    int frameOfRow(int i) const { return i < int(model.trainingFrames.size()) ? model.trainingFrames[i] : 0; }
    ImU32 operator()(int i) const {
        if (clips == 1) return frameColour(double(frameOfRow(i)) / frames);
        const int c = rowsKnown ? model.rowClip(i) : 0;
        return clipColour(colourIndex[std::size_t(c)],
                          double(frameOfRow(i)) / std::max(1, model.clipAt(c).frameCount() - 1), c == 0);
    }
};
}  // namespace

void LatentMapPanel::uploadFreshImage(EditorState& s) {
    LatentImage fresh;
    if (!worker_.take(fresh)) return;
    const PhaseTimer timer(s.profile, s.profile.latentUploadSeconds);
    if (!texture_) glGenTextures(1, &texture_);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, fresh.size, fresh.size, 0, GL_RGBA, GL_UNSIGNED_BYTE, fresh.rgba.data());
    ++imageUploads_;
    fresh.rgba.clear();
    fresh.rgba.shrink_to_fit();
    shown_ = std::move(fresh);
}

LatentMapPanel::MapLayout LatentMapPanel::layoutMap(const gp::GpModel& model,
                                                    const std::vector<int>& colourIndex) const {
    MapLayout m;
    // A model of several clips: a legend (a swatch and the clip's name per clip, flowed into rows)
    // goes under the colour bar; the map gives up the legend's height.
    const int clips = model.clipCount();
    m.avail = ImGui::GetContentRegionAvail();
    m.lineH = ImGui::GetTextLineHeight();
    if (clips > 1) {
        float x = 0.0f;
        m.legendRows = 1;
        for (int c = 0; c < clips; ++c) {
            MapLayout::LegendEntry e{model.clipName(c), model.clipName(c) + (c == 0 ? " (open)" : ""),
                                     clipColour(colourIndex[std::size_t(c)], 1.0, true), 0.0f};
            e.width = m.lineH + 4.0f + ImGui::CalcTextSize(e.label.c_str()).x + 14.0f;
            if (x > 0.0f && x + e.width > m.avail.x) ++m.legendRows, x = 0.0f;
            x += e.width;
            m.legend.push_back(std::move(e));
        }
    }
    // Geometry: a square map with the colour bar upright at its right (its range beside it, its
    // caption in its tooltip), then the "x1" line, the clip legend and the time-path row below:
    // the panel's height goes to the map, which the right column is short of.
    const float below = m.lineH + 4.0f + float(m.legendRows) * (m.lineH + 4.0f) + ImGui::GetFrameHeightWithSpacing();
    const float barRoom = 18.0f + kBarWidth + 6.0f + ImGui::CalcTextSize("0.0e-00").x;
    // Whole pixels, so that the static layer's texels land on screen pixels one to one.
    m.side = std::floor(std::max(64.0f, std::min(m.avail.x - 16.0f - barRoom, m.avail.y - below - 2.0f)));
    m.cur = ImVec2(std::floor(ImGui::GetCursorScreenPos().x), std::floor(ImGui::GetCursorScreenPos().y));
    m.p0 = ImVec2(m.cur.x + 16.0f, m.cur.y);
    m.p1 = ImVec2(m.p0.x + m.side, m.p0.y + m.side);
    if (shown_.size > 0) {
        m.bx0 = shown_.x0, m.by0 = shown_.y0, m.bx1 = shown_.x1, m.by1 = shown_.y1;
    } else {
        latentBox(model, 0.15, m.bx0, m.by0, m.bx1, m.by1);
    }
    return m;
}

void LatentMapPanel::renderStaticLayer(EditorState& s, const StaticLayerKey& key, const gp::GpModel& model,
                                       const MapLayout& map, const std::vector<int>& colourIndex) {
    const PhaseTimer timer(s.profile, s.profile.latentUploadSeconds);
    layer_.render(map.p0, ImVec2(map.side, map.side),
                  [&](ImDrawList& dl) { paintStaticLayer(dl, key, model, map, colourIndex); });
    layerKey_ = key;
    ++layerRenders_;
}

void LatentMapPanel::paintStaticLayer(ImDrawList& dl, const StaticLayerKey& key, const gp::GpModel& model,
                                      const MapLayout& map, const std::vector<int>& colourIndex) const {
    const int clips = model.clipCount();
    const bool rowsKnown = model.trainingFrames.size() == static_cast<std::size_t>(model.N());
    const LatentDotColours dotColour{model, colourIndex, clips, key.frames, rowsKnown};
    if (key.hasImage)
        dl.AddImage(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(texture_)), map.p0, map.p1);
    else
        dl.AddRectFilled(map.p0, map.p1, IM_COL32(40, 40, 48, 255));
    // The training frames joined in time order (thin line under the dots): a continuous
    // layout is one curve per motion, a fragmented one shows long jumps across the map.
    if (showTrajectory_)
        for (const auto& [a, b] : rowsKnown ? clipPairs(model) : std::vector<std::pair<int, int>>{})
            dl.AddLine(map.rowToScreen(model, a), map.rowToScreen(model, b), IM_COL32(235, 235, 240, 120), 1.0f);
    // Training points coloured by frame (several clips: by clip), active set ringed. The
    // other clips' dots go first and smaller, so the open clip's stay on top.
    if (clips > 1)
        for (int i = 0; i < model.N(); ++i)
            if (rowsKnown && model.rowClip(i) != 0) dl.AddCircleFilled(map.rowToScreen(model, i), 1.9f, dotColour(i));
    for (int i = 0; i < model.N(); ++i)
        if (clips == 1 || !rowsKnown || model.rowClip(i) == 0)
            dl.AddCircleFilled(map.rowToScreen(model, i), 2.3f, dotColour(i));
    for (int i : model.active) {
        if (i < 0 || i >= model.N()) continue;
        dl.AddCircle(map.rowToScreen(model, i), 4.2f, IM_COL32(255, 255, 255, 170), 10, 1.0f);
    }
}

ImVec2 LatentMapPanel::drawLatentMarks(ImDrawList& dl, EditorDocument& doc, const gp::GpModel& model,
                                       const MapLayout& map, int nearest) {
    // Path of the current/last drag and the current latent point.
    const auto& path = doc.latentPath();
    for (std::size_t k = 1; k < path.size(); ++k)
        dl.AddLine(map.toScreen(path[k - 1][0], path[k - 1].size() > 1 ? path[k - 1][1] : 0.0),
                   map.toScreen(path[k][0], path[k].size() > 1 ? path[k][1] : 0.0), IM_COL32(255, 70, 70, 230), 2.0f);
    const Eigen::VectorXd xc = doc.currentLatent();
    ImVec2 pc(-1e6f, -1e6f);
    if (xc.size() > 0 && xc.allFinite()) {
        pc = map.toScreen(xc[0], xc.size() > 1 ? xc[1] : 0.0);
        dl.AddCircleFilled(pc, 6.0f, IM_COL32(255, 60, 60, 255));
        dl.AddCircle(pc, 6.5f, IM_COL32(255, 255, 255, 255), 16, 1.5f);
    }
    if (nearest >= 0) dl.AddCircle(map.rowToScreen(model, nearest), 6.0f, IM_COL32(255, 230, 60, 255), 16, 2.0f);
    return pc;
}

void LatentMapPanel::handleMouse(EditorState& s, const gp::GpModel& model, const MapLayout& map,
                                 const MapPointer& pointer) {
    EditorDocument& doc = s.doc;
    const int nearest = pointer.nearest;
    if (pointer.hovered && ImGui::IsMouseClicked(0)) {
        if (pointer.currentD2 <= 9.0f * 9.0f && doc.beginLatentDrag()) {
            dragging_ = true;
            s.playing = false;
        } else if (nearest >= 0 && nearest < int(model.trainingFrames.size())) {
            const int c = model.rowClip(nearest);
            if (c == 0) {
                doc.setFrame(model.trainingFrames[nearest]);
                s.setStatus("jumped to frame " + std::to_string(model.trainingFrames[nearest] + 1));
            } else {  // another clip: the app switches clips (asking first about unsaved changes)
                s.request("model-clip", {model.clipName(c), std::to_string(model.trainingFrames[nearest] + 1)});
            }
        }
    }
    if (dragging_) {
        if (!ImGui::IsMouseDown(0)) {
            doc.endLatentDrag();
            dragging_ = false;
            s.setStatus("posed frame " + std::to_string(doc.frame() + 1) + " from the model mean");
        } else if (ImGui::GetIO().MouseDelta.x != 0.0f || ImGui::GetIO().MouseDelta.y != 0.0f) {
            doc.latentDragTo(map.toLatent(model, pointer.mouse));
        }
    }
}

void LatentMapPanel::showTooltip(EditorState& s, const gp::GpModel& model, const MapPointer& pointer) const {
    const int nearest = pointer.nearest;
    if (nearest >= 0 && !dragging_) {
        s.hoveredTrainingRow = nearest;
        const int frame = nearest < int(model.trainingFrames.size()) ? model.trainingFrames[nearest] : -1;
        const int c = model.rowClip(nearest);
        tooltip(
            "Nearest training pose: %s frame %d\nlatent (%.3f, %.3f)%s\nClick: %s", model.clipName(c).c_str(),
            frame + 1, model.X(nearest, 0), model.latentDim() > 1 ? model.X(nearest, 1) : 0.0,
            std::find(model.active.begin(), model.active.end(), nearest) != model.active.end() ? "  [active set]" : "",
            c == 0 ? "go to this frame" : "open this clip at this frame (the model stays)");
    } else if (pointer.hovered && pointer.currentD2 <= 81.0f && !dragging_) {
        tooltip("Current latent point: drag to pose from the model mean");
    }
}

float LatentMapPanel::drawVarianceBar(ImDrawList& dl, const gp::GpModel& model, const MapLayout& map) const {
    // Upright at the map's right: confident (small σ², yellow) at the top.
    const ImVec2 b0(map.p1.x + 18.0f, map.p0.y), b1(map.p1.x + 18.0f + kBarWidth, map.p1.y);
    const int segs = 48;
    for (int k = 0; k < segs; ++k) {
        const float ya = b0.y + (b1.y - b0.y) * k / segs, yb = b0.y + (b1.y - b0.y) * (k + 1) / segs;
        const ImU32 top = mapColour(1.0 - double(k) / segs), bottom = mapColour(1.0 - double(k + 1) / segs);
        dl.AddRectFilledMultiColor(ImVec2(b0.x, ya), ImVec2(b1.x, yb), top, top, bottom, bottom);
    }
    dl.AddRect(b0, b1, IM_COL32(120, 124, 132, 255));
    // Words on the bar, the numbers in its tooltip (the animator reads "sure", not σ²).
    dl.AddText(ImVec2(b1.x + 6.0f, b0.y), IM_COL32(210, 210, 215, 255), "sure");
    dl.AddText(ImVec2(b1.x + 6.0f, b1.y - map.lineH), IM_COL32(210, 210, 215, 255), "unsure");
    // With d = 3 the map is a slice (latentMapBase): say which.
    char slice[64] = "";
    if (model.latentDim() > 2)
        std::snprintf(slice, sizeof slice, "; x1, x2 at x3 = %.2f (mean)", latentMapBase(model)[2]);
    if (ImGui::IsMouseHoveringRect(b0, ImVec2(b1.x + 6.0f + ImGui::CalcTextSize("unsure").x, b1.y))) {
        if (shown_.size)
            tooltip(
                "how sure the model is of the pose at each point: predictive variance sigma^2(x) from %.2g "
                "(top, bright) to %.2g (bottom), log scale%s",
                std::exp(shown_.minLogVar), std::exp(shown_.maxLogVar), slice);
        else
            tooltip("how sure the model is of the pose at each point (predictive variance): being computed");
    }
    return map.p1.y + map.lineH + 4.0f;
}

float LatentMapPanel::drawClipLegend(ImDrawList& dl, EditorState& s, const MapLayout& map, float top) {
    // The clip legend: a swatch in the clip's colour and its name, the open clip marked.
    const float lineH = map.lineH;
    const ImVec2 cur = map.cur;
    s.clipLegend.clear();
    float lx = cur.x, ly = top;
    for (const MapLayout::LegendEntry& e : map.legend) {
        if (lx > cur.x && lx + e.width > cur.x + map.avail.x) lx = cur.x, ly += lineH + 4.0f;
        dl.AddRectFilled(ImVec2(lx, ly + 1.0f), ImVec2(lx + lineH, ly + 1.0f + lineH), e.colour);
        dl.AddText(ImVec2(lx + lineH + 4.0f, ly + 1.0f), IM_COL32(210, 210, 215, 255), e.label.c_str());
        s.controls["clip legend " + e.name] = {lx, ly + 1.0f, lx + lineH, ly + 1.0f + lineH, true};
        s.clipLegend += e.name + " " + hexColour(e.colour) + (e.label.size() > e.name.size() ? " (open)" : "") + "\n";
        lx += e.width;
    }
    if (map.legendRows > 0) ly += lineH + 4.0f;
    return ly;
}

void LatentMapPanel::draw(EditorState& s) {
    EditorDocument& doc = s.doc;
    const gp::ModelVersionPtr v = doc.model();
    s.hoveredTrainingRow = -1;
    if (!v) {
        ImGui::TextWrapped("No model yet. Train one in the Model panel (Ctrl+T) or open a model file (Ctrl+M).");
        return;
    }
    const gp::GpModel& model = *v->model;
    prefetch(s);
    uploadFreshImage(s);
    const std::vector<int> colourIndex = clipColourIndices(model);
    const MapLayout map = layoutMap(model, colourIndex);

    ImGui::SetCursorScreenPos(map.p0);
    ImGui::InvisibleButton("##latentmap", ImVec2(map.side, map.side));
    s.recordControl("latent map");
    MapPointer pointer;
    pointer.hovered = ImGui::IsItemHovered();
    pointer.mouse = ImGui::GetIO().MousePos;
    const int frames = std::max(1, doc.frameCount() - 1);

    // What changes only with the model, the σ² image or the map's size is drawn once into a
    // texture (the static layer); each frame adds the moving parts on top.
    const StaticLayerKey key{
        v->model.get(), v->number,       shown_.model, shown_.version, texture_ != 0 && shown_.size > 0,
        map.side,       showTrajectory_, frames};
    if (!(key == layerKey_)) renderStaticLayer(s, key, model, map, colourIndex);
    ImDrawList* dl = ImGui::GetWindowDrawList();
    layer_.draw(*dl, map.p0, map.p1);
    drawn_ = {v->model.get(), map.p0.x, map.p0.y, map.side, map.bx0, map.by0, map.bx1, map.by1};
    dl->PushClipRect(map.p0, map.p1, true);
    if (pointer.hovered) pointer.nearest = map.nearestRow(model, pointer.mouse);
    pointer.current = drawLatentMarks(*dl, doc, model, map, pointer.nearest);
    dl->PopClipRect();
    dl->AddRect(map.p0, map.p1, IM_COL32(120, 124, 132, 255));
    dl->AddText(ImVec2(map.p0.x + map.side * 0.5f - 8.0f, map.p1.y + 1.0f), IM_COL32(200, 200, 205, 255), "x1");
    dl->AddText(ImVec2(map.cur.x, map.p0.y + map.side * 0.5f - 7.0f), IM_COL32(200, 200, 205, 255), "x2");

    // Interaction: drag the current point (pose from the model mean), click a training point.
    const ImVec2 pc = pointer.current, mouse = pointer.mouse;
    pointer.currentD2 = (pc.x - mouse.x) * (pc.x - mouse.x) + (pc.y - mouse.y) * (pc.y - mouse.y);
    handleMouse(s, model, map, pointer);
    showTooltip(s, model, pointer);

    // Colour bar, then the clip legend, then the time-path toggle.
    const float ly = drawClipLegend(*dl, s, map, drawVarianceBar(*dl, model, map));
    ImGui::SetCursorScreenPos(ImVec2(map.cur.x, ly));
    ImGui::Checkbox("time path", &showTrajectory_);
    if (ImGui::IsItemHovered()) tooltip("Join the training frames in time order");
    ImGui::SameLine();
    if (!upToDate(s))
        ImGui::TextDisabled("updating variance image...");
    else
        ImGui::TextDisabled("bright: confident  rings: active");
}

}  // namespace mgp::ui
