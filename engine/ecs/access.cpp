#include "engine/ecs/access.h"

#include <algorithm>
#include <stdexcept>

namespace pyro::ecs {

const char* access_mode_name(AccessMode mode) {
  switch (mode) {
    case AccessMode::none:
      return "none";
    case AccessMode::read:
      return "read";
    case AccessMode::write:
      return "write";
  }
  return "unknown";
}

void Access::add_type(std::size_t id, std::string name, AccessMode mode) {
  if (id >= modes_.size()) modes_.resize(id + 1, uint8_t(AccessMode::none));
  for (Entry& e : entries_) {
    if (e.id != id) continue;
    e.mode = std::max(e.mode, mode);
    modes_[id] = uint8_t(e.mode);
    return;
  }
  entries_.push_back({id, std::move(name), mode});
  modes_[id] = uint8_t(mode);
}

std::vector<std::string> Access::read_names() const {
  std::vector<std::string> names;
  for (const Entry& e : entries_)
    if (e.mode == AccessMode::read) names.push_back(e.name);
  return names;
}

std::vector<std::string> Access::write_names() const {
  std::vector<std::string> names;
  for (const Entry& e : entries_)
    if (e.mode == AccessMode::write) names.push_back(e.name);
  return names;
}

bool Access::conflicts_with(const Access& other) const {
  const std::size_t entities = type_id<Entities>();
  if (mode(entities) == AccessMode::write || other.mode(entities) == AccessMode::write) return true;
  for (const Entry& e : entries_) {
    const AccessMode theirs = other.mode(e.id);
    if (theirs == AccessMode::none) continue;
    if (e.mode == AccessMode::write || theirs == AccessMode::write) return true;
  }
  return false;
}

void throw_undeclared_access(const RunningSystem& system, const std::string& type,
                             AccessMode wanted, const char* op) {
  std::string has = "does not declare it";
  for (const Access::Entry& e : system.access->entries())
    if (e.name == type) has = "declares it only as a read";
  const char* verb = wanted == AccessMode::write ? "writes " : "reads ";
  const char* list = wanted == AccessMode::write ? "ecs::Writes<" : "ecs::Reads<";
  throw std::logic_error("system '" + *system.name + "' " + verb + type + " (World::" + op +
                         ") but " + has + "; add " + list + type + "> to its access");
}

}  // namespace pyro::ecs
