// GeoJSON FeatureCollections written as the layers of one GeoPackage through GDAL (plan --gpkg).
#include <atomic>
#include <cstdio>
#include <stdexcept>
#include <unistd.h>

#include <cpl_vsi.h>
#include <ogrsf_frmts.h>

#include "gdal_util.hpp"
#include "wattswath/geometry/geojson.hpp"

namespace wattswath::geometry {
namespace {

/// Copies the one layer of GeoJSON `text` into `out` as layer `name`.
void copyGeoJsonLayer(GDALDataset& out, const std::string& name, const std::string& text, const std::string& path) {
  static std::atomic<unsigned> counter{0};
  const std::string mem = "/vsimem/wattswath_gpkg_" + std::to_string(counter++) + ".geojson";
  VSILFILE* f = VSIFileFromMemBuffer(mem.c_str(), reinterpret_cast<GByte*>(const_cast<char*>(text.data())),
                                     static_cast<vsi_l_offset>(text.size()), FALSE);
  if (!f) throw std::runtime_error(path + ": layer \"" + name + "\": cannot make an in-memory file" + detail::gdalSays());
  VSIFCloseL(f);
  struct Unlink {
    const std::string& n;
    ~Unlink() { VSIUnlink(n.c_str()); }
  } unlink{mem};
  GDALDatasetUniquePtr in(GDALDataset::Open(mem.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
  if (!in || in->GetLayerCount() != 1) {
    throw std::runtime_error(path + ": layer \"" + name + "\": not one GeoJSON FeatureCollection" + detail::gdalSays());
  }
  if (!out.CopyLayer(in->GetLayer(0), name.c_str(), nullptr)) {
    throw std::runtime_error(path + ": layer \"" + name + "\": GDAL could not write it" + detail::gdalSays());
  }
}

}  // namespace

void writeGeoPackage(const std::string& path, const std::vector<std::pair<std::string, std::string>>& layers) {
  detail::QuietGdal quiet;
  GDALDriver* gpkg = GetGDALDriverManager()->GetDriverByName("GPKG");
  if (!gpkg) throw std::runtime_error(path + ": this GDAL has no GeoPackage driver");
  const std::string tmp = path + ".tmp." + std::to_string(::getpid());
  std::remove(tmp.c_str());
  try {
    GDALDatasetUniquePtr out(gpkg->Create(tmp.c_str(), 0, 0, 0, GDT_Unknown, nullptr));
    if (!out) throw std::runtime_error(path + ": cannot create the GeoPackage" + detail::gdalSays());
    for (const auto& [name, text] : layers) copyGeoJsonLayer(*out, name, text, path);
    CPLErrorReset();
    GDALClose(GDALDataset::ToHandle(out.release()));  // writes what is left (GDAL 3.6 has no Close())
    if (CPLGetLastErrorType() >= CE_Failure) throw std::runtime_error(path + ": cannot finish the GeoPackage" + detail::gdalSays());
  } catch (...) {
    std::remove(tmp.c_str());
    throw;
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw std::runtime_error(path + ": cannot rename the finished GeoPackage into place");
  }
}

}  // namespace wattswath::geometry
