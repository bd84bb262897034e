#pragma once
// The world: entity slots, one sparse-set pool per component type, owning groups, and
// world-wide resources.
//
// Rules worth knowing:
//  - Every component access through a dead or stale handle throws std::logic_error, including
//    has() and try_get(): a stale handle is a bug to surface, not a "no".
//  - References returned by emplace/get stay valid until the next structural change (emplace,
//    remove, destroy, group) of that component type.
//  - Inside each<Ts...>(f), f may read and write components and create entities, but it may
//    not add or remove any of Ts (nor destroy an entity that has one, nor touch a pool that
//    shares a group with one): that would move data under the loop, so it throws
//    std::logic_error. Collect such changes and apply them after the loop.
//  - A const-qualified type reads: get<const T>, try_get<const T>, each<const T, U>,
//    resource<const T>; so does every call through a const World. A plain T writes. While a
//    Schedule runs a system, each typed access is checked against the system's declared
//    Access (engine/ecs/access.h) and an undeclared one throws std::logic_error.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "engine/ecs/access.h"
#include "engine/ecs/component_pool.h"
#include "engine/ecs/entity.h"

namespace pyro::ecs {

namespace detail {
template <class... Ts>
inline constexpr bool all_distinct = true;
template <class T, class... Rest>
inline constexpr bool all_distinct<T, Rest...> =
    (!std::is_same_v<std::remove_const_t<T>, std::remove_const_t<Rest>> && ...) &&
    all_distinct<Rest...>;

template <class... Ts>
std::string type_list() {
  std::string s;
  ((s += (s.empty() ? "" : ", ") + type_name<std::remove_const_t<Ts>>()), ...);
  return s;
}
}  // namespace detail

class World {
  // The component or resource type behind a possibly const-qualified T.
  template <class T>
  using bare = std::remove_const_t<T>;

 public:
  World() = default;
  World(const World&) = delete;
  World& operator=(const World&) = delete;
  World(World&&) noexcept = default;
  World& operator=(World&&) noexcept = default;

  // ---- entities ----------------------------------------------------------------------------

  Entity create() {
    check_access<Entities>(AccessMode::write, "create");
    if (!free_.empty()) {
      const uint32_t index = free_.back();
      free_.pop_back();
      slots_[index].alive = true;
      ++alive_count_;
      return {index, slots_[index].generation};
    }
    // UINT32_MAX is the null index, so it is never handed out.
    if (slots_.size() >= std::size_t(UINT32_MAX))
      throw std::length_error("World::create: out of entity indices");
    slots_.push_back({0, true});
    ++alive_count_;
    return {uint32_t(slots_.size() - 1), 0};
  }

  // Removes all of e's components and retires the handle. Throws if e is not alive.
  void destroy(Entity e) {
    check_access<Entities>(AccessMode::write, "destroy");
    require_alive<void>(e, "destroy");
    // Check every pool before touching any, so a refused destroy changes nothing.
    for (auto& p : pools_) {
      if (!p || !p->contains(e.index)) continue;
      require_unlocked(*p, "destroy");
      if (const RunningSystem* s = running_system();
          s && !s->allows(std::size_t(&p - pools_.data()), AccessMode::write))
        throw_undeclared_access(*s, p->component_name(), AccessMode::write, "destroy");
    }
    for (auto& p : pools_)
      if (p && p->contains(e.index)) erase_from(*p, e.index);
    Slot& s = slots_[e.index];
    s.alive = false;
    --alive_count_;
    // Retire a slot whose generation would reach the null generation rather than wrap and
    // risk aliasing a handle from 2^32 lifetimes ago.
    if (++s.generation != UINT32_MAX) free_.push_back(e.index);
  }

  bool alive(Entity e) const {
    return e.index < slots_.size() && slots_[e.index].alive &&
           slots_[e.index].generation == e.generation;
  }

  std::size_t entity_count() const { return alive_count_; }

  // ---- components --------------------------------------------------------------------------

