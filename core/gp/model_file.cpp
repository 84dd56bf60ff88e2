#include "gp/model_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "io/atomic_file.h"
#include "io/clip_json.h"
#include "io/parse_error.h"
#include "io/text_reader.h"
#include "skeleton/clip_match.h"
#include "skeleton/pose_layout.h"

namespace mgp::gp {

namespace {

using nlohmann::json;

constexpr double kMaxAbsLogParam = 100.0;
// An upper bound on D read before the clip (three rotations for each of 1000 joints); the clip's
// own pose vector then fixes it exactly.
constexpr int kMaxPoseColumns = 3000;

json vecJson(const Eigen::VectorXd& v) {
    json a = json::array();
    for (Eigen::Index i = 0; i < v.size(); ++i) a.push_back(v[i]);
    return a;
}

json rowsJson(const Eigen::MatrixXd& m) {
    json a = json::array();
    for (Eigen::Index r = 0; r < m.rows(); ++r) a.push_back(vecJson(m.row(r).transpose()));
    return a;
}

const json& need(const json& j, const char* key, const std::string& file) {
    if (!j.is_object() || !j.contains(key)) throwParseError(file, 0, "field '" + std::string(key) + "'", "none");
    return j.at(key);
}

// An integer that fits in an int. nlohmann's get<int>() converts a float (1e300) or a 64-bit
// value with a plain cast (undefined behaviour for 1e300): check first.
int intOf(const json& v, const std::string& file, const std::string& what) {
    const bool fits = v.is_number_unsigned()
                          ? v.get<unsigned long long>() <= std::numeric_limits<int>::max()
                          : v.is_number_integer() && v.get<long long>() >= std::numeric_limits<int>::min() &&
                                v.get<long long>() <= std::numeric_limits<int>::max();
    if (!fits) throwParseError(file, 0, "an integer for " + what, v.dump());
    return static_cast<int>(v.get<long long>());
}

int needInt(const json& j, const char* key, const std::string& file) {
    return intOf(need(j, key, file), file, "'" + std::string(key) + "'");
}

Eigen::VectorXd readVec(const json& j, const std::string& file, const char* what, Eigen::Index size = -1) {
    if (!j.is_array() || (size >= 0 && static_cast<Eigen::Index>(j.size()) != size))
        throwParseError(
            file, 0, std::string(what) + " as an array of " + (size >= 0 ? std::to_string(size) + " " : "") + "numbers",
            j.is_array() ? std::to_string(j.size()) + " entries" : j.type_name());
    Eigen::VectorXd v(j.size());
    for (std::size_t i = 0; i < j.size(); ++i) {
        if (!j[i].is_number()) throwParseError(file, 0, std::string("numbers in ") + what, j[i].dump());
        v[i] = j[i].get<double>();
        if (!std::isfinite(v[i])) throwParseError(file, 0, std::string("finite numbers in ") + what, j[i].dump());
    }
    return v;
}

std::vector<int> readInts(const json& j, const std::string& file, const char* what) {
    if (!j.is_array()) throwParseError(file, 0, std::string(what) + " as an array of integers", j.type_name());
    std::vector<int> out;
    for (const auto& e : j) {
        out.push_back(intOf(e, file, std::string("integers in ") + what));
    }
    return out;
}

// Version 2: the clips after the primary one and each row's clip index.
void readMoreClips(const json& j, const std::string& file, int n, GpModel& m) {
    const json& more = need(j, "more_clips", file);
    if (!more.is_array() || more.empty())
        throwParseError(file, 0, "more_clips as a non-empty array (a version-2 model has 2 or more clips)",
                        more.is_array() ? "[]" : more.type_name());
    for (const json& e : more) {
        SourceClip c;
        c.file = need(e, "file", file).get<std::string>();
        c.sha256 = need(e, "sha256", file).get<std::string>();
        c.clip = clipFromJson(need(e, "clip", file), file);
        // Rows of every clip share one pose vector, and IK runs on the primary clip's bones.
        std::string difference;
        if (!sameSkeleton(m.clip.skeleton, c.clip.skeleton, &difference))
            throwParseError(file, 0, "clips of one skeleton", "clip " + c.clip.name + ": " + difference);
        m.moreClips.push_back(std::move(c));
    }
    for (int a = 0; a < m.clipCount(); ++a)
        for (int b = 0; b < a; ++b)
            if (m.clipName(a) == m.clipName(b))
                throwParseError(file, 0, "distinct clip names", m.clipName(a) + " twice");
    m.trainingClips = readInts(need(j, "training_clips", file), file, "training_clips");
    if (static_cast<int>(m.trainingClips.size()) != n)
        throwParseError(file, 0, std::to_string(n) + " training clips", std::to_string(m.trainingClips.size()));
    for (int c : m.trainingClips)
        if (c < 0 || c >= m.clipCount())
            throwParseError(file, 0, "training clips in 0.." + std::to_string(m.clipCount() - 1), std::to_string(c));
}

// The document, checked to be a motiongp model file before any field is read.
json parseModelDocument(const std::string& text, const std::string& file) {
    json j;
    try {
        j = json::parse(text);
    } catch (const json::exception& e) {
        throwParseError(file, 0, "a JSON model file (format motiongp-model)",
                        text.empty() ? "an empty file" : std::string("damaged JSON (") + e.what() + ")");
    }
    if (!j.is_object() || !j.contains("format") || !j["format"].is_string() || j["format"] != kModelFileFormat)
        throwParseError(file, 0, std::string("\"format\": \"") + kModelFileFormat + "\"",
                        j.is_object() && j.contains("format") ? j["format"].dump() : "no format field");
    return j;
}

// The file's version, one this build reads.
long long modelVersionOf(const json& j, const std::string& file) {
    const json& ver = need(j, "version", file);
    if (!ver.is_number_integer() || ver.get<long long>() < 1 || ver.get<long long>() > kModelFileVersion)
        throwParseError(file, 0,
                        "model file version ≤ " + std::to_string(kModelFileVersion) +
                            " (this build reads up to version " + std::to_string(kModelFileVersion) + ")",
                        "version " + ver.dump());
    return ver.get<long long>();
}

void readModelKernel(const json& j, const std::string& file, GpModel& m) {
    const std::string kind = need(j, "kernel", file).get<std::string>();
    if (!parseKernelKind(kind, m.kind)) throwParseError(file, 0, "kernel fas or sgplvm", "'" + kind + "'");
    m.logParams = readVec(need(j, "log_params", file), file, "log_params", paramCount(m.kind));
    // exp(ln θ) must stay finite with room for products (α·e^(η), 1/β): a damaged value such
    // as 1e308 would otherwise give an infinite K and NaN poses downstream.
    for (Eigen::Index i = 0; i < m.logParams.size(); ++i)
        if (std::abs(m.logParams[i]) > kMaxAbsLogParam)
            throwParseError(file, 0, "log_params within ±100 (kernel parameters exp(±100))",
                            json(m.logParams[i]).dump());
}

// N (training rows), D (kept pose columns) and latent_dim as the file declares them.
struct ModelSizes {
    int n = 0, D = 0, d = 0;
};

ModelSizes readModelSizes(const json& j, const std::string& file) {
    const int n = needInt(j, "N", file), D = needInt(j, "D", file);
    const int d = needInt(j, "latent_dim", file);
    // latent_dim sizes X before its rows are read: bound it (the latent space never exceeds
    // the pose DOFs, and D never exceeds three per joint of any file we read), else a
    // declared 2^31 − 1 allocated gigabytes. The clip's pose vector checks D exactly below.
    if (n < 1 || D < 1 || D > kMaxPoseColumns || d < 1 || d > D)
        throwParseError(file, 0, "positive N, D ≤ " + std::to_string(kMaxPoseColumns) + " and latent_dim ≤ D",
                        "N=" + std::to_string(n) + " D=" + std::to_string(D) + " latent_dim=" + std::to_string(d));
    return {n, D, d};
}

void readModelLatents(const json& j, const std::string& file, int n, int d, GpModel& m) {
    const json& xj = need(j, "X", file);
    if (!xj.is_array() || static_cast<int>(xj.size()) != n)
        throwParseError(file, 0, std::to_string(n) + " rows of X",
                        xj.is_array() ? std::to_string(xj.size()) : xj.type_name());
    // Check every row's length before allocating N×d: a damaged latent_dim (say 10^9) must
    // be an error, not a multi-GB allocation.
    for (int r = 0; r < n; ++r)
        if (!xj[r].is_array() || static_cast<long long>(xj[r].size()) != d)
            throwParseError(file, 0, "X as an array of " + std::to_string(d) + " numbers",
                            xj[r].is_array() ? std::to_string(xj[r].size()) + " entries" : xj[r].type_name());
    m.X.resize(n, d);
    for (int r = 0; r < n; ++r) m.X.row(r) = readVec(xj[r], file, "X", d).transpose();
}

void readModelActiveSet(const json& j, const std::string& file, int n, GpModel& m) {
    m.active = readInts(need(j, "active", file), file, "active");
    for (int i : m.active)
        if (i < 0 || i >= n)
            throwParseError(file, 0, "active indices in 0.." + std::to_string(n - 1), std::to_string(i));
    if (m.active.empty()) throwParseError(file, 0, "a non-empty active set", "[]");
    // A repeated active row makes K singular (not positive definite without noise); the
    // active set is a set.
    std::vector<char> inActive(static_cast<std::size_t>(n), 0);
    for (int i : m.active)
        if (inActive[static_cast<std::size_t>(i)]++)
            throwParseError(file, 0, "distinct active indices (a positive definite K)", std::to_string(i) + " twice");
}

void readModelColumnsAndFrames(const json& j, const std::string& file, const ModelSizes& size, GpModel& m) {
    m.keptColumns = readInts(need(j, "kept_columns", file), file, "kept_columns");
    m.constantColumns = readInts(need(j, "constant_columns", file), file, "constant_columns");
    m.constantValues = readVec(need(j, "constant_values", file), file, "constant_values",
                               static_cast<Eigen::Index>(m.constantColumns.size()));
    if (static_cast<int>(m.keptColumns.size()) != size.D)
        throwParseError(file, 0, std::to_string(size.D) + " kept columns (D)", std::to_string(m.keptColumns.size()));
    m.trainingFrames = readInts(need(j, "training_frames", file), file, "training_frames");
    if (static_cast<int>(m.trainingFrames.size()) != size.n)
        throwParseError(file, 0, std::to_string(size.n) + " training frames", std::to_string(m.trainingFrames.size()));
}

// The optional training fields: prior, back constraints, objective history.
void readOptionalTrainingFields(const json& t, const std::string& file, GpModel& m) {
    if (t.contains("prior")) {  // absent: the paper's model (no temporal prior)
        const json& pr = t["prior"];
        if (!pr.is_object() || !pr.contains("kind") || !pr["kind"].is_string() ||
            !parseLatentPrior(pr["kind"].get<std::string>(), m.settings.prior))
            throwParseError(file, 0, "training.prior.kind \"none\" or \"smooth\"", pr.dump());
        if (!pr.contains("weight") || !pr["weight"].is_number() || !std::isfinite(pr["weight"].get<double>()) ||
            pr["weight"].get<double>() < 0.0)
            throwParseError(file, 0, "a finite training.prior.weight ≥ 0", pr.dump());
        m.settings.priorWeight = pr["weight"].get<double>();
    }
    if (t.contains("back_constraints")) {
        if (!t["back_constraints"].is_boolean())
            throwParseError(file, 0, "training.back_constraints true or false", t["back_constraints"].dump());
        m.settings.backConstraints = t["back_constraints"].get<bool>();
    }
    if (t.contains("objective_history")) {  // absent in files written before it existed
        const Eigen::VectorXd h = readVec(t["objective_history"], file, "training.objective_history");
        m.objectiveHistory.assign(h.data(), h.data() + h.size());
    }
}

void readTrainingSettings(const json& j, const std::string& file, GpModel& m) {
    const json& t = need(j, "training", file);
    m.settings.activeSize = needInt(t, "active_size", file);
    m.settings.outerIterations = needInt(t, "outer_iterations", file);
    m.settings.scgIterations = needInt(t, "scg_iterations", file);
    m.settings.pointIterations = needInt(t, "point_iterations", file);
    m.settings.tolerance = need(t, "tolerance", file).get<double>();
    m.settings.frameFirst = needInt(t, "frame_first", file);
    m.settings.frameLast = needInt(t, "frame_last", file);
    m.settings.frameStep = needInt(t, "frame_step", file);
    m.iterations = needInt(t, "iterations", file);
    m.converged = need(t, "converged", file).get<bool>();
    readOptionalTrainingFields(t, file, m);
}

// Kept and constant columns partition the clip's pose vector (47 DOFs for ASF clips).
void checkColumnPartition(const std::string& file, const GpModel& m) {
    const int P = PoseLayout(m.clip.skeleton).size();
    if (m.keptColumns.size() + m.constantColumns.size() != static_cast<std::size_t>(P))
        throwParseError(file, 0, "kept and constant columns that partition the " + std::to_string(P) + " pose DOFs",
                        std::to_string(m.keptColumns.size()) + " + " + std::to_string(m.constantColumns.size()));
    std::vector<char> seen(static_cast<std::size_t>(P), 0);
    for (const std::vector<int>* columns : {&m.keptColumns, &m.constantColumns})
        for (int c : *columns) {
            if (c < 0 || c >= P || seen[static_cast<std::size_t>(c)])
                throwParseError(file, 0, "distinct columns 0.." + std::to_string(P - 1), std::to_string(c));
            seen[static_cast<std::size_t>(c)] = 1;
        }
}

// Training rows: each row's clip's pose at its training frame, kept columns.
void rebuildTrainingRows(const std::string& file, int n, int D, GpModel& m) {
    const std::vector<Eigen::MatrixXd> poses = m.clipPoseMatrices();
    m.Y.resize(n, D);
    for (int r = 0; r < n; ++r) {
        const int f = m.trainingFrames[r];
        const Clip& c = m.clipAt(m.rowClip(r));
        if (f < 0 || f >= c.frameCount())
            throwParseError(file, 0,
                            "training frames of clip " + c.name + " in 0.." + std::to_string(c.frameCount() - 1),
                            std::to_string(f));
        for (int k = 0; k < D; ++k) m.Y(r, k) = poses[static_cast<std::size_t>(m.rowClip(r))](f, m.keptColumns[k]);
    }
}

// Rows added by adaptive updates replace their rebuilt rows (absent in older files).
void readEditedRows(const json& j, const std::string& file, int n, int D, GpModel& m) {
    if (!j.contains("edited_rows")) return;
    const json& edited = j["edited_rows"];
    if (!edited.is_array()) throwParseError(file, 0, "edited_rows as an array", edited.type_name());
    for (const json& e : edited) {
        const int r = needInt(e, "row", file);
        if (r < 0 || r >= n)
            throwParseError(file, 0, "edited_rows row in 0.." + std::to_string(n - 1), std::to_string(r));
        m.Y.row(r) = readVec(need(e, "y", file), file, "edited_rows y", D).transpose();
    }
}

}  // namespace

std::string modelToJsonText(const GpModel& m) {
    json j;
    j["format"] = kModelFileFormat;
    // A single-clip model is written as version 1, byte for byte as before multi-clip models.
    j["version"] = m.clipCount() > 1 ? kModelFileVersion : kSingleClipModelFileVersion;
    j["kernel"] = kernelKindName(m.kind);
    j["log_params"] = vecJson(m.logParams);
    const Kernel k = m.kernel();
    j["params"] = {{"alpha", k.alpha()},
                   {"beta", k.beta()},
                   {"gamma", k.gamma()},
                   {"eta", k.hasEta() ? json(k.eta()) : json(nullptr)}};
    j["N"] = m.N();
    j["D"] = m.D();
    j["latent_dim"] = m.latentDim();
    j["w"] = vecJson(m.w);
    j["mu"] = vecJson(m.mu);
    j["X"] = rowsJson(m.X);
    j["active"] = m.active;
    j["kept_columns"] = m.keptColumns;
    j["constant_columns"] = m.constantColumns;
    j["constant_values"] = vecJson(m.constantValues);
    j["training_frames"] = m.trainingFrames;
    if (m.clipCount() > 1) {
        json clips = json::array();
        for (const SourceClip& c : m.moreClips)
            clips.push_back({{"file", c.file}, {"sha256", c.sha256}, {"clip", clipToJson(c.clip)}});
        j["more_clips"] = clips;
        j["training_clips"] =
            m.trainingClips.empty() ? std::vector<int>(static_cast<std::size_t>(m.N()), 0) : m.trainingClips;
    }
    const TrainingSettings& s = m.settings;
    j["training"] = {{"active_size", s.activeSize},
                     {"outer_iterations", s.outerIterations},
                     {"scg_iterations", s.scgIterations},
                     {"point_iterations", s.pointIterations},
                     {"tolerance", s.tolerance},
                     {"frame_first", s.frameFirst},
                     {"frame_last", s.frameLast},
                     {"frame_step", s.frameStep},
                     {"iterations", m.iterations},
                     {"converged", m.converged},
                     {"objective_history", m.objectiveHistory}};
    // Only written for a prior other than none, so the paper model's file is unchanged.
    if (s.prior != LatentPrior::kNone)
        j["training"]["prior"] = {{"kind", latentPriorName(s.prior)}, {"weight", s.priorWeight}};
    if (s.backConstraints) j["training"]["back_constraints"] = true;  // likewise only when used
    j["source"] = {{"file", m.sourceFile}, {"sha256", m.sourceSha256}};
    j["clip"] = clipToJson(m.clip);
    // Y is not stored: a row is the clip's pose at its training frame. A row an adaptive update
    // added holds the ACCEPTED pose, not the captured one, so those rows are written out (only
    // when there are any: a freshly trained model's file is unchanged).
    const std::vector<Eigen::MatrixXd> poses = m.clipPoseMatrices();
    json edited = json::array();
    for (Eigen::Index r = 0; r < m.Y.rows(); ++r) {
        const int f = m.trainingFrames[static_cast<std::size_t>(r)];
        const int c = m.rowClip(static_cast<int>(r));
        bool same = c >= 0 && c < m.clipCount() && f >= 0 && f < m.clipAt(c).frameCount();
        for (int k = 0; same && k < m.D(); ++k)
            same = m.Y(r, k) == poses[static_cast<std::size_t>(c)](f, m.keptColumns[k]);
        if (!same) edited.push_back({{"row", r}, {"y", vecJson(m.Y.row(r).transpose())}});
    }
    if (!edited.empty()) j["edited_rows"] = edited;
    return j.dump(1) + "\n";
}

GpModel modelFromJsonText(const std::string& text, const std::string& file) {
    const json j = parseModelDocument(text, file);
    const long long version = modelVersionOf(j, file);
    GpModel m;
    try {
        readModelKernel(j, file, m);
        const ModelSizes size = readModelSizes(j, file);
        m.w = readVec(need(j, "w", file), file, "w", size.D);
        m.mu = readVec(need(j, "mu", file), file, "mu", size.D);
        readModelLatents(j, file, size.n, size.d, m);
        readModelActiveSet(j, file, size.n, m);
        readModelColumnsAndFrames(j, file, size, m);
        readTrainingSettings(j, file, m);
        const json& src = need(j, "source", file);
        m.sourceFile = need(src, "file", file).get<std::string>();
        m.sourceSha256 = need(src, "sha256", file).get<std::string>();
        m.clip = clipFromJson(need(j, "clip", file), file);
        if (version >= 2) readMoreClips(j, file, size.n, m);
        checkColumnPartition(file, m);
        rebuildTrainingRows(file, size.n, size.D, m);
        readEditedRows(j, file, size.n, size.D, m);
    } catch (const json::exception& e) {
        throwParseError(file, 0, "a valid motiongp-model document", e.what());
    }
    return m;
}

void saveModel(const std::string& path, const GpModel& model) { writeFileAtomically(path, modelToJsonText(model)); }

GpModel loadModel(const std::string& path) {
    // TextReader gives the file checks (missing, directory, special, binary, UTF-16, oversized)
    // their usual words; an ifstream would read a directory as an "empty file" and /dev/zero
    // forever. An empty file keeps the model file's own words.
    std::error_code ec;
    if (std::filesystem::is_regular_file(path, ec) && std::filesystem::file_size(path, ec) == 0)
        throwParseError(path, 0, "a JSON model file (format motiongp-model)", "an empty file");
    TextReader reader = TextReader::fromFile(path);
    std::string text;
    while (!reader.atEnd()) text.append(reader.nextLine()).push_back('\n');
    return modelFromJsonText(text, path);
}

}  // namespace mgp::gp
