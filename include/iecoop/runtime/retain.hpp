// SPDX-License-Identifier: MIT
// iecoop/runtime/retain.hpp — RETAIN and PERSISTENT variables, the image in which a runtime saves
// them over a reset or a restart, and the storage seam that image goes through.
//
//     // VAR RETAIN  iCount : INT := 5;  END_VAR
//     // VAR PERSISTENT  rOffset : REAL;  END_VAR
//     struct PRG_Main : program<PRG_Main> {
//       retain<INT> iCount{5};
//       persistent<REAL> rOffset;
//       void body() { iCount = iCount + 1; }
//     };
//
// A retain<T> or persistent<T> is a plain variable (its value inline, read and written like
// T) that also registers itself in a list, so that the scheduler can find the variables that
// lie inside a program instance or a global variable list, copy their values into a byte
// image before it rebuilds the instance (a reset), copy them back afterwards, and write the
// image to storage for a restart:
//
//   event            RETAIN    PERSISTENT      kinds kept: kept_over(event)
//   reset warm       kept      kept            retain_kinds::both
//   reset cold       reinit    kept            retain_kinds::persistent
//   reset origin     reinit    reinit          retain_kinds::none
//   new download     reinit    kept            retain_kinds::persistent
//   restart          kept      kept            retain_kinds::both
//
// See docs/retain.md.
#pragma once

#include <array>
#include <bit>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <span>
#include <type_traits>

#include <iecoop/config.hpp>
#include <iecoop/detail/scalar_access.hpp>
#include <iecoop/detail/type_hash.hpp>
#include <iecoop/detail/value_operators.hpp>
#include <iecoop/fault.hpp>
#include <iecoop/pou/variables.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

// ---------------------------------------------------------------------------------------
// Kinds and events

/// The two kinds of remanent variables (ST: VAR RETAIN, VAR PERSISTENT).
enum class retain_kind : std::uint8_t {
  retain = 1,      ///< kept over a warm reset and a restart
  persistent = 2,  ///< kept over warm and cold resets, a new download and a restart
};

/**
 * A set of retain_kind: which kinds an operation saves or restores. A retain_kind converts
 * to it, and `|` combines them: `retain_kind::retain | retain_kind::persistent` is
 * `retain_kinds::both`. The default value is `retain_kinds::none`.
 */
class retain_kinds {
 public:
  constexpr retain_kinds() noexcept = default;
  // implicit: a kind is a set of one
  constexpr retain_kinds(retain_kind kind) noexcept : bits_(static_cast<std::uint8_t>(kind)) {}

  static const retain_kinds none;        ///< nothing
  static const retain_kinds retain;      ///< RETAIN only
  static const retain_kinds persistent;  ///< PERSISTENT only
  static const retain_kinds both;        ///< RETAIN and PERSISTENT

  [[nodiscard]] constexpr bool contains(retain_kind kind) const noexcept {
    return (bits_ & static_cast<std::uint8_t>(kind)) != 0;
  }
  [[nodiscard]] constexpr bool empty() const noexcept { return bits_ == 0; }
  /// 1 for RETAIN, 2 for PERSISTENT, or'ed.
  [[nodiscard]] constexpr std::uint8_t bits() const noexcept { return bits_; }

  friend constexpr retain_kinds operator|(retain_kinds a, retain_kinds b) noexcept {
    return from_bits(static_cast<std::uint8_t>(a.bits_ | b.bits_));
  }
  friend constexpr retain_kinds operator&(retain_kinds a, retain_kinds b) noexcept {
    return from_bits(static_cast<std::uint8_t>(a.bits_ & b.bits_));
  }
  constexpr retain_kinds& operator|=(retain_kinds other) noexcept { return *this = *this | other; }
  friend constexpr bool operator==(retain_kinds a, retain_kinds b) noexcept = default;

