#pragma once
// The status line and its history (View > Messages). A message either follows the state it
// describes ("training…" while training runs, "adaptive update queued" until the update is
// done: `holds` returns false once that is over, and the message turns into `after`, or goes
// when `after` is empty) or expires: after a few seconds, or at once when the document changes
// (an error such as "nothing to undo" no longer applies after a successful Redo).
#include <deque>
#include <functional>
#include <string>

namespace mgp::ui {

struct StatusMessage {
    std::string text;
    bool error = false;
    double postedAt = 0.0;        // UI seconds
    long revision = 0;            // the document's revision when posted
    std::function<bool()> holds;  // while true the message stays; null: it expires by time
    std::string after;            // what the message becomes once `holds` turns false ("" = gone)
    bool expired = false;
};

class MessageLog {
public:
    static constexpr double kInfoSeconds = 10.0, kErrorSeconds = 15.0;
    static constexpr std::size_t kHistory = 50;

    void post(std::string text, bool error, double now, long revision, std::function<bool()> holds = nullptr,
              std::string after = "");
    // Applies the rules above; call once per frame before reading current().
    void update(double now, long revision);
    // The message the status line shows, or nullptr when the latest one has expired.
    const StatusMessage* current() const;
    const std::deque<StatusMessage>& history() const { return history_; }  // oldest first
    const std::string& latestText() const;     // the newest message, expired or not ("" if none)
    long postCount() const { return posts_; }  // messages posted so far (the history drops old ones)

private:
    std::deque<StatusMessage> history_;
    long posts_ = 0;
};

}  // namespace mgp::ui
