#include "io/core/image_io.h"

#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "algorithms/core/error.h"
#include "tests/support/shared_data.h"

namespace fs = std::filesystem;

namespace roofsweep {
namespace {

// A colour test card whose three channels differ everywhere.
cv::Mat Card8(int w = 64, int h = 48) {
  cv::Mat m(h, w, CV_8UC3);
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) {
      m.at<cv::Vec3b>(r, c) = cv::Vec3b(static_cast<uchar>(4 * c), static_cast<uchar>(5 * r),
                                        static_cast<uchar>((r * 7 + c * 3) % 256));
    }
  }
  return m;
}

std::vector<std::string> Listing(const std::string& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

void Truncate(const std::string& path, double keep) {
  const auto size = fs::file_size(path);
  fs::resize_file(path, static_cast<uintmax_t>(static_cast<double>(size) * keep));
}

// Writes a raster straight through GDAL, for layouts WriteImage does not make.
void WriteWithGdal(const std::string& path, int w, int h, int bands, GDALDataType type,
                   const std::vector<const char*>& options,
                   const std::function<double(int band, int r, int c)>& value,
                   const GDALColorTable* palette = nullptr) {
  GDALAllRegister();
  GDALDriver* drv = GetGDALDriverManager()->GetDriverByName("GTiff");
  std::vector<const char*> opts = options;
  opts.push_back(nullptr);
  GDALDataset* ds = drv->Create(path.c_str(), w, h, bands, type, const_cast<char**>(opts.data()));
  ASSERT_NE(ds, nullptr);
  for (int b = 1; b <= bands; ++b) {
    std::vector<double> data(static_cast<size_t>(w * h));
    for (int r = 0; r < h; ++r)
      for (int c = 0; c < w; ++c) data[static_cast<size_t>(r * w + c)] = value(b, r, c);
    ASSERT_EQ(
        ds->GetRasterBand(b)->RasterIO(GF_Write, 0, 0, w, h, data.data(), w, h, GDT_Float64, 0, 0),
        CE_None);
  }
  if (palette) {
    ds->GetRasterBand(1)->SetColorTable(const_cast<GDALColorTable*>(palette));
    ds->GetRasterBand(1)->SetColorInterpretation(GCI_PaletteIndex);
  }
  GDALClose(ds);
}

// A 6 x 4 palette image: red in the even columns, teal in the odd ones.
void WriteRedTealPalette(const std::string& path) {
  GDALColorTable table(GPI_RGB);
  const GDALColorEntry red{255, 0, 0, 255}, teal{0, 128, 128, 255};
  table.SetColorEntry(0, &red);
  table.SetColorEntry(1, &teal);
  WriteWithGdal(
      path, 6, 4, 1, GDT_Byte, {}, [](int, int, int c) { return c % 2; }, &table);
}

TEST(ImageIo, PngRoundTripKeepsRgbOrderAndScale) {
  const std::string dir = testing::TempDir();
  const std::string path = dir + "/card.png";
  const cv::Mat card = Card8();
  WriteImage(path, card);
  const ImageInfo info = ProbeImage(path);
  EXPECT_EQ(info.width, 64);
  EXPECT_EQ(info.height, 48);
  EXPECT_EQ(info.bands, 3);
  EXPECT_EQ(info.bits, 8);
  EXPECT_EQ(info.data_type, "Byte");
  EXPECT_EQ(info.driver, "PNG");
  const cv::Mat img = ReadImage(path);
  ASSERT_EQ(img.type(), CV_32FC3);
  for (int r : {0, 17, 47}) {
    for (int c : {0, 33, 63}) {
      const cv::Vec3b want = card.at<cv::Vec3b>(r, c);
      const cv::Vec3f got = img.at<cv::Vec3f>(r, c);
      for (int k = 0; k < 3; ++k) EXPECT_FLOAT_EQ(got[k], want[k] / 255.0f) << r << "," << c;
    }
  }
  // Channel 0 is red: OpenCV's own reader gives BGR, so its last channel.
  const cv::Mat cv_bgr = cv::imread(path, cv::IMREAD_UNCHANGED);
  EXPECT_EQ(cv_bgr.at<cv::Vec3b>(10, 20)[2], card.at<cv::Vec3b>(10, 20)[0]);
  EXPECT_EQ(Listing(dir), std::vector<std::string>{"card.png"});
}

TEST(ImageIo, TiledDeflateTiffRoundTripLeavesNothingElse) {
  const std::string dir = testing::TempDir();
  const std::string path = dir + "/card.tif";
  const cv::Mat card = Card8(300, 260);  // more than one 256-pixel tile
  WriteImage(path, card);
  GDALAllRegister();
  GDALDataset* ds = GDALDataset::Open(path.c_str(), GDAL_OF_RASTER);
  ASSERT_NE(ds, nullptr);
  int bx = 0, by = 0;
  ds->GetRasterBand(1)->GetBlockSize(&bx, &by);
  EXPECT_EQ(bx, 256);
  EXPECT_EQ(by, 256);
  EXPECT_STREQ(ds->GetMetadataItem("COMPRESSION", "IMAGE_STRUCTURE"), "DEFLATE");
  EXPECT_EQ(ds->GetRasterBand(1)->GetColorInterpretation(), GCI_RedBand);
  GDALClose(ds);
  const cv::Mat img = ReadImage(path);
  cv::Mat back;
  img.convertTo(back, CV_8UC3, 255.0);
  EXPECT_EQ(cv::norm(back, card, cv::NORM_INF), 0.0);
  EXPECT_EQ(Listing(dir), std::vector<std::string>{"card.tif"});
}

// A DTM as the simulator writes it: georeferenced, in its CRS, heights kept
// to float precision, nothing else left in the folder.
TEST(ImageIo, HeightRasterIsAGeoreferencedDtm) {
  const std::string dir = testing::TempDir();
  const std::string path = dir + "/dtm.tif";
  cv::Mat z(2, 3, CV_32FC1);
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 3; ++c) z.at<float>(r, c) = 500.25f + 10 * r + c;
  WriteHeightRaster(path, z, {691000, 2, 0, 5335004, 0, -2}, "EPSG:25832");
  EXPECT_EQ(Listing(dir), std::vector<std::string>{"dtm.tif"});
  GDALAllRegister();
  GDALDataset* ds = GDALDataset::Open(path.c_str(), GDAL_OF_RASTER);
  ASSERT_NE(ds, nullptr);
  double gt[6];
  ASSERT_EQ(ds->GetGeoTransform(gt), CE_None);
  EXPECT_EQ(gt[0], 691000);
  EXPECT_EQ(gt[3], 5335004);
  EXPECT_EQ(gt[5], -2);
  ASSERT_NE(ds->GetSpatialRef(), nullptr);
  EXPECT_STREQ(ds->GetSpatialRef()->GetAuthorityCode(nullptr), "25832");
  EXPECT_EQ(ds->GetRasterBand(1)->GetRasterDataType(), GDT_Float32);
  float back[6];
  ASSERT_EQ(ds->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, 3, 2, back, 3, 2, GDT_Float32, 0, 0),
            CE_None);
  GDALClose(ds);
  // Second row (south), third column.
  EXPECT_EQ(back[5], 512.25f);
  EXPECT_THROW(WriteHeightRaster(dir + "/bad.tif", cv::Mat(2, 2, CV_8UC1), {0, 1, 0, 0, 0, -1}, ""),
               Error);
  EXPECT_THROW(WriteHeightRaster(dir + "/bad.tif", z, {0, 1, 0, 0, 0, -1}, "EPSG:999999"), Error);
  EXPECT_EQ(Listing(dir), std::vector<std::string>{"dtm.tif"});
}