 private:
  static constexpr retain_kinds from_bits(std::uint8_t bits) noexcept {
    retain_kinds kinds;
    kinds.bits_ = static_cast<std::uint8_t>(bits & 3U);
    return kinds;
  }
  std::uint8_t bits_ = 0;
};

inline constexpr retain_kinds retain_kinds::none{};
inline constexpr retain_kinds retain_kinds::retain{retain_kind::retain};
inline constexpr retain_kinds retain_kinds::persistent{retain_kind::persistent};
inline constexpr retain_kinds retain_kinds::both =
    retain_kinds{retain_kind::retain} | retain_kinds{retain_kind::persistent};

constexpr retain_kinds operator|(retain_kind a, retain_kind b) noexcept { return retain_kinds(a) | retain_kinds(b); }

/// The events of a controller's life that re-initialise variables.
enum class retain_event : std::uint8_t {
  warm_reset,    ///< CODESYS Online → Reset warm
  cold_reset,    ///< Online → Reset cold
  origin_reset,  ///< Online → Reset origin
  download,      ///< a new download of the application (a changed program)
  restart,       ///< the controller (the process) stops, or aborts, and starts again
};

/// The kinds of remanent variables that keep their values over `event` (the table of
/// CODESYS's documentation; see docs/retain.md).
[[nodiscard]] constexpr retain_kinds kept_over(retain_event event) noexcept {
  switch (event) {
    case retain_event::warm_reset: return retain_kinds::both;
    case retain_event::cold_reset: return retain_kinds::persistent;
    case retain_event::origin_reset: return retain_kinds::none;
    case retain_event::download: return retain_kinds::persistent;
    case retain_event::restart: return retain_kinds::both;
  }
  return retain_kinds::none;
}

// ---------------------------------------------------------------------------------------
// The list of remanent variables

namespace detail {

/// What a remanent variable of type T and kind K is, shared by all such variables.
struct retained_type {
  std::size_t size;
  std::uint32_t type_hash;
  retain_kind kind;
};
template <class T, retain_kind Kind>
inline constexpr retained_type retained_type_of{sizeof(T), type_hash<T>, Kind};

/// A remanent variable's entry in the list: where its value is, and what it is. The links
/// live in the variable; nothing is allocated.
struct retained_node {
  void* value = nullptr;
  const retained_type* type = nullptr;
  retained_node* previous = nullptr;
  retained_node* next = nullptr;
};

/// The list, in order of construction. Constant-initialised, so that variables of global
/// instances may register during dynamic initialisation. Not thread-safe: remanent
/// variables are created and destroyed while no task runs (with their programs and global
/// variable lists).
inline retained_node* retained_first = nullptr;
inline retained_node* retained_last = nullptr;

inline void link_retained(retained_node& node) noexcept {
  node.previous = retained_last;
  node.next = nullptr;
  if (retained_last != nullptr) {
    retained_last->next = &node;
  } else {
    retained_first = &node;
  }
  retained_last = &node;
}

inline void unlink_retained(retained_node& node) noexcept {
  if (node.previous != nullptr) {
    node.previous->next = node.next;
  } else {
    retained_first = node.next;
  }
  if (node.next != nullptr) {
    node.next->previous = node.previous;
  } else {
    retained_last = node.previous;
  }
  node.previous = nullptr;
  node.next = nullptr;
}

/// The common part of retain<T> and persistent<T> (Derived is one of them).
template <class Derived, class T, retain_kind Kind>
class retained_variable : public assignable_variable<Derived, T> {
  static_assert(std::is_trivially_copyable_v<T>,
                "iecoop: a RETAIN or PERSISTENT variable must be trivially copyable, as it is saved and restored "
                "as bytes; use IEC elementary types, STRING<n>, std::array and STRUCTs of them");
  static_assert(!std::is_array_v<T>,
                "iecoop: a RETAIN or PERSISTENT array is written retain<std::array<T, N>>, not retain<T[N]>");
  static_assert(
      !std::is_const_v<T> && !std::is_volatile_v<T>,
      "iecoop: a RETAIN or PERSISTENT variable is written when its value is restored; drop const or volatile");
  using base = assignable_variable<Derived, T>;

