#include "scene/file_policy.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstring>

namespace vct {

namespace fs = std::filesystem;

static int hexValue(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

std::string percentDecode(const std::string& uri) {
    std::string decoded;
    decoded.reserve(uri.size());
    for (size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size()) {
            const int high = hexValue(uri[i + 1]);
            const int low = hexValue(uri[i + 2]);
            if (high >= 0 && low >= 0) {
                decoded += char(high * 16 + low);
                i += 2;
                continue;
            }
        }
        decoded += uri[i];
    }
    return decoded;
}

bool isDataUri(const std::string& uri) { return uri.rfind("data:", 0) == 0; }

// A URI scheme is letters, digits, '+', '-' and '.' starting with a letter, then ':' (RFC 3986 §3.1).
static bool hasScheme(const std::string& uri) {
    const size_t colon = uri.find(':');
    if (colon == std::string::npos || colon == 0) return false;
    if (!std::isalpha(static_cast<unsigned char>(uri[0]))) return false;
    for (size_t i = 1; i < colon; ++i) {
        const char c = uri[i];
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '+' && c != '-' && c != '.') return false;
    }
    return true;
}

// True when `path` is `root` or lies below it; both must be normalised the same way.
static bool isInside(const fs::path& path, const fs::path& root) {
    auto pathPart = path.begin();
    for (auto rootPart = root.begin(); rootPart != root.end(); ++rootPart, ++pathPart) {
        if (rootPart->empty()) continue;  // a trailing separator on the root
        if (pathPart == path.end() || *pathPart != *rootPart) return false;
    }
    return true;
}

ResolvedUri resolveUri(const FilePolicy& policy, const fs::path& baseFolder, const std::string& uri) {
    if (uri.empty()) return {{}, "is empty"};
    if (hasScheme(uri)) return {{}, "is not a relative path or a data: URI (only files beside the scene are read)"};
    const std::string decoded = percentDecode(uri);
    if (decoded.find('\0') != std::string::npos) return {{}, "contains a NUL character"};
    if (decoded[0] == '/' || decoded[0] == '\\')
        return {{}, "is an absolute path; only paths relative to the scene's folder are allowed"};

    // First the lexical check, so `../../x.bin` is refused as an escape even when it does not exist.
    const fs::path joined = (baseFolder / decoded).lexically_normal();
    if (!isInside(joined, policy.root)) return {{}, "leaves the allowed folder '" + policy.root.string() + "'"};

    // Then the real one: symlinks are followed and the result must still be inside the root.
    std::error_code error;
    const fs::path canonical = fs::canonical(joined, error);
    if (error) return {{}, "cannot be opened ('" + joined.string() + "': " + error.message() + ")"};
    if (!isInside(canonical, policy.root))
        return {{}, "leaves the allowed folder '" + policy.root.string() + "' through a symbolic link"};
    const std::string problem = checkRegularFile(canonical, policy.maxFileBytes);
    if (!problem.empty()) return {{}, "names '" + canonical.string() + "', which " + problem};
    return {canonical, {}};
}

static std::string checkStat(const struct stat& status, uint64_t maxFileBytes) {
    if (S_ISDIR(status.st_mode)) return "is a directory";
    if (!S_ISREG(status.st_mode)) return "is not a regular file (a device, FIFO or socket)";
    if (uint64_t(status.st_size) > maxFileBytes)
        return "is " + std::to_string(status.st_size) + " bytes, over the limit of " + std::to_string(maxFileBytes) +
               " bytes";
    return {};
}

std::string checkRegularFile(const fs::path& path, uint64_t maxFileBytes) {
    struct stat status {};
    if (::stat(path.c_str(), &status) != 0) return std::string("cannot be opened: ") + std::strerror(errno);
    return checkStat(status, maxFileBytes);
}

bool readRegularFile(const fs::path& path, uint64_t maxFileBytes, std::vector<uint8_t>& bytes, std::string& problem) {
    // O_NONBLOCK: opening a FIFO must not wait for a writer; it is refused by fstat below.
    const int file = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (file < 0) {
        problem = std::string("cannot be opened: ") + std::strerror(errno);
        return false;
    }
    struct stat status {};
    if (::fstat(file, &status) != 0) {
        problem = std::string("cannot be inspected: ") + std::strerror(errno);
        ::close(file);
        return false;
    }
    problem = checkStat(status, maxFileBytes);
    if (!problem.empty()) {
        ::close(file);
        return false;
    }
    bytes.resize(size_t(status.st_size));
    size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t got = ::read(file, bytes.data() + done, bytes.size() - done);
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) {
            problem = got < 0 ? std::string("cannot be read: ") + std::strerror(errno)
                              : std::string("became shorter while being read");
            ::close(file);
            return false;
        }
        done += size_t(got);
    }
    ::close(file);
    return true;
}

}  // namespace vct
