// Shared machinery that builds on types/: it belongs in types/detail/, the check must say so.
#pragma once
#include <iecoop/types/elementary.hpp>