TEST(ImageIo, AWindowIsThatPartOfTheImage) {
  const std::string dir = testing::TempDir();
  const std::string path = dir + "/window.tif";
  const cv::Mat card = Card8(300, 260);
  WriteImage(path, card);
  const cv::Mat whole = ReadImage(path);
  // Across a tile border (256 px), and the whole image for an empty window.
  const cv::Rect w(200, 240, 90, 17);
  const cv::Mat part = ReadImage(path, w);
  ASSERT_EQ(part.size(), w.size());
  EXPECT_EQ(cv::norm(part, whole(w), cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(ReadImage(path, cv::Rect()), whole, cv::NORM_INF), 0.0);
  for (const cv::Rect& outside : {cv::Rect(250, 0, 51, 10), cv::Rect(-1, 0, 5, 5)}) {
    try {
      ReadImage(path, outside);
      ADD_FAILURE() << "a window beyond the image was read";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("window.tif: window"), std::string::npos) << e.what();
    }
  }
  // A palette image windowed too.
  const std::string pal = dir + "/window_pal.tif";
  WriteRedTealPalette(pal);
  const cv::Mat p = ReadImage(pal, cv::Rect(3, 1, 2, 2));
  ASSERT_EQ(p.size(), cv::Size(2, 2));
  EXPECT_NEAR(cv::norm(p.at<cv::Vec3f>(0, 0) - cv::Vec3f(0, 128 / 255.0f, 128 / 255.0f)), 0, 1e-7);
  EXPECT_NEAR(cv::norm(p.at<cv::Vec3f>(1, 1) - cv::Vec3f(1, 0, 0)), 0, 1e-7);
}