 public:
  retained_variable() noexcept(std::is_nothrow_default_constructible_v<T>) { link(); }
  /// The declaration's initial value: `retain<INT> iCount{5};` (ST: `iCount : INT := 5;`).
  explicit retained_variable(const T& initial) noexcept : base(initial) { link(); }
  /// A copy is a variable of its own, in the list too.
  retained_variable(const retained_variable& other) noexcept : base(other.get()) { link(); }
  /// Copies the value only (ST's `a := b`).
  retained_variable& operator=(const retained_variable& other) noexcept {
    this->assign(other.get());
    return *this;
  }
  ~retained_variable() { unlink_retained(node_); }

  /// Assigning a value (`iCount = 5;`, with ST's conversions), reading, `->`, `[]` and
  /// `ref()` (write access to members: `stRecipe.ref().rSpeed = 1.5;`) are those of every
  /// variable (detail::assignable_variable); compound assignments (`iCount += 1;`) those of
  /// every variable wrapper (detail/value_operators.hpp).
  using base::operator=;

 private:
  void link() noexcept {
    node_.value = &this->storage();
    node_.type = &retained_type_of<T, Kind>;
    link_retained(node_);
  }
  retained_node node_;
};

}  // namespace detail

/**
 * A RETAIN variable (ST: `VAR RETAIN x : INT := 5; END_VAR` → `retain<INT> x{5};`): read and
 * written like a T; kept over a warm reset and a restart, re-initialised by a cold reset, a
 * reset origin and a new download (when the scheduler saves and restores it: see
 * docs/retain.md). T must be trivially copyable: the IEC elementary types, STRING<n>,
 * std::array and STRUCTs of them.
 */
template <class T>
class retain : public detail::retained_variable<retain<T>, T, retain_kind::retain> {
  using base = detail::retained_variable<retain<T>, T, retain_kind::retain>;

 public:
  using base::base;
  using base::operator=;
};

/**
 * A PERSISTENT variable (ST: `VAR PERSISTENT x : REAL; END_VAR` → `persistent<REAL> x;`):
 * as retain<T>, but kept over cold resets and new downloads too; only a reset origin
 * re-initialises it.
 */
template <class T>
class persistent : public detail::retained_variable<persistent<T>, T, retain_kind::persistent> {
  using base = detail::retained_variable<persistent<T>, T, retain_kind::persistent>;

 public:
  using base::base;
  using base::operator=;
};

// ---------------------------------------------------------------------------------------
// The image

