// Every malformed input gives one clear error naming file, line, what was expected and found.
// Table-driven: each case states its exact expected message.
#include <sys/stat.h>

#include "io/amc_reader.h"
#include "io/asf_reader.h"
#include "io/bvh_reader.h"
#include "io/clip_loader.h"
#include "io/parse_error.h"
#include "test_support.h"
#include "tiny_inputs.h"

using namespace mgp;

namespace {

const std::string& kAsf = test::kTinyAsf;
const std::string& kAmc = test::kTinyAmc;
const std::string& kBvh = test::kTinyBvh;
using test::replaced;

std::string errorOf(const std::function<void()>& fn) {
    try {
        fn();
    } catch (const ParseError& e) {
        return e.what();
    }
    return "(no error)";
}

struct Case {
    std::string name;
    std::string text;
    std::string expected;
};

// Each case's text, parsed by `parse`, must fail with exactly its expected message.
void checkCases(const std::vector<Case>& cases, const std::function<void(const std::string&)>& parse) {
    for (const Case& c : cases) {
        CAPTURE(c.name);
        CHECK(errorOf([&] { parse(c.text); }) == c.expected);
    }
}

}  // namespace

TEST_CASE("the valid base files parse") {
    const AsfSkeleton asf = parseAsf("t.asf", kAsf);
    CHECK(parseAmc("t.amc", kAmc, asf).frameCount() == 2);
    CHECK(parseBvh("t.bvh", kBvh).frameCount() == 2);
}

TEST_CASE("bad ASF files") {
    const std::vector<Case> cases = {
        {"unknown section", replaced(kAsf, ":hierarchy", ":hierarchie"),
         "t.asf:32: expected an ASF section (:units, :root, :bonedata, :hierarchy), found ':hierarchie'"},
        {"non-numeric length", replaced(kAsf, "length 7\n     axis 0 0 20", "length seven\n     axis 0 0 20"),
         "t.asf:17: expected a bone length, found 'seven'"},
        {"NaN direction",
         replaced(kAsf, "direction 0 -1 0\n     length 7\n     axis 0 0 20",
                  "direction 0 nan 0\n     length 7\n     axis 0 0 20"),
         "t.asf:16: expected a number, found 'nan'"},
        {"huge length", replaced(kAsf, "length 7\n     axis 0 0 20", "length 1e308\n     axis 0 0 20"),
         "t.asf:17: expected a bone length in [0, 1e6], found '1e308'"},
        {"bad dof", replaced(kAsf, "dof rx\n", "dof rw\n"), "t.asf:30: expected a bone dof among rx ry rz, found 'rw'"},
        {"unknown bone in hierarchy", replaced(kAsf, "lfemur ltibia", "lfemur lknee"),
         "t.asf:35: expected a bone declared in :bonedata, found 'lknee'"},
        {"two parents", replaced(kAsf, "lfemur ltibia", "lfemur ltibia\n    root ltibia"),
         "t.asf:36: expected each bone to have one parent, found a second parent for 'ltibia'"},
        {"bone not in hierarchy", replaced(kAsf, "    lfemur ltibia\n", ""),
         "t.asf:24: expected bone 'ltibia' to appear in :hierarchy, found a bone with no parent"},
        {"truncated in bonedata", std::string(kAsf).substr(0, std::string(kAsf).find("dof rx\n")),
         "t.asf:30: expected 'end' of the bone begun at line 24, found the end of the file"},
        {"no hierarchy", std::string(kAsf).substr(0, std::string(kAsf).find(":hierarchy")),
         "t.asf:31: expected a :hierarchy section, found none"},
        {"duplicate bone", replaced(kAsf, "name ltibia", "name lfemur"),
         "t.asf:24: expected a unique bone name, found a second 'lfemur'"},
        {"zero length unit", replaced(kAsf, "length 0.45", "length 0"),
         "t.asf:5: expected a positive length unit, found '0'"},
        {"bad axis order", replaced(kAsf, "axis 0 0 0 XYZ", "axis 0 0 0 XYQ"),
         "t.asf:29: expected an axis order such as XYZ after the 3 axis angles, found 'XYQ'"},
        {"missing root order", replaced(kAsf, "   order TX TY TZ RX RY RZ\n", ""),
         "t.asf:35: expected an 'order' line in :root, found none"},
    };
    checkCases(cases, [](const std::string& text) { parseAsf("t.asf", text); });
}

