#include "session/recent_files.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "io/atomic_file.h"
#include "io/data_paths.h"
#include "io/parse_error.h"
#include "io/text_reader.h"

namespace mgp {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr const char* kRecentFormat = "motiongp-recent";
constexpr int kRecentVersion = 1;
const char* const kKindNames[] = {"session", "clip", "model"};

std::string env(const char* name) {
    const char* v = std::getenv(name);
    return v ? v : "";
}

std::vector<RecentFile> parseRecent(const std::string& text, const std::string& file) {
    const json j = json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (j.is_discarded())
        throwParseError(file, 0, "a JSON recent-files list", text.empty() ? "an empty file" : "damaged JSON");
    if (!j.is_object() || j.value("format", json()) != kRecentFormat)
        throwParseError(file, 0, std::string("\"format\": \"") + kRecentFormat + "\"", "another document");
    const json version = j.value("version", json());
    if (!version.is_number_integer() || version.get<long long>() < 1 || version.get<long long>() > kRecentVersion)
        throwParseError(file, 0, "version ≤ " + std::to_string(kRecentVersion), quoteToken(version.dump()));
    const json files = j.value("files", json());
    if (!files.is_array()) throwParseError(file, 0, "a 'files' array", quoteToken(files.dump()));
    std::vector<RecentFile> out;
    for (const json& e : files) {
        RecentFile f;
        if (!e.is_object() || !e.value("path", json()).is_string() || !e.value("kind", json()).is_string() ||
            !parseRecentKind(e["kind"].get<std::string>(), f.kind))
            throwParseError(file, 0, "entries {\"path\": string, \"kind\": session|clip|model}", quoteToken(e.dump()));
        f.path = e["path"].get<std::string>();
        out.push_back(std::move(f));
    }
    return out;
}

}  // namespace

std::string userDirectory(const char* overrideVar, const char* xdgVar, const char* homeRelative) {
    fs::path dir;
    if (const std::string o = env(overrideVar); !o.empty())
        dir = o;
    else if (const std::string x = env(xdgVar); !x.empty())
        dir = fs::path(x) / "motiongp";
    else if (const std::string h = env("HOME"); !h.empty())
        dir = fs::path(h) / homeRelative;
    else
        dir = fs::temp_directory_path() / "motiongp";  // no HOME at all (a bare service account)
    std::error_code ec;
    fs::create_directories(dir, ec);
    return dir.string();
}

std::string configDir() { return userDirectory("MOTIONGP_CONFIG_DIR", "XDG_CONFIG_HOME", ".config/motiongp"); }

const char* recentKindName(RecentKind kind) { return kKindNames[static_cast<int>(kind)]; }

bool parseRecentKind(const std::string& name, RecentKind& out) {
    for (int i = 0; i < 3; ++i)
        if (name == kKindNames[i]) {
            out = static_cast<RecentKind>(i);
            return true;
        }
    return false;
}

namespace {
// One entry per real file: symlinks and "." / ".." resolved (as far as the path exists).
std::string realPath(const std::string& path) {
    std::error_code ec;
    const fs::path real = fs::weakly_canonical(absolutePath(path), ec);
    return ec ? absolutePath(path) : real.string();
}
}  // namespace

RecentFiles::RecentFiles(std::string file) : file_(file.empty() ? configDir() + "/recent.json" : std::move(file)) {}

void RecentFiles::add(const std::string& path, RecentKind kind) {
    const std::string abs = realPath(path);
    remove(abs);
    entries_.insert(entries_.begin(), RecentFile{abs, kind});
    if (entries_.size() > kMaxEntries) entries_.resize(kMaxEntries);
}

void RecentFiles::remove(const std::string& path) {
    const std::string abs = realPath(path);
    entries_.erase(std::remove_if(entries_.begin(), entries_.end(), [&](const RecentFile& f) { return f.path == abs; }),
                   entries_.end());
}

std::string RecentFiles::load() {
    entries_.clear();
    std::error_code ec;
    if (!fs::exists(file_, ec)) return "";
    try {
        std::ifstream in(file_, std::ios::binary);
        if (!in || fs::is_directory(file_, ec)) throwParseError(file_, 0, "a readable file", "one that cannot be read");
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        for (const RecentFile& f : parseRecent(text, file_)) {
            const std::string abs = realPath(f.path);
            const bool seen =
                std::any_of(entries_.begin(), entries_.end(), [&](const RecentFile& e) { return e.path == abs; });
            if (!seen && entries_.size() < kMaxEntries) entries_.push_back({abs, f.kind});
        }
    } catch (const ParseError& e) {
        entries_.clear();
        return std::string(e.what()) + " (ignored)";
    }
    return "";
}

void RecentFiles::save() const {
    json files = json::array();
    for (const RecentFile& f : entries_) files.push_back({{"path", f.path}, {"kind", recentKindName(f.kind)}});
    const json j = {{"format", kRecentFormat}, {"version", kRecentVersion}, {"files", files}};
    writeFileAtomically(file_, j.dump(1) + "\n");
}

}  // namespace mgp
