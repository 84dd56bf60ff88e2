#include "ui/shell/message_log.h"

namespace mgp::ui {

void MessageLog::post(std::string text, bool error, double now, long revision, std::function<bool()> holds,
                      std::string after) {
    if (!history_.empty()) history_.back().holds = nullptr;  // superseded: never asked again
    StatusMessage m;
    m.text = std::move(text);
    m.error = error;
    m.postedAt = now;
    m.revision = revision;
    m.holds = std::move(holds);
    m.after = std::move(after);
    history_.push_back(std::move(m));
    ++posts_;
    while (history_.size() > kHistory) history_.pop_front();
}

void MessageLog::update(double now, long revision) {
    if (history_.empty()) return;
    StatusMessage& m = history_.back();
    if (m.expired) return;
    if (m.holds) {
        if (m.holds()) return;
        m.holds = nullptr;
        if (m.after.empty()) {
            m.expired = true;
        } else {
            // The state changed: the message says so and then expires like any other.
            m.text = std::move(m.after);
            m.after.clear();
            m.postedAt = now;
            m.revision = revision;
        }
        return;
    }
    const double life = m.error ? kErrorSeconds : kInfoSeconds;
    if (now - m.postedAt > life || (m.error && revision != m.revision)) m.expired = true;
}

const StatusMessage* MessageLog::current() const {
    return history_.empty() || history_.back().expired ? nullptr : &history_.back();
}

const std::string& MessageLog::latestText() const {
    static const std::string none;
    return history_.empty() ? none : history_.back().text;
}

}  // namespace mgp::ui
