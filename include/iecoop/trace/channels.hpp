// SPDX-License-Identifier: MIT
// iecoop/trace/channels.hpp — the named values a trace recorder or a watch list reads each cycle
// (CODESYS Trace: "Variables"): pins of a block, any variable, a PROPERTY, located variables.
//
//     trace.add_pins("IO_PRG.tJam", io.tJam);          // IN, PT, Q, ET as tJam.IN, tJam.PT, ...
//     trace.add("IO_PRG.bStart", io.bStart);           // one variable
//     trace.add("fbA.prop_iA", fbA.prop_iA);           // a PROPERTY, through its monitoring mode
//     trace.add_located("GVL_IO", gvl);                // every variable of a LOCATED list
//
// What can be recorded: BOOL, the integers and bit strings, REAL, LREAL, TIME, LTIME, the dates
// and times of day, and enumerations (Traceable) — as variables, as a block's var<>/output<>
// wrappers, through VAR_IN_OUT references, PROPERTYs and located variables. A STRING, ARRAY or
// STRUCT is recorded element by element (add each one); add_pins() leaves such pins out.
//
// Names are not copied: give names that live as long as the channels (string literals, or
// strings the program keeps). A channel's scope and name are joined with a dot when written.
// IWYU pragma: private, include <iecoop/trace.hpp>
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string_view>
#include <type_traits>
#include <utility>

#include <iecoop/config.hpp>
#include <iecoop/detail/reflect.hpp>
#include <iecoop/detail/scalar_access.hpp>
#include <iecoop/fault.hpp>
#include <iecoop/pou/call_interface.hpp>
#include <iecoop/pou/variables.hpp>
#include <iecoop/types/date_time.hpp>
#include <iecoop/types/date_time_text.hpp>
#include <iecoop/types/detail/type_hash.hpp>
#include <iecoop/types/detail/value_operators.hpp>
#include <iecoop/types/elementary.hpp>
#include <iecoop/types/enumeration.hpp>
#include <iecoop/types/literal_text.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop {

/// What a traced value is, as the writers show it.
enum class trace_kind : std::uint8_t {
  boolean,           ///< BOOL: a digital lane, a VCD wire
  signed_integer,    ///< SINT .. LINT
  unsigned_integer,  ///< USINT .. ULINT
  bit_string,        ///< BYTE .. LWORD
  real,              ///< REAL, LREAL
  duration,          ///< TIME (a count of ms), LTIME (of ns)
  date_time,         ///< DATE, TOD, DT and their L forms (a count of their unit)
  enumeration,       ///< a count of its base type, shown by its component's name
};

/// The type of a traced value.
struct trace_type {
  trace_kind kind;
  std::uint8_t bytes;          ///< the bytes of its value in a sample (a BOOL takes one bit instead)
  bool is_signed;              ///< a signed integer, or an enumeration with a signed base
  std::uint64_t ns_per_count;  ///< duration and date_time: nanoseconds per unit of the count (TIME: 1'000'000)
  std::string_view name;       ///< BOOL, INT, TIME, ... or the enumeration's name
  std::size_t max_text;        ///< the longest IEC text of a value
  /// Writes the IEC text of a value (`TRUE`, `-5`, `T#1s500ms`, `Run`) from its bytes.
  char* (*text)(char* out, const std::byte* value);
};

/// The types a trace records.
template <class T>
concept Traceable = (std::is_same_v<T, BOOL> || AnyInteger<T> || AnyReal<T> || AnyDuration<T> || AnyDate<T> ||
                     Enumeration<T>)&&std::is_trivially_copyable_v<T> &&
                    std::is_default_constructible_v<T> && sizeof(T) <= 8;

