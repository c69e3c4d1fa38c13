// A progress line for long renders and benches, as command-line tools draw them: on stderr, only
// when stderr is a terminal, redrawn in place ('\r') about four times a second with the time
// since it started, and erased when the work ends. A pipe or a file (tests, logs) gets nothing.
//
// The render itself is one blocking call (a converging frame can take half a minute on
// lavapipe), so a thread redraws the line while the command's own thread waits on the GPU.
#pragma once

#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

namespace vct {

class ProgressLine {
public:
    // `prefix` starts the line ("vct render"); `enabled` defaults to whether stderr is a terminal.
    explicit ProgressLine(std::string prefix);
    ProgressLine(std::string prefix, bool enabled);
    ~ProgressLine();  // stops the redrawing and erases the line
    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;

    bool enabled() const { return enabled_; }
    // What is being done now ("frame 2 of 10"); shown with the time since the line was made.
    void setStage(const std::string& stage);
    // Erases the line while `print` writes its own lines, so they do not land on the progress text.
    void hideWhile(const std::function<void()>& print);
    // Erases the line and stops redrawing it (the destructor does too).
    void finish();

private:
    void redrawLoop();
    void drawLocked();
    void eraseLocked();

    const std::string prefix_;
    const bool enabled_;
    const std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
    std::mutex mutex_;
    std::condition_variable wake_;
    std::string stage_;
    std::string drawn_;  // the line on the terminal now, when shown_
    bool shown_ = false;
    bool stopping_ = false;
    std::thread redrawer_;
};

// "8 s", "2 min 05 s", "1 h 02 min".
std::string elapsedText(double seconds);

}  // namespace vct
