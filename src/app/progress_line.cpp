#include "app/progress_line.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include <cstdio>

namespace vct {
namespace {

// The terminal's width, so the line never wraps (a wrapped line cannot be redrawn with '\r').
size_t terminalColumns() {
    winsize size{};
    if (ioctl(STDERR_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col > 0) return size.ws_col;
    return 80;
}

}  // namespace

std::string elapsedText(double seconds) {
    const long whole = long(seconds);
    char text[32];
    if (whole < 60) std::snprintf(text, sizeof text, "%ld s", whole);
    else if (whole < 3600) std::snprintf(text, sizeof text, "%ld min %02ld s", whole / 60, whole % 60);
    else std::snprintf(text, sizeof text, "%ld h %02ld min", whole / 3600, whole / 60 % 60);
    return text;
}

ProgressLine::ProgressLine(std::string prefix) : ProgressLine(std::move(prefix), isatty(STDERR_FILENO) == 1) {}

ProgressLine::ProgressLine(std::string prefix, bool enabled) : prefix_(std::move(prefix)), enabled_(enabled) {
    if (enabled_) redrawer_ = std::thread([this] { redrawLoop(); });
}

ProgressLine::~ProgressLine() { finish(); }

void ProgressLine::setStage(const std::string& stage) {
    if (!enabled_) return;
    const std::lock_guard<std::mutex> lock(mutex_);
    stage_ = stage;
    drawLocked();
}

void ProgressLine::hideWhile(const std::function<void()>& print) {
    if (!enabled_) return print();
    const std::lock_guard<std::mutex> lock(mutex_);
    eraseLocked();
    print();
    std::fflush(stdout);
    if (!stopping_) drawLocked();
}

void ProgressLine::finish() {
    if (!enabled_) return;
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        if (stopping_) return;
        stopping_ = true;
        eraseLocked();
    }
    wake_.notify_all();
    if (redrawer_.joinable()) redrawer_.join();
}

void ProgressLine::redrawLoop() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!stopping_) {
        drawLocked();
        wake_.wait_for(lock, std::chrono::milliseconds(250));
    }
}

void ProgressLine::drawLocked() {
    if (stage_.empty()) return;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    std::string line = prefix_ + ": " + stage_ + ", " + elapsedText(seconds);
    const size_t columns = terminalColumns();
    if (line.size() >= columns) line.resize(columns - 1);
    if (shown_ && line == drawn_) return;
    drawn_ = line;
    // Back to the line's start, the text, then erase what a longer earlier text left (EL, CSI K).
    std::fprintf(stderr, "\r%s\033[K", line.c_str());
    std::fflush(stderr);
    shown_ = true;
}

void ProgressLine::eraseLocked() {
    if (!shown_) return;
    std::fputs("\r\033[K", stderr);
    std::fflush(stderr);
    shown_ = false;
}

}  // namespace vct
