// Precompiled into every GoogleTest program (ROOFSWEEP_PCH).
#pragma once

#include "common.h"

#include <gtest/gtest.h>
