// The hostile-input table: bad files run end to end through the command line,
// as a user would run them. Every case must end with its one clear error on stderr
// ("motiongp: error: FILE[:LINE]: expected …, found …", asserted exactly) and a non-zero exit —
// never a signal, never a hang (each child is killed after 20 s) and never a huge allocation
// (each child runs under RLIMIT_AS = 2 GiB, so a multi-GB allocation shows up as a bad_alloc
// message instead of the expected one). The parsers' own messages are unit-tested at library
// level in test_bad_inputs.cpp; this file checks what reaches the user, with bounded time and
// memory. Files are generated at test time in a scratch folder.
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <functional>
#include <nlohmann/json.hpp>
#include <random>
#include <regex>
#include <set>
#include <vector>

#include "gp/model_file.h"
#include "gp/train/trainer.h"
#include "io/parse_error.h"
#include "session/session_file.h"
#include "skeleton/synthetic_clip.h"
#include "skip.h"
#include "test_support.h"
#include "tiny_inputs.h"

using namespace mgp;

namespace {

const std::string& kAsf = test::kTinyAsf;
const std::string& kAmc = test::kTinyAmc;
const std::string& kBvh = test::kTinyBvh;
using test::replaced;

// The text up to (not including) `marker`.
std::string cutBefore(const std::string& text, const std::string& marker) {
    const std::size_t at = text.find(marker);
    REQUIRE_MESSAGE(at != std::string::npos, "test setup: '" << marker << "' not in the base file");
    return text.substr(0, at);
}

// The text up to and including `marker`.
std::string cutAfter(const std::string& text, const std::string& marker) {
    const std::size_t at = text.find(marker);
    REQUIRE_MESSAGE(at != std::string::npos, "test setup: '" << marker << "' not in the base file");
    return text.substr(0, at + marker.size());
}

// 1-based line of the first occurrence of `needle`.
int lineOf(const std::string& text, const std::string& needle) {
    const std::size_t at = text.find(needle);
    REQUIRE_MESSAGE(at != std::string::npos, "test setup: '" << needle << "' not in the text");
    return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
}

std::string at(const std::string& path, int line) { return path + ":" + std::to_string(line); }

struct HostileCase {
    HostileCase(std::string g, std::string n, std::vector<std::string> a, std::string e)
        : group(std::move(g)), name(std::move(n)), args(std::move(a)), expected(std::move(e)) {}
    std::string group, name;
    std::vector<std::string> args;
    // The whole stderr must be "motiongp: error: " + expected + "\n" …
    std::string expected;
    // … unless a pattern is given (for messages that quote a third party's words, e.g. the JSON
    // parser's); it must then match the whole stderr.
    std::string pattern;
    int exitCode = 2;
    test::CliLimits limits = test::hostileLimits();
};

void runCase(const HostileCase& c) {
    CAPTURE(c.group);
    CAPTURE(c.name);
    std::string cmd = "motiongp";
    for (const auto& a : c.args) cmd += " " + (a.size() > 200 ? a.substr(0, 200) + "…" : a);
    CAPTURE(cmd);
    const test::CliResult r = test::runCliArgs(c.args, c.limits);
    const std::string shownErr = r.err.size() > 2000 ? r.err.substr(0, 2000) + "…" : r.err;
    CAPTURE(shownErr);
    INFO("outcome: " << test::describe(r));
    CHECK_FALSE(r.timedOut);
    CHECK(r.signal == 0);
    CHECK(r.exitCode == c.exitCode);
    CHECK(r.exitCode != 0);
    if (c.pattern.empty()) {
        CHECK(r.err == "motiongp: error: " + c.expected + "\n");
    } else {
        CHECK(std::regex_match(r.err, std::regex(c.pattern)));
    }
    // One line of error, nothing on stdout (a --json caller must not get half an object).
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(r.out.empty());
}

std::string regexEscape(const std::string& s) {
    static const std::regex special(R"([.^$|()\[\]{}*+?\\])");
    return std::regex_replace(s, special, R"(\$&)");
}

// A small trained model (synthetic walk, 20 frames) written to `path`; the model cases mutate it.
void writeSmallModel(const std::string& path) {
    Clip clip = makeSyntheticWalk(40);
    gp::TrainOptions opt;
    opt.activeSize = 12;
    opt.outerIterations = 2;
    opt.scgIterations = 10;
    opt.pointIterations = 10;
    opt.threads = 1;
    unwrapClip(clip);
    std::vector<int> frames;
    for (int f = 0; f < 40; f += 2) frames.push_back(f);
    gp::TrainResult res = gp::train(gp::trainingDataFromClip(clip, frames), opt);
    res.model.clip = std::move(clip);
    res.model.sourceFile = "synthetic";
    gp::saveModel(path, res.model);
}

std::vector<HostileCase> buildCases(const std::string& dir, const std::string& model) {
    std::vector<HostileCase> cases;
    const std::string asf = dir + "/t.asf", amc = dir + "/t_01.amc", bvh = dir + "/ok.bvh";
    test::writeText(asf, kAsf);
    test::writeText(amc, kAmc);
    test::writeText(bvh, kBvh);

    // ---- ASF (through `info CLIP --skel ASF`) ----------------------------------------------
    auto asfCase = [&](const std::string& name, const std::string& file, const std::string& text,
                       const std::string& expected) {
        const std::string p = dir + "/" + file;
        test::writeText(p, text);
        cases.push_back({"asf", name, {"info", amc, "--skel", p, "--json"}, expected});
    };
    {
        const std::string t = cutAfter(kAsf, "  length");
        asfCase("truncated in :units", "units.asf", t,
                at(dir + "/units.asf", 5) + ": expected a unit value after length, found nothing");
    }
    {
        const std::string t = cutBefore(kAsf, "   position 0 0 0");
        asfCase("truncated in :root", "root.asf", t,
                at(dir + "/root.asf", 9) + ": expected a :bonedata section with bones, found none");
    }
    {
        const std::string t = cutAfter(kAsf, "name lfemur\n     direction 0 -1");
        asfCase("truncated in :bonedata mid-line", "bonedata.asf", t,
                at(dir + "/bonedata.asf", 16) + ": expected 3 numbers for the bone direction, found 2 values");
    }
    {
        const std::string t = cutAfter(kAsf, "    root lfemur\n");
        asfCase("truncated in :hierarchy", "hier.asf", t,
                at(dir + "/hier.asf", lineOf(t, "  begin\n     id 2")) +
                    ": expected bone 'ltibia' to appear in :hierarchy, found a bone with no parent");
    }
    {
        const std::string t =
            replaced(kAsf, "    root lfemur\n    lfemur ltibia\n", "    lfemur ltibia\n    ltibia lfemur\n");
        asfCase("hierarchy cycle", "cycle.asf", t,
                at(dir + "/cycle.asf", lineOf(t, "  begin\n     id 1")) +
                    ": expected bone 'lfemur' to hang from root in :hierarchy, found a cycle through 'lfemur'");
    }
    {
        const std::string t = replaced(kAsf, "    lfemur ltibia\n", "    ltibia ltibia\n");
        asfCase("bone is its own parent", "self.asf", t,
                at(dir + "/self.asf", lineOf(t, "  begin\n     id 2")) +
                    ": expected bone 'ltibia' to hang from root in :hierarchy, found a cycle through 'ltibia'");
    }
    {
        const std::string t = replaced(kAsf, "name ltibia", "name lfemur");
        asfCase("duplicate bone name", "dup.asf", t,
                at(dir + "/dup.asf", lineOf(t, "  begin\n     id 2")) +
                    ": expected a unique bone name, found a second 'lfemur'");
    }
    {
        const std::string t = replaced(kAsf, "lfemur ltibia", "lfemur lknee");
        asfCase("unknown bone in :hierarchy", "unknown.asf", t,
                at(dir + "/unknown.asf", lineOf(t, "lfemur lknee")) +
                    ": expected a bone declared in :bonedata, found 'lknee'");
    }
    asfCase("empty ASF", "empty.asf", "", dir + "/empty.asf: expected mocap text, found an empty file");

    // ---- AMC (through `info CLIP --skel ASF`) ----------------------------------------------
    auto amcCase = [&](const std::string& name, const std::string& file, const std::string& text,
                       const std::string& expected) {
        const std::string p = dir + "/" + file;
        test::writeText(p, text);
        cases.push_back({"amc", name, {"info", p, "--skel", asf, "--json"}, expected});
    };
    {
        const std::string t = cutAfter(kAmc, "2\nroot 1 2 3 4 5 6\nlfemur 1 2");
        amcCase("truncated mid-frame (mid-line)", "cut1.amc", t,
                at(dir + "/cut1.amc", 10) + ": expected 3 values for bone 'lfemur', found 2");
    }
    {
        const std::string t = cutAfter(kAmc, "ltibia 4\n2\n");
        amcCase("truncated after a frame number", "cut2.amc", t,
                at(dir + "/cut2.amc", 8) + ": expected a line for bone 'root' in frame 2, found none");
    }
    amcCase("more values than the bone's dofs", "many.amc", replaced(kAmc, "ltibia 4\n", "ltibia 4 5\n"),
            at(dir + "/many.amc", 7) + ": expected 1 values for bone 'ltibia', found 2");
    amcCase("NaN angle", "nan.amc", replaced(kAmc, "lfemur 1 2 3\nltibia 4", "lfemur 1 nan 3\nltibia 4"),
            at(dir + "/nan.amc", 6) + ": expected a finite number for bone 'lfemur', found 'nan'");
    amcCase("-Inf angle", "inf.amc", replaced(kAmc, "ltibia 5", "ltibia -inf"),
            at(dir + "/inf.amc", 11) + ": expected a finite number for bone 'ltibia', found '-inf'");
    amcCase("1e308 angle", "big.amc", replaced(kAmc, "ltibia 5", "ltibia 1e308"),
            at(dir + "/big.amc", 11) + ": expected an angle within ±1e6 degrees, found '1e308'");
    amcCase("1e999 (overflows a double)", "ovf.amc", replaced(kAmc, "ltibia 5", "ltibia 1e999"),
            at(dir + "/ovf.amc", 11) + ": expected a finite number for bone 'ltibia', found '1e999'");
    amcCase("1e308 root translation", "root.amc",
            replaced(kAmc, "root 1 2 3 4 5 6\nlfemur 1 2 3\nltibia 4", "root 1e308 2 3 4 5 6\nlfemur 1 2 3\nltibia 4"),
            at(dir + "/root.amc", 5) + ": expected a root translation within ±1e7, found '1e308'");
    amcCase("unknown bone", "bone.amc", replaced(kAmc, "ltibia 5", "lknee 5"),
            at(dir + "/bone.amc", 11) + ": expected a bone of " + asf + ", found unknown bone 'lknee'");
    {
        const std::string longName(16u << 20, 'x');  // one 16 MB line
        amcCase("16 MB line", "long.amc", replaced(kAmc, "ltibia 5", longName + " 5"),
                at(dir + "/long.amc", 11) + ": expected a bone of " + asf + ", found unknown bone '" +
                    std::string(40, 'x') + "...'");
    }
    amcCase("NUL byte", "nul.amc", replaced(kAmc, "lfemur 1 2 3\nltibia 5", std::string("lfemur 1 \0 3\nltibia 5", 21)),
            at(dir + "/nul.amc", 10) + ": expected text, found binary data (a NUL byte)");

    // ---- BVH (through `info CLIP`) -------------------------------------------------------
    auto bvhCase = [&](const std::string& name, const std::string& file, const std::string& text,
                       const std::string& expected) {
        const std::string p = dir + "/" + file;
        test::writeText(p, text);
        cases.push_back({"bvh", name, {"info", p, "--json"}, expected});
    };
    auto b = [&](const std::string& file, int line) { return at(dir + "/" + file, line); };
    bvhCase("truncated in the hierarchy", "h.bvh", cutAfter(kBvh, "    CHANNELS 3 Zrotation Yrotation Xrotation\n"),
            b("h.bvh", 9) + ": expected more of the hierarchy, found the end of the file");
    bvhCase("truncated after MOTION", "m.bvh", cutAfter(kBvh, "MOTION\n"),
            b("m.bvh", 16) + ": expected 'Frames: N', found the end of the file");
    bvhCase("truncated after Frames:", "f.bvh", cutAfter(kBvh, "Frames: 2\n"),
            b("f.bvh", 17) + ": expected 'Frame Time: SECONDS', found the end of the file");
    bvhCase("truncated mid-row", "r.bvh", cutAfter(kBvh, "0 17 0 0 0 0 0 0 0\n0 17 0"),
            b("r.bvh", 20) + ": expected 9 values per frame row, found 3");
    bvhCase("more rows than Frames:", "more.bvh", replaced(kBvh, "Frames: 2", "Frames: 1"),
            b("more.bvh", 20) + ": expected 1 frame rows (Frames:), found more rows");
    bvhCase("fewer rows than Frames:", "fewer.bvh", replaced(kBvh, "Frames: 2", "Frames: 3"),
            b("fewer.bvh", 20) + ": expected 3 frame rows (Frames:), found at most 2 lines left");
    bvhCase("more values than channels", "wide.bvh", replaced(kBvh, "0 17 0 0 0 0 5 0 0", "0 17 0 0 0 0 5 0 0 1"),
            b("wide.bvh", 20) + ": expected 9 values per frame row, found 10");
    bvhCase("negative frame count", "neg.bvh", replaced(kBvh, "Frames: 2", "Frames: -2"),
            b("neg.bvh", 17) + ": expected a frame count of at least 1, found '-2'");
    bvhCase("frame count past 64 bits", "huge.bvh", replaced(kBvh, "Frames: 2", "Frames: 99999999999999999999"),
            b("huge.bvh", 17) + ": expected a frame count of at least 1, found '99999999999999999999'");
    bvhCase("frame count that wraps a 64-bit integer", "wrap.bvh",
            replaced(kBvh, "Frames: 2", "Frames: 9999999999999999999"),
            b("wrap.bvh", 17) + ": expected a frame count of at least 1, found '9999999999999999999'");
    {
        // 10^7 frames declared, 2 rows: must fail before allocating anything sized by the header,
        // so it runs under a 256 MiB address space (the whole process, libraries included).
        const std::string p = dir + "/ten_million.bvh";
        test::writeText(p, replaced(kBvh, "Frames: 2", "Frames: 10000000"));
        HostileCase c{"bvh",
                      "10^7 frames declared (fails small)",
                      {"info", p, "--json"},
                      at(p, 20) + ": expected 10000000 frame rows (Frames:), found at most 2 lines left"};
        c.limits.addressSpaceBytes = std::size_t(256) << 20;
        cases.push_back(c);
    }
    bvhCase("NaN in a row", "nan.bvh", replaced(kBvh, "0 17 0 0 0 0 5 0 0", "0 17 0 0 0 0 nan 0 0"),
            b("nan.bvh", 20) + ": expected a finite number (value 7), found 'nan'");
    bvhCase("1e999 in a row", "ovf.bvh", replaced(kBvh, "0 17 0 0 0 0 5 0 0", "0 17 0 0 0 0 5 0 1e999"),
            b("ovf.bvh", 20) + ": expected a finite number (value 9), found '1e999'");
    bvhCase("1e308 offset", "off.bvh", replaced(kBvh, "OFFSET 1 -1 0", "OFFSET 1 1e308 0"),
            b("off.bvh", 8) + ": expected a number within ±1e7, found '1e308'");
    bvhCase("duplicate joint name", "dup.bvh", replaced(kBvh, "JOINT LeftUpLeg", "JOINT Hips"),
            b("dup.bvh", 6) + ": expected a unique joint name, found a second 'Hips'");
    {
        // A BVH cannot spell a cycle, only a joint named as its ancestor: that must not be
        // taken as a back edge.
        const std::string t = replaced(
            kBvh, "    End Site\n    {\n      OFFSET 0 -7 0\n    }\n",
            "    JOINT Hips\n    {\n      OFFSET 0 -7 0\n      CHANNELS 3 Zrotation Yrotation Xrotation\n    }\n");
        bvhCase("joint named as its grandparent (cycle)", "cycle.bvh", t,
                b("cycle.bvh", lineOf(t, "    JOINT Hips")) + ": expected a unique joint name, found a second 'Hips'");
    }
    {
        // 100 000 nested JOINTs: the recursive parser must stop at its depth limit, not overflow
        // the stack.
        std::string t = "HIERARCHY\nROOT J0\n{\nOFFSET 0 0 0\nCHANNELS 3 Zrotation Xrotation Yrotation\n";
        for (int k = 1; k < 100000; ++k)
            t += "JOINT J" + std::to_string(k) + "\n{\nOFFSET 0 1 0\nCHANNELS 3 Zrotation Xrotation Yrotation\n";
        t += "End Site\n{\nOFFSET 0 1 0\n}\n";
        for (int k = 0; k < 100000; ++k) t += "}\n";
        t += "MOTION\nFrames: 1\nFrame Time: 0.01\n" + std::string(300000, '0') + "\n";
        bvhCase(
            "100 000 nested joints (depth bomb)", "deep.bvh", t,
            b("deep.bvh", lineOf(t, "JOINT J257\n")) + ": expected a hierarchy at most 256 joints deep, found 'J257'");
    }
    {
        std::string t = "HIERARCHY\nROOT J0\n{\nOFFSET 0 0 0\nCHANNELS 3 Zrotation Xrotation Yrotation\n";
        for (int k = 1; k < 5000; ++k) t += "JOINT J" + std::to_string(k) + "\n{\nOFFSET 0 1 0\n}\n";
        t += "}\nMOTION\nFrames: 1\nFrame Time: 0.01\n0 0 0\n";
        bvhCase("5 000 sibling joints", "wide_tree.bvh", t,
                b("wide_tree.bvh", lineOf(t, "JOINT J4096\n")) + ": expected at most 4096 joints, found 'J4096'");
    }
    bvhCase("16 MB first line", "longline.bvh", std::string(16u << 20, 'A') + "\n" + kBvh,
            b("longline.bvh", 1) + ": expected 'HIERARCHY', found '" + std::string(40, 'A') + "...'");
    bvhCase("16 MB number in a row", "longnum.bvh",
            replaced(kBvh, "0 17 0 0 0 0 5 0 0", std::string(16u << 20, '1') + " 17 0 0 0 0 5 0 0"),
            b("longnum.bvh", 20) + ": expected a finite number (value 1), found '" + std::string(40, '1') + "...'");
    {
        std::mt19937 rng(8);
        std::string garbage(1u << 20, '\0');
        for (char& ch : garbage) ch = static_cast<char>(1 + rng() % 255);  // no NUL byte
        const std::string p = dir + "/garbage.bvh";
        test::writeText(p, garbage);
        HostileCase c{"bvh", "1 MB of binary garbage (no NUL)", {"info", p, "--json"}, ""};
        c.pattern = "motiongp: error: " + regexEscape(p) + R"(:[0-9]+: expected 'HIERARCHY', found '[^\n]*'\n)";
        cases.push_back(c);
    }
    bvhCase("NUL bytes", "nul.bvh", replaced(kBvh, "ROOT Hips", std::string("ROOT \0\0\0", 8)),
            b("nul.bvh", 2) + ": expected text, found binary data (a NUL byte)");
    {
        std::string utf16 = "\xFF\xFE";
        for (char ch : kBvh) utf16 += std::string{ch, '\0'};
        bvhCase("UTF-16 LE with BOM", "utf16.bvh", utf16,
                dir + "/utf16.bvh: expected UTF-8 or ASCII text, found UTF-16 (byte-order mark FF FE)");
        std::string be = "\xFE\xFF";
        for (char ch : kBvh) be += std::string{'\0', ch};
        bvhCase("UTF-16 BE with BOM", "utf16be.bvh", be,
                dir + "/utf16be.bvh: expected UTF-8 or ASCII text, found UTF-16 (byte-order mark FE FF)");
    }
    bvhCase("empty file", "empty.bvh", "", dir + "/empty.bvh: expected mocap text, found an empty file");
    bvhCase("only blank lines", "blank.bvh", "\n  \r\n\t\n",
            b("blank.bvh", 1) + ": expected 'HIERARCHY', found no text");
    {
        const std::string p = dir + "/folder.bvh";
        ::mkdir(p.c_str(), 0755);
        cases.push_back(
            {"bvh", "directory instead of a file", {"info", p, "--json"}, p + ": expected a file, found a directory"});
        const std::string dev = dir + "/zero.bvh";
        REQUIRE(::symlink("/dev/zero", dev.c_str()) == 0);
        cases.push_back({"bvh",
                         "endless device (/dev/zero)",
                         {"info", dev, "--json"},
                         dev + ": expected a regular file, found a special file"});
        const std::string missing = dir + "/missing.bvh";
        cases.push_back({"bvh",
                         "missing file",
                         {"info", missing, "--json"},
                         missing + ": expected a readable file, found none (No such file or directory)"});
        // chmod 000: root reads it anyway, so the child drops to nobody (65534) before exec.
        const std::string locked = dir + "/locked.bvh";
        test::writeText(locked, kBvh);
        REQUIRE(::chmod(locked.c_str(), 0) == 0);
        HostileCase c{"bvh",
                      "unreadable file (chmod 000)",
                      {"info", locked, "--json"},
                      locked + ": expected a readable file, found a file that cannot be opened (Permission denied)"};
        c.limits.dropRoot = true;
        const std::string unreachable = test::unreachableAsNobody({dir});
        if (unreachable.empty())
            cases.push_back(c);
        else
            MGP_MARK_SKIPPED("the chmod-000 case: " << unreachable);
    }

    // ---- the other verbs that read clips -------------------------------------------------
    {
        const std::string p = dir + "/nan.bvh";
        cases.push_back({"fk",
                         "fk on a NaN-bearing BVH",
                         {"fk", p, "--frame", "1", "--json"},
                         at(p, 20) + ": expected a finite number (value 7), found 'nan'"});
        cases.push_back({"fk",
                         "fk frame 10^7",
                         {"fk", bvh, "--frame", "10000000", "--json"},
                         "expected --frame in 1..2 (clip frames counted from 1), found 10000000"});
        cases.push_back({"fk",
                         "fk frame -1",
                         {"fk", bvh, "--frame", "-1"},
                         "expected --frame in 1..2 (clip frames counted from 1), found -1"});
        const std::string deep = dir + "/deep.bvh";
        cases.push_back({"render",
                         "render a depth bomb",
                         {"render", deep, "--frame", "1", "--out", dir + "/x.png"},
                         at(deep, lineOf(test::readText(deep), "JOINT J257\n")) +
                             ": expected a hierarchy at most 256 joints deep, found 'J257'"});
        const std::string cut = dir + "/cut1.amc";
        cases.push_back({"render",
                         "render a truncated AMC",
                         {"render", cut, "--skel", asf, "--frame", "1", "--out", dir + "/y.png"},
                         at(cut, 10) + ": expected 3 values for bone 'lfemur', found 2"});
        cases.push_back({"train",
                         "train on a truncated AMC",
                         {"train", cut, "--skel", asf, "--out", dir + "/never.json"},
                         at(cut, 10) + ": expected 3 values for bone 'lfemur', found 2"});
        const std::string cycle = dir + "/cycle.asf";
        cases.push_back(
            {"train",
             "train with a cyclic ASF",
             {"train", amc, "--skel", cycle, "--out", dir + "/never.json"},
             at(cycle, lineOf(test::readText(cycle), "  begin\n     id 1")) +
                 ": expected bone 'lfemur' to hang from root in :hierarchy, found a cycle through 'lfemur'"});
        cases.push_back({"train",
                         "train on a BVH of one frame",
                         {"train", bvh, "--out", dir + "/never.json"},
                         "expected at least 3 training frames after --frames/--step, found 1"});
        cases.push_back({"train",
                         "train on 2 frames",
                         {"train", amc, "--skel", asf, "--out", dir + "/never.json"},
                         "expected at least 3 training frames after --frames/--step, found 2"});
    }

    // ---- model files (through `pose MODEL …`, and `render MODEL`) ---------------------------
    const std::string modelText = test::readText(model);
    const nlohmann::json base = nlohmann::json::parse(modelText);
    auto modelCase = [&](const std::string& name, const std::string& file, const std::string& text,
                         const std::string& expected, const std::string& pattern = "") {
        const std::string p = dir + "/" + file;
        test::writeText(p, text);
        HostileCase c{"model", name, {"pose", p, "--frame", "1", "--target", "rfoot=0,5,0", "--json"}, expected};
        c.pattern = pattern;
        cases.push_back(c);
    };
    auto mutated = [&](const std::function<void(nlohmann::json&)>& change) {
        nlohmann::json j = base;
        change(j);
        return j.dump(1);
    };
    auto P = [&](const std::string& file) { return dir + "/" + file; };
    const int D = base["D"].get<int>(), N = base["N"].get<int>();
    modelCase(
        "truncated model JSON", "cut.json", modelText.substr(0, modelText.size() / 2), "",
        "motiongp: error: " + regexEscape(P("cut.json")) +
            R"(: expected a JSON model file \(format motiongp-model\), found damaged JSON \(\[json\.exception\.parse_error\.101\] parse error at line [0-9]+, column [0-9]+: [^\n]*\)\n)");
    modelCase("empty model file", "empty.json", "",
              P("empty.json") + ": expected a JSON model file (format motiongp-model), found an empty file");
    modelCase("wrong D (w disagrees)", "dim.json", mutated([&](nlohmann::json& j) { j["D"] = D - 1; }),
              P("dim.json") + ": expected w as an array of " + std::to_string(D - 1) + " numbers, found " +
                  std::to_string(D) + " entries");
    modelCase("latent_dim 10^9 (must not allocate N×10^9)", "latent.json",
              mutated([&](nlohmann::json& j) { j["latent_dim"] = 1000000000; }),
              P("latent.json") + ": expected positive N, D ≤ 3000 and latent_dim ≤ D, found N=" + std::to_string(N) +
                  " D=" + std::to_string(D) + " latent_dim=1000000000");
    modelCase("N disagrees with X", "rows.json", mutated([&](nlohmann::json& j) { j["N"] = N + 7; }),
              P("rows.json") + ": expected " + std::to_string(N + 7) + " rows of X, found " + std::to_string(N));
    modelCase("NaN parameter (null)", "nan.json", mutated([&](nlohmann::json& j) { j["log_params"][1] = nullptr; }),
              P("nan.json") + ": expected numbers in log_params, found null");
    modelCase(
        "1e999 parameter", "ovf.json", replaced(modelText, "\"log_params\": [", "\"log_params\": [1e999,"), "",
        "motiongp: error: " + regexEscape(P("ovf.json")) +
            R"(: expected a JSON model file \(format motiongp-model\), found damaged JSON \([^\n]*number overflow[^\n]*\)\n)");
    modelCase("ln alpha = 1e308 (exp overflows)", "huge.json",
              mutated([&](nlohmann::json& j) { j["log_params"][0] = 1e308; }),
              P("huge.json") + ": expected log_params within ±100 (kernel parameters exp(±100)), found 1e+308");
    modelCase("non-PD setup (a repeated active point, noiseless)", "nonpd.json", mutated([&](nlohmann::json& j) {
                  j["log_params"][2] = 49.0;  // β = e^49: no noise on the diagonal
                  j["active"] = {0, 1, 0};    // two equal rows and columns in K
              }),
              P("nonpd.json") + ": expected distinct active indices (a positive definite K), found 0 twice");
    modelCase("NaN in the weights (null)", "w.json", mutated([&](nlohmann::json& j) { j["w"][0] = nullptr; }),
              P("w.json") + ": expected numbers in w, found null");
    modelCase("active index out of range", "active.json", mutated([&](nlohmann::json& j) { j["active"][0] = N + 5; }),
              P("active.json") + ": expected active indices in 0.." + std::to_string(N - 1) + ", found " +
                  std::to_string(N + 5));
    modelCase("unknown format", "format.json", mutated([&](nlohmann::json& j) { j["format"] = "motiongp-session"; }),
              P("format.json") + ": expected \"format\": \"motiongp-model\", found \"motiongp-session\"");
    modelCase(
        "future version", "version.json", mutated([&](nlohmann::json& j) { j["version"] = 99; }),
        P("version.json") + ": expected model file version ≤ 2 (this build reads up to version 2), found version 99");
    modelCase("1e308 angle in the clip", "pose.json",
              mutated([&](nlohmann::json& j) { j["clip"]["poses_deg"][0][3] = 1e308; }),
              P("pose.json") + ": expected angles within ±1e10 degrees in clip frame 1, found 1e+308");
    modelCase("a BVH passed as the model", "notjson.json", kBvh, "",
              "motiongp: error: " + regexEscape(P("notjson.json")) +
                  R"(: expected a JSON model file \(format motiongp-model\), found damaged JSON \([^\n]*\)\n)");
    {
        const std::string p = dir + "/model_dir.json";
        ::mkdir(p.c_str(), 0755);
        cases.push_back({"model",
                         "directory instead of a model",
                         {"pose", p, "--frame", "1", "--target", "rfoot=0,5,0"},
                         p + ": expected a file, found a directory"});
        cases.push_back({"model",
                         "render a model with a NaN parameter",
                         {"render", P("nan.json"), "--frame", "1", "--out", dir + "/z.png"},
                         P("nan.json") + ": expected numbers in log_params, found null"});
    }
    return cases;
}

}  // namespace

