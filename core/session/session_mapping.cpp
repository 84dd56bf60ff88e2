#include "session/session_mapping.h"

#include <filesystem>

#include "gp/sha256.h"
#include "io/data_paths.h"
#include "io/parse_error.h"

namespace mgp {

SessionData sessionFromDocument(const EditorDocument& doc) {
    SessionData d;
    const Clip& c = doc.clip();
    d.syntheticClip = doc.synthetic();
    if (!d.syntheticClip) {
        d.clipPath = absolutePath(c.sourcePath);
        d.skeletonPath = absolutePath(c.skeletonPath);
        std::error_code ec;
        if (!c.sourcePath.empty() && std::filesystem::is_regular_file(c.sourcePath, ec))
            d.clipSha256 = gp::sha256OfFile(c.sourcePath);  // warns on open if the clip changed since
    }
    if (const gp::ModelVersionPtr v = doc.model()) {
        d.model = *v->model;
        d.modelVersion = v->number;
    }
    if (const gp::ModelVersionPtr v = doc.compareModel()) d.compareModel = *v->model;
    d.edits = doc.edits();
    d.undoSteps = doc.history().undoSteps();
    d.redoSteps = doc.history().redoSteps();
    d.adaptiveHistory = doc.models().history();
    d.frame = doc.frame();
    for (int i = 0; i < kEffectorCount; ++i) d.pins[i] = doc.pinned(static_cast<Effector>(i));
    d.keys = doc.keys();
    d.compareMode = compareModeName(doc.compareMode());
    d.adaptiveEnabled = doc.models().adaptiveEnabled();
    if (const auto& p = doc.paths().edit()) {
        d.path.present = true;
        d.path.effector = p->effector;
        d.path.keyFrames = p->keyFrames;
        d.path.keyOffsetsCm = p->keyOffsetsCm;
        d.path.mode = p->mode;
    }
    return d;
}

CheckedSession checkSession(SessionData d, const std::string& file) {
    CheckedSession s;
    s.clip = loadSessionClip(d, file);  // none: the model carries it (both validated)
    const Clip& target = s.clip ? *s.clip : d.model->clip;
    if (d.path.present) {
        std::string problem = validatePathKeys(d.path.keyFrames, target.frameCount());
        if (problem.empty() && !target.skeleton.hasEffector(d.path.effector))
            problem =
                std::string("expected an effector of the clip's skeleton, found ") + effectorName(d.path.effector);
        if (problem.empty() && d.path.keyOffsetsCm.size() != d.path.keyFrames.size())
            problem = "expected one offset per key";
        if (!problem.empty()) throw ParseError(file + ": path: " + problem);
    }
    if (d.model) s.model = gp::ModelVersion::make(std::move(*d.model), d.modelVersion);
    if (d.compareModel) s.compareModel = gp::ModelVersion::make(std::move(*d.compareModel));
    d.model.reset();
    d.compareModel.reset();
    s.data = std::move(d);
    return s;
}

void applySession(EditorDocument& doc, CheckedSession& s, const std::string& file) {
    SessionData& d = s.data;
    if (s.model)
        doc.setModel(s.model, true);
    else
        doc.setClip(std::move(*s.clip), d.syntheticClip);
    if (s.compareModel) doc.setCompareModel(s.compareModel);
    doc.setAdaptiveEnabled(d.adaptiveEnabled);
    doc.restoreEdits(std::move(d.edits));
    doc.setFrame(d.frame);
    for (int i = 0; i < kEffectorCount; ++i) doc.setPinned(static_cast<Effector>(i), d.pins[i]);
    if (const std::string problem = doc.restoreKeys(std::move(d.keys)); !problem.empty())
        throw ParseError(file + ": keys: " + problem);
    CompareMode mode = CompareMode::kNone;
    parseCompareMode(d.compareMode, mode);  // checked when the file was read
    doc.setCompareMode(mode);
    doc.restoreHistory(std::move(d.undoSteps), std::move(d.redoSteps));
    if (doc.hasModel()) doc.restoreAdaptiveHistory(std::move(d.adaptiveHistory));
    if (d.path.present) {
        PathEdit p{d.path.effector, d.path.keyFrames, d.path.keyOffsetsCm, d.path.mode};
        if (const std::string problem = doc.paths().set(std::move(p)); !problem.empty())
            throw ParseError(file + ": path edit: " + problem);
    }
}

}  // namespace mgp
