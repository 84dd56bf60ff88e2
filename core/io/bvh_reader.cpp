#include "io/bvh_reader.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "io/bvh_conventions.h"
#include "io/channel.h"
#include "io/parse_error.h"
#include "io/text_reader.h"

namespace mgp {

namespace {

constexpr int kMaxJoints = 4096;
constexpr int kMaxDepth = 256;
constexpr double kMaxAbsValue = 1e7;

struct Token {
    std::string_view text;
    int line;
};

struct RawJoint {
    std::string name;
    int parent = -1;
    int line = 0;
    Eigen::Vector3d offset = Eigen::Vector3d::Zero();
    std::vector<Channel> channels;  // file order
    std::vector<int> children;
    bool hasEndSite = false;
    Eigen::Vector3d endSite = Eigen::Vector3d::Zero();
};

class HierarchyParser {
public:
    explicit HierarchyParser(TextReader& r) : r_(r) {}

    // Tokenizes lines until the MOTION keyword (consumed).
    void tokenize() {
        while (!r_.atEnd()) {
            const int line = r_.lineNumber();
            const std::string_view l = r_.nextLine();
            for (std::string_view t : splitTokens(l)) {
                if (t == "MOTION" || t == "motion") {
                    sawMotion_ = true;
                    return;
                }
                tokens_.push_back({t, line});
            }
        }
    }

    std::vector<RawJoint> parse() {
        if (tokens_.empty()) r_.failAt(1, "'HIERARCHY'", "no text");  // quoted as expect() quotes it
        expect("HIERARCHY");
        expect("ROOT");
        parseJoint(-1, 0);
        if (pos_ < tokens_.size()) fail("MOTION after the root joint's closing brace");
        if (!sawMotion_) r_.failAt(r_.lastLineNumber(), "MOTION", "the end of the file");
        return std::move(joints_);
    }

    int channelCount() const { return channelCount_; }

private:
    const Token& peek() {
        if (pos_ >= tokens_.size())
            r_.failAt(tokens_.empty() ? 1 : tokens_.back().line, "more of the hierarchy",
                      sawMotion_ ? "MOTION" : "the end of the file");
        return tokens_[pos_];
    }
    const Token& take() {
        const Token& t = peek();
        ++pos_;
        return t;
    }
    [[noreturn]] void fail(const std::string& expected) {
        const Token& t = peek();
        r_.failAt(t.line, expected, quoteToken(t.text));
    }
    void expect(std::string_view word) {
        if (peek().text != word) fail("'" + std::string(word) + "'");
        ++pos_;
    }
    double number() {
        const Token& t = peek();
        double v = 0.0;
        if (!parseDouble(t.text, v)) fail("a finite number");
        if (std::abs(v) > kMaxAbsValue) fail("a number within ±1e7");
        ++pos_;
        return v;
    }
    Eigen::Vector3d offset() {
        expect("OFFSET");
        const double x = number(), y = number(), z = number();
        return {x, y, z};
    }

    void parseJoint(int parent, int depth) {
        if (depth > kMaxDepth) fail("a hierarchy at most 256 joints deep");
        if (static_cast<int>(joints_.size()) >= kMaxJoints) fail("at most 4096 joints");
        RawJoint j;
        j.line = peek().line;
        j.name = std::string(take().text);
        if (j.name == "{") r_.failAt(j.line, "a joint name", "'{'");
        if (names_.count(j.name)) r_.failAt(j.line, "a unique joint name", "a second '" + j.name + "'");
        names_.insert(j.name);
        j.parent = parent;
        expect("{");
        j.offset = offset();
        if (peek().text == "CHANNELS") {
            ++pos_;
            const Token& countTok = take();
            long long n = 0;
            if (!parseInt(countTok.text, n) || n < 0 || n > 6)
                r_.failAt(countTok.line, "a channel count from 0 to 6", quoteToken(countTok.text));
            std::set<std::string> seen;
            for (long long i = 0; i < n; ++i) {
                const Token& c = take();
                const std::string lower = toLower(c.text);
                Channel ch;
                if (lower.size() == 9 && lower.compare(1, 8, "rotation") == 0 && lower[0] >= 'x' && lower[0] <= 'z') {
                    ch.axis = lower[0] - 'x';
                } else if (lower.size() == 9 && lower.compare(1, 8, "position") == 0 && lower[0] >= 'x' &&
                           lower[0] <= 'z') {
                    ch.translation = true;
                    ch.axis = lower[0] - 'x';
                    if (parent >= 0)
                        r_.failAt(c.line, "position channels on the root only",
                                  quoteToken(c.text) + " on joint '" + j.name + "'");
                } else {
                    r_.failAt(c.line, "a channel name such as Zrotation or Xposition", quoteToken(c.text));
                }
                if (!seen.insert(lower).second)
                    r_.failAt(c.line, "each channel once per joint", "a repeated " + quoteToken(c.text));
                j.channels.push_back(ch);
            }
            channelCount_ += static_cast<int>(n);
        }
        const int index = static_cast<int>(joints_.size());
        joints_.push_back(std::move(j));
        if (parent >= 0) joints_[parent].children.push_back(index);
        while (true) {
            const Token& t = peek();
            if (t.text == "}") {
                ++pos_;
                return;
            }
            if (t.text == "JOINT") {
                ++pos_;
                parseJoint(index, depth + 1);
            } else if (t.text == "End") {
                ++pos_;
                expect("Site");
                expect("{");
                joints_[index].endSite = offset();
                joints_[index].hasEndSite = true;
                expect("}");
            } else {
                fail("JOINT, End Site or '}' in joint '" + joints_[index].name + "'");
            }
        }
    }