TEST_CASE("hostile inputs through the CLI: one clear error, non-zero exit, bounded time and memory") {
    const std::string dir = test::scratchDir("hostile");
    const std::string model = dir + "/good_model.json";
    writeSmallModel(model);
    const std::vector<HostileCase> cases = buildCases(dir, model);
    // The base files themselves are fine, so each failure below is its mutation's.
    for (const auto& args :
         std::vector<std::vector<std::string>>{{"info", dir + "/t_01.amc", "--skel", dir + "/t.asf", "--json"},
                                               {"info", dir + "/ok.bvh", "--json"},
                                               {"pose", model, "--frame", "1", "--target", "rfoot=0,5,0", "--json"}}) {
        const test::CliResult r = test::runCliArgs(args, test::hostileLimits());
        INFO(args[0] << " " << args[1] << ": " << test::describe(r) << "\n" << r.err);
        REQUIRE(r.exitCode == 0);
    }
    std::set<std::string> names;
    for (const auto& c : cases) CHECK_MESSAGE(names.insert(c.group + "/" + c.name).second, "duplicate case " << c.name);
    MESSAGE(cases.size() << " hostile inputs");
    CHECK(cases.size() >= 40);
    for (const auto& c : cases) runCase(c);
}

TEST_CASE("a UTF-8 byte-order mark is not part of the first keyword") {
    const std::string dir = test::scratchDir("hostile_bom");
    test::writeText(dir + "/bom.bvh", "\xEF\xBB\xBF" + kBvh);
    const test::CliResult r = test::runCliArgs({"info", dir + "/bom.bvh", "--json"}, test::hostileLimits());
    INFO(test::describe(r) << "\n" << r.err);
    CHECK(r.exitCode == 0);
    CHECK(nlohmann::json::parse(r.out)["frames"] == 2);
}

