// Shared machinery that builds on the runtime: the layering check must reject it.
#pragma once
#include <iecoop/runtime/task.hpp>
