#include "edit/compare_mode.h"

namespace mgp {

const char* compareModeName(CompareMode mode) {
    switch (mode) {
        case CompareMode::kPlainIk: return "plain";
        case CompareMode::kSecondModel: return "model";
        case CompareMode::kNone: break;
    }
    return "none";
}

bool parseCompareMode(const std::string& name, CompareMode& mode) {
    for (CompareMode m : {CompareMode::kNone, CompareMode::kPlainIk, CompareMode::kSecondModel}) {
        if (name == compareModeName(m)) {
            mode = m;
            return true;
        }
    }
    return false;
}

}  // namespace mgp
