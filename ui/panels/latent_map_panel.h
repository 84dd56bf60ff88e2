#pragma once
// The latent map: the 2-D latent space with σ²(x) as one colour texture (computed off the UI
// thread after every model change), a colour bar saying what the colour means, the training
// points coloured by frame, the active set ringed, the current latent point and its path during a
// drag, and (toggle "time path", on by default) each clip's training frames joined in time order by
// a thin line, so fragments and loops of the layout show. A model of several clips colours its
// dots by clip (the open clip's strong, the others' pale) with a legend under the map. Hover names
// the nearest training frame and its clip; clicking one jumps the timeline there, or (another clip)
// asks the app to make that clip the open one; dragging the current point poses the character
// from the model mean f(x).
#include "ui/panels/latent_map_image.h"
#include "ui/shell/editor_state.h"
#include "ui/widgets/draw_list_texture.h"

namespace mgp::ui {

class LatentMapPanel {
public:
    LatentMapPanel();
    ~LatentMapPanel();
    LatentMapPanel(const LatentMapPanel&) = delete;
    LatentMapPanel& operator=(const LatentMapPanel&) = delete;
    void draw(EditorState& state);
    // Requests the image of the current model version if not requested yet (no ImGui calls).
    void prefetch(const EditorState& state);
    bool busy() const { return worker_.busy(); }
    void waitIdle() { worker_.waitIdle(); }
    // Whether the texture shows the state's current model version.
    bool upToDate(const EditorState& state) const;
    // How many times the static layer (σ² image, time path, dots, rings) has been drawn: once per
    // model version, σ² image, map size or time-path toggle, never once per frame.
    int layerRenders() const { return layerRenders_; }
    // Changes with every new picture in the panel's textures (an upload of the σ² image, a
    // redrawn static layer): the frame signature's part for what the draw data shows by reference.
    long imageVersion() const { return imageUploads_ + layerRenders_; }
    // Window pixel of training row `row`'s dot as last drawn (false: the map has not drawn the
    // state's current model).
    bool dotPosition(const EditorState& state, int row, float& x, float& y) const;

private:
    LatentImageWorker worker_;
    LatentImage shown_;  // metadata of the uploaded image (pixels dropped after upload)
    unsigned texture_ = 0;
    long imageUploads_ = 0;
    const void* requestedModel_ = nullptr;
    int requestedVersion_ = -1;
    bool dragging_ = false;
    bool showTrajectory_ = true;
    // What the static layer (σ² image, time path, dots, rings) was drawn for. The model pointer
    // also fixes the clip colours: making another clip the working one makes a new model.
    struct StaticLayerKey {
        const void* model = nullptr;
        int version = -1;
        const void* imageModel = nullptr;
        int imageVersion = -1;
        bool hasImage = false;
        float side = 0.0f;
        bool trajectory = false;
        int frames = 0;
        bool operator==(const StaticLayerKey& o) const {
            return model == o.model && version == o.version && imageModel == o.imageModel &&
                   imageVersion == o.imageVersion && hasImage == o.hasImage && side == o.side &&
                   trajectory == o.trajectory && frames == o.frames;
        }
    };
    StaticLayerKey layerKey_;
    // Where the map was last drawn: window pixel of its top-left corner, its side and latent box.
    struct DrawnMap {
        const void* model = nullptr;
        float x0 = 0, y0 = 0, side = 0;
        double bx0 = 0, by0 = 0, bx1 = 1, by1 = 1;
    } drawn_;
    int layerRenders_ = 0;
    DrawListTexture layer_;

    // The phases of draw().
    struct MapLayout;
    struct MapPointer;
    void uploadFreshImage(EditorState& state);
    MapLayout layoutMap(const gp::GpModel& model, const std::vector<int>& colourIndex) const;
    void renderStaticLayer(EditorState& state, const StaticLayerKey& key, const gp::GpModel& model,
                           const MapLayout& map, const std::vector<int>& colourIndex);
    void paintStaticLayer(ImDrawList& dl, const StaticLayerKey& key, const gp::GpModel& model, const MapLayout& map,
                          const std::vector<int>& colourIndex) const;
    // Draws the drag path, the current latent point and the ring round the nearest dot; returns
    // the current point's pixel (far off the map when there is none).
    static ImVec2 drawLatentMarks(ImDrawList& dl, EditorDocument& doc, const gp::GpModel& model, const MapLayout& map,
                                  int nearest);
    void handleMouse(EditorState& state, const gp::GpModel& model, const MapLayout& map, const MapPointer& pointer);
    void showTooltip(EditorState& state, const gp::GpModel& model, const MapPointer& pointer) const;
    // The colour bar upright beside the map, with its range (its caption in its tooltip); returns
    // the top of the row below the map.
    float drawVarianceBar(ImDrawList& dl, const gp::GpModel& model, const MapLayout& map) const;
    // The clip legend from `top` down; returns the top of the row below it.
    static float drawClipLegend(ImDrawList& dl, EditorState& state, const MapLayout& map, float top);
};

}  // namespace mgp::ui
