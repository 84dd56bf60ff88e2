#include "session/session_file.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <set>

#include "gp/model_file.h"
#include "gp/sha256.h"
#include "io/atomic_file.h"
#include "io/clip_loader.h"
#include "io/data_paths.h"
#include "io/parse_error.h"
#include "io/text_reader.h"
#include "skeleton/synthetic_clip.h"

namespace mgp {

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

constexpr int kMaxSyntheticFrames = 1000000;  // ~2.3 h at 120 fps; the editor uses 240

// ---- writing -----------------------------------------------------------------------------------

json vec3Json(const Eigen::Vector3d& v) { return json::array({v.x(), v.y(), v.z()}); }

// An edit without its frame (the caller adds "frame" where the format has it).
json editJson(const EditRecord& rec) {
    json angles = json::array();
    for (const auto& a : rec.pose.anglesDeg) angles.push_back(vec3Json(a));
    json x = json::array();
    for (Eigen::Index i = 0; i < rec.x.size(); ++i) x.push_back(rec.x[i]);
    json out = {{"root_cm", vec3Json(rec.pose.rootCm)}, {"angles_deg", angles}, {"x", x}};
    // Optional (older sessions have none): the effectors the edit put where the animator asked.
    if (!rec.moved.empty()) {
        out["moved"] = json::array();
        for (Effector e : rec.moved) out["moved"].push_back(effectorName(e));
    }
    return out;
}

json frameEditsJson(const FrameEdits& frames) {
    json out = json::array();
    for (const auto& [frame, record] : frames)
        out.push_back({{"frame", frame}, {"edit", record ? editJson(*record) : json(nullptr)}});
    return out;
}

json stepJson(const EditStep& step) {
    return {{"label", step.label}, {"before", frameEditsJson(step.before)}, {"after", frameEditsJson(step.after)}};
}

json modelJson(const std::optional<gp::GpModel>& m) { return m ? json::parse(gp::modelToJsonText(*m)) : json(nullptr); }

std::string relativeTo(const std::string& absPath, const fs::path& dir) {
    return absPath.empty() ? absPath : fs::path(absPath).lexically_relative(dir).string();
}

// ---- reading: every accessor names the field and throws ParseError ------------------------------

std::string describe(const json& j) {
    switch (j.type()) {
        case json::value_t::object: return "an object";
        case json::value_t::array: return "an array of " + std::to_string(j.size());
        case json::value_t::discarded: return "nothing";
        default: {  // a scalar as written in JSON (strings keep their quotes), kept short
            const std::string text = j.dump();
            return text.size() <= 40 ? text : text.substr(0, 40) + "...";
        }
    }
}

class Reader {
public:
    explicit Reader(std::string file) : file_(std::move(file)) {}

    [[noreturn]] void fail(const std::string& expected, const std::string& found) const {
        throwParseError(file_, 0, expected, found);
    }
    [[noreturn]] void bad(const std::string& what, const std::string& as, const json& j) const {
        fail(what + " as " + as, describe(j));
    }