TEST_CASE("bad AMC files") {
    const AsfSkeleton asf = parseAsf("t.asf", kAsf);
    const std::vector<Case> cases = {
        {"unknown bone", replaced(kAmc, "ltibia 5", "lknee 5"),
         "t.amc:11: expected a bone of t.asf, found unknown bone 'lknee'"},
        {"too few values", replaced(kAmc, "lfemur 1 2 3\nltibia 4", "lfemur 1 2\nltibia 4"),
         "t.amc:6: expected 3 values for bone 'lfemur', found 2"},
        {"non-numeric", replaced(kAmc, "ltibia 4", "ltibia four"),
         "t.amc:7: expected a finite number for bone 'ltibia', found 'four'"},
        {"NaN", replaced(kAmc, "ltibia 4", "ltibia nan"),
         "t.amc:7: expected a finite number for bone 'ltibia', found 'nan'"},
        {"Inf", replaced(kAmc, "ltibia 4", "ltibia inf"),
         "t.amc:7: expected a finite number for bone 'ltibia', found 'inf'"},
        {"1e308 angle", replaced(kAmc, "ltibia 4", "ltibia 1e308"),
         "t.amc:7: expected an angle within ±1e6 degrees, found '1e308'"},
        {"overflow", replaced(kAmc, "ltibia 4", "ltibia 1e999"),
         "t.amc:7: expected a finite number for bone 'ltibia', found '1e999'"},
        {"missing bone in a frame", replaced(kAmc, "lfemur 1 2 3\nltibia 5", "lfemur 1 2 3"),
         "t.amc:8: expected a line for bone 'ltibia' in frame 2, found none"},
        {"duplicate bone", replaced(kAmc, "ltibia 5", "ltibia 5\nltibia 5"),
         "t.amc:12: expected bone 'ltibia' once per frame, found it twice"},
        {"frame numbers skip", replaced(kAmc, "\n2\n", "\n3\n"), "t.amc:8: expected frame number 2, found '3'"},
        {"no frames", "#!OML\n:FULLY-SPECIFIED\n:DEGREES\n", "t.amc:3: expected at least one frame, found none"},
        {"data before a frame number", replaced(kAmc, "\n1\n", "\n"),
         "t.amc:4: expected a frame number (a line holding one integer), found 'root 1 2 3 4 5 6'"},
        {"truncated last frame", std::string(kAmc).substr(0, std::string(kAmc).size() - 9),
         "t.amc:8: expected a line for bone 'ltibia' in frame 2, found none"},
        // Regressions (UBSan: signed overflow in parseInt, and in frame number + 1).
        {"frame number beyond long long", replaced(kAmc, "\n1\n", "\n9999999999999999999\n"),
         "t.amc:4: expected a frame number (a line holding one integer), found '9999999999999999999'"},
        {"frame number LLONG_MAX", replaced(kAmc, "\n1\n", "\n9223372036854775807\n"),
         "t.amc:4: expected a frame number within ±1e12, found '9223372036854775807'"},
    };
    checkCases(cases, [&](const std::string& text) { parseAmc("t.amc", text, asf); });
}

TEST_CASE("bad BVH files") {
    const std::vector<Case> cases = {
        {"no HIERARCHY", replaced(kBvh, "HIERARCHY", "HIERARCHIE"),
         "t.bvh:1: expected 'HIERARCHY', found 'HIERARCHIE'"},
        {"missing brace", replaced(kBvh, "  JOINT LeftUpLeg\n  {", "  JOINT LeftUpLeg\n"),
         "t.bvh:8: expected '{', found 'OFFSET'"},
        {"bad channel",
         replaced(kBvh, "Zrotation Yrotation Xrotation\n    End", "Zrotation Yrotation Wrotation\n    End"),
         "t.bvh:9: expected a channel name such as Zrotation or Xposition, found 'Wrotation'"},
        {"channel count", replaced(kBvh, "CHANNELS 3", "CHANNELS 9"),
         "t.bvh:9: expected a channel count from 0 to 6, found '9'"},
        {"NaN offset", replaced(kBvh, "OFFSET 1 -1 0", "OFFSET 1 NaN 0"),
         "t.bvh:8: expected a finite number, found 'NaN'"},
        {"duplicate joint", replaced(kBvh, "JOINT LeftUpLeg", "JOINT Hips"),
         "t.bvh:6: expected a unique joint name, found a second 'Hips'"},
        {"positions on a child", replaced(kBvh, "CHANNELS 3 Zrotation", "CHANNELS 3 Xposition"),
         "t.bvh:9: expected position channels on the root only, found 'Xposition' on joint 'LeftUpLeg'"},
        {"no MOTION", std::string(kBvh).substr(0, std::string(kBvh).find("MOTION")),
         "t.bvh:15: expected MOTION, found the end of the file"},
        {"unclosed hierarchy", replaced(kBvh, "  }\n}\nMOTION", "  }\nMOTION"),
         "t.bvh:14: expected more of the hierarchy, found MOTION"},
        {"frames declared 10^7", replaced(kBvh, "Frames: 2", "Frames: 10000000"),
         "t.bvh:20: expected 10000000 frame rows (Frames:), found at most 2 lines left"},
        {"negative frames", replaced(kBvh, "Frames: 2", "Frames: -5"),
         "t.bvh:17: expected a frame count of at least 1, found '-5'"},
        {"frames beyond long long", replaced(kBvh, "Frames: 2", "Frames: 9999999999999999999"),  // UBSan regression
         "t.bvh:17: expected a frame count of at least 1, found '9999999999999999999'"},
        {"zero frame time", replaced(kBvh, ".0083333", "0"),
         "t.bvh:18: expected a frame time in (0, 10) seconds, found '0'"},
        {"short row", replaced(kBvh, "0 17 0 0 0 0 5 0 0", "0 17 0 0 0 0 5 0"),
         "t.bvh:20: expected 9 values per frame row, found 8"},
        {"too few rows", replaced(kBvh, "Frames: 2", "Frames: 3"),
         "t.bvh:20: expected 3 frame rows (Frames:), found at most 2 lines left"},
        {"too many rows", replaced(kBvh, "Frames: 2", "Frames: 1"),
         "t.bvh:20: expected 1 frame rows (Frames:), found more rows"},
        {"Inf value", replaced(kBvh, "0 17 0 0 0 0 5 0 0", "0 17 0 0 0 0 inf 0 0"),
         "t.bvh:20: expected a finite number (value 7), found 'inf'"},
        {"1e308 value", replaced(kBvh, "0 17 0 0 0 0 5 0 0", "0 17 0 0 0 0 1e308 0 0"),
         "t.bvh:20: expected a value within ±1e7, found '1e308'"},
        {"missing Frame Time", replaced(kBvh, "Frame Time: .0083333\n", ""),
         "t.bvh:18: expected 'Frame Time: SECONDS', found '0'"},
    };
    checkCases(cases, [](const std::string& text) { parseBvh("t.bvh", text); });
}