namespace {

// Loads a session as the editor does (the file, then its clip); the ParseError's words, or "".
std::string sessionError(const std::string& path) {
    try {
        const SessionData s = loadSession(path);
        loadSessionClip(s, path);
    } catch (const ParseError& e) {
        return e.what();
    }
    return "";
}

struct SessionCase {
    std::string name, file, text, expected, pattern;
};

// Writes the good session and every hostile one into a fresh folder; returns the cases.
std::vector<SessionCase> writeHostileSessions(const std::string& dir) {
    const std::string clip = dir + "/ok.bvh";
    test::writeText(clip, kBvh);
    SessionData good;
    good.clipPath = clip;
    good.frame = 1;
    saveSession(dir + "/good.mgsession", good);
    const std::string goodText = test::readText(dir + "/good.mgsession");
    REQUIRE(sessionError(dir + "/good.mgsession") == "");
    const nlohmann::json base = nlohmann::json::parse(goodText);
    auto mutated = [&](const std::function<void(nlohmann::json&)>& change) {
        nlohmann::json j = base;
        change(j);
        return j.dump(1);
    };
    auto P = [&](const std::string& f) { return dir + "/" + f; };
    const std::vector<SessionCase> cases = {
        {"truncated session JSON", "cut.mgsession", goodText.substr(0, goodText.size() / 2), "",
         regexEscape(P("cut.mgsession")) +
             R"(: expected a JSON session file \(format motiongp-session\), found damaged JSON \(\[json\.exception\.parse_error\.101\] parse error at line [0-9]+, column [0-9]+: [^\n]*\))"},
        {"empty session", "empty.mgsession", "",
         P("empty.mgsession") + ": expected a JSON session file (format motiongp-session), found an empty file", ""},
        {"session referencing a missing clip", "missing.mgsession", mutated([&](nlohmann::json& j) {
             j["clip"]["path"] = dir + "/gone.bvh";
             j["clip"]["relative_path"] = "gone.bvh";
         }),
         P("missing.mgsession") + ": expected the session's clip file (gone.bvh relative to the session, or " + dir +
             "/gone.bvh), found neither",
         ""},
        {"frame 10^7", "frame.mgsession", mutated([&](nlohmann::json& j) { j["frame"] = 10000000; }),
         P("frame.mgsession") + ": expected frame in 0..1 (the clip's frames), found 10000000", ""},
        {"negative frame", "neg.mgsession", mutated([&](nlohmann::json& j) { j["frame"] = -3; }),
         P("neg.mgsession") + ": expected frame ≥ 0, found -3", ""},
        {"NaN camera (null)", "nan.mgsession", mutated([&](nlohmann::json& j) { j["camera"]["yaw_deg"] = nullptr; }),
         P("nan.mgsession") + ": expected camera.yaw_deg as a number, found null", ""},
        {"1e999 in the camera", "ovf.mgsession",
         replaced(mutated([&](nlohmann::json& j) { j["camera"]["yaw_deg"] = 12345.5; }), "12345.5", "1e999"), "",
         regexEscape(P("ovf.mgsession")) +
             R"(: expected a JSON session file \(format motiongp-session\), found damaged JSON \([^\n]*number overflow[^\n]*\))"},
        {"UTF-16 session", "utf16.mgsession", std::string("\xFF\xFE{\0}\0", 6),
         P("utf16.mgsession") + ": expected UTF-8 or ASCII text, found UTF-16 (byte-order mark FF FE)", ""},
    };
    for (const auto& c : cases) test::writeText(P(c.file), c.text);
    ::mkdir(P("folder.mgsession").c_str(), 0755);
    std::vector<SessionCase> all = cases;
    all.push_back({"directory instead of a session", "folder.mgsession", "",
                   P("folder.mgsession") + ": expected a file, found a directory", ""});
    return all;
}

}  // namespace