    const json& field(const json& obj, const std::string& key, const std::string& where = "") const {
        const std::string what = where.empty() ? key : where + "." + key;
        if (!obj.is_object() || !obj.contains(key)) fail("field '" + what + "'", "none");
        return obj.at(key);
    }
    double number(const json& j, const std::string& what) const {
        if (!j.is_number()) bad(what, "a number", j);
        const double v = j.get<double>();
        if (!std::isfinite(v)) bad(what, "a finite number", j);
        return v;
    }
    int integer(const json& j, const std::string& what) const {
        if (!j.is_number_integer()) bad(what, "an integer", j);
        const bool fits = j.is_number_unsigned() ? j.get<unsigned long long>() <= std::numeric_limits<int>::max()
                                                 : j.get<long long>() >= std::numeric_limits<int>::min() &&
                                                       j.get<long long>() <= std::numeric_limits<int>::max();
        if (!fits) bad(what, "an integer", j);
        return static_cast<int>(j.get<long long>());
    }
    bool boolean(const json& j, const std::string& what) const {
        if (!j.is_boolean()) bad(what, "true or false", j);
        return j.get<bool>();
    }
    std::string string(const json& j, const std::string& what) const {
        if (!j.is_string()) bad(what, "a string", j);
        return j.get<std::string>();
    }
    const json& array(const json& j, const std::string& what) const {
        if (!j.is_array()) bad(what, "an array", j);
        return j;
    }
    Eigen::VectorXd vector(const json& j, const std::string& what, Eigen::Index size = -1) const {
        if (!j.is_array() || (size >= 0 && static_cast<Eigen::Index>(j.size()) != size))
            bad(what, size >= 0 ? "an array of " + std::to_string(size) + " numbers" : "an array of numbers", j);
        Eigen::VectorXd v(static_cast<Eigen::Index>(j.size()));
        for (std::size_t i = 0; i < j.size(); ++i)
            v[static_cast<Eigen::Index>(i)] = number(j[i], what + "[" + std::to_string(i) + "]");
        return v;
    }
    Eigen::Vector3d vec3(const json& j, const std::string& what) const { return vector(j, what, 3); }
    Effector effector(const json& j, const std::string& what) const {
        Effector e;
        if (!j.is_string() || !parseEffector(j.get<std::string>(), e))
            bad(what, "an effector name (lhand rhand lfoot rfoot head)", j);
        return e;
    }
    std::optional<gp::GpModel> model(const json& j, const std::string& what) const {
        if (j.is_null()) return std::nullopt;
        if (!j.is_object()) bad(what, "a motiongp-model object or null", j);
        return gp::modelFromJsonText(j.dump(), file_);
    }

    const std::string& file() const { return file_; }

private:
    std::string file_;
};

EditRecord readEdit(const Reader& r, const json& e, const std::string& what);

FrameEdits readFrameEdits(const Reader& r, const json& changes, const std::string& what) {
    r.array(changes, what);
    FrameEdits out;
    for (std::size_t i = 0; i < changes.size(); ++i) {
        const std::string w = what + "[" + std::to_string(i) + "]";
        const int frame = r.integer(r.field(changes[i], "frame", w), w + ".frame");
        if (out.count(frame)) r.fail("distinct frames in " + what, "frame " + std::to_string(frame) + " twice");
        const json& e = r.field(changes[i], "edit", w);
        out[frame] = e.is_null() ? std::nullopt : std::optional<EditRecord>(readEdit(r, e, w + ".edit"));
    }
    return out;
}

void readHistory(const Reader& r, const json& h, SessionData& s) {
    for (auto [key, steps] : {std::pair{"undo", &s.undoSteps}, std::pair{"redo", &s.redoSteps}}) {
        const std::string what = std::string("history.") + key;
        const json& list = r.array(r.field(h, key, "history"), what);
        for (std::size_t i = 0; i < list.size(); ++i) {
            const std::string w = what + "[" + std::to_string(i) + "]";
            EditStep step;
            step.label = r.string(r.field(list[i], "label", w), w + ".label");
            step.before = readFrameEdits(r, r.field(list[i], "before", w), w + ".before");
            step.after = readFrameEdits(r, r.field(list[i], "after", w), w + ".after");
            steps->push_back(std::move(step));
        }
    }
}

void readAdaptiveHistory(const Reader& r, const json& list, SessionData& s) {
    r.array(list, "adaptive_history");
    for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string w = "adaptive_history[" + std::to_string(i) + "]";
        const json& e = list[i];
        const auto integer = [&](const char* key) { return r.integer(r.field(e, key, w), w + "." + key); };
        const auto number = [&](const char* key) { return r.number(r.field(e, key, w), w + "." + key); };
        const auto boolean = [&](const char* key) { return r.boolean(r.field(e, key, w), w + "." + key); };
        AdaptiveHistoryEntry h;
        const json& when = r.field(e, "when_unix_ms", w);
        if (!when.is_number_integer()) r.bad(w + ".when_unix_ms", "an integer", when);
        h.when = std::chrono::system_clock::time_point(std::chrono::milliseconds(when.get<long long>()));
        h.frame = integer("frame");
        h.accepted = boolean("accepted");
        h.diagnostic = r.string(r.field(e, "diagnostic", w), w + ".diagnostic");
        h.seconds = number("seconds");
        h.versionBefore = integer("version_before");
        h.versionAfter = integer("version_after");
        h.rowsAfter = integer("rows_after");
        h.activeSize = integer("active_size");
        h.activeChanged = integer("active_changed");
        h.newPointActive = boolean("new_point_active");
        h.objectiveBefore = number("objective_before");
        h.objectiveAfter = number("objective_after");
        s.adaptiveHistory.push_back(std::move(h));
    }
}