namespace detail {

template <class T>
constexpr std::string_view trace_type_name() noexcept {
  if constexpr (Enumeration<T>) {
    const std::string_view full = type_name<T>();
    return full.substr(full.rfind(':') == std::string_view::npos ? 0 : full.rfind(':') + 1);
  } else {
    return iec_name<T>::value;
  }
}

template <class T>
constexpr trace_kind trace_kind_of() noexcept {
  if constexpr (std::is_same_v<T, BOOL>) {
    return trace_kind::boolean;
  } else if constexpr (AnyInteger<T>) {
    return T::kind == integer_kind::bit_string   ? trace_kind::bit_string
           : T::kind == integer_kind::signed_int ? trace_kind::signed_integer
                                                 : trace_kind::unsigned_integer;
  } else if constexpr (AnyReal<T>) {
    return trace_kind::real;
  } else if constexpr (AnyDuration<T>) {
    return trace_kind::duration;
  } else if constexpr (AnyDate<T>) {
    return trace_kind::date_time;
  } else {
    return trace_kind::enumeration;
  }
}

template <class T>
constexpr bool trace_signed() noexcept {
  if constexpr (AnyInteger<T>) {
    return std::is_signed_v<typename T::rep>;
  } else if constexpr (Enumeration<T>) {
    return std::is_signed_v<std::underlying_type_t<T>>;
  } else {
    return false;
  }
}

template <class T>
constexpr std::uint64_t trace_ns_per_count() noexcept {
  if constexpr (AnyDuration<T> || AnyDate<T>) {
    return ns_per_tick<T>;
  } else {
    return 0;
  }
}

template <class T>
char* trace_text(char* out, const std::byte* value) {
  T v{};
  std::memcpy(static_cast<void*>(&v), value, sizeof(T));
  return to_text(out, v);
}

}  // namespace detail

/// The trace_type of T.
template <Traceable T>
inline constexpr trace_type trace_type_of{detail::trace_kind_of<T>(),   static_cast<std::uint8_t>(sizeof(T)),
                                          detail::trace_signed<T>(),    detail::trace_ns_per_count<T>(),
                                          detail::trace_type_name<T>(), max_text_length<T>,
                                          &detail::trace_text<T>};

/// A recorded value, widened: read the member its type's kind says.
struct trace_value {
  trace_kind kind = trace_kind::boolean;
  bool is_signed = false;  ///< `i` holds it (a signed integer, or an enumeration with a signed base)
  std::uint8_t bytes = 0;  ///< the size of its type: a REAL (4) is shown as the float it is
  union {
    std::int64_t i;   ///< is_signed
    std::uint64_t u;  ///< boolean (0 or 1), unsigned_integer, bit_string, duration, date_time, unsigned enums
    double f;         ///< real
  };
  constexpr trace_value() noexcept : u(0) {}

  /// The value as a number (for scaling a chart): a count for durations and dates.
  [[nodiscard]] constexpr double number() const noexcept {
    if (kind == trace_kind::real) return f;
    return is_signed ? static_cast<double>(i) : static_cast<double>(u);
  }
};

/// A named value: where it appears in a sample.
struct trace_channel {
  std::string_view scope;  ///< the block, program or list it belongs to ("IO_PRG.tJam"); may be empty
  std::string_view name;   ///< the variable or pin ("IN")
  const trace_type* type;  ///< what it holds
  std::uint16_t offset;    ///< its place in a sample's values: the bit of a BOOL, else the first byte
};

/// Writes "scope.name" (or "name") with `put(std::string_view)`.
template <class Put>
void put_channel_name(const trace_channel& channel, Put&& put, std::string_view separator = ".") {
  if (!channel.scope.empty()) {
    put(channel.scope);
    put(separator);
  }
  put(channel.name);
}

