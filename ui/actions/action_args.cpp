#include "ui/actions/action_args.h"

#include <climits>

#include "io/text_reader.h"

namespace mgp::ui {

std::string parseIntArg(const std::string& token, const std::string& what, int& out) {
    long long v = 0;
    if (!parseInt(token, v) || v < INT_MIN || v > INT_MAX)
        return "expected " + what + " (an integer), found " + quoteToken(token);
    out = static_cast<int>(v);
    return "";
}

std::string parseFloatArg(const std::string& token, const std::string& what, double& out) {
    double v = 0.0;
    if (!parseDouble(token, v)) return "expected " + what + " (a finite number), found " + quoteToken(token);
    out = v;
    return "";
}

}  // namespace mgp::ui
