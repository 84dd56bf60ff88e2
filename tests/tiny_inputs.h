#pragma once
// Tiny valid ASF, AMC and BVH texts that the bad-input tests damage one way at a time, and the
// helper that damages them. The ASF has root → lfemur → ltibia; the AMC and BVH have 2 frames.
#include <doctest/doctest.h>

#include <string>

namespace mgp::test {

inline const std::string kTinyAsf =
    ":version 1.10\n:name T\n:units\n  mass 1.0\n  length 0.45\n  angle deg\n:root\n"
    "   order TX TY TZ RX RY RZ\n   axis XYZ\n   position 0 0 0\n   orientation 0 0 0\n"
    ":bonedata\n  begin\n     id 1\n     name lfemur\n     direction 0 -1 0\n     length 7\n"
    "     axis 0 0 20  XYZ\n    dof rx ry rz\n    limits (-160.0 20.0)\n (-70.0 70.0)\n (-60.0 70.0)\n  end\n"
    "  begin\n     id 2\n     name ltibia\n     direction 0 -1 0\n     length 7\n     axis 0 0 0 XYZ\n"
    "    dof rx\n  end\n:hierarchy\n  begin\n    root lfemur\n    lfemur ltibia\n  end\n";

inline const std::string kTinyAmc =
    "#!OML:ASF t.asf\n:FULLY-SPECIFIED\n:DEGREES\n1\nroot 1 2 3 4 5 6\nlfemur 1 2 3\nltibia 4\n"
    "2\nroot 1 2 3 4 5 6\nlfemur 1 2 3\nltibia 5\n";

inline const std::string kTinyBvh =
    "HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0 0\n  CHANNELS 6 Xposition Yposition Zposition Zrotation Yrotation "
    "Xrotation\n"
    "  JOINT LeftUpLeg\n  {\n    OFFSET 1 -1 0\n    CHANNELS 3 Zrotation Yrotation Xrotation\n"
    "    End Site\n    {\n      OFFSET 0 -7 0\n    }\n  }\n}\nMOTION\nFrames: 2\nFrame Time: .0083333\n"
    "0 17 0 0 0 0 0 0 0\n0 17 0 0 0 0 5 0 0\n";

// `text` with the first occurrence of `from` replaced by `to` (fails the test if absent).
inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    REQUIRE_MESSAGE(at != std::string::npos, "test setup: '" << from << "' not in the base file");
    return text.replace(at, from.size(), to);
}

}  // namespace mgp::test