EditRecord readEdit(const Reader& r, const json& e, const std::string& what) {
    EditRecord rec;
    rec.pose.rootCm = r.vec3(r.field(e, "root_cm", what), what + ".root_cm");
    const json& angles = r.array(r.field(e, "angles_deg", what), what + ".angles_deg");
    if (angles.empty()) r.bad(what + ".angles_deg", "an array of [3] per joint", angles);
    for (std::size_t k = 0; k < angles.size(); ++k)
        rec.pose.anglesDeg.push_back(r.vec3(angles[k], what + ".angles_deg[" + std::to_string(k) + "]"));
    rec.x = r.vector(r.field(e, "x", what), what + ".x");
    if (e.contains("moved")) {
        const json& moved = r.array(e["moved"], what + ".moved");
        for (std::size_t k = 0; k < moved.size(); ++k)
            rec.moved.push_back(r.effector(moved[k], what + ".moved[" + std::to_string(k) + "]"));
    }
    return rec;
}

void readClipReference(const Reader& r, const json& c, SessionData& s) {
    s.syntheticClip = r.boolean(r.field(c, "synthetic", "clip"), "clip.synthetic");
    s.syntheticFrames = r.integer(r.field(c, "synthetic_frames", "clip"), "clip.synthetic_frames");
    // loadSessionClip builds the walk with this many frames: bound it, else a declared 2^31 − 1
    // allocates without limit when the session is opened.
    if (s.syntheticFrames < 1 || s.syntheticFrames > kMaxSyntheticFrames)
        r.fail("clip.synthetic_frames in 1.." + std::to_string(kMaxSyntheticFrames), std::to_string(s.syntheticFrames));
    s.clipPath = r.string(r.field(c, "path", "clip"), "clip.path");
    s.clipRelativePath = r.string(r.field(c, "relative_path", "clip"), "clip.relative_path");
    s.skeletonPath = r.string(r.field(c, "skeleton_path", "clip"), "clip.skeleton_path");
    s.skeletonRelativePath = r.string(r.field(c, "skeleton_relative_path", "clip"), "clip.skeleton_relative_path");
    s.clipSha256 = r.string(r.field(c, "sha256", "clip"), "clip.sha256");
}

void readEdits(const Reader& r, const json& edits, SessionData& s) {
    r.array(edits, "edits");
    for (std::size_t i = 0; i < edits.size(); ++i) {
        const std::string what = "edits[" + std::to_string(i) + "]";
        const int frame = r.integer(r.field(edits[i], "frame", what), what + ".frame");
        if (frame < 0) r.fail(what + ".frame ≥ 0", std::to_string(frame));
        if (s.edits.count(frame)) r.fail("distinct edit frames", "frame " + std::to_string(frame) + " twice");
        EditRecord rec = readEdit(r, edits[i], what);
        const Eigen::Index dim = s.model ? s.model->latentDim() : 0;
        if (rec.x.size() != 0 && rec.x.size() != dim)
            r.fail(what + ".x of " + std::to_string(dim) + " numbers (" +
                       (s.model ? "the model's latent dimension" : "no model: []") + ")",
                   std::to_string(rec.x.size()));
        s.edits.emplace(frame, std::move(rec));
    }
}

void readPath(const Reader& r, const json& p, SessionPathEdit& path) {
    if (p.is_null()) return;
    if (!p.is_object()) r.bad("path", "an object or null", p);
    path.present = true;
    path.effector = r.effector(r.field(p, "effector", "path"), "path.effector");
    const json& keys = r.array(r.field(p, "key_frames", "path"), "path.key_frames");
    const json& offsets = r.array(r.field(p, "key_offsets_cm", "path"), "path.key_offsets_cm");
    if (offsets.size() != keys.size())
        r.fail(std::to_string(keys.size()) + " path.key_offsets_cm (one per key)", std::to_string(offsets.size()));
    for (std::size_t i = 0; i < keys.size(); ++i) {
        const std::string at = "[" + std::to_string(i) + "]";
        const int k = r.integer(keys[i], "path.key_frames" + at);
        if (k < 0 || (!path.keyFrames.empty() && k <= path.keyFrames.back()))
            r.fail("path.key_frames strictly increasing from 0", std::to_string(k));
        path.keyFrames.push_back(k);
        path.keyOffsetsCm.push_back(r.vec3(offsets[i], "path.key_offsets_cm" + at));
    }
    const std::string mode = r.string(r.field(p, "mode", "path"), "path.mode");
    if (mode == "direct")
        path.mode = PathMode::kDirect;
    else if (mode == "displacement")
        path.mode = PathMode::kDisplacement;
    else
        r.fail("path.mode direct or displacement", describe(json(mode)));
}

