#pragma once
// Internal to geometry/src: what the GDAL readers (area_gdal.cpp, area_formats.cpp, area_wkt.cpp)
// and the writer (gpkg_writer.cpp) share.
#include <mutex>
#include <string>
#include <vector>

#include <cpl_error.h>
#include <gdal_priv.h>
#include <ogr_geometry.h>

#include "area_internal.hpp"

namespace wattswath::geometry::detail {

/// Keeps GDAL's own messages off stderr while a reader or writer runs (library code never prints):
/// they are collected here (the first kKept of them) and quoted in our errors by gdalSays(). GDAL's
/// handler stack is thread-local, so this is safe with other threads; scopes nest.
class QuietGdal {
 public:
  QuietGdal() : outer_(current()) {
    static std::once_flag once;
    std::call_once(once, [] { GDALAllRegister(); });
    CPLPushErrorHandlerEx(&QuietGdal::collect, this);
    current() = this;
    CPLErrorReset();
  }
  ~QuietGdal() {
    CPLPopErrorHandler();
    current() = outer_;
  }
  QuietGdal(const QuietGdal&) = delete;
  QuietGdal& operator=(const QuietGdal&) = delete;

  /// The innermost live scope of this thread, or null.
  static QuietGdal*& current() {
    thread_local QuietGdal* c = nullptr;
    return c;
  }
  /// Warnings and errors GDAL reported in this scope (at most kKept, each once).
  const std::vector<std::string>& messages() const { return messages_; }
  /// True when GDAL reported an error (not only warnings) in this scope since the last clear().
  bool failed() const { return failed_; }
  /// Forgets the messages collected so far (before a step whose messages are quoted alone).
  void clear() {
    messages_.clear();
    failed_ = false;
    CPLErrorReset();
  }

 private:
  static constexpr size_t kKept = 4;
  static void CPL_STDCALL collect(CPLErr cls, CPLErrorNum, const char* msg) {
    auto* self = static_cast<QuietGdal*>(CPLGetErrorHandlerUserData());
    if (!self || cls < CE_Warning) return;
    if (cls >= CE_Failure) self->failed_ = true;
    if (!msg || !*msg || self->messages_.size() >= kKept) return;
    std::string m = msg;
    // Our in-memory file names (parseWithGdal) mean nothing to a user: the message is prefixed by the file's own.
    for (size_t at; (at = m.find("/vsimem/wattswath_area_")) != std::string::npos;) {
      const size_t slash = m.find('/', at + 23);
      m.erase(at, slash == std::string::npos ? std::string::npos : slash + 1 - at);
    }
    for (const auto& kept : self->messages_) {
      if (kept == m) return;
    }
    self->messages_.push_back(m);
  }
  QuietGdal* outer_;
  std::vector<std::string> messages_;
  bool failed_ = false;
};

/// " (GDAL: <its messages in this scope, '; '-separated>)", or "" when GDAL said nothing.
inline std::string gdalSays() {
  const QuietGdal* q = QuietGdal::current();
  std::string all;
  if (q) {
    for (const auto& m : q->messages()) all += (all.empty() ? "" : "; ") + m;
  }
  if (all.empty()) {  // a message recorded before the scope began, or outside any scope
    const char* m = CPLGetLastErrorMsg();
    if (m && *m) all = m;
  }
  return all.empty() ? std::string() : " (GDAL: " + all + ")";
}

/// Vertices over all features beyond which a file is refused (before validation's CGAL work).
inline constexpr size_t kMaxVertices = 1000000;

/// Where an OGR geometry's polygons go, and how they are named.
struct OgrTarget {
  const std::string& source;  ///< file name for messages
  std::string role;           ///< the feature's role (or name when it has no role): no-fly, home
  bool strict;                ///< lines and points other than home are errors (GeoJSON, WKT), not rings / notes
  RawArea& out;               ///< what is read
  size_t& vertices;           ///< vertices read so far in the file (bounded by kMaxVertices)
  bool open_lines_are_paths = false;  ///< KML: a line whose ends do not meet is a drawn path, not an outline
};

/// Adds `g` (lon/lat or metres) to t.out under `name`: polygons (to no_fly when the role says so),
/// collections, curves (linearised), lines as rings (not strict), the home point; throws naming
/// `name` for anything else.
void addOgrGeometry(const OGRGeometry& g, const std::string& name, OgrTarget& t);

}  // namespace wattswath::geometry::detail
