// motiongp: the editor and its command-line verbs (see README.md, docs/guide.md and docs/cli.md).
#include <unistd.h>

#include <algorithm>
#include <climits>
#include <iostream>
#include <map>

#include "cli_common.h"
#include "command_registry.h"
#include "io/parse_error.h"
#include "util/allocator_tuning.h"

namespace mgp::app {

std::vector<CommandInfo>& commandTable() {
    static std::vector<CommandInfo> table;
    return table;
}

GlobalOptions& globalOptions() {
    static GlobalOptions options;
    return options;
}

// Runs when no verb is given (README's run command). Registered as the "" command.
int runDefault();

}  // namespace mgp::app

namespace {
std::string executableDir(const char* argv0) {
    char buf[PATH_MAX];
    const ssize_t n = ::readlink("/proc/self/exe", buf, sizeof(buf) - 1);
    std::string path = n > 0 ? std::string(buf, static_cast<std::size_t>(n)) : std::string(argv0);
    const std::size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? "." : path.substr(0, slash);
}

// `motiongp FILE [gui options]` opens FILE in the editor, as `motiongp gui FILE` does: when the
// first positional argument is not a verb, "gui" is put in front of it (as `blender FILE`).
std::vector<std::string> withImplicitGui(int argc, char** argv, const std::vector<mgp::app::CommandInfo>& verbs) {
    std::vector<std::string> args(argv + 1, argv + argc);
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a == "--data") {  // the one global option that takes a value
            ++i;
            continue;
        }
        if (a.empty() || a[0] == '-') continue;
        const bool verb = std::any_of(verbs.begin(), verbs.end(), [&](const auto& v) { return v.name == a; });
        if (!verb) args.insert(args.begin() + long(i), "gui");
        break;
    }
    return args;
}
}  // namespace

int main(int argc, char** argv) {
    using namespace mgp::app;
    mgp::keepFreedMemoryForReuse();
    CLI::App app{"MotionGP — a motion editor with learned inverse kinematics (FASGPLVM)"};
    app.set_help_all_flag("--help-all", "Show the help of every verb");
    app.set_version_flag("--version", std::string("motiongp ") + MOTIONGP_VERSION);
    globalOptions().exeDir = executableDir(argv[0]);
    app.add_option("--data", globalOptions().dataDir,
                   "Folder with the CMU mocap clips (default: $MOTIONGP_DATA, then ../shared/mocap)");
    std::map<CLI::App*, CommandRunner> runners;
    for (CommandInfo& info : commandTable()) {
        CLI::App* sub = app.add_subcommand(info.name, info.description);
        runners[sub] = info.setup(*sub);
    }
    app.require_subcommand(0, 1);
    try {
        std::vector<std::string> args = withImplicitGui(argc, argv, commandTable());
        std::reverse(args.begin(), args.end());  // CLI11 takes them last first
        app.parse(args);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }
    try {
        for (auto& [sub, run] : runners)
            if (sub->parsed()) return run();
        return runDefault();
    } catch (const mgp::ParseError& e) {
        std::cerr << "motiongp: error: " << e.what() << std::endl;
        return 2;
    } catch (const UsageError& e) {
        std::cerr << "motiongp: error: " << e.what() << std::endl;
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "motiongp: error: " << e.what() << std::endl;
        return 1;
    }
}
