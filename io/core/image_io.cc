#include "io/core/image_io.h"

#include <cpl_conv.h>
#include <gdal_priv.h>
#include <ogr_spatialref.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <memory>
#include <vector>

#include "algorithms/core/error.h"
#include "algorithms/core/format.h"
#include "io/core/gdal_util.h"

namespace fs = std::filesystem;

namespace roofsweep {
namespace {

struct DatasetCloser {
  void operator()(GDALDataset* ds) const { GDALClose(GDALDataset::ToHandle(ds)); }
};
using DatasetPtr = std::unique_ptr<GDALDataset, DatasetCloser>;

// Smallest image roofsweep accepts; a 1-pixel row or column has no
// gradients, and such files are almost always placeholders or icons.
constexpr int kMinImageSide = 2;

DatasetPtr OpenRaster(const std::string& path, gdal::ErrorCapture& errors) {
  gdal::EnsureRegistered();
  std::error_code ec;
  if (!fs::exists(path, ec)) throw Error(path + ": no such file");
  if (fs::is_directory(path, ec)) throw Error(path + ": is a folder, not an image");
  DatasetPtr ds(GDALDataset::FromHandle(
      GDALOpenEx(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr)));
  if (!ds) {
    throw Error(path + ": not a readable image (" +
                errors.Message("GDAL does not recognise the format") + ")");
  }
  return ds;
}

int BitsOf(GDALRasterBand* band) {
  const char* nbits = band->GetMetadataItem("NBITS", "IMAGE_STRUCTURE");
  if (nbits) {
    const int n = std::atoi(nbits);
    if (n > 0 && n <= 32) return n;
  }
  return GDALGetDataTypeSizeBits(band->GetRasterDataType());
}

ImageInfo InfoOf(const std::string& path, GDALDataset* ds) {
  ImageInfo info;
  info.width = ds->GetRasterXSize();
  info.height = ds->GetRasterYSize();
  info.bands = ds->GetRasterCount();
  if (info.bands < 1) throw Error(path + ": the file has no raster bands");
  if (info.width < kMinImageSide || info.height < kMinImageSide) {
    throw Error(path + ": image is " + std::to_string(info.width) + "x" +
                std::to_string(info.height) + " pixels; roofsweep needs at least " +
                std::to_string(kMinImageSide) + "x" + std::to_string(kMinImageSide));
  }
  GDALRasterBand* band = ds->GetRasterBand(1);
  info.data_type = GDALGetDataTypeName(band->GetRasterDataType());
  info.bits = BitsOf(band);
  info.driver = ds->GetDriver() ? ds->GetDriver()->GetDescription() : "";
  return info;
}

// Value that maps to 1.0 for an integer sample type; 0 for floating types,
// which are taken as they are.
double FullScale(GDALRasterBand* band) {
  const GDALDataType t = band->GetRasterDataType();
  if (GDALDataTypeIsFloating(t) || GDALDataTypeIsComplex(t)) return 0.0;
  const int bits = BitsOf(band);
  const bool is_signed = GDALDataTypeIsSigned(t);
  const int value_bits = is_signed ? std::min(bits, GDALGetDataTypeSizeBits(t)) - 1 : bits;
  return std::ldexp(1.0, value_bits) - 1.0;
}

[[noreturn]] void ThrowReadError(const std::string& path, const gdal::ErrorCapture& errors) {
  throw Error(path + ": corrupt or truncated image data (" +
              errors.Message("GDAL could not read the pixels") + ")");
}

cv::Mat ReadPalette(const std::string& path, GDALRasterBand* band, const cv::Rect& window,
                    const gdal::ErrorCapture& errors) {
  const GDALColorTable* table = band->GetColorTable();
  const GDALPaletteInterp interp = table->GetPaletteInterpretation();
  if (interp != GPI_RGB && interp != GPI_Gray) {
    throw Error(path + ": palette type " + GDALGetPaletteInterpretationName(interp) +
                " is not supported (only RGB and grey palettes)");
  }
  const int w = window.width;
  const int h = window.height;
  cv::Mat index(h, w, CV_32SC1);
  if (band->RasterIO(GF_Read, window.x, window.y, w, h, index.data, w, h, GDT_Int32, 0, 0) !=
          CE_None ||
      errors.HasFailure()) {
    ThrowReadError(path, errors);
  }
  const int entries = table->GetColorEntryCount();
  const int channels = interp == GPI_RGB ? 3 : 1;
  cv::Mat out(h, w, channels == 3 ? CV_32FC3 : CV_32FC1);
  for (int r = 0; r < h; ++r) {
    const int32_t* src = index.ptr<int32_t>(r);
    float* dst = out.ptr<float>(r);
    for (int c = 0; c < w; ++c) {
      GDALColorEntry e{0, 0, 0, 255};
      if (src[c] >= 0 && src[c] < entries) e = *table->GetColorEntry(src[c]);
      if (channels == 3) {
        dst[3 * c + 0] = static_cast<float>(e.c1 / 255.0);
        dst[3 * c + 1] = static_cast<float>(e.c2 / 255.0);
        dst[3 * c + 2] = static_cast<float>(e.c3 / 255.0);
      } else {
        dst[c] = static_cast<float>(e.c1 / 255.0);
      }
    }
  }
  return out;
}

std::string LowerExtension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// A name in the target's folder that no concurrent writer picks.
std::string TemporaryName(const std::string& path) {
  static std::atomic<unsigned> counter{0};
  const fs::path p(path);
  return (p.parent_path() /
          ("." + p.filename().string() + ".tmp" + std::to_string(static_cast<long>(::getpid())) +
           "_" + std::to_string(counter++)))
      .string();
}

void RemoveQuietly(const std::string& path) {
  std::error_code ec;
  fs::remove(path, ec);
  fs::remove(path + ".aux.xml", ec);
}

}  // namespace

ImageInfo ProbeImage(const std::string& path) {
  gdal::ErrorCapture errors;
  DatasetPtr ds = OpenRaster(path, errors);
  return InfoOf(path, ds.get());
}

void CheckImageReadable(const std::string& path) {
  gdal::ErrorCapture errors;
  gdal::ScopedThreadConfig strict_jpeg("GDAL_ERROR_ON_LIBJPEG_WARNING", "TRUE");
  DatasetPtr ds = OpenRaster(path, errors);
  const ImageInfo info = InfoOf(path, ds.get());
  // Truncation, the usual corruption, shows in the last block of the file;
  // reading just that block keeps checking a large block cheap (JPEG still
  // decodes up to it).
  for (int b = 1; b <= std::min(info.bands, 3); ++b) {
    GDALRasterBand* band = ds->GetRasterBand(b);
    int bx = 0, by = 0;
    band->GetBlockSize(&bx, &by);
    const int x0 = std::max(0, info.width - bx), y0 = std::max(0, info.height - by);
    const int w = info.width - x0, h = info.height - y0;
    std::vector<float> buf(static_cast<size_t>(w) * h);
    const CPLErr err =
        band->RasterIO(GF_Read, x0, y0, w, h, buf.data(), w, h, GDT_Float32, 0, 0, nullptr);
    if (err != CE_None || errors.HasFailure()) ThrowReadError(path, errors);
  }
}

cv::Mat ReadImage(const std::string& path) { return ReadImage(path, cv::Rect()); }

cv::Mat ReadImage(const std::string& path, const cv::Rect& requested) {
  gdal::ErrorCapture errors;
  // libjpeg reports a truncated stream as a warning and GDAL then returns
  // grey pixels with CE_None; roofsweep must not measure on invented data.
  gdal::ScopedThreadConfig strict_jpeg("GDAL_ERROR_ON_LIBJPEG_WARNING", "TRUE");
  DatasetPtr ds = OpenRaster(path, errors);
  const ImageInfo info = InfoOf(path, ds.get());
  const cv::Rect full(0, 0, info.width, info.height);
  const cv::Rect window = requested.empty() ? full : requested;
  if ((window & full) != window)
    throw Error(path + StrFormat(": window %dx%d at (%d, %d) lies outside the %dx%d image",
                                 window.width, window.height, window.x, window.y, info.width,
                                 info.height));
  GDALRasterBand* first = ds->GetRasterBand(1);
  if (first->GetColorInterpretation() == GCI_PaletteIndex && first->GetColorTable()) {
    return ReadPalette(path, first, window, errors);
  }

  const int channels = info.bands >= 3 ? 3 : 1;
  cv::Mat out(window.height, window.width, channels == 3 ? CV_32FC3 : CV_32FC1);
  int band_map[3] = {1, 2, 3};
  const GSpacing pixel = static_cast<GSpacing>(sizeof(float)) * channels;
  const CPLErr err = ds->RasterIO(GF_Read, window.x, window.y, window.width, window.height,
                                  out.data, window.width, window.height, GDT_Float32, channels,
                                  band_map, pixel, static_cast<GSpacing>(out.step[0]),
                                  static_cast<GSpacing>(sizeof(float)), nullptr);
  if (err != CE_None || errors.HasFailure()) ThrowReadError(path, errors);

  const double full_scale = FullScale(first);
  if (full_scale > 0) {
    // Clamp too: NBITS may understate what a sloppy writer stored.
    out.convertTo(out, out.type(), 1.0 / full_scale);
    cv::min(cv::max(out, 0.0), 1.0, out);
  }
  return out;
}

void WriteImage(const std::string& path, const cv::Mat& rgb8, int jpeg_quality) {
  gdal::EnsureRegistered();
  const std::string ext = LowerExtension(path);
  std::string driver_name;
  std::vector<std::string> options;
  if (ext == ".tif" || ext == ".tiff") {
    driver_name = "GTiff";
    options = {"TILED=YES", "COMPRESS=DEFLATE"};
  } else if (ext == ".jpg" || ext == ".jpeg") {
    driver_name = "JPEG";
    if (jpeg_quality < 1 || jpeg_quality > 100) {
      throw Error(path + ": JPEG quality must be 1..100, got " + std::to_string(jpeg_quality));
    }
    options = {"QUALITY=" + std::to_string(jpeg_quality)};
  } else if (ext == ".png") {
    driver_name = "PNG";
  } else {
    throw Error(path + ": unknown image extension '" + ext + "' (use .tif, .jpg or .png)");
  }
  const int depth = rgb8.depth();
  const int channels = rgb8.channels();
  if (rgb8.empty() || (channels != 1 && channels != 3) ||
      (depth != CV_8U && !(depth == CV_16U && driver_name != "JPEG"))) {
    throw Error(path + ": can only write 8-bit (or, for .tif/.png, 16-bit) grey or RGB images");
  }
  if (channels == 3 && driver_name == "GTiff") options.push_back("PHOTOMETRIC=RGB");

  const GDALDataType type = depth == CV_8U ? GDT_Byte : GDT_UInt16;
  GDALDriver* mem_driver = GetGDALDriverManager()->GetDriverByName("MEM");
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName(driver_name.c_str());
  if (!mem_driver || !driver) throw Error(path + ": GDAL driver " + driver_name + " missing");

  gdal::ErrorCapture errors;
  // Without PAM the PNG and JPEG drivers keep nothing in .aux.xml sidecars,
  // which would otherwise be left behind under the temporary name.
  gdal::ScopedThreadConfig no_pam("GDAL_PAM_ENABLED", "NO");
  const cv::Mat src = rgb8.isContinuous() ? rgb8 : rgb8.clone();
  DatasetPtr mem(mem_driver->Create("", src.cols, src.rows, channels, type, nullptr));
  if (!mem) throw Error(path + ": " + errors.Message("cannot create an in-memory raster"));
  int band_map[3] = {1, 2, 3};
  const GSpacing elem = static_cast<GSpacing>(src.elemSize1());
  if (mem->RasterIO(GF_Write, 0, 0, src.cols, src.rows, const_cast<uchar*>(src.data), src.cols,
                    src.rows, type, channels, band_map, elem * channels,
                    static_cast<GSpacing>(src.step[0]), elem, nullptr) != CE_None) {
    throw Error(path + ": " + errors.Message("cannot fill the in-memory raster"));
  }
  if (channels == 3) {
    for (int b = 0; b < 3; ++b) {
      mem->GetRasterBand(b + 1)->SetColorInterpretation(
          static_cast<GDALColorInterp>(GCI_RedBand + b));
    }
  }

  std::vector<const char*> opts;
  for (const std::string& o : options) opts.push_back(o.c_str());
  opts.push_back(nullptr);
  const std::string tmp = TemporaryName(path);
  DatasetPtr out(driver->CreateCopy(tmp.c_str(), mem.get(), FALSE, const_cast<char**>(opts.data()),
                                    nullptr, nullptr));
  bool ok = out != nullptr && !errors.HasFailure();
  if (out) {
    // Closing flushes; a full disk shows up as a captured error.
    GDALClose(GDALDataset::ToHandle(out.release()));
  }
  if (!ok || errors.HasFailure()) {
    RemoveQuietly(tmp);
    throw Error(path + ": cannot write image (" + errors.Message("GDAL failed") + ")");
  }
  std::error_code ec;
  fs::remove(tmp + ".aux.xml", ec);
  fs::rename(tmp, path, ec);
  if (ec) {
    RemoveQuietly(tmp);
    throw Error(path + ": cannot rename the written image into place (" + ec.message() + ")");
  }
}

void WriteHeightRaster(const std::string& path, const cv::Mat& heights,
                       const std::array<double, 6>& geotransform, const std::string& crs) {
  gdal::EnsureRegistered();
  if (heights.empty() || heights.type() != CV_32FC1)
    throw Error(path + ": a height raster must be one band of 32-bit floats");
  gdal::ErrorCapture errors;
  std::string wkt;
  if (!crs.empty()) {
    OGRSpatialReference srs;
    char* text = nullptr;
    if (srs.SetFromUserInput(crs.c_str()) != OGRERR_NONE || srs.exportToWkt(&text) != OGRERR_NONE) {
      CPLFree(text);
      throw Error(path + ": unknown CRS '" + crs + "'");
    }
    wkt = text;
    CPLFree(text);
  }
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("GTiff");
  if (!driver) throw Error(path + ": GDAL driver GTiff missing");
  const char* options[] = {"COMPRESS=DEFLATE", "PREDICTOR=3", nullptr};
  const std::string tmp = TemporaryName(path);
  DatasetPtr out(driver->Create(tmp.c_str(), heights.cols, heights.rows, 1, GDT_Float32,
                                const_cast<char**>(options)));
  bool ok = out != nullptr;
  if (ok) {
    double gt[6];
    std::copy(geotransform.begin(), geotransform.end(), gt);
    const cv::Mat src = heights.isContinuous() ? heights : heights.clone();
    ok = out->SetGeoTransform(gt) == CE_None &&
         (wkt.empty() || out->SetProjection(wkt.c_str()) == CE_None) &&
         out->GetRasterBand(1)->RasterIO(GF_Write, 0, 0, src.cols, src.rows,
                                         const_cast<uchar*>(src.data), src.cols, src.rows,
                                         GDT_Float32, 0, 0, nullptr) == CE_None;
    GDALClose(GDALDataset::ToHandle(out.release()));
  }
  std::error_code ec;
  if (ok && !errors.HasFailure()) fs::rename(tmp, path, ec);
  if (!ok || errors.HasFailure() || ec) {
    RemoveQuietly(tmp);
    throw Error(path + ": cannot write the height raster (" +
                (ec ? ec.message() : errors.Message("GDAL failed")) + ")");
  }
}

}  // namespace roofsweep