TEST(ImageIo, JpegQualityIsUsed) {
  const std::string dir = testing::TempDir();
  cv::Mat noisy(128, 128, CV_8UC3);
  cv::randu(noisy, 0, 256);
  WriteImage(dir + "/q95.jpg", noisy, 95);
  WriteImage(dir + "/q20.jpg", noisy, 20);
  EXPECT_GT(fs::file_size(dir + "/q95.jpg"), 2 * fs::file_size(dir + "/q20.jpg"));
  EXPECT_EQ(ProbeImage(dir + "/q95.jpg").driver, "JPEG");
  const cv::Mat smooth = Card8();
  WriteImage(dir + "/card.jpeg", smooth, 98);
  cv::Mat back;
  ReadImage(dir + "/card.jpeg").convertTo(back, CV_8UC3, 255.0);
  cv::Mat diff;
  cv::absdiff(back, smooth, diff);
  EXPECT_LT(cv::mean(diff)[0], 3.0);
  EXPECT_EQ(Listing(dir), (std::vector<std::string>{"card.jpeg", "q20.jpg", "q95.jpg"}));
  EXPECT_THROW(WriteImage(dir + "/bad.jpg", smooth, 0), Error);
}

TEST(ImageIo, GreyStaysOneChannel) {
  const std::string dir = testing::TempDir();
  cv::Mat grey(40, 30, CV_8UC1);
  for (int r = 0; r < 40; ++r)
    for (int c = 0; c < 30; ++c) grey.at<uchar>(r, c) = static_cast<uchar>(r * 5 + c);
  WriteImage(dir + "/g.png", grey);
  EXPECT_EQ(ProbeImage(dir + "/g.png").bands, 1);
  const cv::Mat img = ReadImage(dir + "/g.png");
  ASSERT_EQ(img.type(), CV_32FC1);
  EXPECT_FLOAT_EQ(img.at<float>(39, 29), (39 * 5 + 29) / 255.0f);
}

TEST(ImageIo, SixteenBitIsScaledBy65535) {
  const std::string dir = testing::TempDir();
  cv::Mat m(20, 20, CV_16UC3, cv::Scalar(65535, 32768, 1000));
  WriteImage(dir + "/w.tif", m);
  WriteImage(dir + "/w.png", m);
  for (const char* name : {"/w.tif", "/w.png"}) {
    const ImageInfo info = ProbeImage(dir + name);
    EXPECT_EQ(info.bits, 16) << name;
    EXPECT_EQ(info.data_type, "UInt16") << name;
    const cv::Vec3f px = ReadImage(dir + name).at<cv::Vec3f>(5, 5);
    EXPECT_FLOAT_EQ(px[0], 1.0f) << name;
    EXPECT_FLOAT_EQ(px[1], 32768.0f / 65535.0f) << name;
    EXPECT_FLOAT_EQ(px[2], 1000.0f / 65535.0f) << name;
  }
  EXPECT_THROW(WriteImage(dir + "/w.jpg", m), Error);
}

