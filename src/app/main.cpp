// vct: a real-time global-illumination renderer based on voxel cone tracing.
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "app/commands.h"
#include "app/did_you_mean.h"
#include "app/options.h"
#include "error.h"
#include "io/exit_immediately.h"
#include "io/temporary_files.h"

static void printUsage() {
    std::printf(
        "usage: vct <command> [options]\n"
        "\n"
        "commands:\n"
        "  render   render one image to a .pfm (linear radiance) or .png file (vct render --help)\n"
        "  view     open a window and explore a scene interactively (vct view --help)\n"
        "  bench    measure run time against error over a matrix of settings (vct bench --help)\n"
        "\n"
        "\n"
        "  -h, --help   this help; each command has its own (vct render --help)\n"
        "  --version    print the version of vct and exit\n"
        "\n"
        "Errors are reported as one sentence and exit code 1.\n");
}

int main(int argc, char** argv) {
    if (argc < 2) {
        printUsage();
        return 1;
    }
    vct::installTemporaryFileCleanup();  // a signal leaves no OUT.tmp.PID behind
    const std::string command = argv[1];
    vct::setErrorLinePrefix("vct " + command);
    const std::vector<std::string> arguments(argv + 2, argv + argc);
    try {
        if (command == "render") return vct::runRender(arguments);
        if (command == "view") return vct::runView(arguments);
        if (command == "bench") return vct::runBench(arguments);
        if (command == "--help" || command == "-h" || command == "help") {
            printUsage();
            return 0;
        }
        if (command == "--version") {
            std::printf("%s\n", vct::versionText().c_str());
            return 0;
        }
        std::fprintf(stderr, "vct: unknown command '%s'%s\n", command.c_str(),
                     vct::didYouMean(command, {"render", "view", "bench"}).c_str());
        printUsage();
        return 1;
    } catch (const vct::Error& error) {
        std::fprintf(stderr, "vct %s: error: %s\n", command.c_str(), error.what());
        return 1;
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "vct %s: error: out of memory\n", command.c_str());
        return 1;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "vct %s: internal error: %s\n", command.c_str(), error.what());
        return 1;
    }
}