void readCamera(const Reader& r, const json& c, SessionCamera& cam) {
    auto num = [&](const char* key) { return r.number(r.field(c, key, "camera"), std::string("camera.") + key); };
    cam.yawDeg = num("yaw_deg");
    cam.pitchDeg = num("pitch_deg");
    cam.distanceCm = num("distance_cm");
    cam.fovYDeg = num("fov_y_deg");
    cam.targetCm = r.vec3(r.field(c, "target_cm", "camera"), "camera.target_cm");
    cam.followCharacter = r.boolean(r.field(c, "follow_character", "camera"), "camera.follow_character");
}

SessionData readSession(const Reader& r, const json& j) {
    SessionData s;
    readClipReference(r, r.field(j, "clip"), s);
    s.model = r.model(r.field(j, "model"), "model");
    s.modelVersion = r.integer(r.field(j, "model_version"), "model_version");
    if (s.modelVersion < 0) r.fail("model_version ≥ 0", std::to_string(s.modelVersion));
    s.compareModel = r.model(r.field(j, "compare_model"), "compare_model");
    readEdits(r, r.field(j, "edits"), s);
    s.frame = r.integer(r.field(j, "frame"), "frame");
    if (s.frame < 0) r.fail("frame ≥ 0", std::to_string(s.frame));
    const json& pins = r.array(r.field(j, "pins"), "pins");
    for (std::size_t i = 0; i < pins.size(); ++i)
        s.pins[static_cast<int>(r.effector(pins[i], "pins[" + std::to_string(i) + "]"))] = true;
    if (j.contains("keys")) {
        const json& keys = r.array(j.at("keys"), "keys");
        for (std::size_t i = 0; i < keys.size(); ++i) {
            const int k = r.integer(keys[i], "keys[" + std::to_string(i) + "]");
            if (k < 0 || !s.keys.insert(k).second) r.fail("distinct key frames ≥ 0", std::to_string(k));
        }
    }
    const json& sel = r.field(j, "selected_effector");
    s.selectedEffector = sel.is_null() ? -1 : static_cast<int>(r.effector(sel, "selected_effector"));
    s.compareMode = r.string(r.field(j, "compare_mode"), "compare_mode");
    if (CompareMode parsed; !parseCompareMode(s.compareMode, parsed))
        r.fail("compare_mode none, plain or model", describe(json(s.compareMode)));
    s.adaptiveEnabled = r.boolean(r.field(j, "adaptive_enabled"), "adaptive_enabled");
    readCamera(r, r.field(j, "camera"), s.camera);
    readPath(r, r.field(j, "path"), s.path);
    s.ui = r.field(j, "ui");
    if (!s.ui.is_object()) r.bad("ui", "an object", s.ui);
    if (r.field(j, "version").get<long long>() >= 2) {  // version 1 had neither
        readHistory(r, r.field(j, "history"), s);
        readAdaptiveHistory(r, r.field(j, "adaptive_history"), s);
    }
    return s;
}

// A clip file referenced by the session: relative to the session's folder first, then absolute.
std::string resolveReference(const Reader& r, const fs::path& sessionDir, const std::string& rel,
                             const std::string& abs, const std::string& what) {
    std::error_code ec;
    if (!rel.empty()) {
        const fs::path p = (sessionDir / rel).lexically_normal();
        if (fs::is_regular_file(p, ec)) return p.string();
    }
    if (!abs.empty() && fs::is_regular_file(abs, ec)) return abs;
    r.fail(what + " (" + (rel.empty() ? "" : rel + " relative to the session, or ") + abs + ")", "neither");
}

}  // namespace