namespace detail {

/// An instance whose remanent variables are saved and restored: a program instance, a
/// global variable list (a struct of variables), or a single global variable. A remanent
/// variable belongs to it if its value lies within [base, base + size).
struct retained_object {
  const void* base;
  std::size_t size;
};

// The image (every number little-endian):
//   header, 16 bytes:  "IECR", version u16 (1), section count u16, total size u32,
//                      FNV-1a u32 of the bytes after the header
//   per section:       kind u8 (1 RETAIN, 2 PERSISTENT), 3 zero bytes, layout hash u32,
//                      variable count u32, data size u32; then the values, unpadded
inline constexpr std::size_t retain_image_header_size = 16;
inline constexpr std::size_t retain_section_header_size = 16;
inline constexpr std::uint16_t retain_image_version = 1;
inline constexpr std::array<unsigned char, 4> retain_image_magic{'I', 'E', 'C', 'R'};

inline std::uintptr_t retained_address(const void* pointer) noexcept {
  return reinterpret_cast<std::uintptr_t>(pointer);
}

/// Calls f(node, offset) for each remanent variable of `kind` that lies in `object`, in
/// increasing order of its offset in the object. O(variables) when the variables were
/// constructed in address order (as C++ constructs members, bases and nested blocks);
/// otherwise O(variables²), without allocating.
template <class F>
void for_each_retained_in(const retained_object& object, retain_kind kind, F&& f) {
  const std::uintptr_t begin = retained_address(object.base);
  auto offset_of = [&](const retained_node& node, std::size_t& offset) {
    if (node.type->kind != kind) return false;
    const std::uintptr_t at = retained_address(node.value);
    if (at < begin) return false;
    offset = static_cast<std::size_t>(at - begin);
    return offset < object.size && object.size - offset >= node.type->size;
  };
  bool sorted = true;
  bool any = false;
  std::size_t last = 0;
  std::size_t offset = 0;
  for (const retained_node* node = retained_first; node != nullptr && sorted; node = node->next) {
    if (!offset_of(*node, offset)) continue;
    if (any && offset <= last) sorted = false;
    last = offset;
    any = true;
  }
  if (sorted) {
    for (retained_node* node = retained_first; node != nullptr; node = node->next) {
      if (offset_of(*node, offset)) f(*node, offset);
    }
    return;
  }
  // Selection: each round visits the variable with the smallest offset above the last one.
  bool started = false;
  std::size_t previous = 0;
  for (;;) {
    retained_node* best = nullptr;
    std::size_t best_offset = 0;
    for (retained_node* node = retained_first; node != nullptr; node = node->next) {
      if (!offset_of(*node, offset) || (started && offset <= previous)) continue;
      if (best == nullptr || offset < best_offset) {
        best = node;
        best_offset = offset;
      }
    }
    if (best == nullptr) return;
    f(*best, best_offset);
    previous = best_offset;
    started = true;
  }
}

/// The layout of the variables of one kind: what a section's header records.
struct retained_layout {
  std::uint32_t hash = 0;
  std::size_t count = 0;
  std::size_t data_size = 0;
};

/// The current layout of the variables of `kind` in `objects`: the hash runs over the byte
/// order of the machine (values are saved as they are in memory) and, for each variable in
/// object order and then offset order, the object's index, the offset, the size and the
/// type's hash.
inline retained_layout retained_layout_of(std::span<const retained_object> objects, retain_kind kind) {
  fnv1a hash;
  hash.add_byte(std::endian::native == std::endian::little ? 1 : 2);
  retained_layout layout;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    for_each_retained_in(objects[i], kind, [&](const retained_node& node, std::size_t offset) {
      hash.add_number(i).add_number(offset).add_number(node.type->size).add_number(node.type->type_hash);
      ++layout.count;
      layout.data_size += node.type->size;
    });
  }
  layout.hash = hash.value();
  return layout;
}

/// The number of remanent variables of `kinds` that lie in `objects`.
inline std::size_t retained_count(std::span<const retained_object> objects, retain_kinds kinds) {
  std::size_t count = 0;
  for (const retain_kind kind : {retain_kind::retain, retain_kind::persistent}) {
    if (kinds.contains(kind)) count += retained_layout_of(objects, kind).count;
  }
  return count;
}

inline void retained_put(std::byte* at, std::uint64_t value, int bytes) noexcept {
  for (int i = 0; i < bytes; ++i) {
    at[i] = static_cast<std::byte>(value & 0xFFU);
    value >>= 8U;
  }
}
inline std::uint32_t retained_get(const std::byte* at, int bytes) noexcept {
  std::uint32_t value = 0;
  for (int i = bytes - 1; i >= 0; --i) value = (value << 8U) | std::to_integer<std::uint32_t>(at[i]);
  return value;
}
inline std::uint32_t retained_checksum(std::span<const std::byte> bytes) noexcept {
  fnv1a hash;
  for (const std::byte b : bytes) hash.add_byte(std::to_integer<std::uint8_t>(b));
  return hash.value();
}

/// The number of bytes save_retained writes for `kinds` of the variables in `objects`.
inline std::size_t retained_image_size(std::span<const retained_object> objects, retain_kinds kinds) {
  std::size_t size = retain_image_header_size;
  for (const retain_kind kind : {retain_kind::retain, retain_kind::persistent}) {
    if (kinds.contains(kind)) size += retain_section_header_size + retained_layout_of(objects, kind).data_size;
  }
  return size;
}

