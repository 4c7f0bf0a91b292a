#pragma once

#include <array>
#include <opencv2/core.hpp>
#include <string>

namespace roofsweep {

struct ImageInfo {
  int width = 0;
  int height = 0;
  int bands = 0;
  int bits = 8;           // bits per sample (8, 16, 32)
  std::string data_type;  // GDAL name: Byte, UInt16, Float32, ...
  std::string driver;     // GDAL short name: GTiff, JPEG, PNG, ...
};

// Reads the header only. Throws roofsweep::Error "PATH: ..." when the file
// is missing or GDAL cannot read it.
ImageInfo ProbeImage(const std::string& path);

// Reads the header and the last block of pixel data: catches a missing,
// unreadable or truncated image without decoding all of a large block.
void CheckImageReadable(const std::string& path);

// Reads the whole image as float32 in [0, 1]: CV_32FC3 in R, G, B order for
// colour images (the first three bands of 3+ band images), CV_32FC1 for grey
// ones. 16-bit data is scaled by its declared bit depth (NBITS) or 65535.
// Palette images are expanded. Floating-point samples are returned as
// stored. EXIF orientation is ignored (pixels stay in sensor order, as the
// interior orientation expects). Throws on corrupt or truncated data and on
// images smaller than 2x2 pixels.
cv::Mat ReadImage(const std::string& path);

// The same for a window of the image (pixel rows window.y .. y + height - 1
// of columns window.x .. x + width - 1); only that part is decoded where the
// format allows (tiled or striped TIFF). An empty window reads the whole
// image. Throws when the window is not inside the image.
cv::Mat ReadImage(const std::string& path, const cv::Rect& window);

// Writes an 8-bit RGB (CV_8UC3, R, G, B order) or grey image through GDAL;
// the format follows the extension (.tif GeoTIFF tiled/deflate, .jpg JPEG
// quality `jpeg_quality`, .png PNG). Atomic: temporary name + rename.
void WriteImage(const std::string& path, const cv::Mat& rgb8, int jpeg_quality = 90);

// Writes a height raster (CV_32FC1, rows north to south) as a GeoTIFF in
// `crs` (any PROJ definition; empty: none) with the GDAL geotransform
// `geotransform` (x0, dx, 0, y0, 0, -dy): a DTM the block manifest can name.
// Atomic like WriteImage.
void WriteHeightRaster(const std::string& path, const cv::Mat& heights,
                       const std::array<double, 6>& geotransform, const std::string& crs);

}  // namespace roofsweep
