// The fuzz targets compile the filters' sources into their own binaries: no export macros needed.
#pragma once
#define MEDIALFILTERS_EXPORT
