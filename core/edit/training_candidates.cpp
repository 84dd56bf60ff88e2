#include "edit/training_candidates.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>

#include "io/asf_reader.h"
#include "io/clip_loader.h"
#include "skeleton/clip_match.h"

namespace mgp {

namespace {
namespace fs = std::filesystem;

const char* const kBvhReason = "BVH: training on BVH is not supported yet";

std::string lowerExtension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

bool sameFile(const std::string& a, const std::string& b) {
    std::error_code ec;
    return !a.empty() && !b.empty() && fs::equivalent(a, b, ec) && !ec;
}

// The candidate for `path`, reading each ASF once (`verdicts` caches its verdict by ASF path: a reader
// error is kept as the reason).
TrainingCandidate judge(const Clip& open, const std::string& path, std::map<std::string, std::string>& verdicts) {
    TrainingCandidate c;
    c.path = path;
    c.name = fs::path(path).stem().string();
    const std::string ext = lowerExtension(path);
    if (ext == ".bvh") {
        c.usable = false;
        c.reason = kBvhReason;
        return c;
    }
    if (ext != ".amc") {
        c.usable = false;
        c.reason = "expected an ASF/AMC clip (.amc), found '" + ext + "'";
        return c;
    }
    if (!fs::is_regular_file(path)) {
        c.usable = false;
        c.reason = "no such file";
        return c;
    }
    const std::string asf = defaultAsfFor(path);
    auto it = verdicts.find(asf);
    if (it == verdicts.end()) {
        std::string verdict;
        try {
            std::string difference;
            if (!sameSkeleton(open.skeleton, readAsf(asf).skeleton, &difference))
                verdict = "another skeleton (" + fs::path(asf).filename().string() + "): " + difference;
        } catch (const std::exception& e) {
            verdict = std::string("cannot read its skeleton: ") + e.what();
        }
        it = verdicts.emplace(asf, verdict).first;
    }
    c.usable = it->second.empty();
    c.reason = it->second;
    if (c.usable && c.name == open.name) {
        c.usable = false;
        c.reason = "the same name as the open clip (a model names its clips by file stem)";
    }
    return c;
}
}  // namespace

std::vector<TrainingCandidate> trainingCandidates(const Clip& open) {
    std::vector<TrainingCandidate> out;
    TrainingCandidate self;
    self.path = open.sourcePath;
    self.name = open.name;
    self.open = true;
    if (open.format == ClipFormat::kBvh) {
        self.usable = false;
        self.reason = kBvhReason;
    }
    out.push_back(self);
    if (!self.usable || open.sourcePath.empty()) return out;
    std::error_code ec;
    const fs::path dir = fs::path(open.sourcePath).parent_path();
    std::vector<std::string> files;
    for (fs::directory_iterator it(dir.empty() ? fs::path(".") : dir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string ext = lowerExtension(it->path().string());
        if ((ext == ".amc" || ext == ".bvh") && it->is_regular_file(ec) && !sameFile(it->path().string(), open.sourcePath))
            files.push_back(it->path().string());
    }
    std::map<std::string, std::string> verdicts;
    std::vector<TrainingCandidate> offered, refused;
    for (const std::string& f : files) {
        TrainingCandidate c = judge(open, f, verdicts);
        (c.usable ? offered : refused).push_back(std::move(c));
    }
    const auto byName = [](const TrainingCandidate& a, const TrainingCandidate& b) {
        return a.name != b.name ? a.name < b.name : a.path < b.path;
    };
    std::sort(offered.begin(), offered.end(), byName);
    std::sort(refused.begin(), refused.end(), byName);
    out.insert(out.end(), offered.begin(), offered.end());
    out.insert(out.end(), refused.begin(), refused.end());
    return out;
}

TrainingCandidate trainingCandidate(const Clip& open, const std::string& path) {
    std::map<std::string, std::string> verdicts;
    if (open.format == ClipFormat::kBvh) {
        TrainingCandidate c;
        c.path = path;
        c.name = fs::path(path).stem().string();
        c.usable = false;
        c.reason = "the open clip is BVH: training on BVH is not supported yet";
        return c;
    }
    if (sameFile(path, open.sourcePath)) {
        TrainingCandidate c;
        c.path = path;
        c.name = open.name;
        c.usable = false;
        c.reason = "the open clip is always included";
        return c;
    }
    return judge(open, path, verdicts);
}

}  // namespace mgp
