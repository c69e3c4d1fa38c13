#include "io/temporary_files.h"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <mutex>

#include "error.h"

namespace vct {
namespace {

constexpr int kSlots = 32;
constexpr size_t kMaxPath = 4096;  // PATH_MAX on Linux

// A slot is written only while `used` is 0, then published by setting it to 1: the handler reads
// the path of a used slot only.
struct Slot {
    std::atomic<int> used{0};
    char path[kMaxPath];
};
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler reads the slots lock-free");

Slot slots[kSlots];
std::mutex registration;  // registering threads among themselves; the handler takes no lock

constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};

// Async-signal-safe: reads published slots and calls unlink only.
void unlinkRegistered() {
    for (Slot& slot : slots)
        if (slot.used.load() == 1) unlink(slot.path);
}

extern "C" void removeTemporaryFilesAndReraise(int signal) {
    unlinkRegistered();
    // SA_RESETHAND restored the default action; the signal is blocked while this handler runs, so it
    // is delivered, and ends the process, when the handler returns.
    raise(signal);
}

}  // namespace

void installTemporaryFileCleanup() {
    for (int signal : kSignals) {
        struct sigaction previous {};
        if (sigaction(signal, nullptr, &previous) == 0 && previous.sa_handler == SIG_IGN) continue;
        struct sigaction action {};
        action.sa_handler = removeTemporaryFilesAndReraise;
        sigemptyset(&action.sa_mask);
        for (int other : kSignals) sigaddset(&action.sa_mask, other);  // one cleanup at a time
        action.sa_flags = SA_RESETHAND;
        sigaction(signal, &action, nullptr);
    }
}

void removeTemporaryFiles() { unlinkRegistered(); }

void registerTemporaryFile(const std::string& path) {
    if (path.size() >= kMaxPath) throw Error("the path is too long");
    const std::lock_guard<std::mutex> lock(registration);
    for (Slot& slot : slots) {
        if (slot.used.load() != 0) continue;
        std::memcpy(slot.path, path.c_str(), path.size() + 1);
        slot.used.store(1);
        return;
    }
    throw Error(std::to_string(kSlots) + " files are being written already");
}

void unregisterTemporaryFile(const std::string& path) {
    const std::lock_guard<std::mutex> lock(registration);
    for (Slot& slot : slots)
        if (slot.used.load() == 1 && path == slot.path) {
            slot.used.store(0);
            return;
        }
}

std::vector<std::string> registeredTemporaryFiles() {
    const std::lock_guard<std::mutex> lock(registration);
    std::vector<std::string> paths;
    for (const Slot& slot : slots)
        if (slot.used.load() == 1) paths.emplace_back(slot.path);
    return paths;
}

namespace {

// Blocks the cleanup signals for its lifetime; a signal that arrives meanwhile is delivered after.
struct HeldSignals {
    sigset_t previous;
    HeldSignals() {
        sigset_t held;
        sigemptyset(&held);
        for (int signal : kSignals) sigaddset(&held, signal);
        pthread_sigmask(SIG_BLOCK, &held, &previous);
    }
    ~HeldSignals() { pthread_sigmask(SIG_SETMASK, &previous, nullptr); }
};

void removeTemporaries(const std::vector<std::string>& temporaries) {
    for (const std::string& temporary : temporaries) {
        std::remove(temporary.c_str());
        unregisterTemporaryFile(temporary);
    }
}

}  // namespace

// Errors name the user's path: the temporary file's name is ours, not theirs.
void writeFilesAtomically(const std::vector<std::pair<std::string, std::string>>& pathsAndBytes) {
    std::vector<std::string> temporaries;
    for (const auto& [path, bytes] : pathsAndBytes) {
        const std::string temporary = path + ".tmp." + std::to_string(getpid());
        try {
            registerTemporaryFile(temporary);  // before it exists: a signal from here on removes it
        } catch (const Error& error) {
            removeTemporaries(temporaries);
            throw Error("cannot write '" + path + "': " + error.what());
        }
        temporaries.push_back(temporary);
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) {
            const std::string reason = std::strerror(errno);
            removeTemporaries(temporaries);
            throw Error("cannot write '" + path + "': " + reason);
        }
        out.write(bytes.data(), std::streamsize(bytes.size()));
        out.flush();
        if (!out) {
            const std::string reason = std::strerror(errno);
            out.close();
            removeTemporaries(temporaries);
            throw Error("cannot write '" + path + "': " + reason);
        }
    }
    const HeldSignals held;
    for (size_t i = 0; i < temporaries.size(); ++i) {
        if (std::rename(temporaries[i].c_str(), pathsAndBytes[i].first.c_str()) != 0) {
            const std::string reason = std::strerror(errno);
            removeTemporaries(std::vector<std::string>(temporaries.begin() + long(i), temporaries.end()));
            for (size_t done = 0; done < i; ++done) unregisterTemporaryFile(temporaries[done]);
            throw Error("cannot replace '" + pathsAndBytes[i].first + "': " + reason);
        }
        unregisterTemporaryFile(temporaries[i]);
    }
}

}  // namespace vct
