// SPDX-License-Identifier: MIT
// iecoop/iecoop.hpp — everything iecoop offers, in one include. (The optional integrations
// <iecoop/fmt.hpp> and <iecoop/ostream.hpp> are not included: they pull in fmt and
// <ostream>, which the core never needs; nor is the POSIX real-time runner
// <iecoop/realtime.hpp>.)
#pragma once

// IWYU pragma: begin_exports
#include <iecoop/access.hpp>
#include <iecoop/address.hpp>
#include <iecoop/application.hpp>
#include <iecoop/bistables.hpp>
#include <iecoop/config.hpp>
#include <iecoop/conversions.hpp>
#include <iecoop/convert.hpp>
#include <iecoop/counters.hpp>
#include <iecoop/cycle_clock.hpp>
#include <iecoop/dialect.hpp>
#include <iecoop/edges.hpp>
#include <iecoop/extends.hpp>
#include <iecoop/fault.hpp>
#include <iecoop/file_storage.hpp>
#include <iecoop/function_block.hpp>
#include <iecoop/global_variables.hpp>
#include <iecoop/interface.hpp>
#include <iecoop/io.hpp>
#include <iecoop/lifecycle.hpp>
#include <iecoop/literals.hpp>
#include <iecoop/method.hpp>
#include <iecoop/named.hpp>
#include <iecoop/pins.hpp>
#include <iecoop/process_image.hpp>
#include <iecoop/program.hpp>
#include <iecoop/property.hpp>
#include <iecoop/reflect.hpp>
#include <iecoop/retain.hpp>
#include <iecoop/string.hpp>
#include <iecoop/string_functions.hpp>
#include <iecoop/task.hpp>
#include <iecoop/text.hpp>
#include <iecoop/time.hpp>
#include <iecoop/timers.hpp>
#include <iecoop/types.hpp>
#include <iecoop/var.hpp>
// IWYU pragma: end_exports
