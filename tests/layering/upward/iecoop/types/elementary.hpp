// A types/ header that reaches up into runtime/: the layering check must reject it.
#pragma once
#include <iecoop/runtime/task.hpp>
