// SPDX-License-Identifier: MIT
// iecoop/exchange/mqtt_library.hpp — libmosquitto (Debian: libmosquitto-dev), included so that no
// macro of it can leak into the program, owned by an RAII handle, and initialised once. For
// <iecoop/exchange/mqtt.hpp>; link the CMake target iecoop::mqtt.
//
// libmosquitto 2.0's <mosquitto.h> defines no macro that collides with an IEC name (it defines
// bool, true and false only for old MSVC compiling C); it is included between push_macro and
// pop_macro of the names that <windows.h> and friends define all the same, so that neither a
// user's macro changes it nor a later version's leaks out.
// IWYU pragma: private, include <iecoop/exchange/mqtt.hpp>
#pragma once

#include <memory>

#pragma push_macro("TRUE")
#pragma push_macro("FALSE")
#pragma push_macro("IN")
#pragma push_macro("OUT")
#pragma push_macro("ON")
#pragma push_macro("OFF")
#include <mosquitto.h>
#pragma pop_macro("OFF")
#pragma pop_macro("ON")
#pragma pop_macro("OUT")
#pragma pop_macro("IN")
#pragma pop_macro("FALSE")
#pragma pop_macro("TRUE")

#include <iecoop/config.hpp>

#include <iecoop/detail/push_macros.hpp>

namespace iecoop::detail {

/// mosquitto_lib_init(), once per program (thread-safe: a function-local static); the result
/// of the one call (MOSQ_ERR_SUCCESS).
inline int mosquitto_library() noexcept {
  static const int result = ::mosquitto_lib_init();
  return result;
}

struct mosquitto_deleter {
  void operator()(struct mosquitto* client) const noexcept { ::mosquitto_destroy(client); }
};
/// A libmosquitto client, destroyed with the handle.
using mosquitto_handle = std::unique_ptr<struct mosquitto, mosquitto_deleter>;

}  // namespace iecoop::detail

#include <iecoop/detail/pop_macros.hpp>
