// SPDX-License-Identifier: MIT
// iecoop/config.hpp — language requirements and the library's version.
#pragma once

#if defined(_MSVC_LANG)
#define IECOOP_CPLUSPLUS _MSVC_LANG
#else
#define IECOOP_CPLUSPLUS __cplusplus
#endif
#if IECOOP_CPLUSPLUS < 202002L
#error "iecoop: requires C++20; compile with -std=c++20 (or link the CMake target iecoop::iecoop, which requests it)"
#endif

#define IECOOP_VERSION_MAJOR 0
#define IECOOP_VERSION_MINOR 2
#define IECOOP_VERSION_PATCH 0
/// The version as one number: major * 10000 + minor * 100 + patch.
#define IECOOP_VERSION (IECOOP_VERSION_MAJOR * 10000 + IECOOP_VERSION_MINOR * 100 + IECOOP_VERSION_PATCH)