/**
 * Writes the values of the remanent variables of `kinds` that lie in `objects` to `out`, as a
 * self-describing image (a header, then one section per kind in `kinds`, RETAIN first).
 * Returns the bytes written; if `out` is smaller than retained_image_size(objects, kinds),
 * reports fault_kind::invalid_value, writes nothing and returns 0.
 */
inline std::size_t save_retained(std::span<const retained_object> objects, retain_kinds kinds,
                                 std::span<std::byte> out) {
  const std::size_t needed = retained_image_size(objects, kinds);
  if (out.size() < needed) {
    fault(fault_kind::invalid_value,
          "the RETAIN/PERSISTENT image does not fit the buffer; size it with retained_image_size");
    return 0;
  }
  if constexpr (sizeof(std::size_t) > 4) {  // a 32-bit target cannot hold more (and GCC warns the test is always false)
    if (needed > 0xFFFFFFFFU) {
      fault(fault_kind::invalid_value, "the RETAIN/PERSISTENT image exceeds 4 GiB");
      return 0;
    }
  }
  std::size_t position = retain_image_header_size;
  std::uint64_t sections = 0;
  for (const retain_kind kind : {retain_kind::retain, retain_kind::persistent}) {
    if (!kinds.contains(kind)) continue;
    const retained_layout layout = retained_layout_of(objects, kind);
    std::byte* header = out.data() + position;
    retained_put(header, static_cast<std::uint8_t>(kind), 1);
    retained_put(header + 1, 0, 3);
    retained_put(header + 4, layout.hash, 4);
    retained_put(header + 8, layout.count, 4);
    retained_put(header + 12, layout.data_size, 4);
    position += retain_section_header_size;
    for (const retained_object& object : objects) {
      for_each_retained_in(object, kind, [&](const retained_node& node, std::size_t) {
        std::memcpy(out.data() + position, node.value, node.type->size);
        position += node.type->size;
      });
    }
    ++sections;
  }
  std::byte* header = out.data();
  for (std::size_t i = 0; i < retain_image_magic.size(); ++i) header[i] = static_cast<std::byte>(retain_image_magic[i]);
  retained_put(header + 4, retain_image_version, 2);
  retained_put(header + 6, sections, 2);
  retained_put(header + 8, position, 4);
  const std::span<const std::byte> body = out.subspan(retain_image_header_size, position - retain_image_header_size);
  retained_put(header + 12, retained_checksum(body), 4);
  return position;
}

/// TRUE if `in` begins with a complete image of a version this iecoop reads, whose
/// checksum and section structure are intact.
inline bool valid_retained_image(std::span<const std::byte> in) noexcept {
  if (in.size() < retain_image_header_size) return false;
  for (std::size_t i = 0; i < retain_image_magic.size(); ++i) {
    if (std::to_integer<unsigned char>(in[i]) != retain_image_magic[i]) return false;
  }
  if (retained_get(in.data() + 4, 2) != retain_image_version) return false;
  const std::size_t total = retained_get(in.data() + 8, 4);
  if (total < retain_image_header_size || total > in.size()) return false;
  const std::span<const std::byte> body = in.subspan(retain_image_header_size, total - retain_image_header_size);
  if (retained_get(in.data() + 12, 4) != retained_checksum(body)) return false;
  const std::size_t sections = retained_get(in.data() + 6, 2);
  std::size_t position = retain_image_header_size;
  for (std::size_t s = 0; s < sections; ++s) {
    if (total - position < retain_section_header_size) return false;
    const std::uint32_t kind = retained_get(in.data() + position, 1);
    if (kind != 1 && kind != 2) return false;
    const std::size_t data_size = retained_get(in.data() + position + 12, 4);
    if (total - position - retain_section_header_size < data_size) return false;
    position += retain_section_header_size + data_size;
  }
  return position == total;
}