TEST_CASE("bad files at the file level: missing, directory, empty, binary, wrong extension") {
    const std::string dir = test::scratchDir("bad_files");
    test::writeText(dir + "/empty.bvh", "");
    test::writeText(dir + "/binary.bvh", std::string("HIER\0ARCHY", 10));
    test::writeText(dir + "/clip.txt", "hello");
    ::mkdir((dir + "/folder.bvh").c_str(), 0755);
    CHECK(errorOf([&] { loadClip(dir + "/missing.bvh"); }) ==
          dir + "/missing.bvh: expected a readable file, found none (No such file or directory)");
    CHECK(errorOf([&] { loadClip(dir + "/empty.bvh"); }) ==
          dir + "/empty.bvh: expected mocap text, found an empty file");
    CHECK(errorOf([&] { loadClip(dir + "/binary.bvh"); }) ==
          dir + "/binary.bvh:1: expected text, found binary data (a NUL byte)");
    CHECK(errorOf([&] { loadClip(dir + "/folder.bvh"); }) == dir + "/folder.bvh: expected a file, found a directory");
    CHECK(errorOf([&] { loadClip(dir + "/clip.txt"); }) ==
          dir + "/clip.txt: expected a clip ending in .amc, .bvh, .glb or .gltf, found '.txt'");
    CHECK(errorOf([&] { loadClip(test::mocap("asf_amc/35.asf")); }) ==
          test::mocap("asf_amc/35.asf") +
              ": expected a motion clip (.amc or .bvh; pass the .asf with --skel), found a skeleton file");
    // An AMC whose subject ASF is missing names the ASF it looked for.
    test::writeText(dir + "/77_01.amc", kAmc);
    CHECK(errorOf([&] { loadClip(dir + "/77_01.amc"); }) ==
          dir + "/77.asf: expected a readable file, found none (No such file or directory)");
}

TEST_CASE("50 MB of garbage fails fast on its first line") {
    std::string garbage(50u << 20, 'x');
    for (std::size_t i = 0; i < garbage.size(); i += 97) garbage[i] = '\n';
    const std::string dir = test::scratchDir("garbage");
    test::writeText(dir + "/junk.bvh", garbage);
    test::writeText(dir + "/junk.amc", garbage);
    test::writeText(dir + "/junk.asf", garbage);
    // Line 1 is empty (the first byte is a newline); line 2 is the first garbage line.
    const std::string shown = "'xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx...'";
    CHECK(errorOf([&] { loadClip(dir + "/junk.bvh"); }) == dir + "/junk.bvh:2: expected 'HIERARCHY', found " + shown);
    CHECK(errorOf([&] { loadClip(dir + "/junk.amc", dir + "/junk.asf"); }) ==
          dir + "/junk.asf: expected a file of at most 16 MB, found 52428800 bytes");
    const AsfSkeleton asf = parseAsf("t.asf", kAsf);
    CHECK(errorOf([&] { readAmc(dir + "/junk.amc", asf); }) ==
          dir + "/junk.amc:2: expected a frame number (a line holding one integer), found " + shown);
}
