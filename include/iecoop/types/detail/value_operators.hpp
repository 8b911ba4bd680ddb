// SPDX-License-Identifier: MIT
// iecoop/types/detail/value_operators.hpp — the operators of iecoop's variable wrappers (var<>,
// in_out<>, output<>, retain<>, persistent<>, located<>, property<>): in an expression a
// wrapper is its value, and every wrapper that can be written takes the compound
// assignments of its type — one implementation for all of them.
// IWYU pragma: private, include <iecoop/iecoop.hpp>
//
// A wrapper converts to its value implicitly, but C++ applies only one user-defined
// conversion, and not at all to operators that are templates: `rVar * 2.0` (REAL converts
// to float, a second conversion) or `sText == 'abc'` would not compile. These operators
// unwrap the operands first and then use the value's own operators, so exactly the
// expressions that work on T work on a wrapper of T.
#pragma once

#include <iosfwd>  // std::basic_string, declared (the operators never build one)
#include <string_view>
#include <type_traits>
#include <utility>

#include <iecoop/types/elementary.hpp>

namespace iecoop::detail {

/// A variable wrapper: a type that declares `using iecoop_value_wrapper = void;` and whose
/// `get()` is its value. (A type may declare it as something else to opt out, as a property
/// readable only by its block does.)
template <class X>
concept value_wrapper = std::is_void_v<typename std::remove_cvref_t<X>::iecoop_value_wrapper>;

/// An operand's value: a wrapper's get(), anything else itself. The operand keeps its
/// constness, so a property read through a non-const block calls its Get on that block.
template <class X>
constexpr decltype(auto) value_of(X&& x) {
  if constexpr (value_wrapper<X>) {
    return std::forward<X>(x).get();
  } else {
    return std::forward<X>(x);
  }
}

template <class X, bool = value_wrapper<X>>
struct unwrapped {
  using type = std::remove_cvref_t<X>;
};
template <class X>
struct unwrapped<X, true> {
  using type = typename std::remove_cvref_t<X>::value_type;
};
/// The value type of an operand: a wrapper's value_type, anything else itself. (Not
/// decltype(value_of(x)): deducing that return type would instantiate the wrapper's get(),
/// which a write-only property rejects.)
template <class X>
using unwrapped_t = typename unwrapped<X>::type;

template <class X, bool = value_wrapper<X>>
struct argument_type {
  using type = std::remove_cvref_t<X>;
};
template <class X>
struct argument_type<X, true> {
  using type = typename argument_type<typename std::remove_cvref_t<X>::value_type>::type;
};
/// The IEC type an argument of a function stands for (the conversions, the generic standard
/// functions): a wrapper's value type, unwrapped again where that is a wrapper itself (a var<> or
/// an in-out of a subrange: the subrange's base type); anything else itself. The one place where
/// every variable form — a block's var<>, retain<>, a property, a located variable, an in-out or
/// REFERENCE, a method's output<> and temp<>, a subrange, a bit `x.N` — becomes its IEC type.
template <class X>
using argument_t = typename argument_type<X>::type;

/// An argument's value, of type argument_t<X>: value_of until it is no wrapper. A property is
/// read through its Get on the block as given (non-const: Get is called as in any expression).
template <class X>
constexpr decltype(auto) argument_value(X&& x) {
  if constexpr (!value_wrapper<X>) {
    return std::forward<X>(x);
  } else {
    using V = decltype(std::forward<X>(x).get());
    if constexpr (!value_wrapper<V>) {
      return std::forward<X>(x).get();
    } else if constexpr (std::is_reference_v<V>) {
      return argument_value(std::forward<X>(x).get());
    } else {
      // A wrapper returned by value (none of iecoop's today): its value, by value, not a
      // reference into the temporary.
      return argument_t<X>(argument_value(std::forward<X>(x).get()));
    }
  }
}

template <class X>
struct is_std_string : std::false_type {};
template <class C, class Traits, class Alloc>
struct is_std_string<std::basic_string<C, Traits, Alloc>> : std::true_type {};
template <class C, class Traits>
struct is_std_string<std::basic_string_view<C, Traits>> : std::true_type {};

/// What a wrapper's operators take on the other side: a wrapper, an IEC value, a C++ number,
/// pointer or string — not another library's class with operators of its own (doctest's
/// expression decomposer, say), which must keep its own.
template <class X>
concept wrapper_partner = !std::is_class_v<std::remove_cvref_t<X>> || value_wrapper<X> ||
                          is_iec_value<std::remove_cvref_t<X>>::value || is_std_string<std::remove_cvref_t<X>>::value;

template <class A, class B>
concept wrapper_operands = (value_wrapper<A> || value_wrapper<B>)&&wrapper_partner<A> && wrapper_partner<B>;

// A wrapped integer with a C++ number (`count + 1`) is left to the integer's own operators,
// which check the constant while compiling (the wrapper converts to the integer for them).
// (A wrapper of a wrapper of an integer — a var<> of a subrange — counts too.)
template <class X>
concept wrapped_integer =
    AnyInteger<unwrapped_t<X>> || (value_wrapper<unwrapped_t<X>> && AnyInteger<unwrapped_t<unwrapped_t<X>>>);
template <class X, class Y>
concept wrapped_integer_with_number = value_wrapper<X> && wrapped_integer<X> && cpp_integer<std::remove_cvref_t<Y>>;
template <class A, class B>
concept wrapper_arithmetic =
    wrapper_operands<A, B> && !wrapped_integer_with_number<A, B> && !wrapped_integer_with_number<B, A>;

// enable_if rather than requires: Clang 14 substitutes into the return type before checking
// a requires-clause, and would recurse for unrelated operands.
template <bool Enable>
using enable_for = std::enable_if_t<Enable, int>;

/// A wrapper of T that anyone can assign a T (`w = v`): every wrapper but a read-only one and
/// one only its block writes (read_only<>, which declares `iecoop_owner_writes` and has
/// compound assignments of its own for its block).
template <class W>
concept writable_wrapper = value_wrapper<W> && !requires { typename std::remove_cvref_t<W>::iecoop_owner_writes; } &&
                           requires(W&& w, const unwrapped_t<W>& v) { std::forward<W>(w) = v; };

/// A value of V goes into a wrapper of T by assignment where a V would: a wrapper of another
/// type whose value converts to T implicitly (`dOut = i` with a var<INT> i into a var<DINT>;
/// C++ would need two conversions, wrapper -> INT -> DINT, and allows one).
template <class T, class V>
concept converts_through_wrapper =
    value_wrapper<V> && !std::is_same_v<unwrapped_t<V>, T> && std::is_convertible_v<unwrapped_t<V>, T>;

/// An IEC value (or a wrapper of one) that does not convert implicitly into T: assigning it to
/// a wrapper of T is rejected with the conversion to write.
template <class T, class V>
concept rejected_value = rejected_conversion<unwrapped_t<const V&>, T>;
template <class T, class V>
constexpr void reject_value() {
  using from = nominal_t<unwrapped_t<const V&>>;
  if constexpr (!iec_name<from>::value.empty() && !iec_name<T>::value.empty()) {
    no_implicit_conversion<spelled_iec_name_t<from>, spelled_iec_name_t<T>>();
  } else {
    static_assert(dependent_false<V>,
                  "iecoop: the value's type does not convert implicitly to the variable's; convert it explicitly");
  }
}

/// A wrapper of T as a condition (`if (bFlag)`): implicitly for a BOOL (`bool b = bFlag;`, as
/// a BOOL itself converts), explicitly for other types that test as bool (an interface
/// variable), and not at all otherwise. A base class rather than constrained members: g++ 12
/// counts a constrained-out conversion function when it looks for the one conversion of a
/// `switch` condition (a wrapper of an enum would be ambiguous).
template <class Derived, class T>
struct condition_conversion {};
template <class Derived>
struct condition_conversion<Derived, BOOL> {
  constexpr operator bool() const {  // implicit: a BOOL is a condition
    return static_cast<bool>(static_cast<const Derived&>(*this).get());
  }
};
template <class Derived, class T>
  requires(!std::is_same_v<T, BOOL> && std::is_constructible_v<bool, const T&>)
struct condition_conversion<Derived, T> {
  explicit constexpr operator bool() const { return static_cast<bool>(static_cast<const Derived&>(*this).get()); }
};

/// A wrapper of an IEC value T read into a variable of another IEC type that T converts to
/// implicitly (`DINT d = fb.nCount;` with a var<INT>, `ltElapsed := tmr.ET;` into an LTIME),
/// as ST assigns it; C++ alone would need two conversions, the wrapper to T and T to the
/// other type. A base class for the same reason as condition_conversion: a template
/// conversion function on a wrapper of an enumeration would break `switch (eMode)`.
template <class Derived, class T>
struct widening_conversion {};
template <class Derived, class T>
  requires is_iec_value<T>::value
struct widening_conversion<Derived, T> {
  template <class U>
    requires(is_iec_value<U>::value && !std::is_same_v<U, T> && std::is_convertible_v<const T&, U>)
  constexpr operator U() const {  // implicit: reads as the variable
    return static_cast<const Derived&>(*this).get();
  }
};
/// A wrapper of an IEC enumeration reads into its base type (`iVal := eState;` for a VAR eState):
/// one conversion, not a template, so that `switch (eState)` still finds the one to the enum.
template <class Derived, class T>
  requires(std::is_enum_v<T> && !std::is_void_v<typename enum_base_of<T>::type>)
struct widening_conversion<Derived, T> {
  constexpr operator typename enum_base_of<T>::type() const {  // implicit: reads as the variable
    return static_cast<const Derived&>(*this).get();
  }
};

/// What `w->m` reaches through a wrapper of T: T's own `->` where it has one (an interface
/// variable, `ip->M()`), else T's members (`pos->x` for a STRUCT).
template <class T>
constexpr decltype(auto) arrow_of(T& value) noexcept {
  if constexpr (requires { value.operator->(); }) {
    return (value);  // C++ applies T's own operator-> next
  } else {
    return &value;
  }
}

/// A compound assignment's right operand that the wrapper's value type does not take as it is
/// (an intermediate result, or an IEC value of another type): combined with the value by the
/// operator itself, as ST's `x := x + v` does. A constant or a T goes through the other
/// overload, which converts it to T at the call (and checks a constant's range there).
template <class W, class V>
concept compound_operand = writable_wrapper<W> && !std::is_same_v<unwrapped_t<V>, unwrapped_t<W>> &&
                           !(std::is_arithmetic_v<std::remove_cvref_t<V>> &&
                             AnyInteger<unwrapped_t<W>>)&&!std::is_same_v<unwrapped_t<V>, BOOL>;
/// A BOOL on the right of a number's compound assignment (`nCount += bPulse`): ST's
/// `nCount := nCount + bPulse` does not compile, and this says so in one message.
template <class W, class V>
concept bool_into_number =
    writable_wrapper<W> && std::is_same_v<unwrapped_t<V>, BOOL> && number_for_bool<unwrapped_t<W>>;

/// The operations of the compound assignments, as std::plus<> and its kin (which need
/// <functional>, and with it <unordered_map>, in every user's translation unit): `a <op> b`,
/// for operands that have it.
struct add_op {
  template <class A, class B>
  constexpr auto operator()(A&& a, B&& b) const -> decltype(std::forward<A>(a) + std::forward<B>(b)) {
    return std::forward<A>(a) + std::forward<B>(b);
  }
};
struct subtract_op {
  template <class A, class B>
  constexpr auto operator()(A&& a, B&& b) const -> decltype(std::forward<A>(a) - std::forward<B>(b)) {
    return std::forward<A>(a) - std::forward<B>(b);
  }
};
struct multiply_op {
  template <class A, class B>
  constexpr auto operator()(A&& a, B&& b) const -> decltype(std::forward<A>(a) * std::forward<B>(b)) {
    return std::forward<A>(a) * std::forward<B>(b);
  }
};
struct divide_op {
  template <class A, class B>
  constexpr auto operator()(A&& a, B&& b) const -> decltype(std::forward<A>(a) / std::forward<B>(b)) {
    return std::forward<A>(a) / std::forward<B>(b);
  }
};
struct modulo_op {
  template <class A, class B>
  constexpr auto operator()(A&& a, B&& b) const -> decltype(std::forward<A>(a) % std::forward<B>(b)) {
    return std::forward<A>(a) % std::forward<B>(b);
  }
};
struct bit_and_op {
  template <class A, class B>
  constexpr auto operator()(A&& a, B&& b) const -> decltype(std::forward<A>(a) & std::forward<B>(b)) {
    return std::forward<A>(a) & std::forward<B>(b);
  }
};
struct bit_or_op {
  template <class A, class B>
  constexpr auto operator()(A&& a, B&& b) const -> decltype(std::forward<A>(a) | std::forward<B>(b)) {
    return std::forward<A>(a) | std::forward<B>(b);
  }
};
struct bit_xor_op {
  template <class A, class B>
  constexpr auto operator()(A&& a, B&& b) const -> decltype(std::forward<A>(a) ^ std::forward<B>(b)) {
    return std::forward<A>(a) ^ std::forward<B>(b);
  }
};

/// `w = w <op> v` for a wrapper w: read, combine, assign back.
template <class W, class Op, class V>
constexpr auto compound_assign(W&& w, Op op, V&& v)
    -> decltype(std::forward<W>(w) = op(value_of(w), value_of(std::forward<V>(v))), std::forward<W>(w)) {
  std::forward<W>(w) = op(value_of(w), value_of(std::forward<V>(v)));
  return std::forward<W>(w);
}

}  // namespace iecoop::detail