  template <class T, class... A>
  T& emplace(Entity e, A&&... args) {
    static_assert(std::is_same_v<T, std::remove_cvref_t<T>>, "component types are plain values");
    check_access<T>(AccessMode::write, "emplace");
    require_alive<T>(e, "emplace");
    ComponentPool<T>& p = assure<T>();
    if (p.contains(e.index))
      throw std::logic_error("World::emplace<" + type_name<T>() + ">: entity " + to_string(e) +
                             " already has one");
    require_unlocked(p, "emplace");
    T& added = p.emplace(e, std::forward<A>(args)...);
    if (p.group_ == SIZE_MAX) return added;
    try_join(*groups_[p.group_], e.index);
    return p.get(e.index);  // joining may have moved it
  }

  template <class T>
  void remove(Entity e) {
    check_access<T>(AccessMode::write, "remove");
    require_alive<T>(e, "remove");
    ComponentPool<T>* p = pool_ptr<T>();
    if (!p || !p->contains(e.index)) throw_absent<T>("remove", e);
    require_unlocked(*p, "remove");
    erase_from(*p, e.index);
  }

  template <class T>
  bool has(Entity e) const {
    check_access<T>(AccessMode::read, "has");
    require_alive<T>(e, "has");
    const ComponentPool<bare<T>>* p = pool_ptr<bare<T>>();
    return p && p->contains(e.index);
  }

  // get<T> writes (T&), get<const T> reads (const T&).
  template <class T>
  T& get(Entity e) {
    check_access<T>(mode_of<T>, "get");
    return get_unchecked<bare<T>>(e, "get");
  }
  template <class T>
  const bare<T>& get(Entity e) const {
    check_access<T>(AccessMode::read, "get");
    return const_cast<World*>(this)->get_unchecked<bare<T>>(e, "get");
  }

  template <class T>
  T* try_get(Entity e) {
    check_access<T>(mode_of<T>, "try_get");
    return try_get_unchecked<bare<T>>(e);
  }
  template <class T>
  const bare<T>* try_get(Entity e) const {
    check_access<T>(AccessMode::read, "try_get");
    return const_cast<World*>(this)->try_get_unchecked<bare<T>>(e);
  }

  // Number of entities that have a T.
  template <class T>
  std::size_t size() const {
    check_access<T>(AccessMode::read, "size");
    const ComponentPool<bare<T>>* p = pool_ptr<bare<T>>();
    return p ? p->size() : 0;
  }

  // Read-only view of T's storage (nullptr until the first T is emplaced or grouped); for
  // tests, reports and tools that want the dense arrays.
  template <class T>
  const ComponentPool<bare<T>>* pool() const {
    check_access<T>(AccessMode::read, "pool");
    return pool_ptr<bare<T>>();
  }

  // ---- queries -----------------------------------------------------------------------------

  // Calls f(Entity, Ts&...) or f(Ts&...) for every entity that has all of Ts; a const T is
  // read (f gets const T&), a plain T written.
  template <class... Ts, class F>
  void each(F&& f) {
    static_assert(sizeof...(Ts) > 0, "each<Ts...> needs at least one component type");
    static_assert(detail::all_distinct<Ts...>, "each<Ts...> lists a type twice");
    constexpr bool with_entity = std::is_invocable_v<F&, Entity, Ts&...>;
    static_assert(with_entity || std::is_invocable_v<F&, Ts&...>,
                  "each<Ts...>(f): f must be callable as f(Entity, Ts&...) or f(Ts&...)");
    (check_access<Ts>(mode_of<Ts>, "each"), ...);

    const std::array<PoolBase*, sizeof...(Ts)> ps{pool_ptr<bare<Ts>>()...};
    for (PoolBase* p : ps)
      if (!p || p->empty()) return;
    const IterationLock lock(ps);

    if (const Group* g = exact_group(ps)) {
      // Owned and packed: slot i of every pool is the same entity, so walk the dense arrays
      // side by side with no lookups and no branches.
      const std::size_t n = g->size;
      const Entity* ents = ps[0]->entities().data();
      [&](Ts*... d) {
        if constexpr (with_entity) {
          for (std::size_t i = 0; i < n; ++i) f(ents[i], d[i]...);
        } else {
          (void)ents;
          for (std::size_t i = 0; i < n; ++i) f(d[i]...);
        }
      }(static_cast<Ts*>(pool_ptr<bare<Ts>>()->data())...);
      return;
    }

    // Otherwise drive the loop from the smallest pool and look the rest up.
    const PoolBase* lead = *std::min_element(
        ps.begin(), ps.end(),
        [](const PoolBase* a, const PoolBase* b) { return a->size() < b->size(); });
    const Entity* ents = lead->entities().data();
    const std::size_t n = lead->size();
    [&](ComponentPool<bare<Ts>>*... pool) {
      for (std::size_t i = 0; i < n; ++i) {
        const Entity e = ents[i];
        if (!(pool->contains(e.index) && ...)) continue;
        if constexpr (with_entity)
          f(e, static_cast<Ts&>(pool->get(e.index))...);
        else
          f(static_cast<Ts&>(pool->get(e.index))...);
      }
    }(pool_ptr<bare<Ts>>()...);
  }