namespace detail {

/// `v` with the integer of U's width at `p`, sign-extended where v.is_signed.
template <class U>
trace_value widen(trace_value v, const std::byte* p) noexcept {
  U x;
  std::memcpy(&x, p, sizeof x);
  if (v.is_signed) {
    v.i = static_cast<std::make_signed_t<U>>(x);
  } else {
    v.u = x;
  }
  return v;
}

/// Decodes a value of `type` from its bytes in a sample.
inline trace_value decode_trace_value(const trace_type& type, const std::byte* values, std::uint16_t offset) noexcept {
  trace_value v;
  v.kind = type.kind;
  v.is_signed = type.is_signed;
  v.bytes = type.bytes;
  if (type.kind == trace_kind::boolean) {
    v.u = (std::to_integer<unsigned>(values[offset / 8]) >> (offset % 8)) & 1U;
    return v;
  }
  const std::byte* p = values + offset;
  if (type.kind == trace_kind::real) {
    if (type.bytes == 4) {
      float x;
      std::memcpy(&x, p, 4);
      v.f = static_cast<double>(x);
    } else {
      std::memcpy(&v.f, p, 8);
    }
    return v;
  }
  switch (type.bytes) {
    case 1: return widen<std::uint8_t>(v, p);
    case 2: return widen<std::uint16_t>(v, p);
    case 4: return widen<std::uint32_t>(v, p);
    default: return widen<std::uint64_t>(v, p);
  }
}

/// How to read a recorded source of type V: directly from memory (a variable), or by a call
/// (a PROPERTY's monitor(), a located variable, a VAR_IN_OUT's current reference).
template <class V>
struct trace_source {
  static constexpr bool supported = false;
};
// A variable of a Traceable type.
template <Traceable V>
struct trace_source<V> {
  static constexpr bool supported = true;
  static constexpr bool direct = true;
  using value_type = V;
  static const V* address(const V& v) noexcept { return &v; }
};
// A PROPERTY: what a watch list shows (its monitoring mode).
template <class V>
  requires(!Traceable<V>) && requires(const V& v) {
    { v.monitor() } -> Traceable;
  }
struct trace_source<V> {
  static constexpr bool supported = true;
  static constexpr bool direct = false;
  using value_type = std::remove_cvref_t<decltype(std::declval<const V&>().monitor())>;
  static value_type read(const V& v) { return v.monitor(); }
};
// A VAR_IN_OUT: the variable it refers to now (the type's initial value while unbound).
template <class T>
  requires Traceable<std::remove_const_t<T>>
struct trace_source<in_out<T>> {
  static constexpr bool supported = true;
  static constexpr bool direct = false;
  using value_type = std::remove_const_t<T>;
  static value_type read(const in_out<T>& v) { return v.bound() ? value_type(v.get()) : value_type{}; }
};
// A block's variable wrapper (var<>, output<>, an output pin) that keeps its value: read in place.
template <class V>
  requires(!Traceable<V>) && (!requires(const V& v) { v.monitor(); }) && value_wrapper<V> &&
          requires(const V& v) {
            { v.get() } -> std::same_as<const unwrapped_t<const V&>&>;
          } && Traceable<unwrapped_t<const V&>>
struct trace_source<V> {
  static constexpr bool supported = true;
  static constexpr bool direct = true;
  using value_type = unwrapped_t<const V&>;
  static const value_type* address(const V& v) noexcept { return &v.get(); }
};
// Anything else whose get() gives a Traceable value (not a reference): a located variable.
template <class V>
  requires(!Traceable<V>) && (!requires(const V& v) { v.monitor(); }) && requires(const V& v) {
    { v.get() } -> Traceable;
  }
struct trace_source<V> {
  static constexpr bool supported = true;
  static constexpr bool direct = false;
  using value_type = std::remove_cvref_t<decltype(std::declval<const V&>().get())>;
  static value_type read(const V& v) { return v.get(); }
};

template <class V>
inline constexpr bool traceable_source = trace_source<std::remove_cvref_t<V>>::supported;

template <auto Member>
struct pin_object;
template <class T, class C, T C::*Member>
struct pin_object<Member> {
  using type = T;
};

}  // namespace detail

/**
 * The channels of a trace: at most MaxChannels named values, read together into one sample.
 * Adding a channel returns FALSE (and reports fault_kind::invalid_value) when all
 * MaxChannels are taken or while the owner is recording.
 */
template <std::size_t MaxChannels>
class trace_channels {
  static_assert(MaxChannels > 0 && MaxChannels <= 4096, "iecoop: a trace has 1 to 4096 channels; give MaxChannels");

 public:
  trace_channels() = default;
  trace_channels(const trace_channels&) = delete;
  trace_channels& operator=(const trace_channels&) = delete;

  /// Records `variable` as `name` (a variable, a var<>/output<> wrapper, a VAR_IN_OUT, a
  /// PROPERTY or a located variable).
  template <class V>
  bool add(std::string_view name, V&& variable) {
    return add({}, name, std::forward<V>(variable));
  }

  /// Records `variable` as `scope.name`.
  template <class V>
  bool add(std::string_view scope, std::string_view name, V&& variable) {
    static_assert(std::is_lvalue_reference_v<V>,
                  "iecoop: a trace records a variable, not a value (the value is gone when the trace reads it); "
                  "give the variable itself, e.g. trace.add(\"iCount\", prg.iCount)");
    using source = detail::trace_source<std::remove_cvref_t<V>>;
    static_assert(source::supported,
                  "iecoop: a trace records BOOL, integers, bit strings, REAL, LREAL, TIME, LTIME, dates and "
                  "enumerations (as variables, wrappers, VAR_IN_OUT, PROPERTYs or located variables); record a "
                  "STRING, ARRAY or STRUCT element by element");
    if constexpr (!source::supported) {
      return false;  // refused above; no further errors
    } else if constexpr (source::direct) {
      using T = typename source::value_type;
      return add_channel(scope, name, trace_type_of<T>, source::address(variable), nullptr, nullptr);
    } else {
      using T = typename source::value_type;
      return add_channel(
          scope, name, trace_type_of<T>, static_cast<const T*>(nullptr), &variable,
          +[](const void* object, std::byte* out) {
            const T value = source::read(*static_cast<const std::remove_cvref_t<V>*>(object));
            std::memcpy(static_cast<void*>(out), static_cast<const void*>(&value), sizeof(T));
          });
    }
  }

