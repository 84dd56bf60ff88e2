#pragma once
// What the user changed of the editor's layout (the splitters: right column width, timeline
// height), in pixels at scale 1, and where it is remembered (configDir()/layout.json). A missing
// or damaged file gives the automatic layout, never an error.
#include <string>

namespace mgp::ui {

struct LayoutPrefs {
    float rightWidth = 0.0f;      // 0: automatic
    float timelineHeight = 0.0f;  // 0: automatic
};

LayoutPrefs loadLayoutPrefs(const std::string& path);
// Returns "" or why the file could not be written.
std::string saveLayoutPrefs(const std::string& path, const LayoutPrefs& prefs);

}  // namespace mgp::ui
