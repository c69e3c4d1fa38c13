// Which files a scene may make us read: the URI resolution policy for glTF buffers and images.
//
// A glTF file is untrusted input. Its URIs are resolved relative to the scene's folder and must
// stay inside an allowed root folder after canonicalisation (so `..` and symlinks cannot escape);
// absolute paths, other URI schemes, directories, devices, FIFOs and oversized files are refused.
// Each check returns a sentence fragment ("is a directory") for the caller to prefix with the
// file and JSON path, so the message names both the thing and the problem.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace vct {

struct FilePolicy {
    std::filesystem::path root;  // canonical; every resolved file must lie inside it
    uint64_t maxFileBytes = 0;
};

// RFC 3986 percent-decoding ("a%20b.bin" -> "a b.bin"); a malformed escape is kept as written.
std::string percentDecode(const std::string& uri);

// True for `data:` URIs, whose bytes are embedded and never touch the file system.
bool isDataUri(const std::string& uri);

struct ResolvedUri {
    std::filesystem::path path;  // canonical, valid when `problem` is empty
    std::string problem;         // e.g. "is an absolute path", empty when the URI is allowed
};

// Resolves a (percent-encoded) relative URI against `baseFolder` and applies the policy.
ResolvedUri resolveUri(const FilePolicy& policy, const std::filesystem::path& baseFolder, const std::string& uri);

// Checks that `path` names a regular file no larger than `maxFileBytes`; empty when it does.
std::string checkRegularFile(const std::filesystem::path& path, uint64_t maxFileBytes);

// Reads a whole regular file of at most `maxFileBytes` bytes. Opens without blocking and checks
// the opened file itself, so a file swapped for a FIFO or a directory after the check is refused
// too. On failure returns false and sets `problem`.
bool readRegularFile(const std::filesystem::path& path, uint64_t maxFileBytes, std::vector<uint8_t>& bytes,
                     std::string& problem);

}  // namespace vct
