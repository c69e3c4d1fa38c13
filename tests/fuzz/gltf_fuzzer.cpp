// libFuzzer harness over the glTF loader and its validator (tools/fuzz.sh builds and runs it).
//
// Each input is written as scene.glb (when it starts with the GLB magic "glTF") or scene.gltf into a
// folder of its own and loaded through vct::loadGltf, exactly as `vct render --scene` would load
// it. A clean refusal is a vct::Error; anything else (a crash, a sanitizer report, any other
// exception, a hang past -timeout, an allocation past -malloc_limit_mb) is a finding.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "error.h"
#include "scene/load.h"

namespace {

namespace fs = std::filesystem;

// Two folders, so a .gltf input can never see a .glb left by an earlier input (or the reverse).
struct Workspace {
    fs::path root;
    fs::path gltfFile;
    fs::path glbFile;

    Workspace() {
        std::string pattern = (fs::temp_directory_path() / "vct-fuzz-XXXXXX").string();
        if (!mkdtemp(pattern.data())) {
            std::perror("gltf_fuzzer: mkdtemp");
            std::abort();
        }
        root = pattern;
        fs::create_directories(root / "gltf");
        fs::create_directories(root / "glb");
        gltfFile = root / "gltf" / "scene.gltf";
        glbFile = root / "glb" / "scene.glb";
    }
    ~Workspace() {
        std::error_code ignored;
        fs::remove_all(root, ignored);
    }
};

Workspace& workspace() {
    static Workspace instance;
    return instance;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
    const fs::path& file = binary ? workspace().glbFile : workspace().gltfFile;
    {
        std::ofstream out(file, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
        if (!out) {
            std::perror("gltf_fuzzer: cannot write the input");
            std::abort();
        }
    }
    vct::LoadOptions options;
    options.maxFileBytes = uint64_t(64) << 20;  // no input is larger: keeps a hostile length cheap
    try {
        const vct::Scene scene = vct::loadGltf(file.string(), options);
        // Touch what the renderer reads first, so a scene that loads is also one that can be used.
        (void)scene.bounds();
        (void)scene.triangleCount();
    } catch (const vct::Error&) {
        // A clean refusal: the message names the file and the problem.
    }
    return 0;
}
