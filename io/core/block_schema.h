#pragma once

// The text of schemas/block.schema.json, compiled into rs_io_core by CMake
// (configure_file) so validation never depends on finding the source tree.

namespace roofsweep {
extern const char kBlockSchemaJson[];
}
