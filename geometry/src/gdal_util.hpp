#pragma once
// Internal to geometry/src: what the GDAL reader (area_gdal.cpp) and writer (gpkg_writer.cpp) share.
#include <mutex>
#include <string>

#include <cpl_error.h>
#include <gdal_priv.h>

namespace wattswath::geometry::detail {

/// Keeps GDAL's own messages off stderr while this reader runs (library code never prints); the
/// last one is quoted in our errors instead. Thread-local in GDAL, so safe with other threads.
struct QuietGdal {
  QuietGdal() {
    static std::once_flag once;
    std::call_once(once, [] { GDALAllRegister(); });
    CPLPushErrorHandler(CPLQuietErrorHandler);
    CPLErrorReset();
  }
  ~QuietGdal() { CPLPopErrorHandler(); }
  QuietGdal(const QuietGdal&) = delete;
  QuietGdal& operator=(const QuietGdal&) = delete;
};

/// " (GDAL: <its last message>)", or "" when GDAL said nothing.
inline std::string gdalSays() {
  const char* m = CPLGetLastErrorMsg();
  return (m && *m) ? std::string(" (GDAL: ") + m + ")" : std::string();
}

}  // namespace wattswath::geometry::detail
