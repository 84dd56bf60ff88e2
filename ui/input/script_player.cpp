#include "ui/input/script_player.h"

#include "ui/actions/action_args.h"
#include "ui/actions/editor_actions.h"
#include "ui/actions/editor_commands.h"

namespace mgp::ui {

ScriptPlayer::ScriptPlayer(GuiScript script) : script_(std::move(script)) {}

void ScriptPlayer::apply(int frame, InputState& in, EditorCommands& app, std::vector<std::string>& screenshots) {
    const auto& ev = script_.events();
    while (next_ < ev.size() && ev[next_].frame <= frame) {
        const ScriptEvent& e = ev[next_++];
        if (std::string err = play(e, in, app, screenshots); !err.empty())
            errors_.push_back("line " + std::to_string(e.line) + ": " + err);
    }
}

std::string ScriptPlayer::play(const ScriptEvent& e, InputState& in, EditorCommands& app,
                               std::vector<std::string>& screenshots) {
    const auto& a = e.args;
    // Scripts made with GuiScript::add skip parse()'s checks: arguments are checked here too.
    auto need = [&](std::size_t n) {
        return a.size() < n ? "expected " + std::to_string(n) + " argument(s) after '" + e.verb + "'" : std::string();
    };
    if (e.verb == "move" || e.verb == "moveby") {
        double x = 0, y = 0;
        std::string err = need(2);
        if (err.empty()) err = parseFloatArg(a[0], "a pixel x", x);
        if (err.empty()) err = parseFloatArg(a[1], "a pixel y", y);
        if (!err.empty()) return err;
        if (e.verb == "move") {
            in.mouseX = float(x);
            in.mouseY = float(y);
        } else {
            in.mouseX += float(x);
            in.mouseY += float(y);
        }
        return "";
    }
    if (e.verb == "hover") {
        if (std::string err = need(1); !err.empty()) return err;
        float x = 0, y = 0;
        bool onScreen = false;
        if (a[0].rfind("dot:", 0) == 0) {  // dot:CLIP:N, the latent map's dot of clip CLIP frame N
            const std::string spec = a[0].substr(4);
            const std::size_t colon = spec.rfind(':');
            int frame = 0;
            if (colon == std::string::npos) return "expected dot:CLIP:N, found '" + a[0] + "'";
            if (std::string err = parseIntArg(spec.substr(colon + 1), "a frame number after 'dot:CLIP:'", frame);
                !err.empty())
                return err;
            onScreen = app.latentDotScreenPosition(spec.substr(0, colon), frame - 1, x, y);
        } else if (a[0].rfind("key:", 0) == 0) {
            int key = 0;
            if (std::string err = parseIntArg(a[0].substr(4), "a path key number after 'key:'", key); !err.empty())
                return err;
            onScreen = app.keyScreenPosition(key - 1, x, y);
        } else {
            Effector eff;
            onScreen = parseEffector(a[0], eff) && app.handleScreenPosition(eff, x, y);
        }
        if (!onScreen) return "handle '" + a[0] + "' is not on screen";
        in.mouseX = x;
        in.mouseY = y;
        return "";
    }
    if (e.verb == "down" || e.verb == "up") {
        if (std::string err = need(1); !err.empty()) return err;
        const int button = a[0] == "left" ? 0 : a[0] == "right" ? 1 : a[0] == "middle" ? 2 : -1;
        if (button < 0) return "expected left, right or middle, found '" + a[0] + "'";
        in.setButton(button, e.verb == "down");
        return "";
    }
    if (e.verb == "wheel") {
        double dy = 0;
        std::string err = need(1);
        if (err.empty()) err = parseFloatArg(a[0], "a scroll amount", dy);
        if (!err.empty()) return err;
        in.wheel += float(dy);
        return "";
    }
    if (e.verb == "key" || e.verb == "keydown" || e.verb == "keyup") {
        if (std::string err = need(1); !err.empty()) return err;
        const int k = keyFromName(a[0]);
        if (k < 0) return "expected a key name (A-Z, 0-9, SPACE, LEFT, ...), found '" + a[0] + "'";
        in.setKey(k, e.verb != "keyup");
        if (e.verb == "key") in.setKey(k, false);  // a tap: the replay spreads it over two frames
        return "";
    }
    if (e.verb == "action") {
        if (std::string err = need(1); !err.empty()) return err;
        if (a[0] == "screenshot") {
            screenshots.push_back(a.size() > 1 ? a[1] : "screenshot.png");
            return "";
        }
        return ActionTable::editor().run(app, a);
    }
    return "unknown verb '" + e.verb + "'";
}

}  // namespace mgp::ui