/**
 * Copies values from an image save_retained wrote back into the remanent variables of
 * `objects`, for each section whose kind is in `kinds` and whose layout is the variables'
 * current layout (same variables, in the same objects, at the same offsets, of the same
 * sizes and types). A section whose layout differs is skipped, and its variables keep the
 * values they have (their initial values, after a rebuild). An image that is not intact
 * (magic, version, size, checksum, structure) restores nothing. Returns the kinds restored.
 */
inline retain_kinds restore_retained(std::span<const retained_object> objects, retain_kinds kinds,
                                     std::span<const std::byte> in) {
  if (!valid_retained_image(in)) return retain_kinds::none;
  const std::size_t sections = retained_get(in.data() + 6, 2);
  retain_kinds restored;
  std::size_t position = retain_image_header_size;
  for (std::size_t s = 0; s < sections; ++s) {
    const std::byte* header = in.data() + position;
    const auto kind = static_cast<retain_kind>(retained_get(header, 1));
    const std::uint32_t hash = retained_get(header + 4, 4);
    const std::size_t count = retained_get(header + 8, 4);
    const std::size_t data_size = retained_get(header + 12, 4);
    position += retain_section_header_size;
    if (kinds.contains(kind) && !restored.contains(kind)) {
      const retained_layout layout = retained_layout_of(objects, kind);
      if (layout.hash == hash && layout.count == count && layout.data_size == data_size) {
        std::size_t at = position;
        for (const retained_object& object : objects) {
          for_each_retained_in(object, kind, [&](retained_node& node, std::size_t) {
            std::memcpy(node.value, in.data() + at, node.type->size);
            at += node.type->size;
          });
        }
        restored |= kind;
      }
    }
    position += data_size;
  }
  return restored;
}

}  // namespace detail

// ---------------------------------------------------------------------------------------
// The storage seam

/**
 * Where a runtime keeps the image between two runs of the program (a controller restart):
 * `save(data)` stores the bytes, replacing what was stored, and returns whether it
 * succeeded; `load(buffer)` copies the stored bytes into `buffer` and returns how many, or 0
 * when nothing is stored or the buffer is too small. memory_storage and file_storage
 * (<iecoop/runtime/file_storage.hpp>) are two; a firmware writes its own for flash or FRAM.
 */
template <class S>
concept RetainStorage = requires(S& s, std::span<const std::byte> data, std::span<std::byte> buffer) {
  { s.save(data) } -> std::same_as<bool>;
  { s.load(buffer) } -> std::convertible_to<std::size_t>;
};

/**
 * A RetainStorage in RAM, of at most Capacity bytes: for tests, and for firmware that copies
 * it to non-volatile memory itself (or that places it in battery-backed RAM).
 */
template <std::size_t Capacity>
class memory_storage {
 public:
  /// Stores `data`; FALSE (and nothing changed) if it is larger than Capacity.
  bool save(std::span<const std::byte> data) noexcept {
    if (data.size() > Capacity) return false;
    if (!data.empty()) std::memcpy(bytes_.data(), data.data(), data.size());
    size_ = data.size();
    return true;
  }
  /// Copies the stored bytes into `buffer`: their number, or 0 if nothing is stored or
  /// `buffer` is too small.
  std::size_t load(std::span<std::byte> buffer) const noexcept {
    if (size_ == 0 || buffer.size() < size_) return 0;
    std::memcpy(buffer.data(), bytes_.data(), size_);
    return size_;
  }
  /// The stored bytes.
  [[nodiscard]] std::span<const std::byte> data() const noexcept { return {bytes_.data(), size_}; }
  [[nodiscard]] std::size_t size() const noexcept { return size_; }
  /// Forgets what is stored.
  void clear() noexcept { size_ = 0; }
  static constexpr std::size_t capacity() noexcept { return Capacity; }

 private:
  std::array<std::byte, Capacity> bytes_{};
  std::size_t size_ = 0;
};

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