  // Through a const World every component is read: f gets const Ts&.
  template <class... Ts, class F>
  void each(F&& f) const {
    const_cast<World*>(this)->each<const Ts...>(std::forward<F>(f));
  }

  // Number of entities that have all of Ts.
  template <class... Ts>
  std::size_t count() const {
    static_assert(sizeof...(Ts) > 0 && detail::all_distinct<Ts...>);
    (check_access<Ts>(AccessMode::read, "count"), ...);
    const std::array<const PoolBase*, sizeof...(Ts)> ps{pool_ptr<bare<Ts>>()...};
    for (const PoolBase* p : ps)
      if (!p) return 0;
    if (const Group* g = exact_group(ps)) return g->size;
    const PoolBase* lead = *std::min_element(
        ps.begin(), ps.end(),
        [](const PoolBase* a, const PoolBase* b) { return a->size() < b->size(); });
    std::size_t n = 0;
    for (const Entity& e : lead->entities())
      n += std::all_of(ps.begin(), ps.end(),
                       [&](const PoolBase* p) { return p->contains(e.index); });
    return n;
  }

  // ---- owning groups -----------------------------------------------------------------------

  // From now on, entities having all of Ts sit in slots [0, group_size) of every Ts pool, in
  // the same order. Declaring the same set again is a no-op; a pool already owned by a
  // different group throws std::logic_error.
  template <class... Ts>
  void group() {
    static_assert(sizeof...(Ts) > 0, "group<Ts...> needs at least one component type");
    static_assert(detail::all_distinct<Ts...>, "group<Ts...> lists a type twice");
    static_assert((std::is_same_v<Ts, std::remove_cvref_t<Ts>> && ...),
                  "group<Ts...> takes plain component types");
    check_access<Entities>(AccessMode::write, "group");
    (check_access<Ts>(AccessMode::write, "group"), ...);
    const std::array<PoolBase*, sizeof...(Ts)> ps{&assure<Ts>()...};
    if (exact_group(ps)) return;
    for (PoolBase* p : ps) {
      if (p->group_ != SIZE_MAX)
        throw std::logic_error("World::group<" + detail::type_list<Ts...>() +
                               ">: " + p->component_name() + " is already owned by group<" +
                               groups_[p->group_]->name + ">");
      if (p->locks_.load(std::memory_order_relaxed))
        throw std::logic_error("World::group<" + detail::type_list<Ts...>() +
                               ">: " + p->component_name() + " is being iterated");
    }
    auto g = std::make_unique<Group>();
    g->pools.assign(ps.begin(), ps.end());
    g->name = detail::type_list<Ts...>();
    groups_.push_back(std::move(g));
    for (PoolBase* p : ps) p->group_ = groups_.size() - 1;

    // Pack whatever already exists. Copy the lead's indices first: packing reorders it.
    const PoolBase* lead = *std::min_element(
        ps.begin(), ps.end(),
        [](const PoolBase* a, const PoolBase* b) { return a->size() < b->size(); });
    std::vector<uint32_t> candidates;
    candidates.reserve(lead->size());
    for (const Entity& e : lead->entities()) candidates.push_back(e.index);
    for (uint32_t index : candidates) try_join(*groups_.back(), index);
  }

  // Size of the group declared with exactly Ts (any order); throws if there is none.
  template <class... Ts>
  std::size_t group_size() const {
    (check_access<Ts>(AccessMode::read, "group_size"), ...);
    const std::array<const PoolBase*, sizeof...(Ts)> ps{pool_ptr<bare<Ts>>()...};
    for (const PoolBase* p : ps)
      if (!p) throw_no_group<Ts...>();
    const Group* g = exact_group(ps);
    if (!g) throw_no_group<Ts...>();
    return g->size;
  }

