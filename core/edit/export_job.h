#pragma once
// ExportJob: writes an exported motion on a background worker, so that a slow export (FBX goes
// through Blender and takes seconds) never freezes the editor. One export at a time; the stage
// it has reached is readable while it runs (docs/export.md).
#include <mutex>
#include <optional>
#include <string>

#include "skeleton/clip.h"
#include "util/background_worker.h"

namespace mgp {

struct ExportOutcome {
    std::string path;
    int frames = 0;
};

class ExportJob {
public:
    ExportJob();
    ExportJob(const ExportJob&) = delete;
    ExportJob& operator=(const ExportJob&) = delete;

    // Starts writing `clip` to `path` (the format from its extension, io/clip_export.h). Returns
    // "" or why not (an export is running).
    std::string start(Clip clip, const std::string& path);
    bool running() const { return worker_.busy(); }
    // The stage the running export has reached, in words ("" before the first).
    std::string stage() const;
    // The finished export, once (none while running, after a failure, or when already taken).
    std::optional<ExportOutcome> take() { return worker_.take(); }
    // "" or the last export's failure, as one line.
    std::string message() const { return worker_.message(); }
    void join() { worker_.waitIdle(); }

private:
    struct Request {
        Clip clip;
        std::string path;
    };
    mutable std::mutex stageMutex_;
    std::string stage_;
    BackgroundWorker<Request, ExportOutcome> worker_;  // last: its thread stops before the rest goes
};

}  // namespace mgp
