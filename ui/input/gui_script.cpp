#include "ui/input/gui_script.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <set>
#include <sstream>

#include "io/parse_error.h"
#include "io/text_reader.h"
#include "skeleton/skeleton.h"
#include "ui/actions/editor_actions.h"

namespace mgp::ui {

int keyFromName(const std::string& nameIn) {
    std::string n = nameIn;
    for (char& c : n) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (n.size() == 1 && ((n[0] >= 'A' && n[0] <= 'Z') || (n[0] >= '0' && n[0] <= '9'))) return n[0];
    if (long long k = 0; n.size() >= 2 && n.size() <= 3 && n[0] == 'F' && parseInt(n.substr(1), k) && k >= 1 && k <= 12)
        return key::kF1 + static_cast<int>(k) - 1;
    static const std::pair<const char*, int> named[] = {
        {"SPACE", key::kSpace},   {"LEFT", key::kLeft},     {"RIGHT", key::kRight},         {"UP", key::kUp},
        {"DOWN", key::kDown},     {"ESCAPE", key::kEscape}, {"ESC", key::kEscape},          {"ENTER", key::kEnter},
        {"TAB", key::kTab},       {"DELETE", key::kDelete}, {"BACKSPACE", key::kBackspace}, {"HOME", key::kHome},
        {"END", key::kEnd},       {"PAGEUP", key::kPageUp}, {"PAGEDOWN", key::kPageDown},   {"SHIFT", key::kLeftShift},
        {"CTRL", key::kLeftCtrl}, {"ALT", key::kLeftAlt}};
    for (const auto& [s, k] : named)
        if (n == s) return k;
    return -1;
}

namespace {
// The project's strict parsers (io/text_reader.h): the whole token is the number.
bool isNumber(const std::string& s) {
    double v = 0.0;
    return parseDouble(s, v);
}
bool isCount(const std::string& s, int minimum) {
    long long v = 0;
    return parseInt(s, v) && v >= minimum && v <= 1000000000;
}
}  // namespace

GuiScript GuiScript::parse(const std::string& text, const std::string& file) {
    static const std::set<std::string> verbs = {"move",  "moveby", "hover",   "down",  "up",
                                                "wheel", "key",    "keydown", "keyup", "action"};
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
        if (!isCount(tok[0], 0)) throwParseError(file, lineNo, "a frame number ≥ 0 first", "'" + tok[0] + "'");
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
            need(1, "an effector (lhand rhand lfoot rfoot head), key:N or dot:CLIP:N");
            Effector e;
            const bool key = args[0].rfind("key:", 0) == 0 && isCount(args[0].substr(4), 1);
            const std::size_t colon = args[0].rfind(':');
            const bool dot = args[0].rfind("dot:", 0) == 0 && colon > 4 && isCount(args[0].substr(colon + 1), 1);
            if (!key && !dot && !parseEffector(args[0], e))
                throwParseError(file, lineNo, "lhand, rhand, lfoot, rfoot, head, key:N or dot:CLIP:N",
                                "'" + args[0] + "'");
        } else if (verb == "down" || verb == "up") {
            need(1, "a button (left, right, middle)");
            if (args[0] != "left" && args[0] != "right" && args[0] != "middle")
                throwParseError(file, lineNo, "left, right or middle", "'" + args[0] + "'");
        } else if (verb == "wheel") {
            need(1, "a scroll amount");
            if (!isNumber(args[0])) throwParseError(file, lineNo, "a number", "'" + args[0] + "'");
        } else if (verb == "key" || verb == "keydown" || verb == "keyup") {
            need(1, "a key name");
            if (keyFromName(args[0]) < 0)
                throwParseError(file, lineNo, "a key name (A-Z, 0-9, SPACE, LEFT, ...)", "'" + args[0] + "'");
        } else if (verb == "action") {
            need(1, "an action name");
            const ActionTable& table = ActionTable::editor();
            const EditorAction* action = table.find(args[0]);
            if (!action) {
                std::string list;
                for (const EditorAction& a : table.actions()) list += (list.empty() ? "" : ", ") + a.name;
                throwParseError(file, lineNo, "an action (" + list + ")", "'" + args[0] + "'");
            }
            // A synopsis that starts with a required argument ("PATH", not "[PATH]") needs one.
            if (!action->args.empty() && action->args[0] != '[' && args.size() < 2)
                throwParseError(file, lineNo, "an argument after '" + args[0] + "'", "none");
        }
        long long frame = 0;
        parseInt(tok[0], frame);
        script.add(static_cast<int>(frame), verb, std::move(args));
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
