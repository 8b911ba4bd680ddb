// SPDX-License-Identifier: MIT
// iecoop/detail/construction.hpp — which level of a block hierarchy is the whole object while
// the object is being constructed or destroyed, so that FB_Init and FB_Exit run once, on the
// whole object, as CODESYS runs them (docs/design.md, "FB_Init on the whole object").
//
// C++ constructs `FB_C EXTENDS FB_B EXTENDS FB_A` base first: while FB_A's constructor runs,
// the object is an FB_A, and a virtual call dispatches to FB_A's method. CODESYS runs every
// level's FB_Init on the finished FB_C (FB_A.FB_Init calling Meth_MyInit runs FB_C's
// override: its static analysis rule SA0106 documents the order). So each level's
// constructor calls run_fb_init, and only the most derived level's call runs the FB_Init of
// every level; the others are deferred to it. extends<C, B> tells which is which: it has
// an empty marker before B (constructed before any part of B) and one after it (constructed
// when B is complete), which open and close a frame "B is being constructed as a base part".
// While B's own constructor body runs, the top frame names B; a block constructed inside B
// (a member of B) never has the type of the frame above it (it cannot contain itself), so
// the test is exact. Destruction mirrors it: the most derived destructor runs every level's
// FB_Exit and leaves a record that the base levels' destructors read.
//
// The state is per process, like the fault handler: construct and destroy blocks in one
// thread at a time (a lifecycle operation, as the application's are). Nothing here runs in a
// task cycle; it costs a few instructions per construction of a block that EXTENDS another.
// IWYU pragma: private, include <iecoop/pou/lifecycle.hpp>
#pragma once

#include <cstddef>

#include <iecoop/config.hpp>
#include <iecoop/fault.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop::detail {

/// A block type's identity (the address of a variable that exists once per type).
template <class T>
struct lifecycle_tag {
  static inline char tag = 0;
};
template <class T>
constexpr const void* lifecycle_id() noexcept {
  return &lifecycle_tag<T>::tag;
}

/// How deeply constructions of blocks that EXTENDS others may nest in one another (a base
/// part under construction, whose member is a derived block whose base part is under
/// construction, ...); deeper nesting is a fault. Each level costs 32 bytes of RAM on a
/// 32-bit target (the firmware's budget counts them): define IECOOP_LIFECYCLE_NESTING for
/// the whole build to change it.
#if !defined(IECOOP_LIFECYCLE_NESTING)
#define IECOOP_LIFECYCLE_NESTING 12
#endif
inline constexpr int lifecycle_nesting = IECOOP_LIFECYCLE_NESTING;
static_assert(lifecycle_nesting >= 2, "iecoop: IECOOP_LIFECYCLE_NESTING is at least 2; define it larger");

struct construction_frame {
  const void* base = nullptr;  ///< the level under construction as a base part of a derived block
  const void* root = nullptr;  ///< where the object's bottom level lies (set when it is constructed)
  bool deferred = false;       ///< a run_fb_init of this part (or of a part below it) was deferred
};

/// A derived block whose base levels deferred their FB_Init to its constructor, which has not
/// called run_fb_init yet.
struct owed_fb_init {
  const void* derived = nullptr;
  const void* root = nullptr;
  std::size_t size = 0;
  const char* name = nullptr;  ///< the block's name (short_type_name_c: no RAM of its own)
};

struct lifecycle_tracking {
  construction_frame frames[lifecycle_nesting]{};
  int frame_count = 0;
  owed_fb_init owed[lifecycle_nesting]{};
  int owed_count = 0;
  const void* exit_levels[lifecycle_nesting]{};  ///< the level whose destructor comes next
  int exit_count = 0;
};
/// The tracking state, once a block that EXTENDS another has been constructed (nullptr
/// before: a program without EXTENDS has no frames, and links no RAM for them).
inline lifecycle_tracking* tracking_in_use = nullptr;

/// The tracking state, for extends<>'s markers (only they can open frames and records).
inline lifecycle_tracking& extends_tracking() noexcept {
  static constinit lifecycle_tracking storage{};
  tracking_in_use = &storage;
  return storage;
}

/// Reports fault_kind::lifecycle about the block `name`: the fault's text is `message` (a
/// constant), its pou the block's name, so that a report costs no RAM for a composed text.
inline void lifecycle_fault(const char* message, const char* name) {
  report_about(fault_kind::lifecycle, message, name);
}

inline void report_owed(const owed_fb_init& owed) {
  lifecycle_fault(
      "a block's constructor does not call run_fb_init(*this, ...) (an inherited constructor, `using "
      "extends::extends;`, cannot): the FB_Init of the blocks it EXTENDS did not run, as iecoop runs "
      "them on the whole block only from the most derived one; give the block (the fault's pou) a "
      "constructor that calls run_fb_init(*this, <FB_Init parameters>)",
      owed.name);
}

/// Reports (and forgets) the derived blocks whose constructors ended without running their
/// bases' deferred FB_Init, as far as `at` shows: all of them for nullptr (the end of a
/// lifecycle operation), else those `at` does not lie in (a member of a block under
/// construction lies in it).
inline void settle_owed(const void* at) {
  if (tracking_in_use == nullptr) return;
  lifecycle_tracking& tracking = *tracking_in_use;
  while (tracking.owed_count > 0) {
    const owed_fb_init& top = tracking.owed[tracking.owed_count - 1];
    if (at != nullptr && top.root != nullptr) {
      const auto* begin = static_cast<const char*>(top.root);
      const auto* here = static_cast<const char*>(at);
      if (here >= begin && here < begin + top.size) return;
    } else if (at != nullptr) {
      return;  // where the block lies is unknown (a copy): it is reported at the operation's end
    }
    const owed_fb_init forgotten = top;
    --tracking.owed_count;
    report_owed(forgotten);
  }
}

