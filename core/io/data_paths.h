#pragma once
// Where clips are found. The full CMU folder (what table1/table2 and the full benches read):
// --data DIR, then $MOTIONGP_DATA, then ../shared/mocap beside the source tree (path compiled
// in), then relative to the executable's directory — never the working directory. The shipped
// subset (assets/mocap in the repository, assets/mocap/README.md): the compiled-in source path,
// then relative to the executable. A folder counts if it holds asf_amc/ or bvh/.
#include <optional>
#include <string>

namespace mgp {

bool isMocapFolder(const std::string& dir);
std::optional<std::string> findMocapFolder(const std::string& cliDir, const std::string& exeDir);
std::optional<std::string> findShippedMocapFolder(const std::string& exeDir);
// What the editor opens from: the full folder when one is found, else the shipped subset. An
// explicit --data that is not a mocap folder gives nullopt (never silently replaced).
std::optional<std::string> findEditorMocapFolder(const std::string& cliDir, const std::string& exeDir);
// The clip the editor opens by default (a soccer kick, 10_02.amc), if the folder has it.
std::optional<std::string> defaultClipIn(const std::string& mocapDir);
// `path` made absolute and lexically normal, as sessions and the recent list store paths;
// "" stays "", and a path that cannot be resolved (no working directory) is returned as given.
std::string absolutePath(const std::string& path);

}  // namespace mgp