TEST_CASE("hostile session files through the library: one clear error each") {
    const std::string dir = test::scratchDir("hostile_sessions");
    const std::vector<SessionCase> all = writeHostileSessions(dir);
    for (const auto& c : all) {
        CAPTURE(c.name);
        const std::string e = sessionError(dir + "/" + c.file);
        if (c.pattern.empty())
            CHECK(e == c.expected);
        else
            CHECK(std::regex_match(e, std::regex(c.pattern)));
    }
}

TEST_CASE("hostile session files through `motiongp gui --offscreen`: exit 2 and the same one line") {
    const std::string dir = test::scratchDir("hostile_sessions_gui");
    const std::vector<SessionCase> all = writeHostileSessions(dir);
    auto P = [&](const std::string& f) { return dir + "/" + f; };
    // Skipped, with the reason, where no offscreen EGL context can be made (as the gl tests are).
    const test::CliResult probe =
        test::runCliArgs({"gui", P("good.mgsession"), "--offscreen", "--frames", "1"}, test::hostileLimits());
    if (probe.exitCode != 0)
        MGP_SKIP("no offscreen context for `motiongp gui` here (" << test::describe(probe) << ": " << probe.err << ")");
    for (const auto& c : all) {
        CAPTURE(c.name);
        const test::CliResult r =
            test::runCliArgs({"gui", P(c.file), "--offscreen", "--frames", "1"}, test::hostileLimits());
        INFO(test::describe(r) << "\n" << r.err);
        CHECK_FALSE(r.timedOut);
        CHECK(r.signal == 0);
        CHECK(r.exitCode == 2);
        if (c.pattern.empty())
            CHECK(r.err == "motiongp: error: " + c.expected + "\n");
        else
            CHECK(std::regex_match(r.err, std::regex("motiongp: error: " + c.pattern + "\n")));
    }
}
