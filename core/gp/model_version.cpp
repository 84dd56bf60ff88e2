#include "gp/model_version.h"

namespace mgp::gp {

std::shared_ptr<const ModelVersion> ModelVersion::make(GpModel model, int number, const ModelVersion* update) {
    auto v = std::make_shared<ModelVersion>();
    v->number = number;
    auto m = std::make_shared<const GpModel>(std::move(model));
    v->posterior = std::make_shared<const ActiveSetPosterior>(m->posterior());
    if (update) {
        v->range = update->range;
        v->capture = update->capture;
    } else {
        v->range = computeTrainingRange(*m, *v->posterior);
        v->capture = computeCaptureRange(*m);
    }
    v->model = std::move(m);
    return v;
}

}  // namespace mgp::gp
