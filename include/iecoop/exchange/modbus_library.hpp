// SPDX-License-Identifier: MIT
// iecoop/exchange/modbus_library.hpp — libmodbus (Debian: libmodbus-dev), included so that its
// TRUE, FALSE, ON and OFF macros do not leak into the program (they would turn iecoop's TRUE
// into `1`), and owned by RAII handles. For <iecoop/exchange/modbus_server.hpp> and
// <iecoop/exchange/modbus_client.hpp>; link the CMake target iecoop::modbus.
// IWYU pragma: private, include <iecoop/exchange/modbus_server.hpp>
#pragma once

#include <cerrno>
#include <cstdint>
#include <memory>

#pragma push_macro("TRUE")
#pragma push_macro("FALSE")
#pragma push_macro("ON")
#pragma push_macro("OFF")
#include <modbus.h>
#pragma pop_macro("OFF")
#pragma pop_macro("ON")
#pragma pop_macro("FALSE")
#pragma pop_macro("TRUE")

#include <iecoop/config.hpp>
#include <iecoop/types/time.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop::detail {

struct modbus_context_deleter {
  void operator()(modbus_t* context) const noexcept {
    modbus_close(context);
    modbus_free(context);
  }
};
/// A libmodbus context, closed and freed with the handle.
using modbus_context = std::unique_ptr<modbus_t, modbus_context_deleter>;

struct modbus_mapping_deleter {
  void operator()(modbus_mapping_t* mapping) const noexcept { ::modbus_mapping_free(mapping); }
};
/// A libmodbus server's data model.
using modbus_mapping = std::unique_ptr<modbus_mapping_t, modbus_mapping_deleter>;

/// Sets one of libmodbus's timeouts (seconds and microseconds) from an LTIME.
template <class Setter>
void set_modbus_timeout(modbus_t* context, Setter setter, LTIME timeout) noexcept {
  const std::uint64_t us = timeout.count() / 1000u;
  setter(context, static_cast<std::uint32_t>(us / 1000000u), static_cast<std::uint32_t>(us % 1000000u));
}

/// The Modbus exception code libmodbus reports through errno (0 if errno is no exception).
[[nodiscard]] inline std::uint8_t modbus_exception_of(int error) noexcept {
  if (error > MODBUS_ENOBASE && error < MODBUS_ENOBASE + 0x0C) return static_cast<std::uint8_t>(error - MODBUS_ENOBASE);
  return 0;
}

}  // namespace iecoop::detail

#include <iecoop/detail/pop_macros.hpp>
