#include "edit/export_job.h"

#include "io/clip_export.h"

namespace mgp {

ExportJob::ExportJob()
    : worker_(
          WorkerPolicy::kEveryRequest,
          [this](Request& r, const std::atomic<bool>&) -> JobOutcome<ExportOutcome> {
              {
                  std::lock_guard<std::mutex> lock(stageMutex_);
                  stage_ = "starting";
              }
              exportClip(r.clip, r.path, [this](const std::string& what) {
                  std::lock_guard<std::mutex> lock(stageMutex_);
                  stage_ = what;
              });
              return {ExportOutcome{r.path, r.clip.frameCount()}, ""};
          },
          "export failed: ") {}

std::string ExportJob::start(Clip clip, const std::string& path) {
    if (!worker_.startIfIdle(Request{std::move(clip), path}))
        return "an export is still running; try again when it is done";
    return "";
}

std::string ExportJob::stage() const {
    std::lock_guard<std::mutex> lock(stageMutex_);
    return stage_;
}

}  // namespace mgp
