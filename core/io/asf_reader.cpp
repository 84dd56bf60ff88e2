#include "io/asf_reader.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "io/parse_error.h"
#include "io/text_reader.h"

namespace mgp {

namespace {

struct AsfBone {
    std::string name;
    int line = 0;
    Eigen::Vector3d direction = Eigen::Vector3d::Zero();
    double length = 0.0;
    Eigen::Vector3d axisAngles = Eigen::Vector3d::Zero();
    RotationOrder axisOrder = kOrderZYX;
    std::vector<Channel> channels;
    bool hasDirection = false, hasLength = false;
};

// "XYZ" (x applied first) → outermost-first order {Z, Y, X}.
bool parseAxisOrder(std::string_view s, RotationOrder& out) {
    const std::string u = toLower(s);
    if (u.size() != 3) return false;
    RotationOrder order{};
    bool seen[3] = {false, false, false};
    for (int i = 0; i < 3; ++i) {
        const int a = u[i] - 'x';
        if (a < 0 || a > 2 || seen[a]) return false;
        seen[a] = true;
        order[2 - i] = a;
    }
    out = order;
    return true;
}

bool parseChannel(std::string_view token, bool allowTranslation, Channel& out) {
    const std::string t = toLower(token);
    if (t.size() != 2 || (t[0] != 'r' && t[0] != 't') || t[1] < 'x' || t[1] > 'z') return false;
    if (t[0] == 't' && !allowTranslation) return false;
    out.translation = t[0] == 't';
    out.axis = t[1] - 'x';
    return true;
}

double needNumber(const TextReader& r, int line, std::string_view token, const char* what) {
    double v = 0.0;
    if (!parseDouble(token, v)) r.failAt(line, what, quoteToken(token));
    return v;
}

Eigen::Vector3d needVector(const TextReader& r, int line, const std::vector<std::string_view>& tok, std::size_t first,
                           const char* what) {
    if (tok.size() < first + 3)
        r.failAt(line, std::string("3 numbers for ") + what, std::to_string(tok.size() - first) + " values");
    return {needNumber(r, line, tok[first], "a number"), needNumber(r, line, tok[first + 1], "a number"),
            needNumber(r, line, tok[first + 2], "a number")};
}

}  // namespace

int AsfSkeleton::channelCount() const {
    int n = 0;
    for (const auto& c : channels) n += static_cast<int>(c.size());
    return n;
}

namespace {

using AsfTokens = std::vector<std::string_view>;

// What the sections declare, gathered line by line before the skeleton is built.
struct AsfDeclarations {
    double lengthUnit = 1.0;  // ASF default: inches
    std::vector<Channel> rootChannels;
    RotationOrder rootAxisOrder = kOrderZYX;
    Eigen::Vector3d rootOrientation = Eigen::Vector3d::Zero();
    bool sawRoot = false, sawBones = false, sawHierarchy = false;
    std::vector<AsfBone> bones;
    std::map<std::string, int> boneIndex;
    std::vector<int> parentOf;  // per bone: -1 = root, -2 = not yet placed
    std::vector<std::vector<int>> childrenOf = std::vector<std::vector<int>>(1);  // index 0 = root, bone i → i + 1
};

// A ":keyword" line: the section the following lines belong to.
void readAsfSectionHeader(const TextReader& r, int line, std::string_view keyword, std::string& section,
                          AsfDeclarations& d) {
    section = toLower(keyword);
    if (section == ":units" || section == ":root" || section == ":documentation" || section == ":bonedata" ||
        section == ":hierarchy" || section == ":skin")
        ;
    else if (section == ":version" || section == ":name")
        return;
    else
        r.failAt(line, "an ASF section (:units, :root, :bonedata, :hierarchy)", quoteToken(keyword));
    if (section == ":root") d.sawRoot = true;
    if (section == ":bonedata") d.sawBones = true;
    if (section == ":hierarchy") d.sawHierarchy = true;
    // Some writers put a value after the keyword on the same line; nothing we need.
}

void readAsfUnitsLine(const TextReader& r, int line, const AsfTokens& tok, const std::string& key, AsfDeclarations& d,
                      AsfSkeleton& out) {
    if (tok.size() < 2) r.failAt(line, "a unit value after " + key, "nothing");
    if (key == "length") {
        d.lengthUnit = needNumber(r, line, tok[1], "a positive length unit");
        if (!(d.lengthUnit > 0.0)) r.failAt(line, "a positive length unit", quoteToken(tok[1]));
    } else if (key == "angle") {
        const std::string u = toLower(tok[1]);
        if (u != "deg" && u != "rad") r.failAt(line, "angle unit 'deg' or 'rad'", quoteToken(tok[1]));
        out.anglesInRadians = u == "rad";
    }
}

void readAsfRootLine(const TextReader& r, int line, const AsfTokens& tok, const std::string& key, AsfDeclarations& d) {
    if (key == "order") {
        for (std::size_t i = 1; i < tok.size(); ++i) {
            Channel c;
            if (!parseChannel(tok[i], true, c))
                r.failAt(line, "a root channel (TX TY TZ RX RY RZ)", quoteToken(tok[i]));
            d.rootChannels.push_back(c);
        }
    } else if (key == "axis") {
        if (tok.size() < 2 || !parseAxisOrder(tok[1], d.rootAxisOrder))
            r.failAt(line, "a root axis order such as XYZ", tok.size() < 2 ? "nothing" : quoteToken(tok[1]));
    } else if (key == "orientation") {
        d.rootOrientation = needVector(r, line, tok, 1, "the root orientation");
    } else if (key == "position") {
        needVector(r, line, tok, 1, "the root position");
    } else {
        r.failAt(line, "order, axis, position or orientation in :root", quoteToken(tok[0]));
    }
}

void readAsfBoneDofs(const TextReader& r, int line, const AsfTokens& bt, AsfBone& bone) {
    for (std::size_t i = 1; i < bt.size(); ++i) {
        Channel c;
        if (!parseChannel(bt[i], false, c)) r.failAt(line, "a bone dof among rx ry rz", quoteToken(bt[i]));
        for (const Channel& prev : bone.channels)
            if (prev.axis == c.axis) r.failAt(line, "each dof once", "a repeated " + std::string(bt[i]));
        bone.channels.push_back(c);
    }
}

// The lines of one bone after its "begin" (on line `line`) up to and including its "end".
AsfBone readAsfBoneFields(TextReader& r, int line) {
    AsfBone bone;
    bone.line = line;
    bool ended = false;
    bool inLimits = false;
    while (!r.atEnd()) {
        const int bl = r.lineNumber();
        const std::string_view braw = trim(r.nextLine());
        if (braw.empty() || braw.front() == '#') continue;
        const auto bt = splitTokens(braw);
        const std::string bk = toLower(bt[0]);
        if (braw.front() == '(' && inLimits) continue;
        inLimits = false;
        if (bk == "end") {
            ended = true;
            break;
        } else if (bk == "id") {
        } else if (bk == "name") {
            if (bt.size() < 2) r.failAt(bl, "a bone name", "nothing");
            bone.name = std::string(bt[1]);
        } else if (bk == "direction") {
            bone.direction = needVector(r, bl, bt, 1, "the bone direction");
            bone.hasDirection = true;
        } else if (bk == "length") {
            if (bt.size() < 2) r.failAt(bl, "a bone length", "nothing");
            bone.length = needNumber(r, bl, bt[1], "a bone length");
            if (bone.length < 0.0 || bone.length > 1e6) r.failAt(bl, "a bone length in [0, 1e6]", quoteToken(bt[1]));
            bone.hasLength = true;
        } else if (bk == "axis") {
            bone.axisAngles = needVector(r, bl, bt, 1, "the bone axis");
            if (bt.size() < 5 || !parseAxisOrder(bt[4], bone.axisOrder))
                r.failAt(bl, "an axis order such as XYZ after the 3 axis angles",
                         bt.size() < 5 ? "nothing" : quoteToken(bt[4]));
        } else if (bk == "dof") {
            readAsfBoneDofs(r, bl, bt, bone);
        } else if (bk == "limits") {
            inLimits = true;
        } else if (bk == "bodymass" || bk == "cofmass") {
        } else if (bk == "begin" || bk.front() == ':') {
            r.failAt(bl, "'end' of bone '" + bone.name + "'", quoteToken(bt[0]));
        } else {
            r.failAt(bl, "a bone field (id, name, direction, length, axis, dof, limits)", quoteToken(bt[0]));
        }
    }
    if (!ended)
        r.failAt(r.lastLineNumber(), "'end' of the bone begun at line " + std::to_string(bone.line),
                 "the end of the file");
    return bone;
}

// A complete bone, checked, joins the declarations (not yet placed in the hierarchy).
void addAsfBone(const TextReader& r, AsfBone bone, AsfDeclarations& d) {
    if (bone.name.empty()) r.failAt(bone.line, "a 'name' in this bone", "none");
    if (!bone.hasDirection || !bone.hasLength)
        r.failAt(bone.line, "'direction' and 'length' for bone '" + bone.name + "'", "a bone without them");
    if (bone.name == "root" || d.boneIndex.count(bone.name))
        r.failAt(bone.line, "a unique bone name", "a second '" + bone.name + "'");
    d.boneIndex[bone.name] = static_cast<int>(d.bones.size());
    d.bones.push_back(std::move(bone));
    d.parentOf.push_back(-2);
    d.childrenOf.emplace_back();
}

// A name in :hierarchy → its node (0 = root, bone i → i + 1).
int asfHierarchyNode(const TextReader& r, int line, const AsfDeclarations& d, std::string_view name) {
    if (name == "root") return 0;
    const auto it = d.boneIndex.find(std::string(name));
    if (it == d.boneIndex.end()) r.failAt(line, "a bone declared in :bonedata", quoteToken(name));
    return it->second + 1;
}

// "parent child child ...": each child gets its one parent.
void readAsfHierarchyLine(const TextReader& r, int line, const AsfTokens& tok, AsfDeclarations& d) {
    const int parent = asfHierarchyNode(r, line, d, tok[0]);
    for (std::size_t i = 1; i < tok.size(); ++i) {
        const int child = asfHierarchyNode(r, line, d, tok[i]);
        if (child == 0 || d.parentOf[child - 1] != -2)
            r.failAt(line, "each bone to have one parent", "a second parent for '" + std::string(tok[i]) + "'");
        d.parentOf[child - 1] = parent - 1;
        d.childrenOf[parent].push_back(child);
    }
}

void checkAsfSectionsPresent(const TextReader& r, const AsfDeclarations& d) {
    if (!d.sawRoot) r.failAt(r.lastLineNumber(), "a :root section", "none");
    if (!d.sawBones || d.bones.empty()) r.failAt(r.lastLineNumber(), "a :bonedata section with bones", "none");
    if (!d.sawHierarchy) r.failAt(r.lastLineNumber(), "a :hierarchy section", "none");
    if (d.rootChannels.empty()) r.failAt(r.lastLineNumber(), "an 'order' line in :root", "none");
}

void addAsfRootJoint(const AsfDeclarations& d, double angleScale, AsfSkeleton& out) {
    Joint root;
    root.name = root.bone = "root";
    root.axis = eulerMatrix(d.rootOrientation * angleScale, d.rootAxisOrder);
    root.order = rotationOrderOf(d.rootChannels, ChannelListing::kAppliedFirst);
    for (const Channel& c : d.rootChannels)
        if (!c.translation) root.dof[c.axis] = true;
    out.skeleton.joints.push_back(root);
    out.channels.push_back(d.rootChannels);
}

// Depth-first from the root so parents precede children. Returns each node's joint (-1: the
// hierarchy never reaches it).
std::vector<int> addAsfBoneJoints(const AsfDeclarations& d, double angleScale, AsfSkeleton& out) {
    Skeleton& sk = out.skeleton;
    std::vector<int> jointOfNode(d.bones.size() + 1, -1);
    jointOfNode[0] = 0;
    std::vector<int> stack(d.childrenOf[0].rbegin(), d.childrenOf[0].rend());
    while (!stack.empty()) {
        const int node = stack.back();
        stack.pop_back();
        const AsfBone& b = d.bones[node - 1];
        const int parentNode = d.parentOf[node - 1] + 1;
        Joint j;
        j.name = j.bone = b.name;
        j.parent = jointOfNode[parentNode];
        const double norm = b.direction.norm();
        const Eigen::Vector3d dir = norm > 0.0 ? Eigen::Vector3d(b.direction / norm) : Eigen::Vector3d::Zero();
        j.tailCm = dir * b.length * out.cmPerUnit;
        j.offsetCm = parentNode == 0 ? Eigen::Vector3d::Zero() : sk.joints[j.parent].tailCm;
        j.axis = eulerMatrix(b.axisAngles * angleScale, b.axisOrder);
        j.order = rotationOrderOf(b.channels, ChannelListing::kAppliedFirst);
        for (const Channel& c : b.channels) j.dof[c.axis] = true;
        jointOfNode[node] = sk.jointCount();
        sk.joints.push_back(j);
        out.channels.push_back(b.channels);
        for (auto it = d.childrenOf[node].rbegin(); it != d.childrenOf[node].rend(); ++it) stack.push_back(*it);
    }
    return jointOfNode;
}

// A bone the hierarchy never reaches is an error (it could not be placed).
void checkAsfBonesPlaced(const TextReader& r, const AsfDeclarations& d, const std::vector<int>& jointOfNode) {
    for (std::size_t i = 0; i < d.bones.size(); ++i) {
        if (jointOfNode[i + 1] >= 0) continue;
        // Not reached from root: either it (or an ancestor) has no parent, or its parents form
        // a cycle (a ↔ b, or a bone listed as its own child), which "no parent" would misname.
        std::size_t b = i;
        for (std::size_t steps = 0; steps <= d.bones.size() && d.parentOf[b] >= 0; ++steps)
            b = static_cast<std::size_t>(d.parentOf[b]);
        if (d.parentOf[b] >= 0)
            r.failAt(d.bones[i].line, "bone '" + d.bones[i].name + "' to hang from root in :hierarchy",
                     "a cycle through '" + d.bones[i].name + "'");
        r.failAt(d.bones[b].line, "bone '" + d.bones[b].name + "' to appear in :hierarchy", "a bone with no parent");
    }
}

// The joints from the declarations: root first, then the bones in hierarchy order.
void buildAsfSkeleton(const TextReader& r, const AsfDeclarations& d, AsfSkeleton& out) {
    out.cmPerUnit = 2.54 / d.lengthUnit;
    const double angleScale = out.anglesInRadians ? kRadToDeg : 1.0;
    addAsfRootJoint(d, angleScale, out);
    const std::vector<int> jointOfNode = addAsfBoneJoints(d, angleScale, out);
    checkAsfBonesPlaced(r, d, jointOfNode);
    out.skeleton.resolveEffectors();
}

AsfSkeleton readAsfSkeleton(TextReader& r) {
    AsfSkeleton out;
    out.path = r.fileName();
    AsfDeclarations d;
    std::string section;
    while (!r.atEnd()) {
        const int line = r.lineNumber();
        const std::string_view raw = trim(r.nextLine());
        if (raw.empty() || raw.front() == '#') continue;
        const auto tok = splitTokens(raw);
        if (raw.front() == ':') {
            readAsfSectionHeader(r, line, tok[0], section, d);
            continue;
        }
        const std::string key = toLower(tok[0]);
        if (section == ":units") {
            readAsfUnitsLine(r, line, tok, key, d, out);
        } else if (section == ":root") {
            readAsfRootLine(r, line, tok, key, d);
        } else if (section == ":bonedata") {
            if (key != "begin") r.failAt(line, "'begin' of a bone", quoteToken(tok[0]));
            addAsfBone(r, readAsfBoneFields(r, line), d);
        } else if (section == ":hierarchy") {
            if (key == "begin" || key == "end") continue;
            readAsfHierarchyLine(r, line, tok, d);
        } else if (section == ":documentation" || section == ":skin") {
            continue;
        } else {
            r.failAt(line, "a section header such as :units", quoteToken(tok[0]));
        }
    }
    checkAsfSectionsPresent(r, d);
    buildAsfSkeleton(r, d, out);
    return out;
}

}  // namespace

AsfSkeleton readAsf(const std::string& path) {
    TextReader r = TextReader::fromFile(path, 16u << 20);
    return readAsfSkeleton(r);
}

AsfSkeleton parseAsf(const std::string& name, std::string text) {
    TextReader r = TextReader::fromString(name, std::move(text));
    return readAsfSkeleton(r);
}

}  // namespace mgp
