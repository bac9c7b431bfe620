#pragma once

#define SPT_VERSION_MAJOR 0
#define SPT_VERSION_MINOR 1
#define SPT_VERSION_PATCH 0
// The newest .spt format version this library reads and writes.
#define SPT_FORMAT_MAJOR 1
#define SPT_FORMAT_MINOR 5

namespace spt {
const char* library_version();
}
