#include "edit/training_candidates.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>

#include "io/asf_reader.h"
#include "io/bvh_reader.h"
#include "io/clip_loader.h"
#include "skeleton/clip_match.h"

namespace mgp {

namespace {
namespace fs = std::filesystem;

std::string lowerExtension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

bool sameFile(const std::string& a, const std::string& b) {
    std::error_code ec;
    return !a.empty() && !b.empty() && fs::equivalent(a, b, ec) && !ec;
}

// The candidate for `path`, reading each skeleton once (`verdicts` caches its verdict by ASF path,
// or by BVH path: a BVH carries its own; a reader error is kept as the reason).
TrainingCandidate judge(const Clip& open, const std::string& path, std::map<std::string, std::string>& verdicts) {
    TrainingCandidate c;
    c.path = path;
    c.name = fs::path(path).stem().string();
    const std::string ext = lowerExtension(path);
    const bool openIsBvh = open.format == ClipFormat::kBvh;
    if (ext != ".amc" && ext != ".bvh") {
        c.usable = false;
        c.reason = "expected a clip file (.amc or .bvh), found '" + ext + "'";
        return c;
    }
    if ((ext == ".bvh") != openIsBvh) {
        c.usable = false;
        c.reason = openIsBvh ? "an ASF/AMC clip: another skeleton than the open BVH (retargeting is not supported)"
                             : "a BVH clip: another skeleton than the open ASF/AMC (retargeting is not supported)";
        return c;
    }
    if (!fs::is_regular_file(path)) {
        c.usable = false;
        c.reason = "no such file";
        return c;
    }
    const std::string skeletonFile = openIsBvh ? path : defaultAsfFor(path);
    auto it = verdicts.find(skeletonFile);
    if (it == verdicts.end()) {
        std::string verdict;
        try {
            std::string difference;
            const Skeleton other = openIsBvh ? readBvh(path).skeleton : readAsf(skeletonFile).skeleton;
            if (!sameSkeleton(open.skeleton, other, &difference))
                verdict = "another skeleton (" + fs::path(skeletonFile).filename().string() + "): " + difference;
        } catch (const std::exception& e) {
            verdict = std::string("cannot read its skeleton: ") + e.what();
        }
        it = verdicts.emplace(skeletonFile, verdict).first;
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
    out.push_back(self);
    if (open.sourcePath.empty()) return out;
    std::error_code ec;
    const fs::path dir = fs::path(open.sourcePath).parent_path();
    std::vector<std::string> files;
    for (fs::directory_iterator it(dir.empty() ? fs::path(".") : dir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string ext = lowerExtension(it->path().string());
        if ((ext == ".amc" || ext == ".bvh") && it->is_regular_file(ec) &&
            !sameFile(it->path().string(), open.sourcePath))
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