namespace iecoop {

template <class A, class B, detail::enable_for<detail::wrapper_arithmetic<A, B>> = 0>
constexpr auto operator+(A&& a, B&& b)
    -> decltype(detail::value_of(std::forward<A>(a)) + detail::value_of(std::forward<B>(b))) {
  return detail::value_of(std::forward<A>(a)) + detail::value_of(std::forward<B>(b));
}
template <class A, class B, detail::enable_for<detail::wrapper_arithmetic<A, B>> = 0>
constexpr auto operator-(A&& a, B&& b)
    -> decltype(detail::value_of(std::forward<A>(a)) - detail::value_of(std::forward<B>(b))) {
  return detail::value_of(std::forward<A>(a)) - detail::value_of(std::forward<B>(b));
}
template <class A, class B, detail::enable_for<detail::wrapper_arithmetic<A, B>> = 0>
constexpr auto operator*(A&& a, B&& b)
    -> decltype(detail::value_of(std::forward<A>(a)) * detail::value_of(std::forward<B>(b))) {
  return detail::value_of(std::forward<A>(a)) * detail::value_of(std::forward<B>(b));
}
template <class A, class B, detail::enable_for<detail::wrapper_arithmetic<A, B>> = 0>
constexpr auto operator/(A&& a, B&& b)
    -> decltype(detail::value_of(std::forward<A>(a)) / detail::value_of(std::forward<B>(b))) {
  return detail::value_of(std::forward<A>(a)) / detail::value_of(std::forward<B>(b));
}
template <class A, class B, detail::enable_for<detail::wrapper_arithmetic<A, B>> = 0>
constexpr auto operator%(A&& a, B&& b)
    -> decltype(detail::value_of(std::forward<A>(a)) % detail::value_of(std::forward<B>(b))) {
  return detail::value_of(std::forward<A>(a)) % detail::value_of(std::forward<B>(b));
}
template <class A, class B, detail::enable_for<detail::wrapper_arithmetic<A, B>> = 0>
constexpr auto operator&(A&& a, B&& b)
    -> decltype(detail::value_of(std::forward<A>(a)) & detail::value_of(std::forward<B>(b))) {
  return detail::value_of(std::forward<A>(a)) & detail::value_of(std::forward<B>(b));
}
template <class A, class B, detail::enable_for<detail::wrapper_arithmetic<A, B>> = 0>
constexpr auto operator|(A&& a, B&& b)
    -> decltype(detail::value_of(std::forward<A>(a)) | detail::value_of(std::forward<B>(b))) {
  return detail::value_of(std::forward<A>(a)) | detail::value_of(std::forward<B>(b));
}
template <class A, class B, detail::enable_for<detail::wrapper_arithmetic<A, B>> = 0>
constexpr auto operator^(A&& a, B&& b)
    -> decltype(detail::value_of(std::forward<A>(a)) ^ detail::value_of(std::forward<B>(b))) {
  return detail::value_of(std::forward<A>(a)) ^ detail::value_of(std::forward<B>(b));
}
// Comparisons yield what the values' comparison yields (a BOOL for IEC values). Each one is
// declared, not rewritten from <=>, which would yield a C++ bool.
template <class A, class B, detail::enable_for<detail::wrapper_operands<A, B>> = 0>
constexpr auto operator==(A&& a, B&& b)
    -> decltype(detail::value_of(std::forward<A>(a)) == detail::value_of(std::forward<B>(b))) {
  return detail::value_of(std::forward<A>(a)) == detail::value_of(std::forward<B>(b));
}
template <class A, class B, detail::enable_for<detail::wrapper_operands<A, B>> = 0>
constexpr auto operator!=(A&& a, B&& b)
    -> decltype(detail::value_of(std::forward<A>(a)) != detail::value_of(std::forward<B>(b))) {
  return detail::value_of(std::forward<A>(a)) != detail::value_of(std::forward<B>(b));
}
template <class A, class B, detail::enable_for<detail::wrapper_operands<A, B>> = 0>
constexpr auto operator<(A&& a, B&& b)
    -> decltype(detail::value_of(std::forward<A>(a)) < detail::value_of(std::forward<B>(b))) {
  return detail::value_of(std::forward<A>(a)) < detail::value_of(std::forward<B>(b));
}
template <class A, class B, detail::enable_for<detail::wrapper_operands<A, B>> = 0>
constexpr auto operator<=(A&& a, B&& b)
    -> decltype(detail::value_of(std::forward<A>(a)) <= detail::value_of(std::forward<B>(b))) {
  return detail::value_of(std::forward<A>(a)) <= detail::value_of(std::forward<B>(b));
}
template <class A, class B, detail::enable_for<detail::wrapper_operands<A, B>> = 0>
constexpr auto operator>(A&& a, B&& b)
    -> decltype(detail::value_of(std::forward<A>(a)) > detail::value_of(std::forward<B>(b))) {
  return detail::value_of(std::forward<A>(a)) > detail::value_of(std::forward<B>(b));
}
template <class A, class B, detail::enable_for<detail::wrapper_operands<A, B>> = 0>
constexpr auto operator>=(A&& a, B&& b)
    -> decltype(detail::value_of(std::forward<A>(a)) >= detail::value_of(std::forward<B>(b))) {
  return detail::value_of(std::forward<A>(a)) >= detail::value_of(std::forward<B>(b));
}
template <class A, class B, detail::enable_for<detail::wrapper_operands<A, B>> = 0>
constexpr auto operator<=>(A&& a, B&& b)
    -> decltype(detail::value_of(std::forward<A>(a)) <=> detail::value_of(std::forward<B>(b))) {
  return detail::value_of(std::forward<A>(a)) <=> detail::value_of(std::forward<B>(b));
}
template <class A, detail::enable_for<detail::value_wrapper<A>> = 0>
constexpr auto operator-(A&& a) -> decltype(-detail::value_of(std::forward<A>(a))) {
  return -detail::value_of(std::forward<A>(a));
}
template <class A, detail::enable_for<detail::value_wrapper<A>> = 0>
constexpr auto operator!(A&& a) -> decltype(!detail::value_of(std::forward<A>(a))) {
  return !detail::value_of(std::forward<A>(a));
}
template <class A, detail::enable_for<detail::value_wrapper<A>> = 0>
constexpr auto operator~(A&& a) -> decltype(~detail::value_of(std::forward<A>(a))) {
  return ~detail::value_of(std::forward<A>(a));
}

// Compound assignment of every writable wrapper, as ST's `x := x <op> v`: the value is read,
// combined and assigned back (for a property: Get, then Set). A T or a constant is the
// right operand as in any assignment (converted at the call, a constant checked there); an
// intermediate result or a value of another IEC type is combined as it is.
template <class W, detail::enable_for<detail::writable_wrapper<W>> = 0>
constexpr W&& operator+=(W&& w, const std::type_identity_t<detail::unwrapped_t<W>>& v) {
  return detail::compound_assign(std::forward<W>(w), detail::add_op{}, v);
}
template <class W, class V, detail::enable_for<detail::bool_into_number<W, V>> = 0>
constexpr W&& operator+=(W&& w, V&&) {
  detail::bool_is_no_number<detail::unwrapped_t<V>>();
  return std::forward<W>(w);
}
template <class W, class V, detail::enable_for<detail::compound_operand<W, V>> = 0>
constexpr auto operator+=(W&& w, V&& v)
    -> decltype(detail::compound_assign(std::forward<W>(w), detail::add_op{}, std::forward<V>(v))) {
  return detail::compound_assign(std::forward<W>(w), detail::add_op{}, std::forward<V>(v));
}
template <class W, detail::enable_for<detail::writable_wrapper<W>> = 0>
constexpr W&& operator-=(W&& w, const std::type_identity_t<detail::unwrapped_t<W>>& v) {
  return detail::compound_assign(std::forward<W>(w), detail::subtract_op{}, v);
}
template <class W, class V, detail::enable_for<detail::bool_into_number<W, V>> = 0>
constexpr W&& operator-=(W&& w, V&&) {
  detail::bool_is_no_number<detail::unwrapped_t<V>>();
  return std::forward<W>(w);
}
template <class W, class V, detail::enable_for<detail::compound_operand<W, V>> = 0>
constexpr auto operator-=(W&& w, V&& v)
    -> decltype(detail::compound_assign(std::forward<W>(w), detail::subtract_op{}, std::forward<V>(v))) {
  return detail::compound_assign(std::forward<W>(w), detail::subtract_op{}, std::forward<V>(v));
}
template <class W, detail::enable_for<detail::writable_wrapper<W>> = 0>
constexpr W&& operator*=(W&& w, const std::type_identity_t<detail::unwrapped_t<W>>& v) {
  return detail::compound_assign(std::forward<W>(w), detail::multiply_op{}, v);
}
template <class W, class V, detail::enable_for<detail::bool_into_number<W, V>> = 0>
constexpr W&& operator*=(W&& w, V&&) {
  detail::bool_is_no_number<detail::unwrapped_t<V>>();
  return std::forward<W>(w);
}
template <class W, class V, detail::enable_for<detail::compound_operand<W, V>> = 0>
constexpr auto operator*=(W&& w, V&& v)
    -> decltype(detail::compound_assign(std::forward<W>(w), detail::multiply_op{}, std::forward<V>(v))) {
  return detail::compound_assign(std::forward<W>(w), detail::multiply_op{}, std::forward<V>(v));
}
template <class W, detail::enable_for<detail::writable_wrapper<W>> = 0>
constexpr W&& operator/=(W&& w, const std::type_identity_t<detail::unwrapped_t<W>>& v) {
  return detail::compound_assign(std::forward<W>(w), detail::divide_op{}, v);
}
template <class W, class V, detail::enable_for<detail::bool_into_number<W, V>> = 0>
constexpr W&& operator/=(W&& w, V&&) {
  detail::bool_is_no_number<detail::unwrapped_t<V>>();
  return std::forward<W>(w);
}
template <class W, class V, detail::enable_for<detail::compound_operand<W, V>> = 0>
constexpr auto operator/=(W&& w, V&& v)
    -> decltype(detail::compound_assign(std::forward<W>(w), detail::divide_op{}, std::forward<V>(v))) {
  return detail::compound_assign(std::forward<W>(w), detail::divide_op{}, std::forward<V>(v));
}
template <class W, detail::enable_for<detail::writable_wrapper<W>> = 0>
constexpr W&& operator%=(W&& w, const std::type_identity_t<detail::unwrapped_t<W>>& v) {
  return detail::compound_assign(std::forward<W>(w), detail::modulo_op{}, v);
}
template <class W, class V, detail::enable_for<detail::bool_into_number<W, V>> = 0>
constexpr W&& operator%=(W&& w, V&&) {
  detail::bool_is_no_number<detail::unwrapped_t<V>>();
  return std::forward<W>(w);
}
template <class W, class V, detail::enable_for<detail::compound_operand<W, V>> = 0>
constexpr auto operator%=(W&& w, V&& v)
    -> decltype(detail::compound_assign(std::forward<W>(w), detail::modulo_op{}, std::forward<V>(v))) {
  return detail::compound_assign(std::forward<W>(w), detail::modulo_op{}, std::forward<V>(v));
}
template <class W, detail::enable_for<detail::writable_wrapper<W>> = 0>
constexpr W&& operator&=(W&& w, const std::type_identity_t<detail::unwrapped_t<W>>& v) {
  return detail::compound_assign(std::forward<W>(w), detail::bit_and_op{}, v);
}
template <class W, class V, detail::enable_for<detail::bool_into_number<W, V>> = 0>
constexpr W&& operator&=(W&& w, V&&) {
  detail::bool_is_no_number<detail::unwrapped_t<V>>();
  return std::forward<W>(w);
}
template <class W, class V, detail::enable_for<detail::compound_operand<W, V>> = 0>
constexpr auto operator&=(W&& w, V&& v)
    -> decltype(detail::compound_assign(std::forward<W>(w), detail::bit_and_op{}, std::forward<V>(v))) {
  return detail::compound_assign(std::forward<W>(w), detail::bit_and_op{}, std::forward<V>(v));
}
template <class W, detail::enable_for<detail::writable_wrapper<W>> = 0>
constexpr W&& operator|=(W&& w, const std::type_identity_t<detail::unwrapped_t<W>>& v) {
  return detail::compound_assign(std::forward<W>(w), detail::bit_or_op{}, v);
}
template <class W, class V, detail::enable_for<detail::bool_into_number<W, V>> = 0>
constexpr W&& operator|=(W&& w, V&&) {
  detail::bool_is_no_number<detail::unwrapped_t<V>>();
  return std::forward<W>(w);
}
template <class W, class V, detail::enable_for<detail::compound_operand<W, V>> = 0>
constexpr auto operator|=(W&& w, V&& v)
    -> decltype(detail::compound_assign(std::forward<W>(w), detail::bit_or_op{}, std::forward<V>(v))) {
  return detail::compound_assign(std::forward<W>(w), detail::bit_or_op{}, std::forward<V>(v));
}
template <class W, detail::enable_for<detail::writable_wrapper<W>> = 0>
constexpr W&& operator^=(W&& w, const std::type_identity_t<detail::unwrapped_t<W>>& v) {
  return detail::compound_assign(std::forward<W>(w), detail::bit_xor_op{}, v);
}
template <class W, class V, detail::enable_for<detail::bool_into_number<W, V>> = 0>
constexpr W&& operator^=(W&& w, V&&) {
  detail::bool_is_no_number<detail::unwrapped_t<V>>();
  return std::forward<W>(w);
}
template <class W, class V, detail::enable_for<detail::compound_operand<W, V>> = 0>
constexpr auto operator^=(W&& w, V&& v)
    -> decltype(detail::compound_assign(std::forward<W>(w), detail::bit_xor_op{}, std::forward<V>(v))) {
  return detail::compound_assign(std::forward<W>(w), detail::bit_xor_op{}, std::forward<V>(v));
}

/// `++x` and `--x` on a writable wrapper: x := x + 1.
template <class W, detail::enable_for<detail::writable_wrapper<W>> = 0>
constexpr auto operator++(W&& w) -> decltype(++std::declval<detail::unwrapped_t<W>&>(), std::forward<W>(w)) {
  detail::unwrapped_t<W> value = detail::value_of(w);
  ++value;
  std::forward<W>(w) = value;
  return std::forward<W>(w);
}
template <class W, detail::enable_for<detail::writable_wrapper<W>> = 0>
constexpr auto operator--(W&& w) -> decltype(--std::declval<detail::unwrapped_t<W>&>(), std::forward<W>(w)) {
  detail::unwrapped_t<W> value = detail::value_of(w);
  --value;
  std::forward<W>(w) = value;
  return std::forward<W>(w);
}

}  // namespace iecoop