  // ---- resources ---------------------------------------------------------------------------

  // Creates or replaces the world's single T.
  template <class T, class... A>
  T& set_resource(A&&... args) {
    static_assert(std::is_same_v<T, std::remove_cvref_t<T>>, "resource types are plain values");
    check_access<T>(AccessMode::write, "set_resource");
    auto box = std::make_unique<ResourceBox<T>>(std::forward<A>(args)...);
    T& value = box->value;
    const std::size_t id = type_id<T>();
    if (id >= resources_.size()) resources_.resize(id + 1);
    resources_[id] = std::move(box);
    return value;
  }

  // resource<T> writes (T&), resource<const T> reads (const T&).
  template <class T>
  T& resource() {
    check_access<T>(mode_of<T>, "resource");
    if (T* r = try_resource_unchecked<bare<T>>()) return *r;
    throw_no_resource<bare<T>>();
  }
  template <class T>
  const bare<T>& resource() const {
    check_access<T>(AccessMode::read, "resource");
    if (const bare<T>* r = const_cast<World*>(this)->try_resource_unchecked<bare<T>>()) return *r;
    throw_no_resource<bare<T>>();
  }

  template <class T>
  T* try_resource() {
    check_access<T>(mode_of<T>, "try_resource");
    return try_resource_unchecked<bare<T>>();
  }
  template <class T>
  const bare<T>* try_resource() const {
    check_access<T>(AccessMode::read, "try_resource");
    return const_cast<World*>(this)->try_resource_unchecked<bare<T>>();
  }

  template <class T>
  bool has_resource() const {
    check_access<T>(AccessMode::read, "has_resource");
    return const_cast<World*>(this)->try_resource_unchecked<bare<T>>() != nullptr;
  }

  template <class T>
  void remove_resource() {
    check_access<T>(AccessMode::write, "remove_resource");
    const std::size_t id = type_id<T>();
    if (id < resources_.size()) resources_[id].reset();
  }

  // ---- type tables -------------------------------------------------------------------------

  // Grows the pool and resource tables to hold type ids below n, so that creating a pool or a
  // resource of such a type never reallocates a table. The schedule calls it with the ids its
  // systems declare before running them concurrently: systems on other threads read the tables.
  void reserve_type_slots(std::size_t n) {
    if (pools_.size() < n) pools_.resize(n);
    if (resources_.size() < n) resources_.resize(n);
  }

 private:
  struct Slot {
    uint32_t generation;
    bool alive;
  };

  struct Group {
    std::vector<PoolBase*> pools;
    std::size_t size = 0;
    std::string name;
  };

  struct ResourceBoxBase {
    virtual ~ResourceBoxBase() = default;
  };
  template <class T>
  struct ResourceBox final : ResourceBoxBase {
    template <class... A>
    explicit ResourceBox(A&&... args) : value(std::forward<A>(args)...) {}
    T value;
  };

  // Marks pools as being iterated for the lifetime of an each<> call, exceptions included.
  template <std::size_t N>
  struct IterationLock {
    explicit IterationLock(const std::array<PoolBase*, N>& ps) : pools(ps) {
      for (PoolBase* p : pools) p->locks_.fetch_add(1, std::memory_order_relaxed);
    }
    ~IterationLock() {
      for (PoolBase* p : pools) p->locks_.fetch_sub(1, std::memory_order_relaxed);
    }
    IterationLock(const IterationLock&) = delete;
    IterationLock& operator=(const IterationLock&) = delete;
    const std::array<PoolBase*, N>& pools;
  };

  template <class T>
  T& get_unchecked(Entity e, const char* op) {
    require_alive<T>(e, op);
    ComponentPool<T>* p = pool_ptr<T>();
    if (!p || !p->contains(e.index)) throw_absent<T>(op, e);
    return p->get(e.index);
  }

  template <class T>
  T* try_get_unchecked(Entity e) {
    require_alive<T>(e, "try_get");
    ComponentPool<T>* p = pool_ptr<T>();
    return p ? p->try_get(e.index) : nullptr;
  }

  template <class T>
  T* try_resource_unchecked() {
    const std::size_t id = type_id<T>();
    if (id >= resources_.size() || !resources_[id]) return nullptr;
    return &static_cast<ResourceBox<T>*>(resources_[id].get())->value;
  }

