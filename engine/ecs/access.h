#pragma once
// What a system may touch, declared by type:
//
//   ecs::Access::of<ecs::Reads<Camera, RenderSettings>, ecs::Writes<View>>()
//
// Components and resources count alike. A write implies a read. While a Schedule runs a system,
// the World checks every access against the running system's declaration (RunningSystemScope
// below, one per thread, so concurrent systems are checked independently): an undeclared access
// throws std::logic_error naming the system, the type and the operation. Outside any scheduled
// system (building the world, a test poking it) nothing is checked.
//
// The check costs one thread-local load and one table lookup per World call (per query, not per
// element); `pyro bench ecs` measures it against plain arrays in the same run.
#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

#include "engine/ecs/component_pool.h"

namespace pyro::ecs {

template <class... Ts>
struct Reads {};
template <class... Ts>
struct Writes {};

// The entity table itself. Every system reads it implicitly (each component access checks that
// its entity is alive); creating or destroying entities, or declaring groups, while systems run
// needs Writes<Entities>, which conflicts with every other system.
struct Entities {};

enum class AccessMode : uint8_t { none = 0, read = 1, write = 2 };

const char* access_mode_name(AccessMode mode);

namespace detail {
template <class T>
inline constexpr bool is_access_list = false;
template <class... Ts>
inline constexpr bool is_access_list<Reads<Ts...>> = true;
template <class... Ts>
inline constexpr bool is_access_list<Writes<Ts...>> = true;
}  // namespace detail

class Access {
 public:
  struct Entry {
    std::size_t id;    // type_id<T>()
    std::string name;  // type_name<T>()
    AccessMode mode;   // read or write
  };

  // Access::of<Reads<A, B>, Writes<C>>(); a type named in both counts as written.
  template <class... Lists>
  static Access of() {
    static_assert((detail::is_access_list<Lists> && ...),
                  "Access::of<...> takes ecs::Reads<...> and ecs::Writes<...> lists");
    Access a;
    (a.add(Lists{}), ...);
    return a;
  }

  template <class T>
  Access& read() {
    add_type(type_id<T>(), type_name<std::remove_cvref_t<T>>(), AccessMode::read);
    return *this;
  }
  template <class T>
  Access& write() {
    add_type(type_id<T>(), type_name<std::remove_cvref_t<T>>(), AccessMode::write);
    return *this;
  }

  // The strongest access declared for a type id (none if undeclared). Hot: one array read.
  AccessMode mode(std::size_t id) const {
    return id < modes_.size() ? static_cast<AccessMode>(modes_[id]) : AccessMode::none;
  }
  bool allows(std::size_t id, AccessMode wanted) const { return mode(id) >= wanted; }

  // Every declared type, in declaration order.
  const std::vector<Entry>& entries() const { return entries_; }
  // Names of the types only read / of the types written.
  std::vector<std::string> read_names() const;
  std::vector<std::string> write_names() const;

  // True when one of the two writes a type the other reads or writes (Writes<Entities>
  // conflicts with everything): such systems must not run at the same time.
  bool conflicts_with(const Access& other) const;

  // One past the largest declared type id: the World's type tables must be this large before
  // systems run in parallel (World::reserve_type_slots), so that none of them grows a table.
  std::size_t type_slots() const { return modes_.size(); }
  // The AccessMode of each type id below type_slots(), as bytes.
  const uint8_t* mode_table() const { return modes_.data(); }

 private:
  template <class... Ts>
  void add(Reads<Ts...>) {
    (read<Ts>(), ...);
  }
  template <class... Ts>
  void add(Writes<Ts...>) {
    (write<Ts>(), ...);
  }
  void add_type(std::size_t id, std::string name, AccessMode mode);

  std::vector<Entry> entries_;
  std::vector<uint8_t> modes_;  // AccessMode by type id
};

// The system running on this thread under a Schedule, with its access table flattened so that
// a check is one load from it.
struct RunningSystem {
  RunningSystem(const std::string& system_name, const Access& system_access)
      : name(&system_name),
        access(&system_access),
        modes(system_access.mode_table()),
        slots(system_access.type_slots()) {}

  bool allows(std::size_t id, AccessMode wanted) const {
    return id < slots && modes[id] >= static_cast<uint8_t>(wanted);
  }

  const std::string* name;
  const Access* access;
  const uint8_t* modes;
  std::size_t slots;
};

namespace detail {
// constinit: a constant-initialised thread_local needs no per-access initialisation guard.
inline constinit thread_local const RunningSystem* running_system = nullptr;
}  // namespace detail

// The system this thread is running under a schedule, or null.
inline const RunningSystem* running_system() { return detail::running_system; }

// Makes `system` the running system of this thread for the scope's lifetime (nests: the
// previous one is restored).
class RunningSystemScope {
 public:
  explicit RunningSystemScope(const RunningSystem& system) : previous_(detail::running_system) {
    detail::running_system = &system;
  }
  ~RunningSystemScope() { detail::running_system = previous_; }
  RunningSystemScope(const RunningSystemScope&) = delete;
  RunningSystemScope& operator=(const RunningSystemScope&) = delete;

 private:
  const RunningSystem* previous_;
};

// Throws std::logic_error: "system 'S' writes T (World::op) but declares ...".
[[noreturn, gnu::cold]] void throw_undeclared_access(const RunningSystem& system,
                                                     const std::string& type, AccessMode wanted,
                                                     const char* op);

// The check the World makes on every typed access. T may be const-qualified (a read).
template <class T>
inline void check_access(AccessMode wanted, const char* op) {
  const RunningSystem* s = detail::running_system;
  if (s && !s->allows(type_id<T>(), wanted)) [[unlikely]]
    throw_undeclared_access(*s, type_name<std::remove_cvref_t<T>>(), wanted, op);
}

// The mode an access through T needs: const T reads, T writes.
template <class T>
inline constexpr AccessMode mode_of =
    std::is_const_v<std::remove_reference_t<T>> ? AccessMode::read : AccessMode::write;

}  // namespace pyro::ecs
