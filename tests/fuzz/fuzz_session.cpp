// libFuzzer target: the session loader (session/session_file.h: sessionFromJsonText, in memory),
// then, for a session on the built-in synthetic walk, loadSessionClip as the editor does when
// it opens one (sessions that reference clip files are not followed: no file access).
#include "fuzz_common.h"
#include "session/session_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    mgp::fuzz::expectCleanFailure([&] {
        const mgp::SessionData s = mgp::sessionFromJsonText(mgp::fuzz::text(data, size), "fuzz.mgsession");
        if (s.syntheticClip && !s.model) mgp::loadSessionClip(s, "fuzz.mgsession");
    });
    return 0;
}
