// The editor's autosave policy (core/session/autosave_policy.h), on a scratch file, without GL.
#include <doctest/doctest.h>

#include <filesystem>

#include "session/autosave_policy.h"
#include "test_support.h"

using namespace mgp;

TEST_CASE("autosave policy: due only for unsaved changes the last autosave does not hold") {
    const std::string file = test::scratchDir("autosave_policy") + "/autosave-1.mgsession";
    std::filesystem::remove(file);
    AutosavePolicy p(120.0, file);
    CHECK(p.interval() == 120.0);
    CHECK(!p.due(0.0, false, 1));  // nothing unsaved: never
    CHECK(!p.due(0.0, true, 1));   // unsaved: the clock starts now
    CHECK(!p.due(119.0, true, 1));
    CHECK(p.due(120.0, true, 1));  // the whole interval

    SessionData s;
    s.syntheticClip = true;
    p.write(s, 120.0, 1);
    CHECK(std::filesystem::exists(file));
    CHECK(p.file() == file);
    CHECK(!p.due(1000.0, true, 1));  // revision 1 is in the autosave already
    CHECK(!p.due(1000.0, true, 2));  // a new change: the clock starts again
    CHECK(p.due(1120.0, true, 2));

    p.forget(1200.0, 2);  // a save: the autosave is stale
    CHECK(!std::filesystem::exists(file));
    CHECK(!p.due(5000.0, true, 2));

    p.write(s, 5000.0, 3);
    CHECK(std::filesystem::exists(file));
    p.discard();  // a normal quit
    CHECK(!std::filesystem::exists(file));
}