TEST(ImageIo, TwelveBitIsScaledByNbits) {
  const std::string path = testing::TempDir() + "/nbits12.tif";
  WriteWithGdal(path, 8, 8, 3, GDT_UInt16, {"NBITS=12", "PHOTOMETRIC=RGB"},
                [](int b, int r, int c) { return b == 1   ? 4095
                                                 : b == 2 ? 2048
                                                          : r * 8 + c; });
  EXPECT_EQ(ProbeImage(path).bits, 12);
  const cv::Mat img = ReadImage(path);
  EXPECT_FLOAT_EQ(img.at<cv::Vec3f>(3, 4)[0], 1.0f);
  EXPECT_FLOAT_EQ(img.at<cv::Vec3f>(3, 4)[1], 2048.0f / 4095.0f);
  EXPECT_FLOAT_EQ(img.at<cv::Vec3f>(3, 4)[2], 28.0f / 4095.0f);
}

TEST(ImageIo, PaletteIsExpanded) {
  const std::string path = testing::TempDir() + "/pal.tif";
  WriteRedTealPalette(path);
  const cv::Mat img = ReadImage(path);
  ASSERT_EQ(img.type(), CV_32FC3);
  const cv::Vec3f red_px = img.at<cv::Vec3f>(2, 0), teal_px = img.at<cv::Vec3f>(2, 1);
  EXPECT_NEAR(cv::norm(red_px - cv::Vec3f(1, 0, 0)), 0, 1e-7);
  EXPECT_NEAR(cv::norm(teal_px - cv::Vec3f(0, 128 / 255.0f, 128 / 255.0f)), 0, 1e-7);
}

TEST(ImageIo, FourBandsKeepTheFirstThree) {
  const std::string path = testing::TempDir() + "/rgba.tif";
  WriteWithGdal(path, 5, 5, 4, GDT_Byte, {"PHOTOMETRIC=RGB", "ALPHA=YES"},
                [](int b, int, int) { return 50.0 * b; });
  const cv::Mat img = ReadImage(path);
  ASSERT_EQ(img.type(), CV_32FC3);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(img.at<cv::Vec3f>(1, 1)[k], 50.0 * (k + 1) / 255.0, 1e-7);
}

TEST(ImageIo, BigTiffAndJpegInTiffAreRead) {
  const std::string dir = testing::TempDir();
  WriteWithGdal(dir + "/big.tif", 32, 32, 3, GDT_Byte,
                {"BIGTIFF=YES", "PHOTOMETRIC=RGB", "TILED=YES", "BLOCKXSIZE=16", "BLOCKYSIZE=16"},
                [](int b, int r, int c) { return (b * 40 + r + c) % 256; });
  const cv::Mat big = ReadImage(dir + "/big.tif");
  EXPECT_FLOAT_EQ(big.at<cv::Vec3f>(7, 9)[1], (80 + 16) / 255.0f);
  WriteWithGdal(dir + "/jpeg.tif", 64, 64, 3, GDT_Byte,
                {"COMPRESS=JPEG", "PHOTOMETRIC=YCBCR", "JPEG_QUALITY=95"}, [](int b, int r, int c) {
                  return b == 1 ? 200 : b == 2 ? 2 * r : 3 * c;
                });
  const cv::Vec3f px = ReadImage(dir + "/jpeg.tif").at<cv::Vec3f>(20, 30);
  EXPECT_NEAR(px[0] * 255, 200, 4);
  EXPECT_NEAR(px[1] * 255, 40, 4);
  EXPECT_NEAR(px[2] * 255, 90, 4);
}

TEST(ImageIo, MissingFileAndNonImagesAreErrors) {
  const std::string dir = testing::TempDir();
  try {
    ReadImage(dir + "/nope.tif");
    FAIL() << "no exception";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("nope.tif: no such file"), std::string::npos) << e.what();
  }
  std::ofstream(dir + "/notes.txt") << "these are not pixels\n";
  try {
    ProbeImage(dir + "/notes.txt");
    FAIL() << "no exception";
  } catch (const Error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("notes.txt: not a readable image"), std::string::npos) << msg;
  }
  EXPECT_THROW(ReadImage(dir), Error);
}