std::string sessionToJsonText(const SessionData& s, const std::string& sessionPath) {
    const fs::path dir = fs::absolute(sessionPath).lexically_normal().parent_path();
    const std::string clipAbs = absolutePath(s.clipPath), skelAbs = absolutePath(s.skeletonPath);
    json j;
    j["format"] = kSessionFileFormat;
    j["version"] = kSessionFileVersion;
    j["clip"] = {{"synthetic", s.syntheticClip},
                 {"synthetic_frames", s.syntheticFrames},
                 {"path", clipAbs},
                 {"relative_path", relativeTo(clipAbs, dir)},
                 {"skeleton_path", skelAbs},
                 {"skeleton_relative_path", relativeTo(skelAbs, dir)},
                 {"sha256", s.clipSha256}};
    j["model"] = modelJson(s.model);
    j["model_version"] = s.modelVersion;
    j["compare_model"] = modelJson(s.compareModel);
    json edits = json::array();
    for (const auto& [frame, rec] : s.edits) {
        json e = editJson(rec);
        e["frame"] = frame;
        edits.push_back(std::move(e));
    }
    j["edits"] = edits;
    j["frame"] = s.frame;
    json pins = json::array();
    for (int e = 0; e < kEffectorCount; ++e)
        if (s.pins[e]) pins.push_back(effectorName(static_cast<Effector>(e)));
    j["pins"] = pins;
    j["keys"] = s.keys;
    j["selected_effector"] = s.selectedEffector >= 0 && s.selectedEffector < kEffectorCount
                                 ? json(effectorName(static_cast<Effector>(s.selectedEffector)))
                                 : json(nullptr);
    j["compare_mode"] = s.compareMode;
    j["adaptive_enabled"] = s.adaptiveEnabled;
    const SessionCamera& c = s.camera;
    j["camera"] = {
        {"yaw_deg", c.yawDeg},    {"pitch_deg", c.pitchDeg},           {"distance_cm", c.distanceCm},
        {"fov_y_deg", c.fovYDeg}, {"target_cm", vec3Json(c.targetCm)}, {"follow_character", c.followCharacter}};
    if (s.path.present) {
        json offsets = json::array();
        for (const auto& o : s.path.keyOffsetsCm) offsets.push_back(vec3Json(o));
        j["path"] = {{"effector", effectorName(s.path.effector)},
                     {"key_frames", s.path.keyFrames},
                     {"key_offsets_cm", offsets},
                     {"mode", s.path.mode == PathMode::kDirect ? "direct" : "displacement"}};
    } else {
        j["path"] = nullptr;
    }
    j["ui"] = s.ui;
    json undo = json::array(), redo = json::array();
    for (const EditStep& step : s.undoSteps) undo.push_back(stepJson(step));
    for (const EditStep& step : s.redoSteps) redo.push_back(stepJson(step));
    j["history"] = {{"undo", undo}, {"redo", redo}};
    json adaptive = json::array();
    for (const AdaptiveHistoryEntry& h : s.adaptiveHistory) {
        const long long ms = std::chrono::duration_cast<std::chrono::milliseconds>(h.when.time_since_epoch()).count();
        adaptive.push_back({{"when_unix_ms", ms},
                            {"frame", h.frame},
                            {"accepted", h.accepted},
                            {"diagnostic", h.diagnostic},
                            {"seconds", h.seconds},
                            {"version_before", h.versionBefore},
                            {"version_after", h.versionAfter},
                            {"rows_after", h.rowsAfter},
                            {"active_size", h.activeSize},
                            {"active_changed", h.activeChanged},
                            {"new_point_active", h.newPointActive},
                            {"objective_before", h.objectiveBefore},
                            {"objective_after", h.objectiveAfter}});
    }
    j["adaptive_history"] = adaptive;
    return j.dump(1) + "\n";
}

SessionData sessionFromJsonText(const std::string& text, const std::string& file) {
    const Reader r(file);
    json j;
    try {
        j = json::parse(text);
    } catch (const json::exception& e) {
        r.fail("a JSON session file (format motiongp-session)",
               text.empty() ? "an empty file" : std::string("damaged JSON (") + e.what() + ")");
    }
    if (!j.is_object() || !j.contains("format") || j["format"] != kSessionFileFormat)
        r.fail(std::string("\"format\": \"") + kSessionFileFormat + "\"",
               j.is_object() && j.contains("format") ? describe(j["format"]) : "no format field");
    const json& ver = r.field(j, "version");
    if (!ver.is_number_integer() || ver.get<long long>() < 1 || ver.get<long long>() > kSessionFileVersion)
        r.fail("session file version ≤ " + std::to_string(kSessionFileVersion) + " (this build reads up to version " +
                   std::to_string(kSessionFileVersion) + ")",
               "version " + describe(ver));
    SessionData s;
    try {
        s = readSession(r, j);
    } catch (const json::exception& e) {  // the accessors check types first; this is a safety net
        r.fail("a valid motiongp-session document", e.what());
    }
    if (s.model) {
        if (const std::string problem = validateAgainstClip(s, s.model->clip); !problem.empty())
            throw ParseError(file + ": " + problem);
    }
    return s;
}

