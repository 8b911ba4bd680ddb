// SPDX-License-Identifier: MIT
// iecoop/testing/forcing.hpp — forcing and writing values, as CODESYS's online "Force values"
// and "Write values": a forced variable takes its forced value at the start of every cycle
// (after the inputs are latched) and again at its end (before the outputs go to the field),
// so that the program may change it within a cycle but nothing it writes survives a cycle,
// until the test releases it; a written value is written once, at the start of the next cycle.
//
//     plc.force(io.ixStart, TRUE);         // a located input (%IX0.0)
//     plc.force(io.qwSpeedRef, INT(0));    // a located output: the field sees 0
//     plc.force(gvl.bJam, TRUE);           // a global variable
//     plc.force(prg.fbConveyor.wParts, WORD(3));   // a block's variable, even a VAR_OUTPUT
//     CHECK(plc.forced(io.ixStart));
//     plc.release(io.ixStart);             // the variable keeps its value until written
//     plc.write(gvl.wBatchSize, WORD(4));  // once
//
// Variables are BOOL, integers, bit strings, REAL, LREAL, TIME and dates, enumerations,
// STRINGs and STRUCTs up to 256 bytes, and iecoop's wrappers of them (var<>, VAR_OUTPUT,
// RETAIN, PERSISTENT, located variables). A test forces at most force_table::capacity at once.
// IWYU pragma: private, include <iecoop/testing.hpp>
#pragma once

#include <array>
#include <cstddef>
#include <cstring>
#include <new>
#include <optional>
#include <type_traits>

#include <doctest/doctest.h>

#include <iecoop/io/located.hpp>
#include <iecoop/pou/variables.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop::testing {

namespace detail {

/// The value type a test forces on a variable: a wrapper's value, or the variable's own type.
template <class V>
struct forced_value {
  using type = V;
};
template <class V>
  requires requires(const V& v) { v.get(); }
struct forced_value<V> {
  using type = std::remove_cvref_t<decltype(std::declval<const V&>().get())>;
};
template <class V>
using forced_value_t = typename forced_value<std::remove_cvref_t<V>>::type;

/// `target = value`, also for a VAR_OUTPUT (read_only<>), which only its block may write.
template <class V, class T>
void write_variable(V& target, const T& value) {
  if constexpr (iecoop::detail::is_read_only<V>::value) {
    iecoop::detail::read_only_access::ref(target) = value;
  } else {
    target = value;
  }
}

/// A located variable: its bytes in the process image, inputs (%I) too, as a driver writes them.
template <class T, iecoop::detail::fixed_string A, class Image, class U>
void write_variable(located<T, A, Image>& /*target*/, const U& value) {
  Image::template write<T, A>(T(value));
}

/// The value of a variable: a wrapper's get(), or the variable itself.
template <class V>
forced_value_t<V> read_variable(const V& variable) {
  if constexpr (requires { variable.get(); }) {
    return variable.get();
  } else {
    return variable;
  }
}

/// A distinct address per type: with the variable's address, what identifies a forced
/// variable (located variables are empty, and several may share an address).
template <class V>
inline constexpr char type_tag = 0;

}  // namespace detail

/// The located variable of type T at address A (`at<BOOL, "%IX0.0">()`), for forcing an
/// address that no variable is declared at.
template <class T, iecoop::detail::fixed_string A, class Image = default_process_image>
[[nodiscard]] located<T, A, Image>& at() noexcept {
  static located<T, A, Image> variable;
  return variable;
}

/// The forced and written values of a test's driver (plc, cycles).
class force_table {
 public:
  static constexpr std::size_t capacity = 32;
  static constexpr std::size_t max_value_bytes = 256;

  /// Forces `variable` to `value` until release(); forcing it again replaces the value.
  template <class V, class T>
  void force(V& variable, const T& value) {
    set(variable, value, false);
  }

  /// Writes `value` to `variable` once, at the start of the next cycle (a force of it wins).
  template <class V, class T>
  void write(V& variable, const T& value) {
    set(variable, value, true);
  }

  /// Releases `variable`: it keeps its value until the program or the field writes it.
  template <class V>
  void release(const V& variable) noexcept {
    if (entry* e = find(&variable, &detail::type_tag<std::remove_cvref_t<V>>)) remove(*e);
  }

  /// Releases `variable` and gives it back the value it had when it was first forced
  /// (CODESYS: "Unforce and restore values").
  template <class V>
  void release_and_restore(V& variable) {
    if (entry* e = find(&variable, &detail::type_tag<std::remove_cvref_t<V>>)) {
      e->apply(e->target, e->original);
      remove(*e);
    }
  }

  /// Releases every forced variable and drops pending writes.
  void release_all() noexcept { count_ = 0; }

  /// TRUE while `variable` is forced.
  template <class V>
  [[nodiscard]] bool forced(const V& variable) const noexcept {
    return find(&variable, &detail::type_tag<std::remove_cvref_t<V>>) != nullptr;
  }

