// Temporary files that a signal must not leave behind.
//
// Outputs are written to "OUT.tmp.PID" and renamed over OUT when complete (image_io.h). A SIGINT,
// SIGTERM or SIGHUP in between used to leave the temporary file behind. The handler installed by
// installTemporaryFileCleanup() unlinks every registered temporary file, then re-raises the signal
// with its default action, so the process still ends as the signal asks (exit status 128 + N).
// The paths are kept in a fixed static table so the handler only reads memory and calls unlink(),
// both async-signal-safe.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace vct {

// Installs the handler for SIGINT, SIGTERM and SIGHUP (a signal the process ignores stays ignored).
void installTemporaryFileCleanup();

// Registers `path` (to be created by the caller) for removal on a signal; throws vct::Error, with
// the reason only, if the path is too long for the table or the table is full. Unregister once the file is renamed or removed.
void registerTemporaryFile(const std::string& path);
void unregisterTemporaryFile(const std::string& path);

// Removes every registered file now (the signal handler's work, for exitImmediately).
void removeTemporaryFiles();

// The paths registered now (for tests).
std::vector<std::string> registeredTemporaryFiles();

// Writes several files as one set: every file goes to its temporary file first, and only when all
// are written are they renamed, with SIGINT, SIGTERM and SIGHUP held back during the renames, so
// an interrupted run leaves the earlier set whole and no temporary file. Throws vct::Error naming
// the file that could not be written (and removes the temporary files).
void writeFilesAtomically(const std::vector<std::pair<std::string, std::string>>& pathsAndBytes);

}  // namespace vct