std::string validateAgainstClip(const SessionData& s, const Clip& clip) {
    const int n = clip.frameCount(), joints = clip.skeleton.jointCount();
    const std::string range = "in 0.." + std::to_string(n - 1) + " (the clip's frames)";
    if (s.frame < 0 || s.frame >= n) return "expected frame " + range + ", found " + std::to_string(s.frame);
    for (const auto& [frame, rec] : s.edits) {
        if (frame < 0 || frame >= n) return "expected edit frames " + range + ", found " + std::to_string(frame);
        if (static_cast<int>(rec.pose.anglesDeg.size()) != joints)
            return "expected " + std::to_string(joints) + " joint angles per edit (the clip's skeleton), found " +
                   std::to_string(rec.pose.anglesDeg.size()) + " at frame " + std::to_string(frame);
    }
    for (int k : s.path.keyFrames)
        if (k < 0 || k >= n) return "expected path key frames " + range + ", found " + std::to_string(k);
    for (int k : s.keys)
        if (k < 0 || k >= n) return "expected key frames " + range + ", found " + std::to_string(k);
    for (const auto* steps : {&s.undoSteps, &s.redoSteps})
        for (const EditStep& step : *steps)
            for (const FrameEdits* side : {&step.before, &step.after})
                for (const auto& [frame, rec] : *side) {
                    if (frame < 0 || frame >= n)
                        return "expected undo history frames " + range + ", found " + std::to_string(frame) + " in \"" +
                               step.label + "\"";
                    if (rec && static_cast<int>(rec->pose.anglesDeg.size()) != joints)
                        return "expected " + std::to_string(joints) + " joint angles per undo history edit, found " +
                               std::to_string(rec->pose.anglesDeg.size()) + " in \"" + step.label + "\"";
                }
    return "";
}

void saveSession(const std::string& path, const SessionData& session) {
    writeFileAtomically(path, sessionToJsonText(session, path));
}

SessionData loadSession(const std::string& path) {
    std::error_code ec;
    if (fs::is_regular_file(path, ec) && fs::file_size(path, ec) == 0)
        throwParseError(path, 0, "a JSON session file (format motiongp-session)", "an empty file");
    // TextReader gives the file checks (missing, directory, binary, oversized) their usual words.
    TextReader reader = TextReader::fromFile(path, 256u << 20);
    std::string text;
    while (!reader.atEnd()) text.append(reader.nextLine()).push_back('\n');
    SessionData s = sessionFromJsonText(text, path);
    if (s.model || s.syntheticClip) return s;

    const Reader r(path);
    const fs::path dir = fs::absolute(path).lexically_normal().parent_path();
    s.clipPath = resolveReference(r, dir, s.clipRelativePath, s.clipPath, "the session's clip file");
    if (!s.skeletonPath.empty() || !s.skeletonRelativePath.empty())
        s.skeletonPath =
            resolveReference(r, dir, s.skeletonRelativePath, s.skeletonPath, "the session's skeleton file");
    if (!s.clipSha256.empty() && gp::sha256OfFile(s.clipPath) != s.clipSha256)
        s.warnings.push_back(s.clipPath +
                             " changed since the session was saved (SHA-256 differs): "
                             "the edits may not fit the motion");
    return s;
}

std::optional<Clip> loadSessionClip(const SessionData& s, const std::string& file) {
    if (s.model) return std::nullopt;
    Clip clip = s.syntheticClip ? makeSyntheticWalk(s.syntheticFrames) : loadClip(s.clipPath, s.skeletonPath);
    if (const std::string problem = validateAgainstClip(s, clip); !problem.empty())
        throw ParseError(file + ": " + problem);
    return clip;
}

}  // namespace mgp
