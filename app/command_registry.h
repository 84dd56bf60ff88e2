#pragma once
// Command-line verbs register themselves here: each app/cmd_<verb>.cpp defines one static
// CommandRegistration. Setup adds the verb's options to its CLI11 subcommand and returns the
// function that runs it after parsing (exit code as result). Errors are thrown as exceptions
// and reported once by main() (what was expected, what was found, file:line).
#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

namespace mgp::app {

using CommandRunner = std::function<int()>;
using CommandSetup = std::function<CommandRunner(CLI::App& sub)>;

struct CommandInfo {
    std::string name;
    std::string description;
    CommandSetup setup;
};

std::vector<CommandInfo>& commandTable();

struct CommandRegistration {
    CommandRegistration(std::string name, std::string description, CommandSetup setup) {
        commandTable().push_back({std::move(name), std::move(description), std::move(setup)});
    }
};

// Options shared by every verb (set by main before any runner is called).
struct GlobalOptions {
    std::string dataDir;  // --data
    std::string exeDir;   // directory of the running executable
};
GlobalOptions& globalOptions();

}  // namespace mgp::app
