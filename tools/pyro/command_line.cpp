#include "tools/pyro/command_line.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/edit_distance.h"
#include "engine/core/printable_text.h"
#include "engine/core/user_error.h"
#include "engine/gpu/gpu_error.h"
#include "engine/io/io_error.h"
#include "tools/charts/external_tool_error.h"
#include "tools/pyro/interrupt.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

namespace {

int fail(int status, const std::string& message) {
  std::fprintf(stderr, "pyro: error: %s\n", printable(message).c_str());
  return status;
}

std::string quoted_names(const std::vector<std::string_view>& names) {
  std::string out;
  for (std::string_view n : names) out += (out.empty() ? "'" : ", '") + std::string(n) + "'";
  return out;
}

// "; did you mean 'x'?" or "; expected one of 'a', 'b'" (when there are few enough to list).
std::string suggestion(std::string_view wrong, const std::vector<std::string_view>& names) {
  const std::string_view best = closest_candidate(wrong, names);
  if (!best.empty()) return "; did you mean '" + std::string(best) + "'?";
  if (names.size() <= 16) return "; expected one of " + quoted_names(names);
  return "";
}

// The word where a command is expected that names none, with a suggestion; nothing when the
// arguments name commands up to their first option or plain argument.
std::optional<std::string> unknown_command(CLI::App& app, int argc, char** argv) {
  CLI::App* at = &app;
  std::string path = "pyro";
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    const std::vector<CLI::App*> subcommands = at->get_subcommands({});
    if (word.empty() || word[0] == '-' || subcommands.empty()) return std::nullopt;
    CLI::App* next = nullptr;
    std::vector<std::string_view> names;
    for (CLI::App* s : subcommands) {
      names.push_back(s->get_name());
      if (s->check_name(word)) next = s;
    }
    if (next == nullptr) {
      if (at->get_require_subcommand_min() == 0) return std::nullopt;  // a plain argument
      return "unknown command '" + word + "' for '" + path + "'" + suggestion(word, names) +
             " (see '" + path + " --help')";
    }
    at = next;
    path += " " + next->get_name();
  }
  return std::nullopt;
}

// The deepest command the parser had chosen, and its name as typed ("pyro bench scale").
CLI::App* chosen_command(CLI::App& app, std::string& path) {
  CLI::App* at = &app;
  path = "pyro";
  for (;;) {
    const std::vector<CLI::App*> chosen = at->get_subcommands();
    if (chosen.empty()) return at;
    at = chosen.front();
    path += " " + at->get_name();
  }
}

// The first argument after the chosen command that looks like an option and is none of its
// options (nor its parents'), with a suggestion; empty when there is none.
std::string unknown_option(CLI::App* command, const std::string& path, int argc, char** argv) {
  std::vector<std::string> options;
  for (CLI::App* at = command; at != nullptr; at = at->get_parent())
    for (const CLI::Option* o : at->get_options()) {
      for (const std::string& l : o->get_lnames()) options.push_back("--" + l);
      for (const std::string& s : o->get_snames()) options.push_back("-" + s);
    }
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    if (word == "--") break;
    if (word.size() < 2 || word[0] != '-' || (word[1] >= '0' && word[1] <= '9') || word[1] == '.')
      continue;  // a plain argument or a negative number
    const std::string name = word.substr(0, word.find('='));
    if (std::find(options.begin(), options.end(), name) != options.end()) continue;
    const std::vector<std::string_view> names(options.begin(), options.end());
    return "unknown option '" + name + "' for '" + path + "'" + suggestion(name, names) +
           " (see '" + path + " --help')";
  }
  return "";
}

// CLI11's own messages, reworded: an unknown option (reported first, whatever CLI11 found)
// gets the closest of the command's options; every message names the command whose --help
// explains it.
std::string parse_error_message(CLI::App& app, const CLI::ParseError& e, int argc, char** argv) {
  std::string path;
  CLI::App* command = chosen_command(app, path);
  if (std::string unknown = unknown_option(command, path, argc, argv); !unknown.empty()) return unknown;
  std::string message = e.what();
  if (dynamic_cast<const CLI::ExtrasError*>(&e) != nullptr) {
    const std::string::size_type colon = message.find(": ");
    std::string extra = colon == std::string::npos ? message : message.substr(colon + 2);
    return "unexpected argument '" + extra.substr(0, extra.find(' ')) + "' for '" + path +
           "' (see '" + path + " --help')";
  }
  return message + " (see '" + path + " --help')";
}

// --help, --help-all and --version, printed through the checked writer (CLI11 would print them
// on std::cout and lose a write error's cause).
int print_requested_text(CLI::App& app, const CLI::ParseError& e) {
  if (dynamic_cast<const CLI::CallForVersion*>(&e) != nullptr)
    write_stdout(std::string(e.what()) + "\n");
  else if (dynamic_cast<const CLI::CallForAllHelp*>(&e) != nullptr)
    write_stdout(app.help("", CLI::AppFormatMode::All));
  else if (dynamic_cast<const CLI::CallForHelp*>(&e) != nullptr)
    write_stdout(app.help());
  else
    return app.exit(e);
  return 0;
}

int run_parsed(CLI::App& app, int argc, char** argv) {
  if (const std::optional<std::string> unknown = unknown_command(app, argc, argv))
    return fail(2, *unknown);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() != 0) return fail(2, parse_error_message(app, e, argc, argv));
    try {
      return print_requested_text(app, e);
    } catch (const IoError& io) {
      return fail(1, io.what());
    }
  } catch (const UserError& e) {
    return fail(2, e.what());
  } catch (const IoError& e) {
    return fail(1, e.what());
  } catch (const gpu::GpuError& e) {
    return fail(3, std::string("no usable OpenGL context: ") + e.what());
  } catch (const ExternalToolError& e) {
    return fail(1, e.what());
  } catch (const Interrupted& i) {
    return fail(128 + i.signal, std::string("interrupted by ") + sigabbrev_np(i.signal) +
                                    "; nothing half-written was kept");
  } catch (const std::bad_alloc&) {
    return fail(1, "out of memory");
  } catch (const std::exception& e) {
    return fail(1, std::string("internal error: ") + e.what());
  }
  return 0;
}

}  // namespace

int run_command_line(CLI::App& app, int argc, char** argv) {
  int status = run_parsed(app, argc, argv);
  errno = 0;
  if ((std::fflush(stdout) != 0 || std::ferror(stdout)) && status == 0)
    status = fail(1, std::string("standard output: cannot write: ") +
                         std::strerror(errno != 0 ? errno : EIO));
  return status;
}

}  // namespace pyro::cli
