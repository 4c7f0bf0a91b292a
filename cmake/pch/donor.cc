// The one source of the precompiled-header donor targets
// (cmake/RoofsweepHelpers.cmake, roofsweep_pch_donors): a target needs a
// source for its precompiled header to be built.