  /// The value `variable` is forced to, or nullopt if it is not forced.
  template <class V>
  [[nodiscard]] std::optional<detail::forced_value_t<V>> forced_value(const V& variable) const noexcept {
    using U = detail::forced_value_t<V>;
    const entry* e = find(&variable, &detail::type_tag<std::remove_cvref_t<V>>);
    if (e == nullptr) return std::nullopt;
    U value;
    std::memcpy(static_cast<void*>(&value), e->value, sizeof(U));
    return value;
  }

  /// The number of variables forced now.
  [[nodiscard]] std::size_t forced_count() const noexcept {
    std::size_t n = 0;
    for (std::size_t i = 0; i < count_; ++i) n += entries_[i].once ? 0U : 1U;
    return n;
  }

  /// At a cycle's start: the forced values and the pending writes (which are then done).
  void apply_at_start() {
    for (std::size_t i = 0; i < count_; ++i) entries_[i].apply(entries_[i].target, entries_[i].value);
    std::size_t kept = 0;
    for (std::size_t i = 0; i < count_; ++i) {
      if (!entries_[i].once) entries_[kept++] = entries_[i];
    }
    count_ = kept;
  }

  /// At a cycle's end: the forced values.
  void apply_at_end() {
    for (std::size_t i = 0; i < count_; ++i) {
      if (!entries_[i].once) entries_[i].apply(entries_[i].target, entries_[i].value);
    }
  }

 private:
  struct entry {
    const void* key;
    const char* type;
    void* target;
    void (*apply)(void* target, const std::byte* value);
    bool once;
    alignas(16) std::byte value[max_value_bytes];
    alignas(16) std::byte original[max_value_bytes];  // the value before the first force
  };

  template <class V, class T>
  void set(V& variable, const T& value, bool once) {
    using W = std::remove_cvref_t<V>;
    using U = detail::forced_value_t<W>;
    static_assert(!std::is_const_v<V>, "iecoop: a test forces a variable, not a constant; give the variable itself");
    static_assert(std::is_trivially_copyable_v<U> && sizeof(U) <= max_value_bytes && alignof(U) <= 16,
                  "iecoop: a test forces elementary values, enumerations, STRINGs and STRUCTs of up to 256 bytes; "
                  "force a larger variable member by member");
    static_assert(!std::is_arithmetic_v<T> || std::is_same_v<T, bool> || std::is_arithmetic_v<U>,
                  "iecoop: a forced value is a value of the variable's IEC type, not a C++ number; write it as "
                  "one, e.g. force(iCount, INT(11)) or force(wMask, WORD(16#FF))");
    static_assert(std::is_convertible_v<const T&, U>,
                  "iecoop: the forced value is not of the variable's type; give a value of that type, e.g. "
                  "force(wCount, WORD(3))");
    const char* const type = &detail::type_tag<W>;
    entry* e = find(&variable, type, once);
    if (e == nullptr) {
      if (count_ == capacity) {
        DOCTEST_ADD_FAIL_CHECK_AT(__FILE__, __LINE__,
                                  "iecoop: more than 32 forced or written variables at once; release some");
        return;
      }
      e = &entries_[count_++];
      const U before = detail::read_variable(variable);
      std::memcpy(e->original, static_cast<const void*>(&before), sizeof(U));
    }
    e->key = &variable;
    e->type = type;
    e->target = &variable;
    e->once = once;
    e->apply = [](void* target, const std::byte* bytes) {
      U v;
      std::memcpy(static_cast<void*>(&v), bytes, sizeof(U));
      detail::write_variable(*static_cast<W*>(target), v);
    };
    const U converted = value;
    std::memcpy(e->value, static_cast<const void*>(&converted), sizeof(U));
  }

  // The force (once: the pending write) of the variable at `key` of type `type`.
  [[nodiscard]] entry* find(const void* key, const char* type, bool once = false) noexcept {
    for (std::size_t i = 0; i < count_; ++i) {
      if (entries_[i].key == key && entries_[i].type == type && entries_[i].once == once) return &entries_[i];
    }
    return nullptr;
  }
  [[nodiscard]] const entry* find(const void* key, const char* type) const noexcept {
    for (std::size_t i = 0; i < count_; ++i) {
      if (entries_[i].key == key && entries_[i].type == type && !entries_[i].once) return &entries_[i];
    }
    return nullptr;
  }

  void remove(entry& e) noexcept {
    const std::size_t i = static_cast<std::size_t>(&e - entries_.data());
    for (std::size_t j = i + 1; j < count_; ++j) entries_[j - 1] = entries_[j];
    --count_;
  }

  std::array<entry, capacity> entries_{};
  std::size_t count_ = 0;
};

}  // namespace iecoop::testing

#include <iecoop/detail/pop_macros.hpp>
