#include "ui/shell/layout_store.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/atomic_file.h"

namespace mgp::ui {

namespace {
float sane(const nlohmann::json& j, const char* key, float lo, float hi) {
    const auto it = j.find(key);
    if (it == j.end() || !it->is_number()) return 0.0f;
    const float v = it->get<float>();
    return std::isfinite(v) && v >= lo && v <= hi ? v : 0.0f;
}
}  // namespace

LayoutPrefs loadLayoutPrefs(const std::string& path) {
    LayoutPrefs p;
    std::ifstream f(path);
    if (!f) return p;
    std::stringstream ss;
    ss << f.rdbuf();
    const nlohmann::json j = nlohmann::json::parse(ss.str(), nullptr, false);
    if (!j.is_object()) return p;
    p.rightWidth = sane(j, "right_column_width", 100.0f, 4000.0f);
    p.timelineHeight = sane(j, "timeline_height", 40.0f, 2000.0f);
    return p;
}

std::string saveLayoutPrefs(const std::string& path, const LayoutPrefs& prefs) {
    try {
        std::error_code ec;
        std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ec);
        const nlohmann::json j = {{"format", "motiongp-layout"},
                                  {"right_column_width", prefs.rightWidth},
                                  {"timeline_height", prefs.timelineHeight}};
        writeFileAtomically(path, j.dump(2) + "\n");
        return "";
    } catch (const std::exception& e) {
        return e.what();
    }
}

}  // namespace mgp::ui