  template <class T>
  [[noreturn, gnu::cold, gnu::noinline]] static void throw_no_resource() {
    throw std::logic_error("World::resource<" + type_name<T>() +
                           ">: no such resource (call set_resource<" + type_name<T>() +
                           ">() first)");
  }

  template <class T>
  ComponentPool<T>* pool_ptr() const {
    const std::size_t id = type_id<T>();
    return id < pools_.size() ? static_cast<ComponentPool<T>*>(pools_[id].get()) : nullptr;
  }

  template <class T>
  ComponentPool<T>& assure() {
    const std::size_t id = type_id<T>();
    if (id >= pools_.size()) pools_.resize(id + 1);
    if (!pools_[id]) pools_[id] = std::make_unique<ComponentPool<T>>();
    return *static_cast<ComponentPool<T>*>(pools_[id].get());
  }

  // The group owning exactly these (distinct) pools, if any.
  template <class P, std::size_t N>
  const Group* exact_group(const std::array<P*, N>& ps) const {
    const std::size_t gi = ps[0]->group_;
    if (gi == SIZE_MAX || groups_[gi]->pools.size() != N) return nullptr;
    for (const PoolBase* p : ps)
      if (p->group_ != gi) return nullptr;
    return groups_[gi].get();
  }

  // Moves entity `index` to the end of the packed prefix if it now has every owned type.
  static void try_join(Group& g, uint32_t index) {
    for (const PoolBase* p : g.pools)
      if (!p->contains(index)) return;
    if (g.pools[0]->slot(index) < g.size) return;  // already a member
    for (PoolBase* p : g.pools) p->swap_slots(p->slot(index), g.size);
    ++g.size;
  }

  // Removes one component, first moving the entity out of the packed prefix if it is in it.
  void erase_from(PoolBase& p, uint32_t index) {
    if (p.group_ != SIZE_MAX) {
      Group& g = *groups_[p.group_];
      if (p.slot(index) < g.size) {
        --g.size;
        for (PoolBase* q : g.pools) q->swap_slots(q->slot(index), g.size);
      }
    }
    p.erase(index);
  }

  // T names the component in the message (void: none). This sits on every component access,
  // so the message is built in a separate cold function.
  template <class T>
  void require_alive(Entity e, const char* op) const {
    if (!alive(e)) [[unlikely]]
      throw_dead<T>(e, op);
  }

  template <class T>
  [[noreturn, gnu::cold, gnu::noinline]] static void throw_dead(Entity e, const char* op) {
    std::string where = "World::" + std::string(op);
    if constexpr (!std::is_void_v<T>) where += "<" + type_name<T>() + ">";
    throw std::logic_error(where + ": entity " + to_string(e) + " is not alive");
  }

  void require_unlocked(const PoolBase& p, const char* op) const {
    bool locked = p.locks_.load(std::memory_order_relaxed) != 0;
    if (p.group_ != SIZE_MAX)
      for (const PoolBase* q : groups_[p.group_]->pools)
        locked = locked || q->locks_.load(std::memory_order_relaxed) != 0;
    if (locked)
      throw std::logic_error("World::" + std::string(op) + ": " + p.component_name() +
                             " (or a pool grouped with it) is being iterated by each<>; apply "
                             "the change after the loop");
  }

  template <class T>
  [[noreturn, gnu::cold, gnu::noinline]] static void throw_absent(const char* op, Entity e) {
    throw std::logic_error("World::" + std::string(op) + "<" + type_name<T>() + ">: entity " +
                           to_string(e) + " has no " + type_name<T>());
  }

  template <class... Ts>
  [[noreturn]] static void throw_no_group() {
    throw std::logic_error("World::group_size<" + detail::type_list<Ts...>() + ">: no such group");
  }

  std::vector<Slot> slots_;
  std::vector<uint32_t> free_;  // recycled indices, reused last-in first-out
  std::size_t alive_count_ = 0;
  std::vector<std::unique_ptr<PoolBase>> pools_;  // by type_id
  std::vector<std::unique_ptr<Group>> groups_;
  std::vector<std::unique_ptr<ResourceBoxBase>> resources_;  // by type_id
};

}  // namespace pyro::ecs