    TextReader& r_;
    std::vector<Token> tokens_;
    std::size_t pos_ = 0;
    bool sawMotion_ = false;
    std::vector<RawJoint> joints_;
    std::set<std::string> names_;
    int channelCount_ = 0;
};

// Joint tail: the offset of the child that continues the bone (by role, else the only child),
// else the End Site, else the mean of the children's offsets.
Eigen::Vector3d tailOf(const std::vector<RawJoint>& raw, const std::vector<std::string>& roles, int j) {
    const RawJoint& joint = raw[j];
    const std::string wanted = mainChildRole(roles[j]);
    if (!wanted.empty())
        for (int c : joint.children)
            if (roles[c] == wanted) return raw[c].offset;
    if (joint.children.size() == 1) return raw[joint.children[0]].offset;
    if (joint.hasEndSite && joint.children.empty()) return joint.endSite;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (int c : joint.children) mean += raw[c].offset;
    return joint.children.empty() ? mean : Eigen::Vector3d(mean / double(joint.children.size()));
}

Clip readBvhClip(TextReader& r) {
    HierarchyParser hp(r);
    hp.tokenize();
    std::vector<RawJoint> raw = hp.parse();
    const int channelTotal = hp.channelCount();

    // MOTION header.
    r.skipBlankAndComments("");
    // A file cut right after MOTION (or after Frames:) says which header line is missing.
    if (r.atEnd()) r.failAt(r.lastLineNumber(), "'Frames: N'", "the end of the file");
    const int framesLine = r.lineNumber();
    auto framesTok = splitTokens(r.nextLine());
    long long frames = -1;
    if (framesTok.size() == 2 && framesTok[0] == "Frames:")
        parseInt(framesTok[1], frames);
    else if (framesTok.size() == 3 && framesTok[0] == "Frames" && framesTok[1] == ":")
        parseInt(framesTok[2], frames);
    else
        r.failAt(framesLine, "'Frames: N'", quoteToken(framesTok.empty() ? "" : framesTok[0]));
    if (frames < 1) r.failAt(framesLine, "a frame count of at least 1", quoteToken(framesTok.back()));
    r.skipBlankAndComments("");
    if (r.atEnd()) r.failAt(r.lastLineNumber(), "'Frame Time: SECONDS'", "the end of the file");
    const int timeLine = r.lineNumber();
    auto timeTok = splitTokens(r.nextLine());
    double frameTime = 0.0;
    if (!(timeTok.size() == 3 && timeTok[0] == "Frame" && timeTok[1] == "Time:" && parseDouble(timeTok[2], frameTime)))
        r.failAt(timeLine, "'Frame Time: SECONDS'", quoteToken(timeTok.empty() ? "" : timeTok[0]));
    if (!(frameTime > 0.0 && frameTime < 10.0))
        r.failAt(timeLine, "a frame time in (0, 10) seconds", quoteToken(timeTok[2]));

    // Count the rows before allocating anything sized by the header.
    const long long rows = r.lastLineNumber() - r.lineNumber() + 1;
    if (frames > rows)
        r.failAt(r.lastLineNumber(), std::to_string(frames) + " frame rows (Frames:)",
                 "at most " + std::to_string(rows) + " lines left");

    Clip clip;
    clip.sourcePath = r.fileName();
    clip.name = fileStem(r.fileName());
    clip.format = ClipFormat::kBvh;
    double fps = 1.0 / frameTime;
    if (std::abs(fps - std::round(fps)) < 0.01) fps = std::round(fps);
    clip.fps = fps;

    std::vector<std::string> names;
    for (const RawJoint& j : raw) names.push_back(j.name);
    const BvhConvention conv = detectBvhConvention(names);
    clip.convention = conv.name;
    clip.cmPerFileUnit = conv.cmPerUnit;
    std::vector<std::string> roles(raw.size());
    std::set<std::string> usedRoles;
    for (std::size_t i = 0; i < raw.size(); ++i) {
        std::string role = i == 0 ? "root" : boneRoleFor(conv.name, raw[i].name);
        if (i > 0 && role == "root") role.clear();
        if (!role.empty() && !usedRoles.insert(role).second) role.clear();
        roles[i] = role;
        if (role.empty()) clip.unmappedJoints.push_back(raw[i].name);
    }

    Skeleton& sk = clip.skeleton;
    sk.poseVector = PoseVectorKind::kChannels;  // a BVH clip trains on its own channels
    for (std::size_t i = 0; i < raw.size(); ++i) {
        Joint j;
        j.name = raw[i].name;
        j.bone = roles[i];
        j.parent = raw[i].parent;
        j.offsetCm = i == 0 ? Eigen::Vector3d::Zero() : Eigen::Vector3d(raw[i].offset * conv.cmPerUnit);
        j.tailCm = tailOf(raw, roles, static_cast<int>(i)) * conv.cmPerUnit;
        j.order = rotationOrderOf(raw[i].channels, ChannelListing::kOutermostFirst);
        for (const Channel& c : raw[i].channels)
            if (!c.translation) j.dof[c.axis] = true;
        sk.joints.push_back(std::move(j));
    }
    sk.resolveEffectors();
    // The root's OFFSET is where it sits when the position channels are zero.
    const Eigen::Vector3d rootOffset = raw[0].offset * conv.cmPerUnit;

    clip.frames.reserve(static_cast<std::size_t>(frames));
    Pose blank;
    blank.anglesDeg.assign(raw.size(), Eigen::Vector3d::Zero());
    long long read = 0;
    while (!r.atEnd()) {
        const int line = r.lineNumber();
        const auto tok = splitTokens(r.nextLine());
        if (tok.empty()) continue;
        if (read == frames) r.failAt(line, std::to_string(frames) + " frame rows (Frames:)", "more rows");
        if (static_cast<int>(tok.size()) != channelTotal)
            r.failAt(line, std::to_string(channelTotal) + " values per frame row", std::to_string(tok.size()));
        Pose pose = blank;
        pose.rootCm = rootOffset;
        std::size_t k = 0;
        for (std::size_t j = 0; j < raw.size(); ++j)
            for (const Channel& c : raw[j].channels) {
                double v = 0.0;
                if (!parseDouble(tok[k], v))
                    r.failAt(line, "a finite number (value " + std::to_string(k + 1) + ")", quoteToken(tok[k]));
                if (std::abs(v) > kMaxAbsValue) r.failAt(line, "a value within ±1e7", quoteToken(tok[k]));
                ++k;
                if (c.translation)
                    pose.rootCm[c.axis] = rootOffset[c.axis] + v * conv.cmPerUnit;
                else
                    pose.anglesDeg[j][c.axis] = v;
            }
        clip.frames.push_back(std::move(pose));
        ++read;
    }
    if (read != frames)
        r.failAt(r.lastLineNumber(), std::to_string(frames) + " frame rows (Frames:)", std::to_string(read));
    clip.restFrame = conv.convertersAddRestFrame && clip.frames[0].anglesDeg[0].isZero(0.0);
    return clip;
}

}  // namespace

Clip readBvh(const std::string& path) {
    TextReader r = TextReader::fromFile(path);
    return readBvhClip(r);
}

Clip parseBvh(const std::string& name, std::string text) {
    TextReader r = TextReader::fromString(name, std::move(text));
    return readBvhClip(r);
}

}  // namespace mgp
