// Precompiled into every GoogleTest program (ROOFSWEEP_PCH).
#pragma once

#include <gtest/gtest.h>

#include "common.h"
