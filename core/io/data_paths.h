#pragma once
// Where the CMU mocap folder is found (DESIGN.md §1): --data DIR, then $MOTIONGP_DATA, then
// ../shared/mocap beside the source tree (path compiled in), then relative to the executable's
// directory — never the working directory. A folder counts if it holds asf_amc/ or bvh/.
#include <optional>
#include <string>

namespace mgp {

bool isMocapFolder(const std::string& dir);
std::optional<std::string> findMocapFolder(const std::string& cliDir, const std::string& exeDir);
// The clip the editor opens by default (a soccer kick, 10_02.amc), if the folder has it.
std::optional<std::string> defaultClipIn(const std::string& mocapDir);

}  // namespace mgp