  /// Records every pin of the block, program or function `block` (VAR_INPUT, VAR_OUTPUT,
  /// VAR_IN_OUT along its EXTENDS chain, in that order) as `scope.PIN`; without a scope, as
  /// the bare pin names. Pins of a type a trace cannot record (STRING, ARRAY, STRUCT) are
  /// left out. FALSE if some did not fit.
  template <class B>
  bool add_pins(std::string_view scope, B&& block) {
    static_assert(std::is_lvalue_reference_v<B>,
                  "iecoop: a trace records the pins of a block instance, not of a temporary (its pins are gone when "
                  "the trace reads them); give the instance, e.g. trace.add_pins(\"IO_PRG.tJam\", io.tJam)");
    using block_type = std::remove_cvref_t<B>;
    const bool inputs = add_members<inputs_of<block_type>>(scope, block);
    const bool outputs = add_members<outputs_of<block_type>>(scope, block);
    const bool in_outs = add_members<in_outs_of<block_type>>(scope, block);
    return inputs && outputs && in_outs;
  }
  template <class B>
  bool add_pins(B&& block) {
    return add_pins(std::string_view{}, std::forward<B>(block));
  }

  /// Records every variable of the LOCATED list of `list` (a global variable list or a
  /// program: `using LOCATED = pins<...>;`) as `scope.name`.
  template <class L>
  bool add_located(std::string_view scope, const L& list) {
    static_assert(
        requires { typename L::LOCATED; },
        "iecoop: add_located records the variables a type lists in `using LOCATED = pins<...>;`; give "
        "the list one, or add its variables one by one");
    return add_members<typename L::LOCATED>(scope, list);
  }

  /// The channels, in the order they were added.
  [[nodiscard]] std::span<const trace_channel> channels() const noexcept { return {channels_, count_}; }
  [[nodiscard]] std::size_t channel_count() const noexcept { return count_; }
  [[nodiscard]] static constexpr std::size_t max_channels() noexcept { return MaxChannels; }

  /// The index of the channel called `scope.name` (or `name`), or channel_count() if none.
  [[nodiscard]] std::size_t find(std::string_view full_name) const noexcept {
    for (std::size_t c = 0; c < count_; ++c) {
      const trace_channel& ch = channels_[c];
      if (ch.scope.empty()
              ? full_name == ch.name
              : full_name.size() == ch.scope.size() + 1 + ch.name.size() && full_name.starts_with(ch.scope) &&
                    full_name[ch.scope.size()] == '.' && full_name.ends_with(ch.name)) {
        return c;
      }
    }
    return count_;
  }

  /// Removes every channel.
  bool clear_channels() noexcept {
    if (!may_change("clear_channels")) return false;
    count_ = bool_count_ = value_count_ = 0;
    value_bytes_ = 0;
    return true;
  }

  /// The bytes one sample's values take: one bit per BOOL (rounded up to bytes), then each
  /// other value in its own size.
  [[nodiscard]] std::size_t values_bytes() const noexcept { return bool_bytes() + value_bytes_; }

  /// Reads every channel into `values` (values_bytes() bytes).
  void capture(std::byte* values) const {
    const std::size_t full_bytes = bool_count_ / 8;
    for (std::size_t b = 0; b < full_bytes; ++b) {
      const bool_source* s = bool_sources_ + b * 8;
      unsigned byte = 0;
      for (unsigned k = 0; k < 8; ++k) byte |= static_cast<unsigned>(read_bool(s[k])) << k;
      values[b] = static_cast<std::byte>(byte);
    }
    if (const std::size_t rest = bool_count_ % 8; rest != 0) {
      const bool_source* s = bool_sources_ + full_bytes * 8;
      unsigned byte = 0;
      for (unsigned k = 0; k < rest; ++k) byte |= static_cast<unsigned>(read_bool(s[k])) << k;
      values[full_bytes] = static_cast<std::byte>(byte);
    }
    std::byte* const out = values + bool_bytes();
    for (std::size_t v = 0; v < value_count_; ++v) {
      const value_source& s = value_sources_[v];
      std::byte* const to = out + s.offset;
      if (s.address == nullptr) {
        s.read(s.object, to);
        continue;
      }
      switch (s.bytes) {
        case 1: *to = *s.address; break;
        case 2: std::memcpy(to, s.address, 2); break;
        case 4: std::memcpy(to, s.address, 4); break;
        default: std::memcpy(to, s.address, 8); break;
      }
    }
  }

