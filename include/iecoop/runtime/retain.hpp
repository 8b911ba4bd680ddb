// SPDX-License-Identifier: MIT
// iecoop/runtime/retain.hpp — RETAIN and PERSISTENT variables, and which of them survive which
// event. The image a runtime saves them in is <iecoop/runtime/retain_image.hpp>, the storage
// that image goes through <iecoop/runtime/retain_storage.hpp>.
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
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <type_traits>

#include <iecoop/config.hpp>
#include <iecoop/detail/scalar_access.hpp>
#include <iecoop/fault.hpp>
#include <iecoop/pou/variables.hpp>
#include <iecoop/runtime/detail/value_validity.hpp>
#include <iecoop/types/detail/type_hash.hpp>
#include <iecoop/types/detail/value_operators.hpp>

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
// What a start found

/**
 * What became of the RETAIN or the PERSISTENT variables when the application started (the
 * states of TwinCAT's bootDataFlags, and the reasons CODESYS reports a retain mismatch).
 * Whatever was not restored starts with its initial values.
 */
enum class retain_load : std::uint8_t {
  initial,            ///< nothing to restore: a first start, no storage, nothing stored, or a reset origin
  restored,           ///< the values saved last were restored
  restored_previous,  ///< the last image was unusable; the one saved before it was restored
  not_kept,           ///< the event does not keep this kind (RETAIN over a new download or a cold reset)
  damaged,            ///< the stored image is damaged: magic, version, size, checksum or structure
  changed,            ///< the variables changed since the image was saved (added, removed, moved, retyped)
  invalid_value,      ///< a saved value is no value of its variable's type (a BOOL of 2, a STRING without end)
  too_large,          ///< the stored image is larger than the retain memory (retain_capacity<N>)
};

/// The name of a retain_load, as written above ("restored_previous").
[[nodiscard]] constexpr std::string_view to_string(retain_load load) noexcept {
  switch (load) {
    case retain_load::initial: return "initial";
    case retain_load::restored: return "restored";
    case retain_load::restored_previous: return "restored_previous";
    case retain_load::not_kept: return "not_kept";
    case retain_load::damaged: return "damaged";
    case retain_load::changed: return "changed";
    case retain_load::invalid_value: return "invalid_value";
    case retain_load::too_large: return "too_large";
  }
  return "?";
}

/**
 * What the last start() or reset() of an application did with its retained data: readable by
 * the application (application::retain_status()) and by its programs (retain_info(), as
 * TwinCAT's `_AppInfo`), from FB_Init on.
 */
struct retain_status {
  retain_load retain = retain_load::initial;      ///< the RETAIN variables
  retain_load persistent = retain_load::initial;  ///< the PERSISTENT variables
  /// The stored image was rejected and moved aside by the storage (set_aside()), so that the
  /// next save does not overwrite it.
  bool set_aside = false;
  /// TwinCAT's `_AppInfo.BootDataLoaded`: the PERSISTENT variables were restored.
  BOOL BootDataLoaded = FALSE;
  /// TwinCAT's `_AppInfo.OldBootData`: they were restored from the image saved before the last.
  BOOL OldBootData = FALSE;
  /// The restored values came back only after FB_Init had run, so FB_Init saw the initial
  /// values: the remanent variables were constructed in another order than that of their
  /// addresses (docs/retain.md, "Start-up order"). FALSE when the values were in place
  /// before FB_Init, as in CODESYS, and when nothing was restored.
  bool restored_after_init = false;

  /// The status of `kind`.
  [[nodiscard]] constexpr retain_load of(retain_kind kind) const noexcept {
    return kind == retain_kind::retain ? retain : persistent;
  }
  /// TRUE if a stored image was found but not (or not wholly) used.
  [[nodiscard]] constexpr bool rejected() const noexcept {
    auto bad = [](retain_load load) {
      return load == retain_load::damaged || load == retain_load::changed || load == retain_load::invalid_value ||
             load == retain_load::too_large;
    };
    return bad(retain) || bad(persistent);
  }
  friend constexpr bool operator==(const retain_status&, const retain_status&) noexcept = default;
};

namespace detail {
inline retain_status last_retain_status{};
}  // namespace detail

/// What the last start() or reset() of an application in this process did with its retained
/// data (see retain_status): for a program, as TwinCAT's `_AppInfo.BootDataLoaded`.
[[nodiscard]] inline const retain_status& retain_info() noexcept { return detail::last_retain_status; }

// ---------------------------------------------------------------------------------------
// The list of remanent variables

namespace detail {

/// What a remanent variable of type T and kind K is, shared by all such variables: its size,
/// its type's hash, and the check that bytes are a value of it (detail/value_validity.hpp).
struct retained_type {
  std::size_t size;
  std::uint32_t type_hash;
  retain_kind kind;
  bool (*valid)(const std::byte*) noexcept;
};
template <class T, retain_kind Kind>
inline constexpr retained_type retained_type_of{sizeof(T), type_hash<T>, Kind, &valid_value_bytes<T>};

/// A remanent variable's entry in the list: where its value is, and what it is. The links
/// live in the variable; nothing is allocated.
struct retained_node {
  void* value = nullptr;
  const retained_type* type = nullptr;
  retained_node* previous = nullptr;
  retained_node* next = nullptr;
};

/**
 * A restore under way while instances are constructed (detail::retained_restore_session,
 * <iecoop/runtime/retain_image.hpp>): every remanent variable constructed while one is set
 * hands its list entry to `take`, which gives it its kept value, so that the value is in place
 * before the FB_Init of the block around it runs (as CODESYS has it).
 */
struct retained_restore_hook {
  void (*take)(retained_restore_hook& self, retained_node& node) noexcept = nullptr;
};
inline retained_restore_hook* retained_restoring = nullptr;

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
                "as bytes; use IEC elementary types, STRING<n>, ARRAY<T, l, u> and STRUCTs of them");
  static_assert(!std::is_array_v<T>,
                "iecoop: a RETAIN or PERSISTENT array is written retain<ARRAY<T, 1, N>>, not retain<T[N]>");
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
    if (retained_restoring != nullptr) retained_restoring->take(*retained_restoring, node_);
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
  retain()
    requires(!std::is_enum_v<T>)
  = default;
  /// A variable of an enumeration declared without an initial value: its start, or refused
  /// here where iecoop does not know it, so that the report names the declaration's own line.
  retain() noexcept
    requires(std::is_enum_v<T>)
      : base(detail::enum_start_or_zero<T>()) {
    detail::refuse_unknown_enum_start<T>();
  }
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
  persistent()
    requires(!std::is_enum_v<T>)
  = default;
  /// A variable of an enumeration declared without an initial value: its start, or refused
  /// here where iecoop does not know it, so that the report names the declaration's own line.
  persistent() noexcept
    requires(std::is_enum_v<T>)
      : base(detail::enum_start_or_zero<T>()) {
    detail::refuse_unknown_enum_start<T>();
  }
  using base::base;
  using base::operator=;
};

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
