// pyro: the Pyrocumulus command line. Exit status: 0 success, 1 internal error, 2 a user error
// (bad scene file, bad argument; the message names the file and the place), 3 no usable GPU
// context; a missing or failing helper program (the plotting script) is a 1 with its own message,
// and so is a write the system refused (full disk, read-only file system: the file and strerror).
#include <cstdio>
#include <exception>

#include <CLI/CLI.hpp>

#include "engine/core/user_error.h"
#include "engine/gpu/gpu_error.h"
#include "engine/io/io_error.h"
#include "tools/pyro/app.h"
#include "tools/pyro/external_tool_error.h"

int main(int argc, char** argv) {
  CLI::App app{"Pyrocumulus: real-time gaseous phenomena (clouds, fog, mist) splatted as "
               "Gaussian particles"};
  pyro::cli::add_pyro_commands(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  } catch (const pyro::UserError& e) {
    std::fprintf(stderr, "pyro: error: %s\n", e.what());
    return 2;
  } catch (const pyro::IoError& e) {
    std::fprintf(stderr, "pyro: error: %s\n", e.what());
    return 1;
  } catch (const pyro::gpu::GpuError& e) {
    std::fprintf(stderr, "pyro: GPU error: %s\n", e.what());
    return 3;
  } catch (const pyro::cli::ExternalToolError& e) {
    std::fprintf(stderr, "pyro: error: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pyro: internal error: %s\n", e.what());
    return 1;
  }
  return 0;
}
