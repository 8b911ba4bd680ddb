// SPDX-License-Identifier: MIT
// iecoop/detail/single_instance.hpp — a type of which one instance lives at a time, reachable
// from anywhere: PROGRAMs and global variable lists.
// IWYU pragma: private, include <iecoop/pou/program.hpp>
#pragma once

#include <string_view>

#include <iecoop/detail/type_name.hpp>
#include <iecoop/fault.hpp>

namespace iecoop::detail {

/// How many live applications list T (a global variable list in globals<...>, a program in a
/// task): tells instance() whether T is missing from every application or only not started.
template <class T>
inline int listed_by_applications = 0;

/// The fault messages of single_instance<Self, ...>: the rule and the fix; the fault's pou
/// names Self. Built for size (-Os: __OPTIMIZE_SIZE__, as a firmware is), each is one text for
/// every PROGRAM and list, in fewer words, which names Self only through the pou (a text that
/// named it would be a copy per PROGRAM: 550 bytes of flash each in full, 180 in short).
/// Otherwise each names Self twice, in the rule and in the fix.
#if defined(__OPTIMIZE_SIZE__)
inline constexpr char unlisted_program_text[] =
    "PROGRAM (the pou) in no task; name it in a task<...>; a scratch instance stands in";
inline constexpr char unlisted_list_text[] =
    "global variable list (the pou) in no application; add globals<...>; a scratch instance stands in";
inline constexpr char not_started_text[] =
    "the pou is used while its application is stopped; start() constructs it; a scratch instance stands in";
inline constexpr char duplicate_text[] = "a second instance of the pou, not registered; the application owns the one";

template <class Self, bool List>
struct single_instance_messages {
  static constexpr const char* unlisted() noexcept { return List ? unlisted_list_text : unlisted_program_text; }
  static constexpr const char* not_started() noexcept { return not_started_text; }
  static constexpr const char* duplicate() noexcept { return duplicate_text; }
};
#else
template <class Self, bool List>
struct single_instance_messages {
  static constexpr std::string_view name = short_type_name<Self>();
  static constexpr std::string_view unlisted_rule =
      List ? ": no application lists this global variable list in globals<...> and no instance of it is declared; "
             "add it to the application, as in application{..., globals<"
           : ": no task of an application calls this PROGRAM and no instance of it is declared; name it in a "
             "task of the application, as in application{task<";
  static constexpr std::string_view unlisted_end =
      List ? ">{}} (or declare its one instance yourself); a scratch instance stands in"
           : ">{\"Main\", cyclic{\"T#10ms\"_iec}, 1}} (or declare its one instance yourself); a scratch instance "
             "stands in";
  static constexpr std::string_view not_started_rule =
      ": used while its application is stopped (before start() or after stop()); start() constructs it — a scratch "
      "instance stands in";
  static constexpr std::string_view duplicate_rule =
      List ? ": a global variable list has exactly one instance; this second one is not registered (an application "
             "that lists it in globals<...> owns it: do not declare it too)"
           : ": a PROGRAM has exactly one instance; this second one is not registered (an application whose task "
             "calls it owns it: do not declare it too)";
  static constexpr auto unlisted_text = joined_text<name, unlisted_rule, name, unlisted_end>;
  static constexpr auto not_started_text = joined_text<name, not_started_rule>;
  static constexpr auto duplicate_text = joined_text<name, duplicate_rule>;
  static constexpr const char* unlisted() noexcept { return unlisted_text.data(); }
  static constexpr const char* not_started() noexcept { return not_started_text.data(); }
  static constexpr const char* duplicate() noexcept { return duplicate_text.data(); }
};
#endif

/// How many scratch instances are under construction: while one is, no program or global
/// variable list (also one nested in it) registers as the live instance of its type.
inline int scratch_depth = 0;

/// Marks the construction of a scratch instance for its lifetime.
class scratch_scope {
 public:
  scratch_scope() noexcept { ++scratch_depth; }
  ~scratch_scope() { --scratch_depth; }
  scratch_scope(const scratch_scope&) = delete;
  scratch_scope& operator=(const scratch_scope&) = delete;
};

/**
 * The base of `Self` (CRTP) that registers the instance under construction as the one of
 * its type. Constructing a second while the first lives reports `duplicate` (with
 * `duplicate_message`) and leaves the first registered; copies (made by an online change)
 * are not registered. Without an instance, instance() reports fault_kind::invalid_value and
 * returns a scratch instance, which is never registered. Each fault names Self in its pou, and
 * its message says the fix: an application that lists Self but is stopped, or none that lists it.
 */
template <class Self, fault_kind Duplicate>
class single_instance {
  using messages = single_instance_messages<Self, Duplicate == fault_kind::duplicate_globals>;

 public:
  /// The live instance (or, reporting a fault, a scratch one).
  static Self& instance() {
    if (live_ == nullptr) {
      report_about(fault_kind::invalid_value,
                   listed_by_applications<Self> > 0 ? messages::not_started() : messages::unlisted(),
                   short_type_name_c<Self>.data());
      return scratch();
    }
    return *live_;
  }
  /// TRUE while an instance lives.
  static bool exists() noexcept { return live_ != nullptr; }

  // Public, so that a program or list stays an aggregate (`PLC_PRG p{};`).
  single_instance() {
    if (scratch_depth > 0) return;
    if (live_ != nullptr) {
      report_about(Duplicate, messages::duplicate(), short_type_name_c<Self>.data());
      return;
    }
    // The destructor takes the registration back; GCC 12 at -O3 does not see that for an
    // instance that is a local variable (an application in a function) and warns.
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 12
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdangling-pointer"
#endif
    live_ = static_cast<Self*>(this);
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 12
#pragma GCC diagnostic pop
#endif
  }
  single_instance(const single_instance&) noexcept {}  // a copy is not the instance
  single_instance& operator=(const single_instance&) noexcept { return *this; }
  ~single_instance() {
    if (live_ == static_cast<Self*>(this)) live_ = nullptr;
  }

 private:
  // The scratch instance: constructed at its first use, between `enter` and `leave` (members
  // are constructed in their order), so that it does not register; one static with one guard.
  struct scratch_enter {
    scratch_enter() noexcept { ++scratch_depth; }
  };
  struct scratch_leave {
    scratch_leave() noexcept { --scratch_depth; }
  };
  struct scratch_made {
    [[no_unique_address]] scratch_enter enter;
    Self object;
    [[no_unique_address]] scratch_leave leave;
  };
  static Self& scratch() {
    static scratch_made made;
    return made.object;
  }
  static inline Self* live_ = nullptr;
};

}  // namespace iecoop::detail
