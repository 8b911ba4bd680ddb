# The data exchange's targets (docs/exchange.md), each where its library is found with pkg-config:
#   iecoop::modbus  iecoop and libmodbus (Debian: libmodbus-dev): <iecoop/exchange/modbus_server.hpp>,
#                   <iecoop/exchange/modbus_client.hpp>
#   iecoop::mqtt    iecoop and libmosquitto (Debian: libmosquitto-dev): <iecoop/exchange/mqtt.hpp>
# Both also link the threads library: each runs its network side in threads of its own. The
# rest of iecoop needs neither library. Included by iecoop's CMakeLists.txt and by the installed
# package's iecoopConfig.cmake (where `_iecoop_exchange_base` is iecoop::iecoop).
if(NOT DEFINED _iecoop_exchange_base)
  set(_iecoop_exchange_base iecoop)
endif()
find_package(PkgConfig QUIET)
find_package(Threads QUIET)
if(PKG_CONFIG_FOUND AND Threads_FOUND)
  if(NOT TARGET iecoop::modbus)
    pkg_check_modules(IECOOP_LIBMODBUS QUIET IMPORTED_TARGET libmodbus)
    if(TARGET PkgConfig::IECOOP_LIBMODBUS)
      add_library(iecoop_modbus INTERFACE IMPORTED GLOBAL)
      add_library(iecoop::modbus ALIAS iecoop_modbus)
      target_link_libraries(iecoop_modbus INTERFACE ${_iecoop_exchange_base} PkgConfig::IECOOP_LIBMODBUS Threads::Threads)
    endif()
  endif()
  if(NOT TARGET iecoop::mqtt)
    pkg_check_modules(IECOOP_LIBMOSQUITTO QUIET IMPORTED_TARGET libmosquitto)
    if(TARGET PkgConfig::IECOOP_LIBMOSQUITTO)
      add_library(iecoop_mqtt INTERFACE IMPORTED GLOBAL)
      add_library(iecoop::mqtt ALIAS iecoop_mqtt)
      target_link_libraries(iecoop_mqtt INTERFACE ${_iecoop_exchange_base} PkgConfig::IECOOP_LIBMOSQUITTO Threads::Threads)
    endif()
  endif()
endif()