TEST(ImageIo, TinyImagesAreRefused) {
  const std::string dir = testing::TempDir();
  WriteImage(dir + "/one.png", cv::Mat(1, 1, CV_8UC3, cv::Scalar(1, 2, 3)));
  try {
    ProbeImage(dir + "/one.png");
    FAIL() << "no exception";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("1x1 pixels"), std::string::npos) << e.what();
  }
  EXPECT_THROW(ReadImage(dir + "/one.png"), Error);
}

TEST(ImageIo, TruncatedFilesAreErrorsNamingTheFile) {
  const std::string dir = testing::TempDir();
  cv::Mat noisy(256, 256, CV_8UC3);
  cv::randu(noisy, 0, 256);
  for (const char* name : {"/cut.png", "/cut.jpg", "/cut.tif"}) {
    const std::string path = dir + name;
    WriteImage(path, noisy, 90);
    Truncate(path, 0.5);
    try {
      ReadImage(path);
      FAIL() << name << ": truncated file was read";
    } catch (const Error& e) {
      const std::string msg = e.what();
      EXPECT_EQ(msg.rfind(path + ": ", 0), 0u) << msg;
      EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    }
  }
}

TEST(ImageIo, WriteFailuresLeaveNothing) {
  const std::string dir = testing::TempDir();
  EXPECT_THROW(WriteImage(dir + "/missing/sub/x.png", Card8()), Error);
  EXPECT_THROW(WriteImage(dir + "/x.bmp", Card8()), Error);
  EXPECT_THROW(WriteImage(dir + "/x.png", cv::Mat(4, 4, CV_32FC3)), Error);
  EXPECT_TRUE(Listing(dir).empty());
}

TEST(ImageIo, WriteReplacesAtomically) {
  const std::string dir = testing::TempDir();
  WriteImage(dir + "/a.png", Card8(10, 10));
  WriteImage(dir + "/a.png", Card8(12, 10));
  EXPECT_EQ(ProbeImage(dir + "/a.png").width, 12);
  EXPECT_EQ(Listing(dir), std::vector<std::string>{"a.png"});
}

TEST(ImageIo, RealJpegInTiffAerialImage) {
  ROOFSWEEP_SHARED_PATH_OR_SKIP(
      path, "data/multiview/orthority-ngi-aerial/3324c_2015_1004_05_0182_RGB.tif");
  const ImageInfo info = ProbeImage(path);
  EXPECT_EQ(info.width, 640);
  EXPECT_EQ(info.height, 1152);
  EXPECT_EQ(info.bands, 3);
  EXPECT_EQ(info.driver, "GTiff");
  const cv::Mat img = ReadImage(path);
  ASSERT_EQ(img.type(), CV_32FC3);
  double lo = 0, hi = 0;
  cv::minMaxLoc(img.reshape(1), &lo, &hi);
  EXPECT_GE(lo, 0.0);
  EXPECT_LE(hi, 1.0);
  // OpenCV decodes the same file through libtiff; the two readers agree
  // up to JPEG chroma upsampling.
  const cv::Mat bgr = cv::imread(path, cv::IMREAD_COLOR);
  ASSERT_FALSE(bgr.empty());
  cv::Mat rgb, ours;
  cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
  img.convertTo(ours, CV_8UC3, 255.0, 0.5);
  cv::Mat diff;
  cv::absdiff(ours, rgb, diff);
  const cv::Scalar mean_diff = cv::mean(diff);
  for (int k = 0; k < 3; ++k) EXPECT_LT(mean_diff[k], 2.0) << "channel " << k;
}

TEST(ImageIo, RealDroneImages) {
  ROOFSWEEP_SHARED_PATH_OR_SKIP(dir, "data/multiview/orthority-odm-drone/images");
  int n = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    const ImageInfo info = ProbeImage(e.path().string());
    EXPECT_EQ(info.width, 1368);
    EXPECT_EQ(info.height, 912);
    const cv::Mat img = ReadImage(e.path().string());
    EXPECT_EQ(img.channels(), 3);
    const cv::Scalar mean = cv::mean(img);
    EXPECT_GT(mean[0], 0.05);
    EXPECT_LT(mean[0], 0.95);
    ++n;
  }
  EXPECT_EQ(n, 4);
}

}  // namespace
}  // namespace roofsweep