 protected:
  /// The owner (a recorder) forbids changes while it records.
  void lock_channels(bool locked) noexcept { locked_ = locked; }

 private:
  struct bool_source {
    const bool* address;  // a BOOL in memory, or nullptr: read(object)
    const void* object;
    void (*read)(const void*, std::byte*);
  };
  struct value_source {
    const std::byte* address;  // the value in memory, or nullptr: read(object, out)
    const void* object;
    void (*read)(const void*, std::byte*);
    std::uint16_t offset;  // after the BOOL bits
    std::uint8_t bytes;
  };

  static bool read_bool(const bool_source& s) {
    if (s.address != nullptr) return *s.address;
    std::byte value{};
    s.read(s.object, &value);
    return value != std::byte{0};
  }

  [[nodiscard]] std::size_t bool_bytes() const noexcept { return (bool_count_ + 7) / 8; }

  bool may_change(const char* what) noexcept {
    (void)what;
    if (locked_) {
      fault(fault_kind::invalid_value,
            "iecoop: a trace's channels change only while it is stopped; stop() it, add or clear the channels, "
            "then start() it again");
      return false;
    }
    return true;
  }

  template <class Pins, class B>
  bool add_members(std::string_view scope, const B& block) {
    bool all = true;
    [&]<std::size_t... I>(std::index_sequence<I...>) {
      ((all = add_member<pin<Pins, I>>(scope, block) && all), ...);
    }(std::make_index_sequence<Pins::size>{});
    return all;
  }

  template <auto Member, class B>
  bool add_member(std::string_view scope, const B& block) {
    using member_type = typename detail::pin_object<Member>::type;
    if constexpr (detail::traceable_source<member_type>) {
      return add(scope, member_name<Member>, block.*Member);
    } else {
      return true;  // a pin a trace cannot show
    }
  }

  template <class T>
  bool add_channel(std::string_view scope, std::string_view name, const trace_type& type, const T* address,
                   const void* object, void (*read)(const void*, std::byte*)) {
    if (!may_change("add")) return false;
    if (count_ == MaxChannels) {
      fault(fault_kind::invalid_value,
            "iecoop: a trace's channels are all taken; give the recorder more (its MaxChannels template argument)");
      return false;
    }
    trace_channel& channel = channels_[count_];
    channel.scope = scope;
    channel.name = name;
    channel.type = &type;
    if (type.kind == trace_kind::boolean) {
      const bool* direct = nullptr;
      if constexpr (std::is_same_v<T, BOOL>) {
        if (address != nullptr) direct = &detail::scalar_access::ref(*address);
      }
      bool_sources_[bool_count_] = bool_source{direct, object, read};
      channel.offset = static_cast<std::uint16_t>(bool_count_++);
    } else {
      value_sources_[value_count_++] = value_source{reinterpret_cast<const std::byte*>(address), object, read,
                                                    static_cast<std::uint16_t>(value_bytes_), type.bytes};
      channel.offset = static_cast<std::uint16_t>(value_bytes_);  // after the BOOL bits: see layout()
      value_bytes_ += type.bytes;
    }
    ++count_;
    layout();
    return true;
  }

  // A BOOL's offset is its bit; every other value's is its byte, after the BOOL bits.
  void layout() noexcept {
    std::size_t bit = 0;
    for (std::size_t c = 0; c < count_; ++c) {
      if (channels_[c].type->kind == trace_kind::boolean) channels_[c].offset = static_cast<std::uint16_t>(bit++);
    }
    std::size_t v = 0;
    for (std::size_t c = 0; c < count_; ++c) {
      if (channels_[c].type->kind != trace_kind::boolean) {
        channels_[c].offset = static_cast<std::uint16_t>(bool_bytes() + value_sources_[v++].offset);
      }
    }
  }

  trace_channel channels_[MaxChannels]{};
  bool_source bool_sources_[MaxChannels]{};
  value_source value_sources_[MaxChannels]{};
  std::size_t count_ = 0;
  std::size_t bool_count_ = 0;
  std::size_t value_count_ = 0;
  std::size_t value_bytes_ = 0;
  bool locked_ = false;
};

}  // namespace iecoop

#include <iecoop/detail/pop_macros.hpp>
