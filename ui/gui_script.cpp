#include "gui_script.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <set>
#include <sstream>

#include "io/parse_error.h"
#include "skeleton/skeleton.h"

namespace mgp::ui {

int keyFromName(const std::string& nameIn) {
    std::string n = nameIn;
    for (char& c : n) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (n.size() == 1 && ((n[0] >= 'A' && n[0] <= 'Z') || (n[0] >= '0' && n[0] <= '9'))) return n[0];
    if (n.size() >= 2 && n.size() <= 3 && n[0] == 'F' && std::isdigit(static_cast<unsigned char>(n[1]))) {
        const int k = std::atoi(n.c_str() + 1);
        if (k >= 1 && k <= 12) return key::kF1 + k - 1;
    }
    static const std::pair<const char*, int> named[] = {
        {"SPACE", key::kSpace},   {"LEFT", key::kLeft},         {"RIGHT", key::kRight},   {"UP", key::kUp},
        {"DOWN", key::kDown},     {"ESCAPE", key::kEscape},     {"ESC", key::kEscape},    {"ENTER", key::kEnter},
        {"TAB", key::kTab},       {"DELETE", key::kDelete},     {"BACKSPACE", key::kBackspace},
        {"HOME", key::kHome},     {"END", key::kEnd},           {"PAGEUP", key::kPageUp}, {"PAGEDOWN", key::kPageDown},
        {"SHIFT", key::kLeftShift}, {"CTRL", key::kLeftCtrl},   {"ALT", key::kLeftAlt}};
    for (const auto& [s, k] : named)
        if (n == s) return k;
    return -1;
}

namespace {
bool isNumber(const std::string& s) {
    if (s.empty()) return false;
    char* end = nullptr;
    std::strtod(s.c_str(), &end);
    return end && *end == '\0';
}
}  // namespace

GuiScript GuiScript::parse(const std::string& text, const std::string& file) {
    static const std::set<std::string> verbs = {"move", "moveby", "hover", "down", "up", "wheel",
                                                "key", "keydown", "keyup", "action"};
    static const std::set<std::string> actions = {"open", "open-model", "save-model", "train", "train-compare", "cancel-train",
                                                  "wait", "play", "pause", "frame", "pin", "compare",
                                                  "frame-camera", "screenshot", "undo", "redo", "path", "path-keys",
                                                  "path-offset", "path-mode", "regenerate", "save-session",
                                                  "open-session", "export-bvh", "export-png", "autosave",
                                                  "restore-autosave", "quit", "discard-and-quit"};
    GuiScript script;
    std::istringstream in(text);
    std::string line;
    int lineNo = 0;
    while (std::getline(in, line)) {
        ++lineNo;
        if (const auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
        std::istringstream ls(line);
        std::vector<std::string> tok;
        for (std::string t; ls >> t;) tok.push_back(t);
        if (tok.empty()) continue;
        if (!isNumber(tok[0]) || std::atoi(tok[0].c_str()) < 0)
            throwParseError(file, lineNo, "a frame number ≥ 0 first", "'" + tok[0] + "'");
        if (tok.size() < 2) throwParseError(file, lineNo, "a verb after the frame number", "end of line");
        const std::string& verb = tok[1];
        if (!verbs.count(verb))
            throwParseError(file, lineNo, "move, moveby, hover, down, up, wheel, key, keydown, keyup or action",
                            "'" + verb + "'");
        std::vector<std::string> args(tok.begin() + 2, tok.end());
        auto need = [&](std::size_t n, const char* what) {
            if (args.size() < n) throwParseError(file, lineNo, what, std::to_string(args.size()) + " arguments");
        };
        if (verb == "move" || verb == "moveby") {
            need(2, "two pixel coordinates");
            if (!isNumber(args[0]) || !isNumber(args[1]))
                throwParseError(file, lineNo, "two numbers", "'" + args[0] + " " + args[1] + "'");
        } else if (verb == "hover") {
            need(1, "an effector (lhand rhand lfoot rfoot head) or key:N");
            Effector e;
            const bool key = args[0].rfind("key:", 0) == 0 && isNumber(args[0].substr(4)) && std::atoi(args[0].c_str() + 4) >= 1;
            if (!key && !parseEffector(args[0], e))
                throwParseError(file, lineNo, "lhand, rhand, lfoot, rfoot, head or key:N", "'" + args[0] + "'");
        } else if (verb == "down" || verb == "up") {
            need(1, "a button (left, right, middle)");
            if (args[0] != "left" && args[0] != "right" && args[0] != "middle")
                throwParseError(file, lineNo, "left, right or middle", "'" + args[0] + "'");
        } else if (verb == "wheel") {
            need(1, "a scroll amount");
            if (!isNumber(args[0])) throwParseError(file, lineNo, "a number", "'" + args[0] + "'");
        } else if (verb == "key" || verb == "keydown" || verb == "keyup") {
            need(1, "a key name");
            if (keyFromName(args[0]) < 0) throwParseError(file, lineNo, "a key name (A-Z, 0-9, SPACE, LEFT, ...)", "'" + args[0] + "'");
        } else if (verb == "action") {
            need(1, "an action name");
            if (!actions.count(args[0])) {
                std::string list;
                for (const std::string& n : actions) list += (list.empty() ? "" : ", ") + n;
                throwParseError(file, lineNo, "an action (" + list + ")", "'" + args[0] + "'");
            }
            static const std::set<std::string> needArgument = {
                "open", "open-model", "save-model", "screenshot", "frame", "pin", "compare", "path", "path-keys",
                "path-mode", "save-session", "open-session", "export-bvh", "export-png"};
            const std::string& a = args[0];
            if (needArgument.count(a) && args.size() < 2)
                throwParseError(file, lineNo, "an argument after '" + a + "'", "none");
            if (a == "path-offset" && (args.size() != 5 || !isNumber(args[1]) || !isNumber(args[2]) ||
                                       !isNumber(args[3]) || !isNumber(args[4])))
                throwParseError(file, lineNo, "path-offset KEY DX DY DZ (numbers)", std::to_string(args.size() - 1) + " arguments");
        }
        script.add(std::atoi(tok[0].c_str()), verb, std::move(args));
        script.events_.back().line = lineNo;
    }
    return script;
}

GuiScript GuiScript::load(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    if (!f) throwParseError(path, 0, "a readable script file", "nothing (cannot open)");
    std::ostringstream ss;
    ss << f.rdbuf();
    return parse(ss.str(), path);
}

void GuiScript::add(int frame, std::string verb, std::vector<std::string> args) {
    ScriptEvent e{frame, std::move(verb), std::move(args), 0};
    const auto pos = std::upper_bound(events_.begin(), events_.end(), frame,
                                      [](int f, const ScriptEvent& ev) { return f < ev.frame; });
    events_.insert(pos, std::move(e));
}

int GuiScript::lastFrame() const { return events_.empty() ? -1 : events_.back().frame; }

}  // namespace mgp::ui
