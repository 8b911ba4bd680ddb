// SPDX-License-Identifier: MIT
// iecoop/detail/lifecycle_state.hpp — what the lifecycle operation under way passes to
// FB_Init and FB_Exit, and whether instances are being relocated (an online change).
// IWYU pragma: private, include <iecoop/pou/lifecycle.hpp>
#pragma once

#include <cstddef>

#include <iecoop/detail/construction.hpp>

namespace iecoop::detail {

struct lifecycle_flags {
  bool init_retains = true;      ///< bInitRetains of FB_Init
  bool in_copy_code = false;     ///< bInCopyCode of FB_Init and FB_Exit
  bool exit_suppressed = false;  ///< destruction of a scratch copy: no FB_Exit
  bool relocating = false;       ///< copying an instance during an online change
  bool init_suppressed = false;  ///< construction of a probe (a layout check): no FB_Init
};

/// The flags of the operation under way. Lifecycle operations are not thread-safe: run them
/// while no task runs.
inline lifecycle_flags current_lifecycle{};

/// Set while instances are constructed with their RETAIN/PERSISTENT values restored at
/// construction (detail::retained_restore_session): TRUE if the variable at [address,
/// address + size) is a remanent variable that got its kept value. run_fb_init leaves such a
/// variable out of the named initial values: a kept value is not initialised again.
inline bool (*kept_at_construction)(const void* address, std::size_t size) noexcept = nullptr;

/// Sets the flags for the duration of a scope. At its end, a derived block constructed in it
/// whose constructor did not run its bases' FB_Init is reported (detail/construction.hpp).
class lifecycle_scope {
 public:
  explicit lifecycle_scope(lifecycle_flags flags) noexcept : saved_(current_lifecycle) { current_lifecycle = flags; }
  ~lifecycle_scope() {
    current_lifecycle = saved_;
    settle_owed(nullptr);
  }
  lifecycle_scope(const lifecycle_scope&) = delete;
  lifecycle_scope& operator=(const lifecycle_scope&) = delete;

 private:
  lifecycle_flags saved_;
};

}  // namespace iecoop::detail