inline bool nesting_overflow() {
  fault(fault_kind::lifecycle,
        "blocks that EXTENDS others are nested deeper than IECOOP_LIFECYCLE_NESTING (12 unless defined) while being "
        "constructed or destroyed; FB_Init and FB_Exit may not run on the whole block: define it larger for the "
        "whole build");
  return true;
}

/// extends<Derived, Base>'s first base is constructed (at `where`): Base's construction as a
/// part of a Derived begins.
inline void begin_base_construction(const void* base, const void* where) noexcept {
  lifecycle_tracking& tracking = extends_tracking();
  if (tracking.frame_count == lifecycle_nesting) {
    (void)nesting_overflow();
    return;
  }
  settle_owed(where);
  tracking.frames[tracking.frame_count++] = construction_frame{base, nullptr, false};
}

/// The bottom level of a block (function_block<Self>'s first base) is being constructed at
/// `root`: the frames opened for this object learn where it lies.
inline void root_constructed(const void* root) noexcept {
  if (tracking_in_use == nullptr) return;
  lifecycle_tracking& tracking = *tracking_in_use;
  for (int i = tracking.frame_count - 1; i >= 0 && tracking.frames[i].root == nullptr; --i) {
    tracking.frames[i].root = root;
  }
}

/// Whether the block of type B whose constructor calls run_fb_init is only a base part of the
/// object under construction (its FB_Init then waits for the most derived level's call).
template <class B>
bool fb_init_deferred() noexcept {
  if (tracking_in_use == nullptr || tracking_in_use->frame_count == 0) return false;
  lifecycle_tracking& tracking = *tracking_in_use;
  construction_frame& top = tracking.frames[tracking.frame_count - 1];
  if (top.base != lifecycle_id<B>()) return false;
  top.deferred = true;
  return true;
}

/// extends<Derived, Base>'s last base is constructed: Base is complete. If Derived is itself a
/// base part of a block under construction, what Base deferred waits for that one; otherwise
/// Derived is the whole object, whose constructor owes the deferred FB_Init.
inline void end_base_construction(const void* derived, const void* base, std::size_t size, const char* name) noexcept {
  lifecycle_tracking& tracking = extends_tracking();
  if (tracking.frame_count == 0 || tracking.frames[tracking.frame_count - 1].base != base) return;
  const construction_frame done = tracking.frames[--tracking.frame_count];
  if (!done.deferred) return;
  if (tracking.frame_count > 0 && tracking.frames[tracking.frame_count - 1].base == derived) {
    tracking.frames[tracking.frame_count - 1].deferred = true;
    return;
  }
  if (tracking.owed_count == lifecycle_nesting) {
    (void)nesting_overflow();
    return;
  }
  tracking.owed[tracking.owed_count++] = owed_fb_init{derived, done.root, size, name};
}

/// The most derived level B runs the FB_Init of every level: it takes its own owed entry (and
/// reports forgotten ones above it).
template <class B>
void fb_init_runs(const void* root) {
  settle_owed(root);
  if (tracking_in_use == nullptr) return;
  lifecycle_tracking& tracking = *tracking_in_use;
  if (tracking.owed_count > 0 && tracking.owed[tracking.owed_count - 1].derived == lifecycle_id<B>()) {
    --tracking.owed_count;
  }
}

/// Whether the FB_Exit of level B already ran, from the destructor of a block derived from it.
template <class B>
bool fb_exit_ran_for() noexcept {
  if (tracking_in_use == nullptr) return false;
  const lifecycle_tracking& tracking = *tracking_in_use;
  return tracking.exit_count > 0 && tracking.exit_levels[tracking.exit_count - 1] == lifecycle_id<B>();
}

/// The most derived level B runs the FB_Exit of every level: the base levels' destructors
/// will find the record.
template <class B>
void fb_exit_runs() {
  lifecycle_tracking& tracking = extends_tracking();
  if (tracking.exit_count == lifecycle_nesting) {
    (void)nesting_overflow();
    return;
  }
  tracking.exit_levels[tracking.exit_count++] = lifecycle_id<B>();
}

/// extends<Derived, Base>'s last base is destroyed: if Derived's destructor ran the FB_Exit
/// chain, the record moves on to Base (whose destructor is next). FALSE if there is no record.
inline bool fb_exit_level_done(const void* derived, const void* base) noexcept {
  lifecycle_tracking& tracking = extends_tracking();
  if (tracking.exit_count == 0 || tracking.exit_levels[tracking.exit_count - 1] != derived) return false;
  tracking.exit_levels[tracking.exit_count - 1] = base;
  return true;
}

/// extends<Derived, Base>'s first base is destroyed: Base is gone; the record ends if Base was
/// the bottom level.
inline void end_fb_exit_record(const void* base) noexcept {
  lifecycle_tracking& tracking = extends_tracking();
  if (tracking.exit_count > 0 && tracking.exit_levels[tracking.exit_count - 1] == base) --tracking.exit_count;
}

}  // namespace iecoop::detail

#include <iecoop/detail/pop_macros.hpp>
