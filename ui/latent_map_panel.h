#pragma once
// The latent map: the 2-D latent space with σ²(x) as one colour texture (computed off the UI
// thread after every model change), a colour bar saying what the colour means, the training
// points coloured by frame, the active set ringed, the current latent point and its path during a
// drag, and (toggle "time path", on by default) each clip's training frames joined in time order by
// a thin line, so fragments and loops of the layout show. Hover names the nearest training frame; clicking a training point jumps the timeline
// there; dragging the current point poses the character from the model mean f(x).
#include "draw_list_texture.h"
#include "editor_state.h"
#include "latent_map_image.h"

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

private:
    LatentImageWorker worker_;
    LatentImage shown_;  // metadata of the uploaded image (pixels dropped after upload)
    unsigned texture_ = 0;
    const void* requestedModel_ = nullptr;
    int requestedVersion_ = -1;
    bool dragging_ = false;
    bool showTrajectory_ = true;
    // What the static layer (σ² image, time path, dots, rings) was drawn for.
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
            return model == o.model && version == o.version && imageModel == o.imageModel && imageVersion == o.imageVersion &&
                   hasImage == o.hasImage && side == o.side && trajectory == o.trajectory && frames == o.frames;
        }
    };
    StaticLayerKey layerKey_;
    int layerRenders_ = 0;
    DrawListTexture layer_;
};

}  // namespace mgp::ui
