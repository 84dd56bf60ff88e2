#pragma once
// The Model panel (clip facts, model facts, training with progress/ETA/Cancel, open/save, the
// adaptive update switch), the model's details (a tab beside the IK readout: the compare ghost and
// the model's numbers) and the IK readout (per-target residual in cm, reached or not, σ²(x), L_IK).
#include "ui/shell/editor_state.h"

namespace mgp::ui {

void drawModelPanel(EditorState& state);
// The training options (kernel, M, T, S, C; the prior in the tooltip), clamped to sane ranges:
// the Model panel's Train and Model ▸ Train on clips… share them (EditorState::trainOptions).
void drawTrainOptions(gp::TrainOptions& options);
void drawIkReadout(EditorState& state);
// The model's details, each a collapsible section: α, γ, η, β and the noise σ (open), the W summary,
// the training convergence plot and the history of adaptive updates.
void drawModelDetails(EditorState& state);

}  // namespace mgp::ui
