#include "tools/farm/slurm_options.h"

#include <algorithm>
#include <cctype>
#include <vector>

#include "engine/core/user_error.h"

namespace pyro {

namespace {

bool all_digits(const std::string& s) {
  return !s.empty() && s.size() <= 9 &&
         std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c) != 0; });
}

std::vector<std::string> split(const std::string& s, char separator) {
  std::vector<std::string> parts(1);
  for (char c : s) {
    if (c == separator)
      parts.emplace_back();
    else
      parts.back().push_back(c);
  }
  return parts;
}

// "A", "A:B" or "A:B:C" with every field digits and those after the first below 60; at most
// `max_fields` fields.
bool is_clock(const std::string& s, size_t max_fields) {
  const std::vector<std::string> fields = split(s, ':');
  if (fields.size() > max_fields) return false;
  for (size_t i = 0; i < fields.size(); ++i)
    if (!all_digits(fields[i]) || (i > 0 && (fields[i].size() > 2 || std::stoi(fields[i]) >= 60)))
      return false;
  return true;
}

// The option an sbatch argument names: "--qos=high" -> "--qos", "-A" / "-Aproj" -> "-A".
std::string sbatch_option_name(const std::string& arg) {
  if (arg.rfind("--", 0) == 0) return arg.substr(0, arg.find('='));
  return arg.substr(0, 2);
}

// The sbatch options an --sbatch-arg may not give, and why.
std::string forbidden_sbatch_option(const std::string& name) {
  static const std::vector<std::string> pyro_sets = {
      "--array", "-a", "--dependency", "-d", "--parsable", "--output", "-o", "--error", "-e",
      "--job-name", "-J", "--wrap", "--requeue", "--no-requeue", "--chdir", "-D"};
  static const std::vector<std::pair<std::string, std::string>> own = {
      {"--time", "--time"},       {"-t", "--time"},       {"--mem", "--mem"},
      {"--cpus-per-task", "--cpus-per-task"}, {"-c", "--cpus-per-task"},
      {"--account", "--account"}, {"-A", "--account"},    {"--partition", "--partition"},
      {"-p", "--partition"}};
  if (std::find(pyro_sets.begin(), pyro_sets.end(), name) != pyro_sets.end())
    return "pyro farm sets " + name + " itself";
  for (const auto& [option, farm_option] : own)
    if (option == name) return "give it as pyro farm's own " + farm_option;
  return {};
}

void check_sbatch_arg(const std::string& arg) {
  if (arg.size() < 2 || arg[0] != '-' || arg == "--")
    throw UserError("", "--sbatch-arg",
                    "an sbatch option such as --sbatch-arg=--qos=high (one word, starting with "
                    "'-'); got \"" + arg + "\"");
  const std::string why = forbidden_sbatch_option(sbatch_option_name(arg));
  if (!why.empty())
    throw UserError("", "--sbatch-arg", "an sbatch option pyro farm does not set; got \"" + arg +
                                            "\": " + why);
}

bool is_account(const std::string& a) {
  return !a.empty() && a.size() <= 64 && std::all_of(a.begin(), a.end(), [](unsigned char c) {
    return std::isalnum(c) != 0 || c == '_' || c == '-' || c == '.';
  });
}

}  // namespace

bool is_slurm_time(const std::string& time) {
  std::string upper = time;
  for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (upper == "UNLIMITED" || upper == "INFINITE") return true;
  const size_t dash = time.find('-');
  if (dash == std::string::npos) return is_clock(time, 3);
  const std::string hours = time.substr(dash + 1);
  return all_digits(time.substr(0, dash)) && is_clock(hours, 3) &&
         split(hours, ':')[0].size() <= 2 && std::stoi(split(hours, ':')[0]) < 24;
}

bool is_slurm_memory(const std::string& mem) {
  if (mem.empty()) return false;
  const char unit = static_cast<char>(std::toupper(static_cast<unsigned char>(mem.back())));
  const bool has_unit = unit == 'K' || unit == 'M' || unit == 'G' || unit == 'T';
  return all_digits(has_unit ? mem.substr(0, mem.size() - 1) : mem);
}

void check_farm_scheduler(const FarmScheduler& s) {
  if (!s.time.empty() && !is_slurm_time(s.time))
    throw UserError("", "--time",
                    "a time limit in one of Slurm's forms: MINUTES, MINUTES:SECONDS, "
                    "HOURS:MINUTES:SECONDS, DAYS-HOURS, DAYS-HOURS:MINUTES, "
                    "DAYS-HOURS:MINUTES:SECONDS (e.g. 90, 2:30:00, 1-12), or UNLIMITED; got \"" +
                        s.time + "\"");
  if (!s.mem.empty() && !is_slurm_memory(s.mem))
    throw UserError("", "--mem",
                    "memory per task as a whole number with an optional unit K, M, G or T "
                    "(e.g. 4G, 500M; no unit: megabytes); got \"" + s.mem + "\"");
  if (s.cpus_per_task < 0)
    throw UserError("", "--cpus-per-task", "at least 1 CPU per task");
  if (!s.account.empty() && !is_account(s.account))
    throw UserError("", "--account",
                    "a Slurm account name (letters, digits, '_', '-', '.'); got \"" + s.account +
                        "\"");
  for (const std::string& arg : s.sbatch_args) check_sbatch_arg(arg);
}

}  // namespace pyro
