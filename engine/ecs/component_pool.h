#pragma once
// Sparse-set storage, one pool per component type.
//
//   data_[slot]      the components, packed (dense)
//   entities_[slot]  which entity owns data_[slot]
//   sparse_[index]   entity index -> slot, or npos
//
// Add appends, remove swaps the last slot into the hole, lookup is two array reads. Packing
// is what lets queries and owning groups (see world.h) run flat loops over data_.
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "engine/ecs/entity.h"

namespace pyro::ecs {

namespace detail {
inline std::size_t next_type_id() {
  static std::atomic<std::size_t> next{0};
  return next.fetch_add(1, std::memory_order_relaxed);
}
template <class T>
std::size_t type_id_of() {
  // One counter value per type, assigned on first use: a dense index for the world's pool
  // table, with no typeid/map lookup on the hot path.
  static const std::size_t id = next_type_id();
  return id;
}
}  // namespace detail

// Dense, process-wide id of a (cv/ref-stripped) type. Ids depend on first-use order, so never
// persist them; use type_name() for anything a human or a file sees.
template <class T>
std::size_t type_id() {
  return detail::type_id_of<std::remove_cvref_t<T>>();
}

// Readable type name taken from the compiler's function signature, for messages and reports.
template <class T>
std::string type_name() {
  // g++:   "std::string pyro::ecs::type_name() [with T = Foo; std::string = ...]"
  // clang: "std::string pyro::ecs::type_name() [T = Foo]"
  const std::string_view sig = __PRETTY_FUNCTION__;
  std::size_t begin = sig.find("T = ");
  if (begin == std::string_view::npos) return "unknown";
  begin += 4;
  // Stop at the ';' or ']' that closes T, not at one nested inside it (e.g. "int [3]").
  int depth = 0;
  std::size_t end = begin;
  for (; end < sig.size(); ++end) {
    const char c = sig[end];
    if (c == '<' || c == '(' || c == '[') ++depth;
    if (c == '>' || c == ')') --depth;
    if (c == ']') {
      if (depth == 0) break;
      --depth;
    }
    if (c == ';' && depth == 0) break;
  }
  return std::string(sig.substr(begin, end - begin));
}

class World;

// The type-independent half of a pool: entity bookkeeping plus the hooks the world needs to
// reorder or erase slots without knowing T.
class PoolBase {
 public:
  static constexpr uint32_t npos = UINT32_MAX;

  virtual ~PoolBase() = default;
  PoolBase() = default;
  PoolBase(const PoolBase&) = delete;
  PoolBase& operator=(const PoolBase&) = delete;

  std::size_t size() const { return entities_.size(); }
  bool empty() const { return entities_.empty(); }
  bool contains(uint32_t index) const { return index < sparse_.size() && sparse_[index] != npos; }
  // Slot of an entity index; only meaningful when contains(index).
  std::size_t slot(uint32_t index) const { return sparse_[index]; }
  // Owners of each slot, in slot order.
  const std::vector<Entity>& entities() const { return entities_; }

  // Swap-remove the component of entity `index` (which must be present).
  virtual void erase(uint32_t index) = 0;

  // Exchange two slots, keeping the sparse index consistent. Used to pack groups.
  void swap_slots(std::size_t a, std::size_t b) {
    if (a == b) return;
    std::swap(entities_[a], entities_[b]);
    sparse_[entities_[a].index] = uint32_t(a);
    sparse_[entities_[b].index] = uint32_t(b);
    swap_data(a, b);
  }

  virtual std::string component_name() const = 0;

 protected:
  virtual void swap_data(std::size_t a, std::size_t b) = 0;

  std::vector<Entity> entities_;
  std::vector<uint32_t> sparse_;

 private:
  friend class World;
  // World bookkeeping: the owning group (SIZE_MAX if none) and how many each<> loops are
  // currently walking this pool (structural changes are refused while it is non-zero). Atomic:
  // systems that only read a pool may walk it from several threads at once.
  std::size_t group_ = SIZE_MAX;
  std::atomic<uint32_t> locks_{0};
};

template <class T>
class ComponentPool final : public PoolBase {
  static_assert(std::is_same_v<T, std::remove_cvref_t<T>>,
                "components are plain value types (no const, no references)");
  static_assert(std::is_move_constructible_v<T> && std::is_move_assignable_v<T>,
                "swap-remove needs movable components");

 public:
  // Precondition: !contains(e.index). Strong guarantee: a throwing constructor leaves the
  // pool as it was.
  template <class... A>
  T& emplace(Entity e, A&&... args) {
    if (e.index >= sparse_.size()) sparse_.resize(std::size_t(e.index) + 1, npos);
    entities_.push_back(e);
    try {
      // Parenthesised init also accepts aggregates in C++20 (Position{1, 2, 3} as (1, 2, 3)).
      data_.emplace_back(std::forward<A>(args)...);
    } catch (...) {
      entities_.pop_back();
      throw;
    }
    sparse_[e.index] = uint32_t(data_.size() - 1);
    return data_.back();
  }

  void erase(uint32_t index) override {
    const std::size_t hole = sparse_[index];
    const std::size_t last = data_.size() - 1;
    if (hole != last) {
      data_[hole] = std::move(data_[last]);
      entities_[hole] = entities_[last];
      sparse_[entities_[hole].index] = uint32_t(hole);
    }
    data_.pop_back();
    entities_.pop_back();
    sparse_[index] = npos;
  }

  // Preconditions: contains(index).
  T& get(uint32_t index) { return data_[sparse_[index]]; }
  const T& get(uint32_t index) const { return data_[sparse_[index]]; }

  T* try_get(uint32_t index) { return contains(index) ? &data_[sparse_[index]] : nullptr; }
  const T* try_get(uint32_t index) const {
    return contains(index) ? &data_[sparse_[index]] : nullptr;
  }

  // Dense component array, parallel to entities().
  T* data() { return data_.data(); }
  const T* data() const { return data_.data(); }

  std::string component_name() const override { return type_name<T>(); }

 private:
  void swap_data(std::size_t a, std::size_t b) override {
    using std::swap;
    swap(data_[a], data_[b]);
  }

  std::vector<T> data_;
};

}  // namespace pyro::ecs
