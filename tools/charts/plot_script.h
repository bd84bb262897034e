#pragma once
// Runs a plotting script of tools/plots (Debian's matplotlib through /usr/bin/python3): the
// charts of `pyro analyze projection-error --surface` and `pyro chart`. The script's messages go
// to stderr, so that stdout holds only pyro's own report.
#include <string>
#include <vector>

namespace pyro::cli {

// Exit status of the plotting scripts when matplotlib cannot be imported.
constexpr int kPlotExitNoMatplotlib = 3;

// Where the scripts live: $PYRO_TOOLS_DIR, else the source tree's tools/ folder.
std::string tools_dir();
// $PYRO_PYTHON, else /usr/bin/python3 (Debian's, which has python3-matplotlib; not the first
// python3 on PATH, which may be another installation without it).
std::string python_interpreter();
// Quotes `s` for /bin/sh.
std::string shell_quote(const std::string& s);

// Runs tools/plots/`script` with `arguments`. Throws ExternalToolError when the script is
// missing, python cannot run, matplotlib is missing, or the script fails; `written_note` (e.g.
// "; the CSV files are written in DIR") ends each message.
void run_plot_script(const std::string& script, const std::vector<std::string>& arguments,
                     const std::string& written_note);

}  // namespace pyro::cli
