#include "io/amc_reader.h"

#include <cmath>
#include <unordered_map>

#include "io/parse_error.h"
#include "io/text_reader.h"

namespace mgp {

namespace {

constexpr double kMaxAbsAngleDeg = 1e6;  // beyond this a value is corrupt, not a pose
constexpr double kMaxAbsTranslation = 1e7;
constexpr long long kMaxAbsFrameNumber = 1'000'000'000'000;

bool isFrameNumberLine(const std::vector<std::string_view>& tok, long long& number) {
    return tok.size() == 1 && parseInt(tok[0], number);
}

Clip readAmcClip(TextReader& r, const AsfSkeleton& asf) {
    Clip clip;
    clip.sourcePath = r.fileName();
    clip.skeletonPath = asf.path;
    clip.name = fileStem(r.fileName());
    clip.format = ClipFormat::kAmc;
    clip.convention = "cmu-asf";
    clip.fps = 120.0;  // not stored in AMC; CMU captured at 120 Hz
    clip.cmPerFileUnit = asf.cmPerUnit;
    clip.skeleton = asf.skeleton;
    const Skeleton& sk = clip.skeleton;

    std::unordered_map<std::string, int> jointByName;
    int bonesWithDofs = 0;
    for (int j = 0; j < sk.jointCount(); ++j) {
        jointByName[sk.joints[j].name] = j;
        if (!asf.channels[j].empty()) ++bonesWithDofs;
    }

    bool radians = asf.anglesInRadians;
    // Header: lines starting with '#' or ':' before the first frame number.
    while (!r.atEnd()) {
        const std::string_view t = trim(r.peekLine());
        if (t.empty() || t.front() == '#') {
            r.nextLine();
            continue;
        }
        if (t.front() != ':') break;
        const std::string key = toLower(splitTokens(t)[0]);
        if (key == ":radians") radians = true;
        if (key == ":degrees") radians = false;
        r.nextLine();
    }
    const double angleScale = radians ? kRadToDeg : 1.0;

    Pose blank;
    blank.anglesDeg.assign(sk.jointCount(), Eigen::Vector3d::Zero());
    std::vector<int> seenInFrame(sk.jointCount(), -1);
    long long expectedNumber = 0;
    int frameLine = 0;
    int bonesThisFrame = 0;

    auto finishFrame = [&]() {
        if (clip.frames.empty()) return;
        if (bonesThisFrame == bonesWithDofs) return;
        for (int j = 0; j < sk.jointCount(); ++j)
            if (!asf.channels[j].empty() && seenInFrame[j] != clip.frameCount() - 1)
                r.failAt(frameLine,
                         "a line for bone '" + sk.joints[j].name + "' in frame " + std::to_string(expectedNumber - 1),
                         "none");
    };

    while (!r.atEnd()) {
        const int line = r.lineNumber();
        const std::string_view raw = trim(r.nextLine());
        if (raw.empty() || raw.front() == '#') continue;
        const auto tok = splitTokens(raw);
        long long number = 0;
        if (isFrameNumberLine(tok, number)) {
            finishFrame();
            // Bounded so that number + 1 (and label + frame index later) cannot overflow: a
            // label of 2^63 − 1 was undefined behaviour.
            if (number < -kMaxAbsFrameNumber || number > kMaxAbsFrameNumber)
                r.failAt(line, "a frame number within ±1e12", quoteToken(tok[0]));
            if (!clip.frames.empty() && number != expectedNumber)
                r.failAt(line, "frame number " + std::to_string(expectedNumber), quoteToken(tok[0]));
            if (clip.frames.empty()) clip.firstFrameLabel = number;
            if (clip.frames.size() >= 10'000'000u) r.failAt(line, "at most 10,000,000 frames", "more");
            expectedNumber = number + 1;
            frameLine = line;
            bonesThisFrame = 0;
            clip.frames.push_back(blank);
            continue;
        }
        if (clip.frames.empty()) r.failAt(line, "a frame number (a line holding one integer)", quoteToken(raw));
        const auto it = jointByName.find(std::string(tok[0]));
        if (it == jointByName.end()) r.failAt(line, "a bone of " + asf.path, "unknown bone " + quoteToken(tok[0]));
        const int j = it->second;
        const auto& channels = asf.channels[j];
        if (channels.empty()) r.failAt(line, "only bones with DOFs", "bone '" + sk.joints[j].name + "' which has none");
        if (seenInFrame[j] == clip.frameCount() - 1)
            r.failAt(line, "bone '" + sk.joints[j].name + "' once per frame", "it twice");
        if (tok.size() - 1 != channels.size())
            r.failAt(line, std::to_string(channels.size()) + " values for bone '" + sk.joints[j].name + "'",
                     std::to_string(tok.size() - 1));
        Pose& pose = clip.frames.back();
        for (std::size_t i = 0; i < channels.size(); ++i) {
            double v = 0.0;
            if (!parseDouble(tok[i + 1], v))
                r.failAt(line, "a finite number for bone '" + sk.joints[j].name + "'", quoteToken(tok[i + 1]));
            if (channels[i].translation) {
                if (std::abs(v) > kMaxAbsTranslation)
                    r.failAt(line, "a root translation within ±1e7", quoteToken(tok[i + 1]));
                pose.rootCm[channels[i].axis] = v * asf.cmPerUnit;
            } else {
                v *= angleScale;
                if (std::abs(v) > kMaxAbsAngleDeg)
                    r.failAt(line, "an angle within ±1e6 degrees", quoteToken(tok[i + 1]));
                pose.anglesDeg[j][channels[i].axis] = v;
            }
        }
        seenInFrame[j] = clip.frameCount() - 1;
        ++bonesThisFrame;
    }
    if (clip.frames.empty()) r.failAt(r.lastLineNumber(), "at least one frame", "none");
    finishFrame();
    return clip;
}

}  // namespace

Clip readAmc(const std::string& amcPath, const AsfSkeleton& asf) {
    TextReader r = TextReader::fromFile(amcPath);
    return readAmcClip(r, asf);
}

Clip parseAmc(const std::string& name, std::string text, const AsfSkeleton& asf) {
    TextReader r = TextReader::fromString(name, std::move(text));
    return readAmcClip(r, asf);
}

}  // namespace mgp
