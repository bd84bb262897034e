#include "tools/charts/plot_script.h"

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "tools/charts/external_tool_error.h"

namespace pyro::cli {

std::string tools_dir() {
  if (const char* env = std::getenv("PYRO_TOOLS_DIR"); env && *env) return env;
  return PYRO_DEFAULT_TOOLS_DIR;
}

std::string python_interpreter() {
  if (const char* env = std::getenv("PYRO_PYTHON"); env && *env) return env;
  return "/usr/bin/python3";
}

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) {
    if (c == '\'')
      q += "'\\''";
    else
      q += c;
  }
  return q + "'";
}

void run_plot_script(const std::string& script_name, const std::vector<std::string>& arguments,
                     const std::string& written_note) {
  const std::string python = python_interpreter();
  const std::filesystem::path script = std::filesystem::path(tools_dir()) / "plots" / script_name;
  if (!std::filesystem::exists(script))
    throw ExternalToolError("cannot find the plotting script " + script.string() +
                            " (set PYRO_TOOLS_DIR to the source tree's tools/ folder)" + written_note);
  std::string command = shell_quote(python) + " " + shell_quote(script.string());
  for (const std::string& a : arguments) command += " " + shell_quote(a);
  command += " 1>&2";
  std::fflush(stdout);
  const int status = std::system(command.c_str());
  if (status == -1) throw ExternalToolError("cannot start a shell to run " + python + written_note);
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  if (code == 0) return;
  if (code == kPlotExitNoMatplotlib)
    throw ExternalToolError("the PNG charts need matplotlib, which " + python +
                            " cannot import: install the Debian package python3-matplotlib "
                            "(./tools/install-deps.sh), or pass --csv-only" +
                            written_note);
  if (code == 127)
    throw ExternalToolError("cannot run " + python +
                            " (not found; install python3, or set PYRO_PYTHON)" + written_note);
  throw ExternalToolError("the plotting script " + script.string() + " failed with exit status " +
                          std::to_string(code) + " (its messages are above)" + written_note);
}

}  // namespace pyro::cli
