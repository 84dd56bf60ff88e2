// The tiers' include rules, read from the sources themselves (docs/architecture.md §1–§2): core/
// never includes render/, ui/, app/ or a GL, GLFW or ImGui header; render/ never includes ui/;
// core's folders include one another without a cycle; and only the ui shell includes
// ui/shell/editor_app.h (the rest of ui/ asks the app through ui/actions/editor_commands.h).
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include "test_paths.h"

namespace fs = std::filesystem;

namespace {

struct LayeringInclude {
    std::string file;  // relative to the checkout, e.g. "core/edit/editor_document.cpp"
    int line = 0;
    std::string header;  // as written between the quotes or angle brackets
};

fs::path layeringRoot() { return fs::path(MOTIONGP_TEST_SOURCE_DIR).parent_path(); }

std::vector<LayeringInclude> layeringIncludes(const std::string& folder) {
    static const std::regex kInclude(R"(^\s*#\s*include\s*[<"]([^>"]+)[>"])");
    std::vector<LayeringInclude> out;
    const fs::path root = layeringRoot();
    for (const auto& entry : fs::recursive_directory_iterator(root / folder)) {
        const std::string ext = entry.path().extension().string();
        if (!entry.is_regular_file() || (ext != ".h" && ext != ".cpp")) continue;
        std::ifstream in(entry.path());
        std::string text;
        for (int line = 1; std::getline(in, text); ++line) {
            std::smatch m;
            if (std::regex_search(text, m, kInclude))
                out.push_back({fs::relative(entry.path(), root).generic_string(), line, m[1]});
        }
    }
    return out;
}

bool layeringStartsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

std::string layeringWhere(const LayeringInclude& inc) {
    return inc.file + ":" + std::to_string(inc.line) + " includes " + inc.header;
}

// The core/ folder of a header core includes as "folder/name.h" ("gp/train" for "gp/train/ivm.h"),
// "" for one that is not a core header.
std::string layeringCoreFolder(const std::string& header) {
    const auto slash = header.rfind('/');
    if (slash == std::string::npos || !fs::exists(layeringRoot() / "core" / header)) return "";
    return header.substr(0, slash);
}

}  // namespace

TEST_CASE("layering: core includes no render, ui, app, GL, GLFW or ImGui header, and render no ui header") {
    const std::vector<std::string> coreForbidden = {"render/", "ui/", "app/", "GL/", "GLFW/", "EGL/", "imgui", "glad"};
    const std::vector<LayeringInclude> core = layeringIncludes("core");
    REQUIRE(core.size() > 100);  // the walk found the sources
    for (const LayeringInclude& inc : core)
        for (const std::string& prefix : coreForbidden)
            CHECK_MESSAGE(!layeringStartsWith(inc.header, prefix), layeringWhere(inc));
    for (const LayeringInclude& inc : layeringIncludes("render"))
        CHECK_MESSAGE((!layeringStartsWith(inc.header, "ui/") && !layeringStartsWith(inc.header, "imgui")),
                      layeringWhere(inc));
}

TEST_CASE("layering: core's folders include one another without a cycle") {
    std::map<std::string, std::map<std::string, std::string>> edges;  // folder -> folder -> first include
    for (const LayeringInclude& inc : layeringIncludes("core")) {
        const std::string from = fs::path(inc.file).parent_path().generic_string().substr(5);  // after "core/"
        const std::string to = layeringCoreFolder(inc.header);
        if (!to.empty() && to != from) edges[from].emplace(to, layeringWhere(inc));
    }
    REQUIRE(edges.size() >= 8);  // skeleton, io, gp, gp/train, ik, motion, edit, session, eval, util
    // Depth-first search; a folder met again while still on the stack closes a cycle.
    std::map<std::string, int> state;  // 0 unseen, 1 on the stack, 2 done
    std::vector<std::string> stack;
    std::string cycle;
    std::function<void(const std::string&)> visit = [&](const std::string& f) {
        state[f] = 1;
        stack.push_back(f);
        for (const auto& [to, first] : edges[f]) {
            if (!cycle.empty()) return;
            if (state[to] == 1) {
                for (auto it = std::find(stack.begin(), stack.end(), to); it != stack.end(); ++it)
                    cycle += *it + " -> ";
                cycle += to + " (" + first + ")";
            } else if (state[to] == 0) {
                visit(to);
            }
        }
        stack.pop_back();
        state[f] = 2;
    };
    for (const auto& [folder, unused] : edges)
        if (state[folder] == 0 && cycle.empty()) visit(folder);
    CHECK_MESSAGE(cycle.empty(), "expected no include cycle between core folders, found " << cycle);
}

TEST_CASE("layering: only the ui shell includes editor_app.h") {
    int shellIncludes = 0;
    for (const LayeringInclude& inc : layeringIncludes("ui")) {
        if (inc.header != "ui/shell/editor_app.h") continue;
        CHECK_MESSAGE(layeringStartsWith(inc.file, "ui/shell/"), layeringWhere(inc));
        ++shellIncludes;
    }
    CHECK(shellIncludes >= 1);  // editor_app.cpp itself
}
